#include "ergo/ergonomics/planar_pressure_map.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <glog/logging.h>
#include <Eigen/Geometry>

namespace ergo {

namespace {

// The triangles of `surface` whose outward normal points along `facing` (+y or −y).
Triangles FacingTriangles(const TriMesh& surface, PlanarPressureMap::Facing facing) {
  std::vector<int> kept;
  for (Eigen::Index f = 0; f < surface.triangles.rows(); ++f) {
    const Eigen::Vector3d a = surface.vertices.row(surface.triangles(f, 0));
    const Eigen::Vector3d b = surface.vertices.row(surface.triangles(f, 1));
    const Eigen::Vector3d c = surface.vertices.row(surface.triangles(f, 2));
    const double normal_y = (b - a).cross(c - a).y();
    if (facing == PlanarPressureMap::Facing::kUp ? normal_y > 0 : normal_y < 0)
      kept.push_back(static_cast<int>(f));
  }
  Triangles facing_triangles(static_cast<Eigen::Index>(kept.size()), 3);
  for (size_t k = 0; k < kept.size(); ++k)
    facing_triangles.row(static_cast<Eigen::Index>(k)) = surface.triangles.row(kept[k]);
  return facing_triangles;
}

PlanarPoints SeenAlongY(const TriMesh& surface) {
  PlanarPoints points(surface.vertices.rows(), 2);
  points.col(0) = surface.vertices.col(0);
  points.col(1) = surface.vertices.col(2);
  return points;
}

}  // namespace

PlanarPressureMap PlanarPressureMap::FromVertexForces(const TriMesh& surface,
                                                      const Eigen::VectorXd& force, Facing facing) {
  const Eigen::Index n = surface.vertices.rows();
  CHECK_EQ(force.size(), n);
  const PlanarPoints points = SeenAlongY(surface);
  const Triangles facing_triangles = FacingTriangles(surface, facing);
  Eigen::VectorXd covered = Eigen::VectorXd::Zero(n);  // ŝ_v
  for (Eigen::Index f = 0; f < facing_triangles.rows(); ++f) {
    const Eigen::Vector2d a = points.row(facing_triangles(f, 0)),
                          b = points.row(facing_triangles(f, 1)),
                          c = points.row(facing_triangles(f, 2));
    const Eigen::Vector2d ab = b - a, ac = c - a;
    const double third = std::abs(ab.x() * ac.y() - ab.y() * ac.x()) / 6;
    for (int k = 0; k < 3; ++k) covered[facing_triangles(f, k)] += third;
  }
  Eigen::VectorXd pressure = Eigen::VectorXd::Zero(n);
  double unplaced = 0;
  for (Eigen::Index v = 0; v < n; ++v) {
    if (covered[v] > 0) {
      pressure[v] = force[v] / covered[v];
    } else {
      unplaced += std::abs(force[v]);
    }
  }
  PlanarPressureMap map = FromSurface(surface, pressure, covered, facing);
  map.unplaced_force_ = unplaced;
  return map;
}

PlanarPressureMap PlanarPressureMap::FromSurface(const TriMesh& surface,
                                                 const Eigen::VectorXd& pressure,
                                                 const Eigen::VectorXd& area, Facing facing) {
  const Eigen::Index n = surface.vertices.rows();
  CHECK_EQ(pressure.size(), n);
  CHECK_EQ(area.size(), n);
  const PlanarPoints points = SeenAlongY(surface);
  const Triangles facing_triangles = FacingTriangles(surface, facing);

  PlanarPressureMap map;
  map.locator_ = std::make_shared<const PlanarTriangleLocator>(points, facing_triangles);
  map.vertex_pressure_ = std::make_shared<const Eigen::VectorXd>(pressure);
  map.source_lower_ = map.locator_->lower();
  map.source_upper_ = map.locator_->upper();
  map.points_ = points;
  map.pressure_ = pressure;
  map.area_ = area;
  return map;
}

PlanarPressureMap PlanarPressureMap::FromGrid(const PressureGrid& grid) {
  CHECK_GT(grid.pitch, 0);
  PlanarPressureMap map;
  map.grid_ = std::make_shared<const PressureGrid>(grid);
  const Eigen::Index rows = grid.rows(), columns = grid.columns();
  map.points_.resize(rows * columns, 2);
  map.pressure_.resize(rows * columns);
  map.area_ = Eigen::VectorXd::Constant(rows * columns, grid.pitch * grid.pitch);
  for (Eigen::Index r = 0; r < rows; ++r) {
    for (Eigen::Index c = 0; c < columns; ++c) {
      const Eigen::Index i = r * columns + c;
      map.points_.row(i) = grid.CellCentre(r, c).transpose();
      map.pressure_[i] = grid.pressure(r, c);
    }
  }
  // The bilinear field reaches one pitch beyond the outer centres.
  map.source_lower_ = grid.origin - Eigen::Vector2d::Constant(0.5 * grid.pitch);
  map.source_upper_ = grid.origin + grid.pitch * Eigen::Vector2d(static_cast<double>(columns) + 0.5,
                                                                 static_cast<double>(rows) + 0.5);
  return map;
}

double PlanarPressureMap::PressureAt(const Eigen::Vector2d& q) const {
  const Eigen::Vector2d source = placement_.Inverse().Apply(q);
  if (grid_) return grid_->PressureAt(source);
  thread_local std::vector<PlanarHit> hits;
  locator_->Locate(source, &hits);
  double value = 0;
  bool found = false;
  for (const PlanarHit& hit : hits) {
    double p = 0;
    for (int k = 0; k < 3; ++k)
      p += hit.barycentric[k] * (*vertex_pressure_)[locator_->triangles()(hit.triangle, k)];
    value = found ? std::max(value, p) : p;
    found = true;
  }
  return value;
}

void PlanarPressureMap::Bounds(Eigen::Vector2d* lower, Eigen::Vector2d* upper) const {
  *lower = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  *upper = -*lower;
  for (int corner = 0; corner < 4; ++corner) {
    const Eigen::Vector2d q((corner & 1) ? source_upper_.x() : source_lower_.x(),
                            (corner & 2) ? source_upper_.y() : source_lower_.y());
    const Eigen::Vector2d moved = placement_.Apply(q);
    *lower = lower->cwiseMin(moved);
    *upper = upper->cwiseMax(moved);
  }
}

PlanarPressureMap PlanarPressureMap::Moved(const RigidMotion2d& motion) const {
  PlanarPressureMap moved = *this;
  moved.placement_ = motion.After(placement_);
  const Eigen::Matrix2d rotation = motion.Rotation();
  for (Eigen::Index i = 0; i < points_.rows(); ++i)
    moved.points_.row(i) = (rotation * points_.row(i).transpose() + motion.translation).transpose();
  return moved;
}

}  // namespace ergo
