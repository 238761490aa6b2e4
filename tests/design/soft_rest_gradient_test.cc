// The score's gradient with respect to a soft support's rest shape (paper Eq. 21–23) against
// central differences of ζ through the whole equilibrium: a cube of tissue on a foam block
// whose top's rest positions move (the interior following by RestExtension, the sides and
// the held base staying), each perturbed design's equilibrium solved again to 1e-12 of the
// load; along random directions and along the gradient itself.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>

#include <gtest/gtest.h>

#include "ergo/body/core_lock.h"
#include "ergo/body/elastic_part.h"
#include "ergo/body/rest_extension.h"
#include "ergo/design/design_problem.h"
#include "ergo/design/rest_shape_gradient.h"
#include "ergo/equilibrium/equilibrium_solver.h"
#include "ergo/equilibrium/placement.h"
#include "ergo/ergonomics/contact_pressures.h"
#include "ergo/ergonomics/pressure_score.h"
#include "ergo/mesh/primitives.h"
#include "ergo/mesh/surface_geometry.h"
#include "tests/support/body/body_fixtures.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

struct Scored {
  bool ok = false;
  double zeta = 0;
  BodyState state;
  Vertices positions;  // the foam's deformed positions
};

class SoftRestShape : public ::testing::Test {
 protected:
  void SetUp() override {
    LayeredBodyOptions options;
    // Pressed straight down (rotations locked: a cube tipping on soft foam makes Newton crawl
    // through projected steps), turned about the vertical so that the grids do not align.
    options.lock = ParseCoreLock("tx,tz,rx,ry,rz");
    options.external_force = Eigen::Vector3d(0, -20, 0);
    const Eigen::Matrix3d turn = RotationExp(Eigen::Vector3d(0, 0.2, 0));
    body_ = std::make_unique<LayeredBody>(testing::MakeHollowCubeBody(
        0.1, 6, 1e4, 0.45, options, Eigen::Vector3d(0.004, 0.06, -0.003), turn));
    const TetMesh mesh = MakeTetGrid({-0.1, -0.04, -0.1}, {0.1, 0, 0.1}, {10, 2, 10});
    std::vector<bool> base(static_cast<size_t>(mesh.vertices.rows()));
    for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v)
      base[v] = mesh.vertices(v, 1) < -0.04 + 1e-9;
    foam_ = std::make_shared<const ElasticPart>(ElasticPart::Create(
        mesh, base, UniformMaterial(mesh.tets.rows(), 5e4, 0.3), {}, "foam block"));
    // Designed: the top's vertices; fixed: the rest of the boundary and the base.
    const Eigen::VectorXi& boundary = foam_->boundary().surface_to_tet;
    designed_.assign(mesh.vertices.rows(), false);
    std::vector<bool> fixed(mesh.vertices.rows(), false);
    for (Eigen::Index i = 0; i < boundary.size(); ++i) {
      const int v = boundary[i];
      (mesh.vertices(v, 1) > -1e-9 && std::abs(mesh.vertices(v, 0)) < 0.1 - 1e-9 &&
               std::abs(mesh.vertices(v, 2)) < 0.1 - 1e-9
           ? designed_
           : fixed)[v] = true;
    }
    extension_ = std::make_unique<RestExtension>(mesh, designed_, fixed);
    equilibrium_.contact_stiffness = 3e7;
    equilibrium_.contact_skin_share = 0.5;
    equilibrium_.relative_tolerance = 1e-12;
    equilibrium_.stall_iterations = 0;
    evaluator_ = std::make_unique<ContactPressureEvaluator>(*body_, foam_->boundary().surface,
                                                            PressureCostOptions());
  }

  // ζ at the equilibrium on the foam with rest positions `rest`, from `start` (the foam's
  // deformed positions kept: its displacements are re-based on the new rest shape).
  Scored Solve(const Vertices& rest, const BodyState& start, const Vertices& start_positions,
               TotalPotential::Evaluation* exact = nullptr,
               std::shared_ptr<const ElasticPart>* part_out = nullptr) const {
    auto part = std::make_shared<const ElasticPart>(foam_->WithRestPositions(rest));
    EquilibriumSolver solver(*body_, equilibrium_, part);
    const Support surface = SoftSupportSurface(*part);
    BodyState state = start;
    if (start_positions.rows() > 0)
      state.support_displacement = part->FreeComponents(start_positions - rest);
    const EquilibriumResult result = solver.Solve(surface, state);
    Scored out;
    out.ok = result.converged;
    EXPECT_TRUE(result.converged) << result.FullReport();
    out.state = result.state;
    TotalPotential::Evaluation e;
    solver.potential().Evaluate(result.state, surface, HessianKind::kExact, true, nullptr, &e);
    const ContactPressures pressures =
        evaluator_->Evaluate(e.contacts, BarycentricVertexAreas(part->boundary().surface));
    out.zeta = pressures.human.cost + pressures.support.cost;
    out.positions = e.support_positions;
    if (exact) *exact = std::move(e);
    if (part_out) *part_out = part;
    return out;
  }

  std::unique_ptr<LayeredBody> body_;
  std::shared_ptr<const ElasticPart> foam_;
  std::vector<bool> designed_;
  std::unique_ptr<RestExtension> extension_;
  EquilibriumOptions equilibrium_;
  std::unique_ptr<ContactPressureEvaluator> evaluator_;
};

