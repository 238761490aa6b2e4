#include "problems/implicit_shapes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <glog/logging.h>

namespace ergo {
namespace {

// Bisection on s for the closest-point equation Σ (r_i z_i / (s + r_i))² = 1 (Eberly,
// "Distance from a point to an ellipse, an ellipsoid, or a hyperellipsoid"): the function
// is monotone decreasing in s on the bracket, so bisection is robust. The closest point's
// coordinates are r_i y_i / (s + r_i) with s + r_i ≥ s + 1 > 0, so a bracket narrower than
// 1e-13 (s + 1) gives them to ~1e-13 relative accuracy; near the medial axis (s → −1)
// bisection runs to the double resolution instead.
template <int N>
double ClosestPointRoot(const std::array<double, N>& r, const std::array<double, N>& z, double g) {
  std::array<double, N> n;
  double length = 0;
  for (int i = 0; i < N; ++i) {
    n[i] = r[i] * z[i];
    length = std::max(length, std::abs(n[i]));
  }
  double norm = 0;
  for (int i = 0; i < N; ++i) norm += (n[i] / length) * (n[i] / length);
  norm = length * std::sqrt(norm);
  double s0 = z[N - 1] - 1, s1 = g < 0 ? 0 : norm - 1;
  double s = 0;
  for (int iteration = 0; iteration < 2000; ++iteration) {
    s = 0.5 * (s0 + s1);
    if (s == s0 || s == s1 || s1 - s0 < 1e-13 * (s0 + 1)) break;
    double value = -1;
    for (int i = 0; i < N; ++i) {
      const double ratio = n[i] / (s + r[i]);
      value += ratio * ratio;
    }
    if (value > 0) {
      s0 = s;
    } else if (value < 0) {
      s1 = s;
    } else {
      break;
    }
  }
  return s;
}

// Distance from (y0, y1), both ≥ 0, to the ellipse with semi-axes e0 ≥ e1 > 0.
double EllipseDistance(double e0, double e1, double y0, double y1) {
  if (y1 > 0) {
    if (y0 > 0) {
      const double z0 = y0 / e0, z1 = y1 / e1, g = z0 * z0 + z1 * z1 - 1;
      if (g == 0) return 0;
      const double r0 = (e0 / e1) * (e0 / e1);
      const double s = ClosestPointRoot<2>({r0, 1.0}, {z0, z1}, g);
      const double x0 = r0 * y0 / (s + r0), x1 = y1 / (s + 1);
      return std::hypot(x0 - y0, x1 - y1);
    }
    return std::abs(y1 - e1);
  }
  const double numerator = e0 * y0, denominator = e0 * e0 - e1 * e1;
  if (numerator < denominator) {
    const double ratio = numerator / denominator;
    const double x0 = e0 * ratio, x1 = e1 * std::sqrt(std::max(0.0, 1 - ratio * ratio));
    return std::hypot(x0 - y0, x1);
  }
  return std::abs(y0 - e0);
}

// Distance from y (all ≥ 0) to the ellipsoid with semi-axes e0 ≥ e1 ≥ e2 > 0.
double EllipsoidDistance(double e0, double e1, double e2, double y0, double y1, double y2) {
  if (y2 > 0) {
    if (y1 > 0) {
      if (y0 > 0) {
        const double z0 = y0 / e0, z1 = y1 / e1, z2 = y2 / e2;
        const double g = z0 * z0 + z1 * z1 + z2 * z2 - 1;
        if (g == 0) return 0;
        const double r0 = (e0 / e2) * (e0 / e2), r1 = (e1 / e2) * (e1 / e2);
        const double s = ClosestPointRoot<3>({r0, r1, 1.0}, {z0, z1, z2}, g);
        const double x0 = r0 * y0 / (s + r0), x1 = r1 * y1 / (s + r1), x2 = y2 / (s + 1);
        return std::sqrt((x0 - y0) * (x0 - y0) + (x1 - y1) * (x1 - y1) + (x2 - y2) * (x2 - y2));
      }
      return EllipseDistance(e1, e2, y1, y2);
    }
    if (y0 > 0) return EllipseDistance(e0, e2, y0, y2);
    return std::abs(y2 - e2);
  }
  // y2 = 0: the closest point may leave the plane z = 0 (points deep inside).
  const double d0 = e0 * e0 - e2 * e2, d1 = e1 * e1 - e2 * e2;
  const double n0 = e0 * y0, n1 = e1 * y1;
  if (n0 < d0 && n1 < d1) {
    const double r0 = n0 / d0, r1 = n1 / d1, discriminant = 1 - r0 * r0 - r1 * r1;
    if (discriminant > 0) {
      const double x0 = e0 * r0, x1 = e1 * r1, x2 = e2 * std::sqrt(discriminant);
      return std::sqrt((x0 - y0) * (x0 - y0) + (x1 - y1) * (x1 - y1) + x2 * x2);
    }
  }
  return EllipseDistance(e0, e1, y0, y1);
}

}  // namespace

double SignedDistance(const Ellipsoid& ellipsoid, const Eigen::Vector3d& p) {
  const Eigen::Vector3d q = ellipsoid.axes.transpose() * (p - ellipsoid.centre);
  // Sort the axes by decreasing semi-axis, carrying |q| along.
  // Components within 1e-12 of a semi-axis of a principal plane are on it (rounding in the
  // rotation would otherwise leave the exact branch for an ill-conditioned bisection).
  std::array<std::pair<double, double>, 3> axis;
  for (int i = 0; i < 3; ++i) {
    const double e = ellipsoid.semi_axes[i], y = std::abs(q[i]);
    axis[i] = {e, y < 1e-12 * e ? 0.0 : y};
  }
  std::sort(axis.begin(), axis.end(),
            [](const auto& x, const auto& y) { return x.first > y.first; });
  const double distance = EllipsoidDistance(axis[0].first, axis[1].first, axis[2].first,
                                            axis[0].second, axis[1].second, axis[2].second);
  double level = 0;
  for (int i = 0; i < 3; ++i)
    level += (q[i] / ellipsoid.semi_axes[i]) * (q[i] / ellipsoid.semi_axes[i]);
  return level < 1 ? -distance : distance;
}

double SignedDistance(const RoundCone& cone, const Eigen::Vector3d& p) {
  // Order so that ball A is the larger one; the problem is planar in (axial, radial).
  const bool swap = cone.radius_b > cone.radius_a;
  const Eigen::Vector3d& a = swap ? cone.b : cone.a;
  const Eigen::Vector3d& b = swap ? cone.a : cone.b;
  const double ra = swap ? cone.radius_b : cone.radius_a;
  const double rb = swap ? cone.radius_a : cone.radius_b;
  const Eigen::Vector3d axis = b - a;
  const double length = axis.norm();
  if (length <= ra - rb) return (p - a).norm() - ra;  // ball B inside ball A
  const Eigen::Vector3d u = axis / length;
  const Eigen::Vector3d d = p - a;
  const double x = d.dot(u);
  const double y = std::sqrt(std::max(0.0, d.squaredNorm() - x * x));
  // The outer tangent line touches ball A at ra·n and ball B at (length, 0) + rb·n, with
  // n = (sin θ, cos θ), sin θ = (ra − rb)/length; t = (cos θ, −sin θ) runs along it.
  const double sine = (ra - rb) / length, cosine = std::sqrt(1 - sine * sine);
  const double along = x * cosine - y * sine;
  if (along < 0) return std::hypot(x, y) - ra;
  if (along > length * cosine) return std::hypot(x - length, y) - rb;
  return x * sine + y * cosine - ra;
}

double SmoothMin(double a, double b, double blend) {
  const double h = std::max(blend - std::abs(a - b), 0.0) / blend;
  return std::min(a, b) - 0.25 * blend * h * h;
}

Eigen::Matrix3d EulerXYZ(double ax, double ay, double az) {
  return (Eigen::AngleAxisd(az, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(ay, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(ax, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

BlendedShape::BlendedShape(double blend_radius, double region_width, int region_count)
    : blend_radius_(blend_radius), region_width_(region_width), region_count_(region_count) {
  CHECK_GT(blend_radius, 0.0);
  CHECK_GT(region_width, 0.0);
  CHECK_GE(region_count, 1);
}

double BlendedShape::Primitive::Distance(const Eigen::Vector3d& p) const {
  return is_ellipsoid ? SignedDistance(ellipsoid, p) : SignedDistance(cone, p);
}

void BlendedShape::Push(Primitive primitive) {
  CHECK(primitive.region >= 0 && primitive.region < region_count_) << primitive.region;
  primitives_.push_back(std::move(primitive));
}

void BlendedShape::Add(const Ellipsoid& ellipsoid, int region) {
  CHECK((ellipsoid.semi_axes.array() > 0).all());
  CHECK_LT((ellipsoid.axes.transpose() * ellipsoid.axes - Eigen::Matrix3d::Identity()).norm(),
           1e-9);
  Primitive primitive;
  primitive.ellipsoid = ellipsoid;
  primitive.region = region;
  primitive.outer_centre = primitive.inner_centre = ellipsoid.centre;
  primitive.outer_radius = ellipsoid.semi_axes.maxCoeff();
  primitive.inner_radius = ellipsoid.semi_axes.minCoeff();
  Push(primitive);
}

void BlendedShape::Add(const RoundCone& cone, int region) {
  CHECK_GT(cone.radius_a, 0.0);
  CHECK_GT(cone.radius_b, 0.0);
  Primitive primitive;
  primitive.is_ellipsoid = false;
  primitive.cone = cone;
  primitive.region = region;
  // Bounding ball: around the midpoint; inscribed: the larger end ball.
  primitive.outer_centre = 0.5 * (cone.a + cone.b);
  primitive.outer_radius = 0.5 * (cone.b - cone.a).norm() + std::max(cone.radius_a, cone.radius_b);
  const bool a_larger = cone.radius_a >= cone.radius_b;
  primitive.inner_centre = a_larger ? cone.a : cone.b;
  primitive.inner_radius = std::max(cone.radius_a, cone.radius_b);
  Push(primitive);
}

double BlendedShape::Evaluate(const Eigen::Vector3d& p, double* weights) const {
  CHECK(!primitives_.empty());
  // Distances of a superset (the bounding ball) and a subset (the inscribed ball) bound
  // each primitive's signed distance from below and above.
  double upper = std::numeric_limits<double>::infinity();
  for (const Primitive& q : primitives_)
    upper = std::min(upper, (p - q.inner_centre).norm() - q.inner_radius);
  const double cutoff = upper + std::max(blend_radius_, region_width_);
  constexpr int kMaxPrimitives = 64;
  CHECK_LE(primitives_.size(), static_cast<size_t>(kMaxPrimitives));
  std::array<double, kMaxPrimitives> distance;
  double nearest = std::numeric_limits<double>::infinity(), blended = 0;
  bool first = true;
  for (size_t i = 0; i < primitives_.size(); ++i) {
    const Primitive& q = primitives_[i];
    if ((p - q.outer_centre).norm() - q.outer_radius >= cutoff) {
      distance[i] = std::numeric_limits<double>::infinity();
      continue;
    }
    distance[i] = q.Distance(p);
    nearest = std::min(nearest, distance[i]);
    blended = first ? distance[i] : SmoothMin(blended, distance[i], blend_radius_);
    first = false;
  }
  if (weights != nullptr) {
    std::fill(weights, weights + region_count_, 0.0);
    double total = 0;
    for (size_t i = 0; i < primitives_.size(); ++i) {
      const double t = (distance[i] - nearest) / region_width_;
      if (!(t < 1)) continue;
      const double w = (1 - t) * (1 - t) * (1 - t);
      weights[primitives_[i].region] += w;
      total += w;
    }
    for (int r = 0; r < region_count_; ++r) weights[r] /= total;
  }
  return blended;
}

Eigen::AlignedBox3d BlendedShape::Bounds(double margin) const {
  Eigen::AlignedBox3d box;
  for (const Primitive& q : primitives_) {
    const Eigen::Vector3d r = Eigen::Vector3d::Constant(q.outer_radius + margin);
    box.extend(q.outer_centre - r);
    box.extend(q.outer_centre + r);
  }
  return box;
}

}  // namespace ergo
