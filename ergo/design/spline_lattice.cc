#include "ergo/design/spline_lattice.h"

#include <array>
#include <cmath>
#include <map>
#include <tuple>
#include <vector>

#include <glog/logging.h>

namespace ergo {

double SplineLattice::CubicBSpline(double t) {
  const double a = std::abs(t);
  if (a >= 2) return 0;
  if (a >= 1) return (2 - a) * (2 - a) * (2 - a) / 6;
  return 2.0 / 3.0 - a * a + 0.5 * a * a * a;
}

SplineLattice::SplineLattice(const Eigen::MatrixXd& points, double spacing,
                             const Eigen::Vector3d& origin)
    : spacing_(spacing), origin_(origin) {
  CHECK(spacing > 0 && std::isfinite(spacing)) << "a spline lattice needs a spacing > 0 m";
  CHECK_EQ(points.cols(), 3);
  const Eigen::Index count = points.rows();
  // Lattice indices are ints: the tools refuse knot spacings below 1 mm (scene_flags.cc).
  CHECK(count == 0 ||
        ((points.rowwise() - origin.transpose()).cwiseAbs().maxCoeff() / spacing < 1e8))
      << "a spline lattice of spacing " << spacing << " m is too fine for these points";

  // Per point the 4 x 4 x 4 controls around it and their weights; the controls are numbered
  // in lexicographic lattice order, so the numbering depends on the geometry only.
  std::map<std::tuple<int, int, int>, int> index;
  struct Entry {
    int point;
    std::tuple<int, int, int> control;
    double weight;
  };
  std::vector<Entry> entries;
  entries.reserve(static_cast<size_t>(count) * 64);
  for (Eigen::Index p = 0; p < count; ++p) {
    std::array<std::array<double, 4>, 3> weights;
    std::array<int, 3> first;
    for (int axis = 0; axis < 3; ++axis) {
      const double u = (points(p, axis) - origin_[axis]) / spacing;
      first[axis] = static_cast<int>(std::floor(u)) - 1;
      for (int a = 0; a < 4; ++a) weights[axis][a] = CubicBSpline(u - (first[axis] + a));
    }
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        for (int c = 0; c < 4; ++c) {
          const double w = weights[0][a] * weights[1][b] * weights[2][c];
          if (w <= 0) continue;  // a point on a knot plane: the outer layer does not reach it
          const auto key = std::make_tuple(first[0] + a, first[1] + b, first[2] + c);
          index.emplace(key, 0);
          entries.push_back({static_cast<int>(p), key, w});
        }
  }
  controls_.resize(static_cast<Eigen::Index>(index.size()), 3);
  int next = 0;
  for (auto& [key, number] : index) {  // std::map: lexicographic (i, j, k)
    number = next;
    controls_.row(next) << std::get<0>(key), std::get<1>(key), std::get<2>(key);
    ++next;
  }
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(entries.size());
  for (const Entry& e : entries) triplets.emplace_back(e.point, index.at(e.control), e.weight);
  basis_.resize(count, controls_.rows());
  basis_.setFromTriplets(triplets.begin(), triplets.end());
  basis_.makeCompressed();
}

Eigen::Vector3d SplineLattice::ControlPosition(int control) const {
  return origin_ + spacing_ * controls_.row(control).transpose().cast<double>();
}

}  // namespace ergo