TEST_F(SoftRestShape, ScoreGradientMatchesFiniteDifferencesThroughTheEquilibrium) {
  const Vertices& rest = foam_->rest().vertices;
  const Support surface = SoftSupportSurface(*foam_);
  const BodyState placed = PlaceAboveSupport(*body_, RestState(*body_), surface, 1e-3).state;
  TotalPotential::Evaluation e;
  std::shared_ptr<const ElasticPart> part;
  const Scored at = Solve(rest, placed, Vertices(), &e, &part);
  ASSERT_TRUE(at.ok);
  ASSERT_GT(e.contacts.support.size(), 5);
  const TotalPotential potential(
      *body_,
      SurfaceContactOptions{equilibrium_.contact_stiffness, equilibrium_.contact_skin_share, true},
      part);
  const ContactPressures pressures =
      evaluator_->Evaluate(e.contacts, BarycentricVertexAreas(part->boundary().surface));
  SparseCholesky cholesky, no_newton_factor;  // the factorising path of SolveAdjoint
  const RestShapeGradient gradient =
      SoftSupportRestGradient(potential, at.state, e, ScorePressures(pressures, *body_, true, true),
                              no_newton_factor, &cholesky);
  EXPECT_EQ(gradient.factorizations, 1);
  ASSERT_TRUE(gradient.ok) << gradient.message;
  const Vertices design_gradient = extension_->PullBack(gradient.gradient);
  ASSERT_GT(design_gradient.norm(), 0);

  std::mt19937 rng(13);
  std::normal_distribution<double> normal;
  double worst = 0;
  const int trials = testing::SanitizedBuild() ? 2 : 4;
  for (int trial = 0; trial < trials; ++trial) {
    Vertices direction = Vertices::Zero(rest.rows(), 3);
    for (Eigen::Index v = 0; v < rest.rows(); ++v) {
      if (!designed_[v]) continue;
      if (trial == 0) {
        direction.row(v) = -design_gradient.row(v);
      } else {
        direction.row(v) << normal(rng), normal(rng), normal(rng);
      }
    }
    direction /= direction.norm();
    const Vertices moved = extension_->Extend(direction);
    const double analytic = (gradient.gradient.array() * moved.array()).sum();
    double best = INFINITY;
    for (double h : {3e-6, 1e-6, 3e-7}) {
      const Scored plus = Solve(rest + h * moved, at.state, at.positions);
      const Scored minus = Solve(rest - h * moved, at.state, at.positions);
      const double fd = (plus.zeta - minus.zeta) / (2 * h);
      best = std::min(best, std::abs(fd - analytic) / std::abs(analytic));
      std::printf("[ FD       ] trial %d h %.0e: fd %.9e analytic %.9e\n", trial, h, fd, analytic);
    }
    EXPECT_LT(best, 1e-4) << "trial " << trial;
    worst = std::max(worst, best);
  }
  std::printf("[ FD       ] soft support rest-shape design gradient: worst %.2e\n", worst);
}

// The same through DesignProblem, the optimisers' objective: the design moves the foam top's
// rest positions (one coordinate triple per designed vertex), each evaluation places the
// cube afresh on the foam at rest and solves; ∇φ against central differences of φ.
TEST_F(SoftRestShape, DesignProblemGradientMatchesFiniteDifferences) {
  DesignOptions options;
  options.equilibrium = equilibrium_;
  options.soft_support = foam_;
  const Eigen::VectorXi& boundary = foam_->boundary().surface_to_tet;
  options.active.assign(boundary.size(), false);
  for (Eigen::Index i = 0; i < boundary.size(); ++i) options.active[i] = designed_[boundary[i]];
  const TriMesh& surface = foam_->boundary().surface;
  const BodyState start =
      PlaceAboveSupport(*body_, RestState(*body_), Support(surface, "foam"), 1e-3).state;
  DesignProblem problem(*body_, surface, start, options);
  const Eigen::VectorXd x0 = problem.InitialDesign();
  const DesignEvaluation at = problem.Evaluate(x0, true);
  ASSERT_TRUE(at.ok) << at.message;
  ASSERT_GT(at.gradient.norm(), 0);
  std::mt19937 rng(17);
  std::normal_distribution<double> normal;
  double worst = 0;
  const int trials = testing::SanitizedBuild() ? 1 : 3;
  for (int trial = 0; trial < trials; ++trial) {
    Eigen::VectorXd d(x0.size());
    for (Eigen::Index i = 0; i < d.size(); ++i) d[i] = normal(rng);
    if (trial == 0) d = -at.gradient;
    d.normalize();
    const double analytic = at.gradient.dot(d);
    double best = INFINITY;
    for (double h : {1e-6, 3e-7}) {
      const DesignEvaluation plus = problem.Evaluate(x0 + h * d, false);
      const DesignEvaluation minus = problem.Evaluate(x0 - h * d, false);
      ASSERT_TRUE(plus.ok && minus.ok) << plus.message << minus.message;
      best = std::min(best,
                      std::abs((plus.phi - minus.phi) / (2 * h) - analytic) / std::abs(analytic));
    }
    EXPECT_LT(best, 1e-4) << "trial " << trial;
    worst = std::max(worst, best);
  }
  std::printf("[ FD       ] DesignProblem on a soft support: worst %.2e\n", worst);
}

}  // namespace
}  // namespace ergo
