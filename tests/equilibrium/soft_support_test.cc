// A soft support (ergo/body/elastic_part.h) in the equilibrium (TotalPotential with a soft
// part): the coupled gradient and exact Hessian — the support's block and the contact's cross
// blocks between skin and support DOFs — against finite differences, the projected one's
// semi-definiteness, and a solved equilibrium's balance: the body's contact force carries its
// load, and the support's base carries the body's load plus the support's own weight.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "ergo/body/core_lock.h"
#include "ergo/body/elastic_part.h"
#include "ergo/equilibrium/equilibrium_solver.h"
#include "ergo/equilibrium/placement.h"
#include "ergo/equilibrium/total_potential.h"
#include "ergo/mesh/primitives.h"
#include "tests/support/body/body_fixtures.h"
#include "tests/support/dense_symmetric.h"
#include "tests/support/finite_difference.h"

namespace ergo {
namespace {

using testing::DenseSymmetric;

// A foam part on `mesh` with the vertices at or below `base_y` held.
std::shared_ptr<const ElasticPart> MakeFoam(const TetMesh& mesh, double base_y, double modulus,
                                            double density) {
  std::vector<bool> base(static_cast<size_t>(mesh.vertices.rows()));
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v)
    base[v] = mesh.vertices(v, 1) < base_y + 1e-9;
  ElasticPartOptions options;
  options.density = density;
  options.gravity = Eigen::Vector3d(0, -9.81, 0);
  return std::make_shared<const ElasticPart>(ElasticPart::Create(
      mesh, base, UniformMaterial(mesh.tets.rows(), modulus, 0.3), options, "foam block"));
}

// A foam block [lo, hi] on a Kuhn grid with its bottom face held.
std::shared_ptr<const ElasticPart> MakeSoftBlock(const Eigen::Vector3d& lo,
                                                 const Eigen::Vector3d& hi,
                                                 const Eigen::Vector3i& cells, double modulus,
                                                 double density) {
  return MakeFoam(MakeTetGrid(lo, hi, cells), lo.y(), modulus, density);
}

struct Scene {
  LayeredBody body;
  std::shared_ptr<const ElasticPart> block;
  BodyState state;
};

// A 10 cm hollow cube turned a little and pressed 2 mm into a foam block of 2 cm cells (finer
// than the cube's 3.3 cm skin, so that block vertices poke the skin's faces), with both
// parts' free vertices jittered.
Scene MakeScene(unsigned seed) {
  LayeredBodyOptions options;
  options.lock = ParseCoreLock("tx,tz");
  options.external_force = Eigen::Vector3d(0, -30, 0);
  const Eigen::Matrix3d turn = RotationExp(Eigen::Vector3d(0.05, 0.3, -0.04));
  Scene scene{testing::MakeHollowCubeBody(0.1, 3, 1e4, 0.45, options,
                                          Eigen::Vector3d(0.003, 0.049, -0.002), turn),
              MakeSoftBlock({-0.12, -0.04, -0.12}, {0.12, 0, 0.12}, {12, 2, 12}, 5e4, 60),
              {}};
  scene.state = RestState(scene.body);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-1, 1);
  for (Eigen::Index i = 0; i < scene.state.free_displacement.size(); ++i)
    scene.state.free_displacement[i] = 2e-4 * uniform(rng);
  scene.state.centre.y() -= 2e-3;
  for (Eigen::Index i = 0; i < scene.state.free_displacement.size() / 3; ++i)
    scene.state.free_displacement[3 * i + 1] -= 2e-3;
  scene.state.support_displacement = Eigen::VectorXd::Zero(scene.block->size());
  for (Eigen::Index i = 0; i < scene.block->size(); ++i)
    scene.state.support_displacement[i] = 2e-4 * uniform(rng);
  return scene;
}

// A soft support's contact is two-way whatever the options say (TotalPotential): asking
// for one-way gives the same potential.
SurfaceContactOptions ContactOptions(bool two_way) {
  SurfaceContactOptions contact;
  contact.stiffness = 3e7;
  contact.skin_share = 0.5;
  contact.support_springs = two_way;
  return contact;
}

class SoftSupportPotential : public ::testing::TestWithParam<bool> {};

