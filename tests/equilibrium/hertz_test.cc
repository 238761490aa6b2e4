// Hertz contact (an answer known without the code): an elastic ball of radius R with a
// small rigid core, pressed onto a rigid plane — or onto a soft slab, a second elastic body
// (ergo/body/elastic_part.h) — by a force F on the core, in the small-strain regime.
// Theory: contact radius a = (3FR / 4E*)^(1/3), peak pressure p0 = 3F / (2π a²), pressure
// p(r) = p0 √(1 − r²/a²), with 1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂ (the rigid plane: E₂ = ∞).
// The simulated a and p0 come from a least-squares fit of that profile to the skin-vertex
// pressures (Ceres, hand-written Jacobian); both must be within 10 % and, on the rigid plane,
// improve under refinement.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <vector>

#include <ceres/ceres.h>
#include <gtest/gtest.h>

#include "ergo/body/core_lock.h"
#include "ergo/body/elastic_part.h"
#include "ergo/body/layer_builder.h"
#include "ergo/equilibrium/calibrate_contact_stiffness.h"
#include "ergo/equilibrium/equilibrium_solver.h"
#include "ergo/equilibrium/placement.h"
#include "ergo/mesh/primitives.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

constexpr double kRadius = 0.05, kCore = 0.015, kYoung = 1e4, kPoisson = 0.3;

// Residual p0 √(1 − r²/a²)₊ − p for one vertex; parameters (p0, a).
class HertzProfileResidual : public ceres::SizedCostFunction<1, 2> {
 public:
  HertzProfileResidual(double r, double p, double weight) : r_(r), p_(p), w_(weight) {}
  bool Evaluate(double const* const* parameters, double* residual,
                double** jacobians) const override {
    const double p0 = parameters[0][0], a = parameters[0][1];
    const double s = 1 - r_ * r_ / (a * a);
    const double root = s > 0 ? std::sqrt(s) : 0;
    residual[0] = w_ * (p0 * root - p_);
    if (jacobians && jacobians[0]) {
      jacobians[0][0] = w_ * root;
      // d/da √(1 − r²/a²) = r² / (a³ √(…)); capped near the rim where the profile is vertical.
      jacobians[0][1] = root > 1e-3 ? w_ * p0 * r_ * r_ / (a * a * a * root) : 0;
    }
    return true;
  }

 private:
  double r_, p_, w_;
};

struct HertzMeasurement {
  double a = 0, p0 = 0, a_moment = 0;
  int vertices = 0, contacts = 0;
  double penetration = 0;
};

// Grid lines from 0 to ±`extent`: `fine` apart up to `fine_extent`, then growing by 35 % a
// cell (the last cell ends at `extent`). Sorted, with 0 included.
std::vector<double> GradedLines(double fine, double fine_extent, double extent, bool both_sides) {
  std::vector<double> half = {0};
  double cell = fine;
  while (half.back() < extent - 1e-12) {
    if (half.back() >= fine_extent - 1e-12) cell *= 1.35;
    half.push_back(std::min(extent, half.back() + cell));
  }
  std::vector<double> lines;
  if (both_sides)
    for (auto it = half.rbegin(); it + 1 != half.rend(); ++it) lines.push_back(-*it);
  for (double x : half) lines.push_back(x);
  return lines;
}

// A slab under the ball: top face at y = 0, 80 mm each side, 70 mm deep with its bottom held;
// `fine` cells within 15 mm of the axis and 10 mm of the top, graded coarser outwards.
std::shared_ptr<const ElasticPart> MakeSoftSlab(double fine, double modulus) {
  const std::vector<double> xs = GradedLines(fine, 0.015, 0.08, true);
  std::vector<double> ys = GradedLines(fine, 0.01, 0.07, false);
  for (double& y : ys) y = -y;
  std::reverse(ys.begin(), ys.end());
  const TetMesh mesh = MakeRectilinearTetGrid(xs, ys, xs);
  std::vector<bool> base(static_cast<size_t>(mesh.vertices.rows()));
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v)
    base[v] = mesh.vertices(v, 1) < ys.front() + 1e-9;
  return std::make_shared<const ElasticPart>(
      ElasticPart::Create(mesh, base, UniformMaterial(mesh.tets.rows(), modulus, kPoisson),
                          ElasticPartOptions{}, "soft slab"));
}

