// A contact-pressure map seen along the load on the support's plane (x, z), y up: the field
// p(q) that footprints, correlations and pictures are computed from, and the force-carrying
// samples (point q_i, pressure p_i, area a_i; force p_i a_i) that totals, region shares and
// peaks are summed over, so that a map's total is exactly the force its source reports.
// Built from a surface with per-vertex pressures (a sensor map interpolated onto the support,
// ergo's support-side samples) or per-vertex contact forces (ergo's skin at equilibrium: the
// pressure a plate would read is the force over the area the vertex covers seen from below,
// ‖f_v‖ / ŝ_v with ŝ_v the projected barycentric area of the facing triangles around v, so the
// field integrates to exactly the total force — ergo's own skin pressure ‖f_v‖ / s_v is per
// area at rest, and plantar skin in contact stretches: on the quick shoe the contact vertices'
// areas grow by 1.37 (median) and up to 2.5 times); the field is piecewise linear over the
// triangles that face the other body, the largest value where projected triangles overlap, so
// a layer out of contact never hides the one in contact. Or from a pressure plate's grid
// (bilinear, PressureGrid). A map moves rigidly in the plane (Moved), field and samples
// together. Pa, m², m, N.
#pragma once

#include <memory>

#include <Eigen/Core>

#include "ergo/ergonomics/planar_triangle_locator.h"
#include "ergo/ergonomics/pressure_grid.h"
#include "ergo/ergonomics/rigid_motion_2d.h"
#include "ergo/mesh/tri_mesh.h"

namespace ergo {

class PlanarPressureMap {
 public:
  // Which triangles carry the field: those whose outward normal points up (+y: a support's
  // top) or down (−y: the skin resting on it).
  enum class Facing { kUp, kDown };

  // `pressure` (Pa) and `area` (m²) per vertex of `surface` (metres); the samples are every
  // vertex, projected to (x, z).
  static PlanarPressureMap FromSurface(const TriMesh& surface, const Eigen::VectorXd& pressure,
                                       const Eigen::VectorXd& area, Facing facing);
  // `force` (N, magnitude) per vertex of `surface` (metres, deformed): samples of pressure
  // force_v / ŝ_v and area ŝ_v (ŝ_v = Σ over the facing triangles around v of a third of
  // their area projected onto (x, z)). A vertex with force but no facing triangle carries it
  // in unplaced_force() and no sample pressure.
  static PlanarPressureMap FromVertexForces(const TriMesh& surface, const Eigen::VectorXd& force,
                                            Facing facing);
  // The plate's cells as samples (area h² each) and its bilinear field, in the plate's frame.
  static PlanarPressureMap FromGrid(const PressureGrid& grid);

  // The field at q (this map's frame), Pa; 0 where the map has no data.
  double PressureAt(const Eigen::Vector2d& q) const;

  const PlanarPoints& sample_points() const { return points_; }         // m, this map's frame
  const Eigen::VectorXd& sample_pressure() const { return pressure_; }  // Pa
  const Eigen::VectorXd& sample_area() const { return area_; }          // m²
  // Σ p_i a_i, N.
  double TotalForce() const { return pressure_.dot(area_); }
  // Force of vertices the field cannot show (FromVertexForces), N; 0 otherwise.
  double unplaced_force() const { return unplaced_force_; }
  // A box (this map's frame) outside which the field is zero.
  void Bounds(Eigen::Vector2d* lower, Eigen::Vector2d* upper) const;

  // This map moved by `motion` (applied after its current placement).
  PlanarPressureMap Moved(const RigidMotion2d& motion) const;
  // Source frame (the surface's (x, z), the plate's frame) → this map's frame.
  const RigidMotion2d& placement() const { return placement_; }

 private:
  PlanarPressureMap() = default;

  // One of the two sources, shared between moved copies.
  std::shared_ptr<const PlanarTriangleLocator> locator_;
  std::shared_ptr<const Eigen::VectorXd> vertex_pressure_;
  std::shared_ptr<const PressureGrid> grid_;
  Eigen::Vector2d source_lower_ = Eigen::Vector2d::Zero(), source_upper_ = Eigen::Vector2d::Zero();
  RigidMotion2d placement_;
  PlanarPoints points_;
  Eigen::VectorXd pressure_, area_;
  double unplaced_force_ = 0;
};

}  // namespace ergo
