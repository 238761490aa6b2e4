#include "ergo/body/heel_bisector.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include <Eigen/Dense>

#include "ergo/mesh/input_error.h"

namespace ergo {

HeelBisector MeasureHeelBisector(const TriMesh& foot, bool heel_at_min_z, double medial_sign,
                                 const HeelBisectorOptions& options, const std::string& source) {
  if (!(options.rear_fraction > 0 && options.rear_fraction <= 1) || !(options.lowest_height >= 0) ||
      !(options.highest_height > options.lowest_height) || !(options.height_step > 0) ||
      !(options.min_slices >= 2)) {
    throw InputError(source, "heel bisector options",
                     "need a rear fraction in (0, 1], heights 0 <= lowest < highest, a positive "
                     "step and at least two slices",
                     "check HeelBisectorOptions");
  }
  const Vertices& v = foot.vertices;
  if (v.rows() == 0 || foot.triangles.rows() == 0)
    throw InputError(source, "", "no skin to find the heel's bisector on", "");
  const double min_z = v.col(2).minCoeff(), max_z = v.col(2).maxCoeff();
  const double reach = options.rear_fraction * (max_z - min_z);
  auto in_heel = [&](double z) { return heel_at_min_z ? z <= min_z + reach : z >= max_z - reach; };
  double floor_y = std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 0; i < v.rows(); ++i)
    if (in_heel(v(i, 2))) floor_y = std::min(floor_y, v(i, 1));

  // Each slice's outline across the foot: where the skin's edges cross the slice's height.
  const int count =
      static_cast<int>(std::floor(
          (options.highest_height - options.lowest_height) / options.height_step + 1e-9)) +
      1;
  std::vector<double> lo(count, std::numeric_limits<double>::infinity());
  std::vector<double> hi(count, -std::numeric_limits<double>::infinity());
  auto height_of = [&](int k) { return floor_y + options.lowest_height + k * options.height_step; };
  for (Eigen::Index t = 0; t < foot.triangles.rows(); ++t) {
    for (int e = 0; e < 3; ++e) {
      const Eigen::Vector3d a = v.row(foot.triangles(t, e)).transpose();
      const Eigen::Vector3d b = v.row(foot.triangles(t, (e + 1) % 3)).transpose();
      const double y0 = std::min(a.y(), b.y()), y1 = std::max(a.y(), b.y());
      if (!(y1 > y0)) continue;
      const int first =
          std::max(0, static_cast<int>(
                          std::ceil((y0 - floor_y - options.lowest_height) / options.height_step)));
      for (int k = first; k < count && height_of(k) <= y1; ++k) {
        const double h = height_of(k);
        if (h < y0) continue;
        const Eigen::Vector3d p = a + (h - a.y()) / (b.y() - a.y()) * (b - a);
        if (!in_heel(p.z())) continue;
        lo[k] = std::min(lo[k], p.x());
        hi[k] = std::max(hi[k], p.x());
      }
    }
  }
  std::vector<double> heights, mids;
  for (int k = 0; k < count; ++k) {
    if (!(hi[k] > lo[k])) continue;
    heights.push_back(height_of(k) - floor_y);
    mids.push_back(0.5 * (lo[k] + hi[k]));
  }
  const int n = static_cast<int>(heights.size());
  if (n < options.min_slices) {
    std::ostringstream what;
    what << "the heel's outline was found at " << n << " of " << count << " heights ("
         << 1e3 * options.lowest_height << "-" << 1e3 * options.highest_height
         << " mm above its lowest skin), too few to draw its bisector";
    throw InputError(source, "heel", what.str(),
                     "check that the scan has its heel, closed, and the foot's axes (y up, the "
                     "length along z), or give the roll in degrees");
  }
  // Least squares x = x0 + lean·h.
  Eigen::MatrixXd design(n, 2);
  Eigen::VectorXd x(n);
  for (int i = 0; i < n; ++i) {
    design(i, 0) = 1;
    design(i, 1) = heights[i];
    x(i) = mids[i];
  }
  const Eigen::Vector2d fit = design.colPivHouseholderQr().solve(x);
  HeelBisector bisector;
  bisector.lean = fit(1);
  bisector.eversion = std::atan(medial_sign * fit(1));
  bisector.slices = n;
  bisector.rms_residual = std::sqrt((design * fit - x).squaredNorm() / n);
  bisector.heel_floor_y = floor_y;
  return bisector;
}

}  // namespace ergo
