#include "problems/bump_scenario.h"

#include <cmath>

#include "ergo/body/core_lock.h"
#include "ergo/body/layer_builder.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/primitives.h"

namespace ergo {

LayeredBody MakeSoftBall(double radius, double core_radius, double youngs_modulus,
                         double poisson_ratio, double edge_length, const Eigen::Vector3d& centre,
                         const LayeredBodyOptions& options) {
  if (!(core_radius > 0 && core_radius < radius)) {
    throw InputError("ball", "", "core radius must lie strictly between 0 and the ball radius",
                     "choose 0 < core_radius < ball_radius");
  }
  ImplicitLayer layer;
  layer.outer = [=](const Eigen::Vector3d& p) { return (p - centre).norm() - radius; };
  layer.core = [=](const Eigen::Vector3d& p) { return (p - centre).norm() - core_radius; };
  const Eigen::Vector3d margin = Eigen::Vector3d::Constant(1.2 * radius);
  layer.bounds = Eigen::AlignedBox3d(centre - margin, centre + margin);
  BuilderOptions builder;
  builder.edge_length = edge_length;
  const BuiltLayer built = BuildLayerFromImplicit(layer, builder, "soft ball");
  TissueMaterial material;
  material.youngs_modulus = Eigen::VectorXd::Constant(built.mesh.tets.rows(), youngs_modulus);
  material.poisson_ratio = Eigen::VectorXd::Constant(built.mesh.tets.rows(), poisson_ratio);
  return LayeredBody::Create(built.mesh, built.attached, material, options, "soft ball");
}

Scenario MakeBumpScenario(const BumpScenarioOptions& o) {
  if (!(o.bump_height >= 0 && o.bump_height < o.plate_thickness) || !(o.bump_width > 0)) {
    throw InputError("bump scenario", "",
                     "the bump must be non-negative, lower than the plate thickness, and wide",
                     "use 0 <= bump_height < plate_thickness and bump_width > 0");
  }
  Scenario scenario;
  scenario.name = "bump";
  scenario.description = "soft ball (R " + std::to_string(o.ball_radius) +
                         " m) on a plate with a " + std::to_string(o.bump_height * 1e3) +
                         " mm bump of width " + std::to_string(o.bump_width * 1e3) + " mm";
  const Eigen::Vector2d c = o.bump_centre;
  const double w2 = 2 * o.bump_width * o.bump_width;
  scenario.support = MakeHeightfieldBlock(
      {-o.plate_half_width, -o.plate_thickness, -o.plate_half_width},
      {o.plate_half_width, 0, o.plate_half_width}, {o.plate_cells, 1, o.plate_cells},
      [&](double x, double z) {
        return o.bump_height *
               std::exp(-((x - c.x()) * (x - c.x()) + (z - c.y()) * (z - c.y())) / w2);
      });

  LayeredBodyOptions body_options;
  body_options.lock = ParseCoreLock("tx,tz,rx,ry,rz");
  // Resting over the plate's centre, just above the bump's highest point.
  double top = 0;
  for (Eigen::Index v = 0; v < scenario.support.vertices.rows(); ++v)
    top = std::max(top, scenario.support.vertices(v, 1));
  const Eigen::Vector3d centre(0, top + o.ball_radius + o.drop_height, 0);
  scenario.body = std::make_shared<LayeredBody>(MakeSoftBall(o.ball_radius, o.core_radius,
                                                             o.youngs_modulus, o.poisson_ratio,
                                                             o.edge_length, centre, body_options));
  scenario.start = RestState(*scenario.body);
  scenario.design.placement_gap = o.drop_height;

  scenario.design.equilibrium.contact_stiffness = o.contact_stiffness;
  scenario.design.parameterization = DesignParameterization::kNormalDisplacement;
  scenario.design.active.resize(static_cast<size_t>(scenario.support.vertices.rows()));
  for (Eigen::Index v = 0; v < scenario.support.vertices.rows(); ++v) {
    // The top face: every vertex above the plate's mid-plane that is not on the rim.
    const Eigen::Vector3d p = scenario.support.vertices.row(v);
    scenario.design.active[v] =
        p.y() > -0.5 * o.plate_thickness &&
        std::max(std::abs(p.x()), std::abs(p.z())) < o.plate_half_width - 1e-9;
  }
  return scenario;
}

}  // namespace ergo
