#include "problems/seated_body.h"

#include <array>
#include <string>

#include "ergo/mesh/input_error.h"

namespace ergo {
namespace {

enum SeatedRegion { kButtocks = 0, kThighs = 1, kLowerBack = 2, kPelvis = 3, kSeatedRegions = 4 };

}  // namespace

ImplicitBodySpec MakeSeatedBodySpec(const SeatedBodyOptions& o) {
  const double depths[] = {o.buttock_depth, o.thigh_depth, o.back_depth, o.pelvis_depth};
  for (double d : depths) {
    if (!(d > 0 && d < 0.08)) {
      throw InputError("seated body", "depth", "tissue depths must lie in (0, 0.08) m",
                       "e.g. buttocks 0.045, thighs 0.03, back 0.022 m");
    }
  }
  if (!(o.hip_breadth > 0.25 && o.hip_breadth < 0.6) ||
      !(o.buttock_knee_length > 0.35 && o.buttock_knee_length < 0.75)) {
    throw InputError("seated body", "dimensions",
                     "hip breadth must lie in (0.25, 0.6) m and buttock–knee length in "
                     "(0.35, 0.75) m",
                     "use adult dimensions, e.g. 0.38 and 0.53 m");
  }
  ImplicitBodySpec spec{
      "seated body",   BlendedShape(o.blend_radius, o.region_width, kSeatedRegions),
      nullptr,         nullptr,
      o.poisson_ratio, 1050,
      o.total_mass};
  const double bz = o.back_z;
  // Buttocks: two ellipsoids whose outer sides make the hip breadth and whose lowest points
  // (under the ischial tuberosities) are at y = 0.
  const Eigen::Vector3d buttock_axes(0.10, 0.12, 0.10);
  const double buttock_x = 0.5 * o.hip_breadth - buttock_axes.x();
  for (double side : {-1.0, 1.0}) {
    spec.shape.Add(
        Ellipsoid{Eigen::Vector3d(side * buttock_x, buttock_axes.y(), bz + buttock_axes.z()),
                  buttock_axes, Eigen::Matrix3d::Identity()},
        kButtocks);
  }
  // Pelvis: joins the buttocks and carries the lower back; clear of the seat.
  spec.shape.Add(Ellipsoid{Eigen::Vector3d(0, 0.16, bz + 0.13),
                           Eigen::Vector3d(0.5 * o.hip_breadth - 0.03, 0.12, 0.11),
                           Eigen::Matrix3d::Identity()},
                 kPelvis);
  // Thighs: tapered limbs from the hips forward to near the knees, undersides near the seat.
  const double hip_radius = 0.085, knee_radius = 0.06;
  const double knee_z = bz + o.buttock_knee_length - knee_radius;
  for (double side : {-1.0, 1.0}) {
    spec.shape.Add(RoundCone{Eigen::Vector3d(side * (buttock_x + 0.005), hip_radius, bz + 0.16),
                             Eigen::Vector3d(side * (buttock_x + 0.02), knee_radius + 0.01, knee_z),
                             hip_radius, knee_radius},
                   kThighs);
  }
  // Lower back: a flattened ellipsoid rising behind the pelvis, leaning back by 10°.
  spec.shape.Add(
      Ellipsoid{Eigen::Vector3d(0, 0.30, bz + 0.08),
                Eigen::Vector3d(0.5 * o.hip_breadth - 0.04, 0.16, 0.08), EulerXYZ(-0.17, 0, 0)},
      kLowerBack);

  const std::array<double, kSeatedRegions> depth = {o.buttock_depth, o.thigh_depth, o.back_depth,
                                                    o.pelvis_depth};
  const std::array<double, kSeatedRegions> modulus = {o.buttock_modulus, o.thigh_modulus,
                                                      o.back_modulus, o.pelvis_modulus};
  spec.depth = [depth](const Eigen::Vector3d&, const double* w) {
    double d = 0;
    for (int r = 0; r < kSeatedRegions; ++r) d += w[r] * depth[r];
    return d;
  };
  spec.stiffness = [modulus](const Eigen::Vector3d&, const double* w) {
    double e = 0;
    for (int r = 0; r < kSeatedRegions; ++r) e += w[r] * modulus[r];
    return e;
  };
  return spec;
}

}  // namespace ergo