TEST_P(SoftSupportPotential, CoupledGradientAndHessianMatchFiniteDifferences) {
  const bool two_way = GetParam();
  const Scene scene = MakeScene(5);
  const Support rest_surface = SoftSupportSurface(*scene.block);
  const TotalPotential potential(scene.body, ContactOptions(two_way), scene.block);
  EXPECT_TRUE(potential.contact().options().support_springs);
  const ReducedLayout& layout = potential.layout();
  ASSERT_EQ(layout.support_size(), scene.block->size());

  TotalPotential::Evaluation at;
  potential.Evaluate(scene.state, rest_surface, HessianKind::kExact, true, nullptr, &at);
  ASSERT_GT(at.contacts.skin.size(), 3) << "the cube's skin must press into the block";
  ASSERT_GT(at.contacts.support.size(), 3) << "block vertices must poke the skin";
  EXPECT_NEAR(potential.Energy(scene.state, rest_surface), at.energy, 1e-12 * std::abs(at.energy));
  ASSERT_EQ(at.hessian().rows(), layout.size());

  auto energy = [&](const Eigen::VectorXd& step) {
    return potential.Energy(potential.Retract(scene.state, step), rest_surface);
  };
  auto gradient = [&](const Eigen::VectorXd& step) {
    TotalPotential::Evaluation e;
    potential.Evaluate(potential.Retract(scene.state, step), rest_surface, HessianKind::kExact,
                       false, nullptr, &e);
    return e.gradient;
  };
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(layout.size());
  std::string report;
  // Smooth within the contact configuration: steps of 1e-7..1e-10 m stay inside it.
  const double gradient_error =
      testing::WorstGradientError(energy, at.gradient, zero, 1e-6 * at.gradient.norm(),
                                  testing::StepSweep(1e-7, 4), 4, 0, 3, &report);
  EXPECT_LT(gradient_error, 1e-6) << report;

  // K̂ against differences of the gradient on every translational DOF (free body vertices,
  // the core's ty, the block's free vertices); the exp-map retraction makes the rotation
  // rows differ from the symmetric K̂ away from equilibrium (total_potential_test.cc).
  std::vector<Eigen::Index> translational;
  for (Eigen::Index i = 0; i < layout.core_offset(); ++i) translational.push_back(i);
  for (int j = 0; j < layout.core_count(); ++j)
    if (layout.core_components()[j] < 3) translational.push_back(layout.core_offset() + j);
  for (Eigen::Index i = layout.support_offset(); i < layout.size(); ++i) translational.push_back(i);
  const Eigen::MatrixXd hessian = DenseSymmetric(at.hessian());
  // The cross blocks are there: some body row couples to some block column.
  EXPECT_GT(hessian.topRightCorner(layout.support_offset(), layout.support_size()).norm(), 0);
  std::mt19937 rng(9);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 5; ++trial) {
    Eigen::VectorXd d = Eigen::VectorXd::Zero(layout.size());
    for (Eigen::Index i : translational) d[i] = trial == 0 ? at.gradient[i] : normal(rng);
    if (trial == 1) d.head(layout.support_offset()).setZero();  // the block's DOFs alone
    d.normalize();
    double best = INFINITY;
    for (double h : {1e-7, 3e-8, 1e-8}) {
      const Eigen::VectorXd fd = (gradient(h * d) - gradient(-h * d)) / (2 * h);
      const Eigen::VectorXd analytic = hessian * d;
      double error = 0, scale = 0;
      for (Eigen::Index i : translational) {
        error += (fd[i] - analytic[i]) * (fd[i] - analytic[i]);
        scale += analytic[i] * analytic[i];
      }
      best = std::min(best, std::sqrt(error / scale));
    }
    EXPECT_LT(best, 1e-5) << (two_way ? "two-way" : "one-way") << " trial " << trial;
  }

  TotalPotential::Evaluation projected;
  potential.Evaluate(scene.state, rest_surface, HessianKind::kProjectedPsd, true, nullptr,
                     &projected);
  const Eigen::VectorXd eigenvalues =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(DenseSymmetric(projected.hessian()))
          .eigenvalues();
  EXPECT_GT(eigenvalues.minCoeff(), -1e-9 * eigenvalues.cwiseAbs().maxCoeff());
}