// `slab_modulus` 0: the rigid plane.
HertzMeasurement Simulate(double fine_edge, double force, double slab_modulus = 0) {
  // The ball, refined near its bottom (the contact) and coarse elsewhere.
  const Eigen::Vector3d centre(0, kRadius, 0), bottom(0, 0, 0);
  ImplicitLayer layer;
  layer.outer = [&](const Eigen::Vector3d& p) { return (p - centre).norm() - kRadius; };
  layer.core = [&](const Eigen::Vector3d& p) { return (p - centre).norm() - kCore; };
  layer.bounds = Eigen::AlignedBox3d(centre - Eigen::Vector3d::Constant(1.2 * kRadius),
                                     centre + Eigen::Vector3d::Constant(1.2 * kRadius));
  BuilderOptions builder;
  builder.edge_length = 0.012;
  builder.edge_length_field = [=](const Eigen::Vector3d& p) {
    const double d = (p - bottom).norm();
    return std::min(0.012, fine_edge + std::max(0.0, d - 0.016) * 0.4);
  };
  const BuiltLayer built = BuildLayerFromImplicit(layer, builder, "Hertz ball");
  TissueMaterial material;
  material.youngs_modulus = Eigen::VectorXd::Constant(built.mesh.tets.rows(), kYoung);
  material.poisson_ratio = Eigen::VectorXd::Constant(built.mesh.tets.rows(), kPoisson);
  LayeredBodyOptions options;
  options.gravity.setZero();  // the load is F alone
  options.external_force = Eigen::Vector3d(0, -force, 0);
  options.lock = ParseCoreLock("tx,tz,rx,ry,rz");
  const LayeredBody body =
      LayeredBody::Create(built.mesh, built.attached, material, options, "Hertz ball");

  const std::shared_ptr<const ElasticPart> slab =
      slab_modulus > 0 ? MakeSoftSlab(fine_edge, slab_modulus) : nullptr;
  const Support plane =
      slab ? SoftSupportSurface(*slab, "soft slab")
           : Support(MakeBox({-0.1, -0.05, -0.1}, {0.1, 0, 0.1}, {1, 1, 1}), "rigid plane");
  const BodyState start = PlaceAboveSupport(body, RestState(body), plane, 1e-4).state;
  EquilibriumOptions eq;
  eq.contact_stiffness = 1e7;  // κ, Pa/m: a first guess for the calibration
  EquilibriumSolver solver(body, eq, slab);
  // Penalty penetration ~1 % of the Hertz indentation a²/R (2 mm here).
  const double compliance =
      (1 - kPoisson * kPoisson) / kYoung + (slab ? (1 - kPoisson * kPoisson) / slab_modulus : 0.0);
  const double a_theory = std::cbrt(3 * force * kRadius * compliance / 4);
  EquilibriumResult result;
  const CalibrationResult calibration = CalibrateContactStiffness(
      solver, plane, start, 0.01 * a_theory * a_theory / kRadius, CalibrationOptions(), &result);
  EXPECT_TRUE(calibration.converged) << calibration.BriefReport();
  result = solver.Solve(plane, result.state);
  EXPECT_TRUE(result.converged) << result.FullReport();

  TotalPotential::Evaluation e;
  solver.potential().Evaluate(result.state, plane, HessianKind::kExact, false, nullptr, &e);
  ceres::Problem problem;
  double parameters[2] = {3 * force / (2 * M_PI * a_theory * a_theory), a_theory};
  double moment = 0, total = 0;
  HertzMeasurement m;
  const Skin& skin = body.skin();
  std::vector<double> pressure(static_cast<size_t>(skin.vertices.size()), 0.0);
  for (Eigen::Index l = 0; l < skin.vertices.size(); ++l)
    pressure[l] = e.contacts.skin_force.row(l).norm() / skin.rest_areas[l];
  for (Eigen::Index i = 0; i < skin.vertices.size(); ++i) {
    const Eigen::Vector3d p = e.positions.row(skin.vertices[i]);
    const double r = std::hypot(p.x() - result.state.centre.x(), p.z() - result.state.centre.z());
    if (p.y() > 0.3 * kRadius || r > 2 * a_theory) continue;  // the contact neighbourhood
    // Weight by √area: the fit is then a discretised L² fit of the pressure field.
    problem.AddResidualBlock(
        new HertzProfileResidual(r, pressure[i], std::sqrt(skin.rest_areas[i])), nullptr,
        parameters);
    const double f = pressure[i] * skin.rest_areas[i];
    moment += f * r * r;
    total += f;
  }
  ceres::Solver::Options fit;
  fit.max_num_iterations = 200;
  ceres::Solver::Summary summary;
  ceres::Solve(fit, &problem, &summary);
  m.p0 = parameters[0];
  m.a = parameters[1];
  m.a_moment = std::sqrt(2.5 * moment / total);  // ∫p r² dA / ∫p dA = 2a²/5 for Hertz
  m.vertices = static_cast<int>(body.rest().vertices.rows()) +
               (slab ? static_cast<int>(slab->rest().vertices.rows()) : 0);
  m.contacts = result.contact_vertices;
  m.penetration = result.max_penetration;
  return m;
}

