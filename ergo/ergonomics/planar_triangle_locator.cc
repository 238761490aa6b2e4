#include "ergo/ergonomics/planar_triangle_locator.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glog/logging.h>

namespace ergo {
namespace {

double Cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// A point on an edge shared by two triangles belongs to both: a barycentric coordinate down
// to −1e-10 (round-off of the cross products, relative to the triangle) still counts.
constexpr double kInsideTolerance = 1e-10;
// More buckets per side than this would cost more memory than the queries save.
constexpr int kMaxBucketsPerSide = 2048;

}  // namespace

PlanarTriangleLocator::PlanarTriangleLocator(PlanarPoints points, Triangles triangles)
    : points_(std::move(points)), triangles_(std::move(triangles)) {
  for (Eigen::Index f = 0; f < triangles_.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      CHECK(triangles_(f, k) >= 0 && triangles_(f, k) < points_.rows()) << "index out of range";
  if (triangles_.rows() == 0) {
    bucket_start_.assign(1, 0);
    return;
  }
  lower_ = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  upper_ = -lower_;
  for (Eigen::Index f = 0; f < triangles_.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      lower_ = lower_.cwiseMin(points_.row(triangles_(f, k)).transpose());
      upper_ = upper_.cwiseMax(points_.row(triangles_(f, k)).transpose());
    }
  }
  const Eigen::Vector2d extent = (upper_ - lower_).cwiseMax(1e-12);
  const double box_area = extent.x() * extent.y();
  std::vector<int> valid;
  for (Eigen::Index f = 0; f < triangles_.rows(); ++f) {
    const Eigen::Vector2d a = points_.row(triangles_(f, 0)), b = points_.row(triangles_(f, 1)),
                          c = points_.row(triangles_(f, 2));
    if (std::abs(Cross(b - a, c - a)) > 1e-12 * box_area) valid.push_back(static_cast<int>(f));
  }
  // About one triangle per bucket.
  bucket_size_ = std::sqrt(box_area / std::max<size_t>(valid.size(), 1));
  bucket_size_ =
      std::max({bucket_size_, extent.x() / kMaxBucketsPerSide, extent.y() / kMaxBucketsPerSide});
  columns_ = std::max(1, static_cast<int>(std::ceil(extent.x() / bucket_size_)));
  rows_ = std::max(1, static_cast<int>(std::ceil(extent.y() / bucket_size_)));
  std::vector<int> count(static_cast<size_t>(columns_) * rows_ + 1, 0);
  auto cell_range = [&](int f, int* i0, int* i1, int* j0, int* j1) {
    Eigen::Vector2d lo = points_.row(triangles_(f, 0)), hi = lo;
    for (int k = 1; k < 3; ++k) {
      lo = lo.cwiseMin(points_.row(triangles_(f, k)).transpose());
      hi = hi.cwiseMax(points_.row(triangles_(f, k)).transpose());
    }
    *i0 = std::clamp(static_cast<int>(std::floor((lo.x() - lower_.x()) / bucket_size_)), 0,
                     columns_ - 1);
    *i1 = std::clamp(static_cast<int>(std::floor((hi.x() - lower_.x()) / bucket_size_)), 0,
                     columns_ - 1);
    *j0 = std::clamp(static_cast<int>(std::floor((lo.y() - lower_.y()) / bucket_size_)), 0,
                     rows_ - 1);
    *j1 = std::clamp(static_cast<int>(std::floor((hi.y() - lower_.y()) / bucket_size_)), 0,
                     rows_ - 1);
  };
  for (int f : valid) {
    int i0, i1, j0, j1;
    cell_range(f, &i0, &i1, &j0, &j1);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) ++count[BucketIndex(i, j) + 1];
  }
  for (size_t b = 1; b < count.size(); ++b) count[b] += count[b - 1];
  bucket_start_ = count;
  bucket_triangles_.resize(static_cast<size_t>(count.back()));
  std::vector<int> fill(count.begin(), count.end() - 1);
  for (int f : valid) {
    int i0, i1, j0, j1;
    cell_range(f, &i0, &i1, &j0, &j1);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) bucket_triangles_[fill[BucketIndex(i, j)]++] = f;
  }
}

void PlanarTriangleLocator::Locate(const Eigen::Vector2d& q, std::vector<PlanarHit>* hits) const {
  hits->clear();
  if (bucket_triangles_.empty()) return;
  const double slack = 1e-9 * bucket_size_;
  if (q.x() < lower_.x() - slack || q.y() < lower_.y() - slack || q.x() > upper_.x() + slack ||
      q.y() > upper_.y() + slack)
    return;
  const int i = std::clamp(static_cast<int>(std::floor((q.x() - lower_.x()) / bucket_size_)), 0,
                           columns_ - 1);
  const int j =
      std::clamp(static_cast<int>(std::floor((q.y() - lower_.y()) / bucket_size_)), 0, rows_ - 1);
  const int b = BucketIndex(i, j);
  for (int k = bucket_start_[b]; k < bucket_start_[b + 1]; ++k) {
    const int f = bucket_triangles_[k];
    const Eigen::Vector2d a = points_.row(triangles_(f, 0)), p1 = points_.row(triangles_(f, 1)),
                          p2 = points_.row(triangles_(f, 2));
    const double twice_area = Cross(p1 - a, p2 - a);
    const double l1 = Cross(q - a, p2 - a) / twice_area;
    const double l2 = Cross(p1 - a, q - a) / twice_area;
    const double l0 = 1 - l1 - l2;
    if (l0 < -kInsideTolerance || l1 < -kInsideTolerance || l2 < -kInsideTolerance) continue;
    PlanarHit hit;
    hit.triangle = f;
    hit.barycentric = Eigen::Vector3d(l0, l1, l2);
    hits->push_back(hit);
  }
}

}  // namespace ergo
