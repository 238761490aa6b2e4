// Smooth implicit shapes for the generated body parts (paper §3.1 scans real people; we have
// no scans, so problems/ builds plausible body parts from primitives): exact signed distances
// of ellipsoids and round cones (capsules with two end radii), a polynomial smooth union, and
// a BlendedShape whose primitives carry region tags that give smooth region weights (for
// depth and stiffness fields). Signed distances are negative inside; metres.
#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace ergo {

struct Ellipsoid {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d semi_axes = Eigen::Vector3d::Ones();  // along the local axes, m, > 0
  // Columns: the local axes in world coordinates (a rotation).
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
};

// The convex hull of two balls (a capsule when the radii are equal): a tapered limb.
struct RoundCone {
  Eigen::Vector3d a = Eigen::Vector3d::Zero(), b = Eigen::Vector3d::UnitX();
  double radius_a = 0.1, radius_b = 0.1;  // m, > 0
};

// Exact signed Euclidean distance to the ellipsoid's surface (Eberly's bisection on the
// closest-point equation, to ~1e-12 relative accuracy).
double SignedDistance(const Ellipsoid& ellipsoid, const Eigen::Vector3d& p);

// Exact signed distance to the round cone's surface (one ball contains the other: to the
// larger ball).
double SignedDistance(const RoundCone& cone, const Eigen::Vector3d& p);

// Polynomial smooth minimum: min(a, b) − blend·h²/4 with h = max(blend − |a − b|, 0)/blend.
// Equal to min(a, b) when |a − b| ≥ blend; never above it; C¹. blend > 0 (m).
double SmoothMin(double a, double b, double blend);

// Rotation taking the x, y, z axes to unit vectors by angles (radians) about x, then y, then z
// (R = Rz·Ry·Rx): for orienting primitives.
Eigen::Matrix3d EulerXYZ(double ax, double ay, double az);

// A body outline: the smooth union of tagged primitives. Evaluate() gives the signed distance
// (sequential SmoothMin with `blend_radius`) and per-region weights from each primitive's
// distance excess over the nearest one, w ∝ Σ (1 − (f_i − f_min)/region_width)³₊, summing to 1.
// Primitives whose bounding ball is farther than the nearest one's inscribed ball by more than
// max(blend, region width) are skipped: the result is the same, only faster.
class BlendedShape {
 public:
  // blend_radius > 0 (m), region_width > 0 (m), region_count ≥ 1.
  BlendedShape(double blend_radius, double region_width, int region_count);

  void Add(const Ellipsoid& ellipsoid, int region);
  void Add(const RoundCone& cone, int region);

  int region_count() const { return region_count_; }
  int primitive_count() const { return static_cast<int>(primitives_.size()); }
  // Signed distance of the blended outline (negative inside, m); `weights` (may be null)
  // receives region_count() non-negative weights summing to 1. Thread-safe.
  double Evaluate(const Eigen::Vector3d& p, double* weights = nullptr) const;
  // A box holding every primitive, grown by `margin` metres.
  Eigen::AlignedBox3d Bounds(double margin) const;

 private:
  struct Primitive {
    bool is_ellipsoid = true;
    Ellipsoid ellipsoid;
    RoundCone cone;
    int region = 0;
    Eigen::Vector3d outer_centre, inner_centre;  // bounding ball and an inscribed ball
    double outer_radius = 0, inner_radius = 0;
    double Distance(const Eigen::Vector3d& p) const;
  };
  void Push(Primitive primitive);

  double blend_radius_, region_width_;
  int region_count_;
  std::vector<Primitive> primitives_;
};

}  // namespace ergo
