#include "problems/hand_body.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "ergo/mesh/input_error.h"
#include "problems/smooth_step.h"

namespace ergo {
namespace {

enum HandRegion { kPalm = 0, kFingers = 1, kThumb = 2, kHandRegions = 3 };

// Signed distance to the union of the balls.
double UnionDistance(const std::vector<Ball>& balls, const Eigen::Vector3d& p) {
  double d = std::numeric_limits<double>::infinity();
  for (const Ball& b : balls) d = std::min(d, (p - b.centre).norm() - b.radius);
  return d;
}

// Smallest clearance between the balls and a tapered segment (sampled along its axis).
double SegmentClearance(const std::vector<Ball>& balls, const Eigen::Vector3d& a,
                        const Eigen::Vector3d& b, double ra, double rb) {
  double clearance = std::numeric_limits<double>::infinity();
  for (int k = 0; k <= 24; ++k) {
    const double t = k / 24.0;
    clearance = std::min(clearance, UnionDistance(balls, a + t * (b - a)) - (ra + t * (rb - ra)));
  }
  return clearance;
}

// A digit: joints from `base`, each segment turned from direction u towards v by a growing
// angle until it rests on the balls with `gap` clearance (a relaxed curl): the angle of each
// segment starts at the previous one's; a segment that meets nothing curls by `idle_curl`.
std::vector<Eigen::Vector3d> CurlDigit(const std::vector<Ball>& balls, const Eigen::Vector3d& base,
                                       const Eigen::Vector3d& u, const Eigen::Vector3d& v,
                                       const std::vector<double>& lengths,
                                       const std::vector<double>& radii, double gap,
                                       double idle_curl) {
  constexpr double kMaxAngle = 1.5, kStep = 0.01;
  std::vector<Eigen::Vector3d> joints = {base};
  double angle = 0;
  for (size_t k = 0; k < lengths.size(); ++k) {
    const Eigen::Vector3d& a = joints.back();
    auto clearance = [&](double theta) {
      const Eigen::Vector3d b = a + lengths[k] * (std::cos(theta) * u + std::sin(theta) * v);
      return SegmentClearance(balls, a, b, radii[k], radii[k + 1]) - gap;
    };
    double theta = angle;
    if (clearance(theta) <= 0) {
      // Already touching: straighten until free.
      while (theta > angle - 1.0 && clearance(theta) <= 0) theta -= kStep;
    } else {
      double previous = theta;
      while (theta < kMaxAngle && clearance(theta) > 0) previous = theta, theta += kStep;
      if (clearance(theta) > 0) {
        theta = std::min(angle + idle_curl, kMaxAngle);  // meets nothing: relaxed curl
      } else {
        double lo = previous, hi = theta;  // clearance(lo) > 0 ≥ clearance(hi)
        for (int i = 0; i < 40; ++i) {
          const double mid = 0.5 * (lo + hi);
          (clearance(mid) > 0 ? lo : hi) = mid;
        }
        theta = lo;
      }
    }
    angle = theta;
    joints.push_back(a + lengths[k] * (std::cos(theta) * u + std::sin(theta) * v));
  }
  return joints;
}

}  // namespace

ImplicitBodySpec MakeHandSpec(const HandOptions& o, const std::vector<Ball>& balls) {
  if (balls.empty()) {
    throw InputError("hand", "", "there is nothing to rest the hand on", "give the mouse's balls");
  }
  if (!(o.palm_breadth > 0.05 && o.palm_breadth < 0.12) ||
      !(o.palm_length > 0.06 && o.palm_length < 0.14) ||
      !(o.palm_thickness > 0.015 && o.palm_thickness < 0.05) ||
      !(o.finger_scale > 0.6 && o.finger_scale < 1.5)) {
    throw InputError("hand", "dimensions", "the palm or finger dimensions are not an adult's",
                     "palm breadth 0.05–0.12 m, length 0.06–0.14 m, thickness 0.015–0.05 m, "
                     "finger scale 0.6–1.5");
  }
  for (double d : {o.palm_depth, o.dorsal_depth, o.finger_depth, o.thumb_depth}) {
    if (!(d > 0 && d < 0.5 * o.palm_thickness)) {
      throw InputError("hand", "depth", "tissue depths must be positive and below half the palm",
                       "e.g. palm 0.010, back 0.005, fingers 0.004 m");
    }
  }
  ImplicitBodySpec spec{"hand",          BlendedShape(o.blend_radius, o.region_width, kHandRegions),
                        nullptr,         nullptr,
                        o.poisson_ratio, 1050,
                        o.total_mass};
  const Eigen::Matrix3d tilt = EulerXYZ(o.palm_tilt, 0, 0);
  const Eigen::Vector3d semi(0.5 * o.palm_breadth, 0.5 * o.palm_thickness, 0.5 * o.palm_length);

  // Palm: lowered onto the balls (bisection on its height) until its clearance is the gap.
  auto palm_clearance = [&](double y) {
    const Eigen::Vector3d centre(0, y, o.palm_centre_z);
    double clearance = std::numeric_limits<double>::infinity();
    for (int i = 0; i <= 24; ++i) {
      for (int j = 0; j < 48; ++j) {
        const double theta = M_PI * i / 24, phi = M_PI * j / 24;
        const Eigen::Vector3d local(semi.x() * std::sin(theta) * std::cos(phi),
                                    semi.y() * std::cos(theta),
                                    semi.z() * std::sin(theta) * std::sin(phi));
        clearance = std::min(clearance, UnionDistance(balls, centre + tilt * local));
      }
    }
    return clearance - o.clearance;
  };
  double top = -std::numeric_limits<double>::infinity();
  for (const Ball& b : balls) top = std::max(top, b.centre.y() + b.radius);
  double lo = top - 0.5 * o.palm_thickness, hi = top + 0.2;
  if (palm_clearance(lo) > 0) {
    throw InputError("hand", "", "no ball lies under the palm",
                     "move the palm (palm_centre_z) over the mouse");
  }
  for (int i = 0; i < 50; ++i) {
    const double mid = 0.5 * (lo + hi);
    (palm_clearance(mid) > 0 ? hi : lo) = mid;
  }
  const Eigen::Vector3d palm_centre(0, hi, o.palm_centre_z);
  spec.shape.Add(Ellipsoid{palm_centre, semi, tilt}, kPalm);
  auto palm_point = [&](double x, double y, double z) {
    return Eigen::Vector3d(palm_centre + tilt * Eigen::Vector3d(x, y, z));
  };

  // Fingers (index, middle, ring, little): phalanges 45/30/25 % of the length to the tip's
  // centre, from the knuckles at the palm's front edge.
  const struct {
    double x, length, r_base, r_tip;
  } fingers[] = {{0.32, 0.085, 0.0095, 0.0078},
                 {0.10, 0.095, 0.0095, 0.008},
                 {-0.13, 0.090, 0.009, 0.0075},
                 {-0.35, 0.070, 0.008, 0.0068}};
  const Eigen::Vector3d forward = tilt * Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d down = tilt * -Eigen::Vector3d::UnitY();
  for (const auto& f : fingers) {
    const double length = o.finger_scale * f.length;
    const std::vector<double> lengths = {0.45 * length, 0.30 * length, 0.25 * length};
    std::vector<double> radii(4);
    for (int k = 0; k < 4; ++k) radii[k] = f.r_base + (f.r_tip - f.r_base) * k / 3.0;
    const Eigen::Vector3d knuckle = palm_point(f.x * o.palm_breadth, 0, 0.42 * o.palm_length);
    const std::vector<Eigen::Vector3d> joints =
        CurlDigit(balls, knuckle, forward, down, lengths, radii, o.clearance, 0.3);
    for (int k = 0; k < 3; ++k)
      spec.shape.Add(RoundCone{joints[k], joints[k + 1], radii[k], radii[k + 1]}, kFingers);
  }
  // Thumb: from the base of the palm's +x side, forward and down along the mouse's side.
  {
    const Eigen::Vector3d u = (tilt * Eigen::Vector3d(0.25, -0.2, 0.95)).normalized();
    Eigen::Vector3d v = tilt * Eigen::Vector3d(-0.15, -0.99, 0);
    v = (v - v.dot(u) * u).normalized();
    const std::vector<double> lengths = {0.040 * o.finger_scale, 0.032 * o.finger_scale,
                                         0.025 * o.finger_scale};
    const std::vector<double> radii = {0.013, 0.011, 0.0095, 0.009};
    const Eigen::Vector3d base =
        palm_point(0.36 * o.palm_breadth, -0.1 * o.palm_thickness, -0.15 * o.palm_length);
    const std::vector<Eigen::Vector3d> joints =
        CurlDigit(balls, base, u, v, lengths, radii, o.clearance, 0.25);
    for (int k = 0; k < 3; ++k)
      spec.shape.Add(RoundCone{joints[k], joints[k + 1], radii[k], radii[k + 1]}, kThumb);
  }

  // Depth: under the palm palm_depth, over its back dorsal_depth (a smooth step across the
  // palm's mid-plane), fingers and thumb their own.
  const Eigen::Matrix3d to_palm = tilt.transpose();
  const double half = semi.y();
  const double palm_depth = o.palm_depth, dorsal = o.dorsal_depth;
  const double finger_depth = o.finger_depth, thumb_depth = o.thumb_depth;
  spec.depth = [=](const Eigen::Vector3d& p, const double* w) {
    const double height = (to_palm * (p - palm_centre)).y();
    const double palm =
        palm_depth + (dorsal - palm_depth) * SmoothStep(-0.5 * half, 0.5 * half, height);
    return w[kPalm] * palm + w[kFingers] * finger_depth + w[kThumb] * thumb_depth;
  };
  const std::array<double, kHandRegions> modulus = {o.palm_modulus, o.finger_modulus,
                                                    o.thumb_modulus};
  spec.stiffness = [modulus](const Eigen::Vector3d&, const double* w) {
    return w[kPalm] * modulus[kPalm] + w[kFingers] * modulus[kFingers] +
           w[kThumb] * modulus[kThumb];
  };
  return spec;
}

}  // namespace ergo