TEST(Equilibrium, HertzContactRadiusAndPeakPressureConvergeToTheory) {
  const double E_star = kYoung / (1 - kPoisson * kPoisson);
  const double a_target = 0.2 * kRadius;  // a/R = 0.2: small strain
  const double force = 4 * E_star * a_target * a_target * a_target / (3 * kRadius);
  const double a = std::cbrt(3 * force * kRadius / (4 * E_star)),
               p0 = 3 * force / (2 * M_PI * a * a);
  double previous_error = INFINITY;
  for (double fine : {0.0032, 0.0022}) {
    const HertzMeasurement m = Simulate(fine, force);
    const double a_error = std::abs(m.a - a) / a, p_error = std::abs(m.p0 - p0) / p0;
    std::cout << "h=" << fine * 1e3 << " mm: " << m.vertices << " vertices, " << m.contacts
              << " contacts, penetration " << m.penetration * 1e3 << " mm; a=" << m.a * 1e3
              << " mm (theory " << a * 1e3 << ", moment estimate " << m.a_moment * 1e3
              << "), p0=" << m.p0 << " Pa (theory " << p0 << "); errors " << a_error * 100 << " %, "
              << p_error * 100 << " %\n";
    EXPECT_LT(a_error, 0.10);
    EXPECT_LT(p_error, 0.10);
    const double error = std::max(a_error, p_error);
    EXPECT_LT(error, previous_error) << "refinement did not reduce the error";
    previous_error = error;
  }
}

// The ball on a slab of the same material: E* halves, so the contact is 2^(1/3) wider than on
// the rigid plane under the same force. Checks that the second deformable body and its
// contact carry the load as the theory of two elastic bodies says (the slab is 8 contact
// radii wide and 7 deep: its finite size moves a by about 1–2 %).
TEST(Equilibrium, HertzContactOfTwoSoftBodiesUsesTheirEffectiveModulus) {
  // 12.6k vertices solved together: minutes under ASan. The sanitizers see the same soft-support
  // code in the smaller scenes of soft_support_test.cc; this is the Release run's check.
  if (testing::SanitizedBuild()) GTEST_SKIP() << "Release-only: the two-body Hertz scene";
  const double slab_modulus = kYoung;
  const double compliance = 2 * (1 - kPoisson * kPoisson) / kYoung;
  const double a_target = 0.2 * kRadius;
  const double force = 4 * a_target * a_target * a_target / (3 * kRadius * compliance);
  const double a = std::cbrt(3 * force * kRadius * compliance / 4),
               p0 = 3 * force / (2 * M_PI * a * a);
  const HertzMeasurement m = Simulate(0.0025, force, slab_modulus);
  const double a_error = std::abs(m.a - a) / a, p_error = std::abs(m.p0 - p0) / p0;
  const double a_rigid = std::cbrt(3 * force * kRadius * (1 - kPoisson * kPoisson) / kYoung / 4);
  std::cout << "soft slab: " << m.vertices << " vertices, " << m.contacts
            << " contacts; a=" << m.a * 1e3 << " mm (theory " << a * 1e3 << ", moment estimate "
            << m.a_moment * 1e3 << "; on a rigid plane it would be " << a_rigid * 1e3
            << "), p0=" << m.p0 << " Pa (theory " << p0 << "); errors " << a_error * 100 << " %, "
            << p_error * 100 << " %\n";
  EXPECT_LT(a_error, 0.10);
  EXPECT_LT(p_error, 0.10);
  EXPECT_LT(std::abs(m.a_moment - a) / a, 0.10);
}

}  // namespace
}  // namespace ergo