// zᵀ G as a function of the foam's rest positions X with every deformed position held (the
// foam rebuilt on X, its displacements x − X): its X-gradient is RestShapeAdjoint — the
// element forces, the weight, and the support springs' rest areas — along random directions
// and along the analytic gradient itself, over the foam's free vertices (the held base's
// positions are its rest positions).
TEST(SoftSupport, RestShapeAdjointMatchesFiniteDifferencesOfTheResidual) {
  const Scene scene = MakeScene(5);
  const SurfaceContactOptions contact = ContactOptions(true);
  const TotalPotential potential(scene.body, contact, scene.block);
  TotalPotential::Evaluation at;
  potential.Evaluate(scene.state, SoftSupportSurface(*scene.block), HessianKind::kExact, false,
                     nullptr, &at);
  ASSERT_GT(at.contacts.support.size(), 3) << "the area terms need support springs";
  std::mt19937 rng(21);
  std::normal_distribution<double> normal;
  Eigen::VectorXd z(potential.size());
  for (Eigen::Index i = 0; i < z.size(); ++i) z[i] = normal(rng);
  const Vertices analytic = potential.RestShapeAdjoint(scene.state, z, at);
  const TetMesh& rest = scene.block->rest();
  const Vertices deformed = at.support_positions;
  auto contracted = [&](const Eigen::VectorXd& rest_vector) {
    TetMesh moved = rest;
    moved.vertices = Eigen::Map<const Vertices>(rest_vector.data(), rest.vertices.rows(), 3);
    const auto foam = MakeFoam(moved, -0.04, 5e4, 60);
    const TotalPotential at_x(scene.body, contact, foam);
    BodyState state = scene.state;
    state.support_displacement = foam->FreeComponents(deformed - moved.vertices);
    TotalPotential::Evaluation e;
    at_x.Evaluate(state, SoftSupportSurface(*foam), HessianKind::kExact, false, nullptr, &e);
    return e.gradient.dot(z);
  };
  // Only free vertices move; the analytic gradient restricted to them.
  Eigen::VectorXd gradient = Eigen::Map<const Eigen::VectorXd>(analytic.data(), analytic.size());
  for (Eigen::Index v = 0; v < rest.vertices.rows(); ++v)
    if (scene.block->held()[v]) gradient.segment<3>(3 * v).setZero();
  const Eigen::VectorXd x0 =
      Eigen::Map<const Eigen::VectorXd>(rest.vertices.data(), rest.vertices.size());
  double worst = 0;
  for (int trial = 0; trial < 4; ++trial) {
    Eigen::VectorXd d = Eigen::VectorXd::Zero(x0.size());
    if (trial == 0) {
      d = gradient;
    } else {
      for (Eigen::Index v = 0; v < rest.vertices.rows(); ++v)
        if (!scene.block->held()[v])
          for (int c = 0; c < 3; ++c) d[3 * v + c] = normal(rng);
    }
    d.normalize();
    const testing::SweepResult sweep = testing::CheckDirectional(
        contracted, x0, d, gradient.dot(d), 1e-6 * gradient.norm(), testing::StepSweep(1e-6, 4));
    EXPECT_LT(sweep.best_relative_error, 1e-6) << "trial " << trial << "\n" << sweep.report;
    worst = std::max(worst, sweep.best_relative_error);
  }
  std::printf("[ FD       ] soft support rest-shape term z^T dG/dX: %.2e\n", worst);
  // The area terms matter: without them the check above would fail by more than this.
  const Vertices elastic_only = scene.block->RestShapeAdjoint(at.support_positions, [&] {
    Vertices zs = Vertices::Zero(rest.vertices.rows(), 3);
    const Eigen::Index offset = potential.layout().support_offset();
    for (Eigen::Index k = 0; k < scene.block->free_vertices().size(); ++k)
      zs.row(scene.block->free_vertices()[k]) = z.segment<3>(offset + 3 * k).transpose();
    return zs;
  }());
  EXPECT_GT((analytic - elastic_only).norm(), 1e-3 * analytic.norm());
}

