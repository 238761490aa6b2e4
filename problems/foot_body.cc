#include "problems/foot_body.h"

#include <algorithm>
#include <array>

#include "ergo/mesh/input_error.h"
#include "problems/smooth_step.h"

namespace ergo {
namespace {

enum FootRegion { kHeel = 0, kArch = 1, kBall = 2, kToes = 3, kAnkle = 4, kFootRegions = 5 };

}  // namespace

ImplicitBodySpec MakeFootSpec(const FootOptions& o) {
  if (!(o.length > 0.18 && o.length < 0.34) || !(o.breadth_scale > 0.6 && o.breadth_scale < 1.6)) {
    throw InputError("foot", "dimensions",
                     "the foot length must lie in (0.18, 0.34) m and the breadth scale in "
                     "(0.6, 1.6)",
                     "use adult dimensions, e.g. 0.26 m and 1.0");
  }
  for (double d : {o.heel_depth, o.arch_depth, o.ball_depth, o.dorsal_depth}) {
    if (!(d > 0 && d < 0.03)) {
      throw InputError("foot", "depth", "plantar and dorsal depths must lie in (0, 0.03) m",
                       "e.g. heel 0.018, arch 0.010, ball 0.013, dorsal 0.006 m");
    }
  }
  const double s = o.length / 0.26;  // every length is given for a 0.26 m foot
  const double bx = o.breadth_scale;
  // Local design coordinates (heel's back at z = 0) → the foot's frame (centred on z = 0).
  auto at = [&](double x, double y, double z) {
    return Eigen::Vector3d(s * bx * x, s * y, s * z - 0.5 * o.length);
  };
  auto axes = [&](double x, double y, double z) {
    return Eigen::Vector3d(s * bx * x, s * y, s * z);
  };
  ImplicitBodySpec spec{
      "foot",          BlendedShape(s * o.blend_radius, s * o.region_width, kFootRegions),
      nullptr,         nullptr,
      o.poisson_ratio, 1050,
      o.total_mass};
  // Heel: its lowest point at y = 0 and its back at z = 0.
  spec.shape.Add(
      Ellipsoid{at(0, 0.033, 0.045), axes(0.031, 0.033, 0.045), Eigen::Matrix3d::Identity()},
      kHeel);
  // Midfoot: rolled so the medial (+x) arch is higher than the lateral border.
  spec.shape.Add(
      Ellipsoid{at(-0.002, 0.045, 0.115), axes(0.040, 0.032, 0.07), EulerXYZ(0, 0, 0.26)}, kArch);
  // Ball (metatarsal heads): turned so the medial side reaches further forward.
  spec.shape.Add(
      Ellipsoid{at(0.005, 0.024, 0.185), axes(0.050, 0.024, 0.03), EulerXYZ(0, -0.17, 0)}, kBall);
  // Toes, big toe first (medial), each a tapered limb from its base forward.
  const struct {
    double x0, y0, z0, r0, x1, y1, z1, r1;
  } toes[] = {{0.028, 0.020, 0.205, 0.014, 0.032, 0.014, 0.245, 0.012},
              {0.006, 0.016, 0.205, 0.009, 0.006, 0.011, 0.238, 0.0085},
              {-0.012, 0.016, 0.200, 0.0085, -0.014, 0.011, 0.230, 0.008},
              {-0.028, 0.015, 0.193, 0.008, -0.031, 0.010, 0.220, 0.0075},
              {-0.042, 0.014, 0.183, 0.0075, -0.046, 0.010, 0.205, 0.007}};
  for (const auto& t : toes) {
    spec.shape.Add(RoundCone{at(t.x0, t.y0, t.z0), at(t.x1, t.y1, t.z1), s * t.r0, s * t.r1},
                   kToes);
  }
  // Ankle and the start of the leg, above the heel and the back of the arch.
  spec.shape.Add(RoundCone{at(0, 0.06, 0.06), at(0, 0.13, 0.05), s * 0.034, s * 0.032}, kAnkle);

  // Depth: plantar values by region under the sole, the dorsal value over the top (a smooth
  // step in height), and the toes all tissue (their depth exceeds their radius).
  const double toe_depth = s * 0.016;
  const double low = s * 0.012, high = s * 0.040;
  const std::array<double, kFootRegions> plantar = {o.heel_depth, o.arch_depth, o.ball_depth,
                                                    toe_depth, o.dorsal_depth};
  const double dorsal = o.dorsal_depth;
  spec.depth = [plantar, dorsal, toe_depth, low, high](const Eigen::Vector3d& p, const double* w) {
    const double rest = 1 - w[kToes];
    if (rest < 1e-12) return toe_depth;
    double sole = 0;
    for (int r : {kHeel, kArch, kBall, kAnkle}) sole += w[r] * plantar[r];
    sole /= rest;
    const double side = dorsal + (sole - dorsal) * (1 - SmoothStep(low, high, p.y()));
    return w[kToes] * toe_depth + rest * side;
  };
  const std::array<double, kFootRegions> modulus = {o.heel_modulus, o.arch_modulus, o.ball_modulus,
                                                    o.toe_modulus, o.dorsal_modulus};
  spec.stiffness = [modulus](const Eigen::Vector3d&, const double* w) {
    double e = 0;
    for (int r = 0; r < kFootRegions; ++r) e += w[r] * modulus[r];
    return e;
  };
  return spec;
}

}  // namespace ergo
