// The equilibrium's total potential with the area-weighted contact of both kinds (skin
// vertices inside the support, support vertices inside the skin) against finite differences:
// its reduced gradient along random directions and along the gradient itself, its exact
// Hessian against differences of the gradient, the projected Hessian's semi-definiteness,
// and the energy-only evaluation against the full one. A support finer than the skin makes
// support vertices poke the skin's triangles, so the blocks over a skin triangle's three
// vertices (ReducedSystem::AddVertexBlockHessian) are on.
#include "ergo/equilibrium/total_potential.h"

#include <cmath>
#include <random>
#include <set>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "ergo/body/core_lock.h"
#include "ergo/mesh/primitives.h"
#include "tests/support/body/body_fixtures.h"
#include "tests/support/dense_symmetric.h"
#include "tests/support/finite_difference.h"

namespace ergo {
namespace {

using testing::DenseSymmetric;

struct Scene {
  LayeredBody body;
  Support support;
  BodyState state;
};

// A 10 cm hollow cube (3.3 cm skin edges) turned a little and pressed 1 mm into a 1 cm grid
// with gentle bumps, its free vertices jittered; rotation free so the lever arms matter.
Scene MakeScene(unsigned seed) {
  LayeredBodyOptions options;
  options.lock = ParseCoreLock("tx,tz");
  options.external_force = Eigen::Vector3d(0, -30, 0);
  const Eigen::Matrix3d turn = RotationExp(Eigen::Vector3d(0.05, 0.3, -0.04));
  LayeredBody body = testing::MakeHollowCubeBody(0.1, 3, 1e4, 0.45, options,
                                                 Eigen::Vector3d(0.003, 0.049, -0.002), turn);
  TriMesh ground = MakeHeightfieldBlock(
      {-0.12, -0.05, -0.12}, {0.12, 0, 0.12}, {24, 1, 24},
      [](double x, double z) { return 0.001 * std::sin(40 * x) * std::cos(35 * z); });
  Scene scene{std::move(body), Support(ground, "bumpy ground"), {}};
  scene.state = RestState(scene.body);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-1, 1);
  for (Eigen::Index i = 0; i < scene.state.free_displacement.size(); ++i)
    scene.state.free_displacement[i] = 2e-4 * uniform(rng);
  scene.state.centre.y() -= 2e-3;
  for (Eigen::Index i = 0; i < scene.state.free_displacement.size() / 3; ++i)
    scene.state.free_displacement[3 * i + 1] -= 2e-3;
  return scene;
}

// κ for about a millimetre of the cube's pressing; α = ½; the support's springs push when
// two-way.
SurfaceContactOptions ContactOptions(bool two_way) {
  SurfaceContactOptions contact;
  contact.stiffness = 3e7;
  contact.skin_share = 0.5;
  contact.support_springs = two_way;
  return contact;
}

class EquilibriumTotalPotential : public ::testing::TestWithParam<bool> {};

TEST_P(EquilibriumTotalPotential, GradientAndExactHessianMatchFiniteDifferences) {
  const bool two_way = GetParam();
  const Scene scene = MakeScene(5);
  const SurfaceContactOptions contact = ContactOptions(two_way);
  const TotalPotential potential(scene.body, contact);
  const ReducedLayout& layout = potential.system().layout();

  TotalPotential::Evaluation at;
  potential.Evaluate(scene.state, scene.support, HessianKind::kExact, true, nullptr, &at);
  ASSERT_GT(at.contacts.skin.size(), 3) << "the cube's skin must press into the ground";
  ASSERT_GT(at.contacts.support.size(), 3) << "ground vertices must poke into the skin";
  std::set<FeatureType> types;
  for (const Contact& c : at.contacts.support.contacts) types.insert(c.anchor.feature.type);
  EXPECT_TRUE(types.count(FeatureType::kFace)) << "a support spring must slide on a skin face";
  // The energy-only path gives the same energy.
  EXPECT_NEAR(potential.Energy(scene.state, scene.support), at.energy, 1e-12 * std::abs(at.energy));

  auto energy = [&](const Eigen::VectorXd& step) {
    return potential.Energy(layout.Retract(scene.state, step), scene.support);
  };
  auto gradient = [&](const Eigen::VectorXd& step) {
    TotalPotential::Evaluation e;
    potential.Evaluate(layout.Retract(scene.state, step), scene.support, HessianKind::kExact, false,
                       nullptr, &e);
    return e.gradient;
  };
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(layout.size());
  std::string report;
  // Smooth within the contact configuration: steps of 1e-7..1e-10 m stay inside it.
  const double gradient_error =
      testing::WorstGradientError(energy, at.gradient, zero, 1e-6 * at.gradient.norm(),
                                  testing::StepSweep(1e-7, 4), 4, 0, 3, &report);
  EXPECT_LT(gradient_error, 1e-6) << report;

  // The exact Hessian against differences of the gradient, along random directions and
  // along the gradient (the retraction's second-order term makes ∂G/∂y differ from the
  // symmetric K̂ only in the rotation block at a non-equilibrium state: compare the
  // displacement block and the full matrix–vector product with a tolerance for it).
  const Eigen::MatrixXd hessian = DenseSymmetric(at.body.hessian);
  std::mt19937 rng(9);
  std::normal_distribution<double> normal;
  const Eigen::Index free = layout.core_offset();
  for (int trial = 0; trial < 4; ++trial) {
    Eigen::VectorXd d = Eigen::VectorXd::Zero(layout.size());
    if (trial == 0) {
      d.head(free) = at.gradient.head(free);
    } else {
      for (Eigen::Index i = 0; i < free; ++i) d[i] = normal(rng);
    }
    d.normalize();
    double best = INFINITY;
    for (double h : {1e-7, 3e-8, 1e-8}) {
      const Eigen::VectorXd fd = (gradient(h * d) - gradient(-h * d)) / (2 * h);
      const Eigen::VectorXd analytic = hessian * d;
      best = std::min(best, (fd - analytic).head(free).norm() / analytic.head(free).norm());
    }
    EXPECT_LT(best, 1e-5) << (two_way ? "two-way" : "one-way") << " trial " << trial;
  }

  // Newton's fallback: every block projected, the whole matrix positive semi-definite.
  TotalPotential::Evaluation projected;
  potential.Evaluate(scene.state, scene.support, HessianKind::kProjectedPsd, true, nullptr,
                     &projected);
  const Eigen::VectorXd eigenvalues =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(DenseSymmetric(projected.body.hessian))
          .eigenvalues();
  EXPECT_GT(eigenvalues.minCoeff(), -1e-9 * eigenvalues.cwiseAbs().maxCoeff());
}

// A Newton iteration of the one-way equilibrium leaves the score-only support samples out;
// filled in afterwards they are the samples an evaluation with them gives, bit for bit, and
// leaving them out changes no energy, gradient or Hessian entry. Two-way, the support's
// springs push, so they are always evaluated.
TEST_P(EquilibriumTotalPotential, SupportSamplesLeftOutAndFilledInLaterAreTheSame) {
  const bool two_way = GetParam();
  const Scene scene = MakeScene(7);
  const SurfaceContactOptions contact = ContactOptions(two_way);
  const TotalPotential eager(scene.body, contact), lazy(scene.body, contact);

  TotalPotential::Evaluation full, partial;
  eager.Evaluate(scene.state, scene.support, HessianKind::kExact, true, nullptr, &full);
  lazy.Evaluate(scene.state, scene.support, HessianKind::kExact, true, nullptr, &partial,
                /*with_support_samples=*/false);
  ASSERT_GT(full.contacts.support.size(), 3) << "ground vertices must poke into the skin";
  EXPECT_EQ(partial.contacts.support_sampled, two_way);
  EXPECT_EQ(partial.contacts.support.size(), two_way ? full.contacts.support.size() : 0);
  EXPECT_EQ(partial.energy, full.energy);
  EXPECT_EQ((partial.gradient - full.gradient).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(Eigen::MatrixXd(partial.body.hessian - full.body.hessian).cwiseAbs().maxCoeff(), 0.0);

  lazy.AddSupportSamples(scene.support, true, &partial);
  ASSERT_TRUE(partial.contacts.support_sampled);
  ASSERT_EQ(partial.contacts.support.size(), full.contacts.support.size());
  for (int i = 0; i < full.contacts.support.size(); ++i) {
    const Contact& a = full.contacts.support.contacts[i];
    const Contact& b = partial.contacts.support.contacts[i];
    EXPECT_EQ(a.point, b.point);
    EXPECT_EQ(a.spring.energy, b.spring.energy);
    EXPECT_EQ((a.spring.gradient - b.spring.gradient).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ((a.spring.hessian - b.spring.hessian).cwiseAbs().maxCoeff(), 0.0);
  }
  EXPECT_EQ((partial.contacts.support_load - full.contacts.support_load).cwiseAbs().maxCoeff(),
            0.0);
  EXPECT_EQ((partial.contacts.skin_force - full.contacts.skin_force).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(partial.contacts.max_penetration, full.contacts.max_penetration);
  EXPECT_EQ(partial.contacts.energy, full.contacts.energy);
}

// The support's samples skip vertices whose distance bound shows them outside the skin. After
// a design step (the support's vertices moved, each by its own amount) the bounds of the
// last evaluation still decide, shrunk by each vertex's move: the samples must be those of a
// potential that never saw the old support.
TEST_P(EquilibriumTotalPotential, SupportSamplesAfterTheSupportMovedAreThoseOfAFreshPotential) {
  const bool two_way = GetParam();
  const Scene scene = MakeScene(11);
  const SurfaceContactOptions contact = ContactOptions(two_way);
  const TotalPotential stale(scene.body, contact), fresh(scene.body, contact);
  TotalPotential::Evaluation before, after, reference;
  // First half the ground 3 mm lower (its vertices outside the skin, with positive bounds),
  // then the ground itself: those vertices rise into the skin while the skin stands still.
  TriMesh lowered = scene.support.mesh();
  for (Eigen::Index j = 0; j < lowered.vertices.rows(); ++j)
    if (lowered.vertices(j, 0) > 0) lowered.vertices(j, 1) -= 3e-3;
  stale.Evaluate(scene.state, Support(lowered, "lowered ground"), HessianKind::kExact, true,
                 nullptr, &before);
  const Support& stepped = scene.support;
  stale.Evaluate(scene.state, stepped, HessianKind::kExact, true, nullptr, &after);
  fresh.Evaluate(scene.state, stepped, HessianKind::kExact, true, nullptr, &reference);
  std::set<int> earlier, newly;
  for (const Contact& c : before.contacts.support.contacts) earlier.insert(c.point);
  for (const Contact& c : reference.contacts.support.contacts)
    if (!earlier.count(c.point)) newly.insert(c.point);
  ASSERT_GT(newly.size(), 3u) << "raised ground vertices must newly poke into the skin";
  ASSERT_EQ(after.contacts.support.size(), reference.contacts.support.size());
  for (int i = 0; i < reference.contacts.support.size(); ++i) {
    EXPECT_EQ(after.contacts.support.contacts[i].point,
              reference.contacts.support.contacts[i].point);
    EXPECT_NEAR(after.contacts.support.contacts[i].spring.energy,
                reference.contacts.support.contacts[i].spring.energy,
                1e-12 * reference.contacts.support.energy);
  }
  EXPECT_NEAR(after.energy, reference.energy, 1e-12 * std::abs(reference.energy));
}

INSTANTIATE_TEST_SUITE_P(ContactModels, EquilibriumTotalPotential, ::testing::Values(true, false),
                         [](const auto& info) { return info.param ? "two_way" : "one_way"; });

}  // namespace
}  // namespace ergo