TEST_P(SoftSupportPotential, EquilibriumBalancesTheLoadOnTheBodyAndOnTheBase) {
  const bool two_way = GetParam();
  LayeredBodyOptions options;
  options.lock = ParseCoreLock("tx,tz");
  options.external_force = Eigen::Vector3d(0, -20, 0);
  const LayeredBody body =
      testing::MakeHollowCubeBody(0.1, 3, 1e4, 0.45, options, Eigen::Vector3d(0, 0.06, 0));
  const auto block = MakeSoftBlock({-0.1, -0.04, -0.1}, {0.1, 0, 0.1}, {10, 4, 10}, 5e4, 60);
  const Support rest_surface = SoftSupportSurface(*block);
  EquilibriumOptions eq;
  eq.contact_support_springs = two_way;
  EquilibriumSolver solver(body, eq, block);
  const BodyState start = PlaceAboveSupport(body, RestState(body), rest_surface, 1e-3).state;
  const EquilibriumResult result = solver.Solve(rest_surface, start);
  ASSERT_TRUE(result.converged) << result.FullReport();
  ASSERT_EQ(result.state.support_displacement.size(), block->size());

  const Eigen::Vector3d load = body.TotalLoad();
  // The body: contact carries its load along the free ty to Newton's tolerance (1e-8 of the
  // load); the locked tx, tz take whatever sideways force the contact leaves.
  EXPECT_LE(std::abs(result.contact_force.y() + load.y()), 1e-6 * load.norm());
  // The block: its held base balances the contact force on it (minus the body's, Newton's
  // third law: each spring's forces sum to zero) and its own weight.
  const TotalPotential::Evaluation& e = solver.last_evaluation();
  Eigen::Vector3d base_reaction = Eigen::Vector3d::Zero();
  for (Eigen::Index v = 0; v < block->rest().vertices.rows(); ++v)
    if (block->held()[v]) base_reaction += e.support.vertex_gradient.row(v).transpose();
  const double block_weight = block->vertex_mass().sum() * 9.81;
  const Eigen::Vector3d expected = result.contact_force + Eigen::Vector3d(0, block_weight, 0);
  EXPECT_LE((base_reaction - expected).norm(), 1e-6 * load.norm())
      << "base " << base_reaction.transpose() << ", expected " << expected.transpose();
  // The block's top sank under the cube.
  double deepest = 0;
  for (Eigen::Index v = 0; v < block->rest().vertices.rows(); ++v)
    deepest = std::min(deepest, e.support_positions(v, 1) - block->rest().vertices(v, 1));
  EXPECT_LT(deepest, -1e-4);
  std::printf(
      "[ soft     ] %s: %d Newton iterations, block top sank %.3f mm, base reaction "
      "%.4f N for load %.4f N + block weight %.4f N\n",
      two_way ? "two-way" : "one-way", result.iterations, -deepest * 1e3, base_reaction.y(),
      -load.y(), block_weight);
}

// Several soft supports are one part of several components (ElasticPart::Join). A block the
// body never touches changes nothing: the body on block A joined with a far block B reaches
// A's own equilibrium (B only sags under its weight, its base carrying exactly that); and a
// body straddling two blocks has its load shared between their bases, which together carry
// load plus weights to Newton's tolerance, each a large share.
TEST(SoftSupports, JoinedBlocksCarryTheirSharesAndAnUntouchedOneChangesNothing) {
  LayeredBodyOptions options;
  options.lock = ParseCoreLock("tx,tz,rx,ry,rz");
  options.external_force = Eigen::Vector3d(0, -20, 0);
  const LayeredBody body =
      testing::MakeHollowCubeBody(0.1, 3, 1e4, 0.45, options, Eigen::Vector3d(0, 0.06, 0));
  auto solve = [&](std::shared_ptr<const ElasticPart> foam) {
    const Support surface = SoftSupportSurface(*foam);
    EquilibriumOptions eq;
    eq.relative_tolerance = 1e-10;
    auto solver = std::make_shared<EquilibriumSolver>(body, eq, foam);
    const BodyState start = PlaceAboveSupport(body, RestState(body), surface, 1e-3).state;
    const EquilibriumResult result = solver->Solve(surface, start);
    EXPECT_TRUE(result.converged) << result.FullReport();
    return std::make_pair(result, solver);
  };
  // Base reaction of the held vertices in [from, to) of the part.
  auto reaction = [](const ElasticPart& part, const TotalPotential::Evaluation& e,
                     Eigen::Index from, Eigen::Index to) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (Eigen::Index v = from; v < to; ++v)
      if (part.held()[v]) sum += e.support.vertex_gradient.row(v).transpose();
    return sum;
  };

  const auto a = MakeSoftBlock({-0.1, -0.04, -0.1}, {0.1, 0, 0.1}, {8, 3, 8}, 5e4, 60);
  const auto far = MakeSoftBlock({0.5, -0.04, -0.1}, {0.6, 0, 0.1}, {4, 3, 8}, 2e4, 60);
  const auto joined =
      std::make_shared<const ElasticPart>(ElasticPart::Join({a.get(), far.get()}, "two blocks"));
  ASSERT_EQ(joined->size(), a->size() + far->size());
  ASSERT_EQ(joined->material().youngs_modulus.size(),
            a->rest().tets.rows() + far->rest().tets.rows());
  EXPECT_EQ(joined->material().youngs_modulus[a->rest().tets.rows()], 2e4);
  const auto [alone, alone_solver] = solve(a);
  const auto [both, both_solver] = solve(joined);
  EXPECT_LE((both.contact_force - alone.contact_force).norm(), 1e-8 * body.TotalLoad().norm());
  EXPECT_NEAR(both.state.centre.y(), alone.state.centre.y(), 1e-9);
  const Eigen::VectorXd a_part = both.state.support_displacement.head(a->size());
  EXPECT_LE((a_part - alone.state.support_displacement).lpNorm<Eigen::Infinity>(), 1e-9);
  const Eigen::Index na = a->rest().vertices.rows();
  const Eigen::Vector3d far_base =
      reaction(*joined, both_solver->last_evaluation(), na, joined->rest().vertices.rows());
  EXPECT_NEAR(far_base.y(), far->vertex_mass().sum() * 9.81, 1e-8);  // residual ≤ 2e-9 N

  // Straddling: two mirror-image blocks 2 cm apart under the cube's middle.
  const auto left = MakeSoftBlock({-0.11, -0.04, -0.1}, {-0.01, 0, 0.1}, {5, 3, 10}, 5e4, 60);
  TetMesh mirrored = left->rest();
  mirrored.vertices.col(0) *= -1;
  for (Eigen::Index t = 0; t < mirrored.tets.rows(); ++t)
    std::swap(mirrored.tets(t, 2), mirrored.tets(t, 3));  // mirroring turns every tet
  const auto right = MakeFoam(mirrored, -0.04, 5e4, 60);
  const auto pair =
      std::make_shared<const ElasticPart>(ElasticPart::Join({left.get(), right.get()}, "pair"));
  const auto [straddle, straddle_solver] = solve(pair);
  const TotalPotential::Evaluation& e = straddle_solver->last_evaluation();
  const Eigen::Index nl = left->rest().vertices.rows();
  const Eigen::Vector3d on_left = reaction(*pair, e, 0, nl);
  const Eigen::Vector3d on_right = reaction(*pair, e, nl, pair->rest().vertices.rows());
  const double weights = pair->vertex_mass().sum() * 9.81, load = -body.TotalLoad().y();
  EXPECT_NEAR(on_left.y() + on_right.y(), load + weights, 1e-6 * load);
  // Both carry a large share; not half each: the cube's tets are not mirror-symmetric and its
  // bottom vertices at x = ±16.7 mm sit 6.7 mm from the gap's edges (measured 57 / 43 %).
  EXPECT_NEAR(on_left.y() / (on_left.y() + on_right.y()), 0.5, 0.2);
  std::printf("[ soft     ] two blocks: bases carry %.4f N and %.4f N of %.4f N + %.4f N\n",
              on_left.y(), on_right.y(), load, weights);
}

INSTANTIATE_TEST_SUITE_P(ContactOptions, SoftSupportPotential, ::testing::Values(true, false),
                         [](const auto& info) {
                           return info.param ? "two_way_asked" : "one_way_asked";
                         });

}  // namespace
}  // namespace ergo
