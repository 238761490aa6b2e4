// The soft-support part (ergo/body/elastic_part.h): a patch test (a homogeneous deformation
// imposed on the boundary is reproduced inside), a column under its own weight (the base's
// reaction equals the weight; the top settles by ρgL²/2E), and its energy, forces, stiffness
// and rest-shape adjoint term against finite differences.
#include "ergo/body/elastic_part.h"

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "ergo/mesh/input_error.h"
#include "ergo/mesh/primitives.h"
#include "ergo/mesh/sparse_cholesky.h"
#include "ergo/mesh/tet_components.h"
#include "tests/support/dense_symmetric.h"
#include "tests/support/finite_difference.h"

namespace ergo {
namespace {

using testing::DenseSymmetric;

// Vertices on the box's boundary (within 1e-9 of a face).
std::vector<bool> OnBoundary(const TetMesh& mesh, const Eigen::Vector3d& lo,
                             const Eigen::Vector3d& hi) {
  std::vector<bool> on(static_cast<size_t>(mesh.vertices.rows()), false);
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v)
    for (int c = 0; c < 3; ++c)
      on[v] = on[v] || std::abs(mesh.vertices(v, c) - lo[c]) < 1e-9 ||
              std::abs(mesh.vertices(v, c) - hi[c]) < 1e-9;
  return on;
}

// Newton on the part's free DOFs from `positions` (held vertices stay), exact stiffness.
// Returns the final residual norm.
double SolveForFreeVertices(const ElasticPart& part, Vertices* positions) {
  SparseCholesky cholesky;
  cholesky.Analyze(part.pattern());
  ElasticPart::Evaluation e;
  double residual = 0;
  for (int iteration = 0; iteration < 30; ++iteration) {
    part.Evaluate(*positions, HessianKind::kExact, true, &e);
    const Eigen::VectorXd gradient = part.FreeComponents(e.vertex_gradient);
    residual = gradient.norm();
    if (residual < 1e-13) break;
    EXPECT_TRUE(cholesky.Factorize(e.hessian).ok);
    *positions = part.Positions(*positions, -cholesky.Solve(gradient));
  }
  return residual;
}

TEST(ElasticPart, ReproducesAHomogeneousDeformationImposedOnItsBoundary) {
  const Eigen::Vector3d lo(0, 0, 0), hi(0.1, 0.06, 0.08);
  const TetMesh mesh = MakeTetGrid(lo, hi, Eigen::Vector3i(4, 3, 4));
  const ElasticPart part = ElasticPart::Create(
      mesh, OnBoundary(mesh, lo, hi), UniformMaterial(mesh.tets.rows(), 5e4, 0.3), {}, "block");
  ASSERT_GT(part.free_vertices().size(), 10);
  Eigen::Matrix3d f;
  f << 1.1, 0.05, -0.02,  //
      0.03, 0.9, 0.04,    //
      -0.01, 0.02, 1.05;
  const Eigen::RowVector3d shift(0.01, -0.02, 0.005);
  const Vertices exact = (mesh.vertices * f.transpose()).rowwise() + shift;
  Vertices positions = exact;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-2e-3, 2e-3);
  for (Eigen::Index v : part.free_vertices())
    for (int c = 0; c < 3; ++c) positions(v, c) += jitter(rng);
  const double residual = SolveForFreeVertices(part, &positions);
  EXPECT_LT(residual, 1e-10);
  // Linear tets represent F exactly: the interior lands on F X + t to round-off.
  EXPECT_LT((positions - exact).cwiseAbs().maxCoeff(), 1e-12);
  // Every tet has that F: the same volume change det F − 1 and the same stress.
  const Eigen::VectorXd volume_change = part.VolumeChange(positions);
  const Eigen::VectorXd von_mises = part.VonMisesStress(positions);
  EXPECT_LT((volume_change.array() - (f.determinant() - 1)).abs().maxCoeff(), 1e-12);
  EXPECT_GT(von_mises.minCoeff(), 0);
  EXPECT_LT(von_mises.maxCoeff() - von_mises.minCoeff(), 1e-9 * von_mises.maxCoeff());
}

TEST(ElasticPart, AColumnUnderItsOwnWeightCarriesItOnItsBaseAndSettlesAsTheory) {
  // ν = 0: no lateral contraction, so the held base imposes none and the column is in
  // uniaxial stress σ(y) = ρ g (L − y); the top settles by ρ g L² / (2E) (small strain: E =
  // 1 MPa keeps the strain ≤ 1e-3, the neo-Hookean correction of that order).
  const double length = 0.1, density = 1000, modulus = 1e6, g = 9.81;
  const Eigen::Vector3d lo(0, 0, 0), hi(0.03, length, 0.03);
  const TetMesh mesh = MakeTetGrid(lo, hi, Eigen::Vector3i(3, 10, 3));
  std::vector<bool> base(static_cast<size_t>(mesh.vertices.rows()));
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) base[v] = mesh.vertices(v, 1) < 1e-9;
  ElasticPartOptions options;
  options.density = density;
  options.gravity = Eigen::Vector3d(0, -g, 0);
  const ElasticPart part = ElasticPart::Create(
      mesh, base, UniformMaterial(mesh.tets.rows(), modulus, 0.0), options, "column");
  Vertices positions = mesh.vertices;
  EXPECT_LT(SolveForFreeVertices(part, &positions), 1e-10);

  ElasticPart::Evaluation e;
  part.Evaluate(positions, HessianKind::kExact, false, &e);
  // A held vertex's gradient is the force its holder exerts on it (it balances the elastic
  // force and its own weight); the free ones' is zero, so the base's reactions sum to the
  // whole weight (conservation of momentum, to Newton's tolerance).
  Eigen::Vector3d reaction = Eigen::Vector3d::Zero();
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v)
    if (base[v]) reaction += e.vertex_gradient.row(v).transpose();
  const double weight = density * g * 0.03 * 0.03 * length;
  EXPECT_NEAR(reaction.y(), weight, 1e-9 * weight);
  EXPECT_NEAR(reaction.x(), 0, 1e-9 * weight);
  EXPECT_NEAR(reaction.z(), 0, 1e-9 * weight);

  double top_settlement = 0;
  int top = 0;
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
    if (std::abs(mesh.vertices(v, 1) - length) > 1e-9) continue;
    top_settlement += mesh.vertices(v, 1) - positions(v, 1);
    ++top;
  }
  top_settlement /= top;
  // Uniaxial stress ρ g (L − y): the von Mises stress of each tet is |σ_yy| at its centroid
  // (the lumped load makes it piecewise constant per layer: within half a layer's weight).
  const Eigen::VectorXd von_mises = part.VonMisesStress(positions);
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    double y = 0;
    for (int k = 0; k < 4; ++k) y += mesh.vertices(mesh.tets(t, k), 1) / 4;
    EXPECT_NEAR(von_mises[t], density * g * (length - y), density * g * 0.5 * length / 10)
        << "tet " << t << " at height " << y;
  }
  const double theory = density * g * length * length / (2 * modulus);
  std::printf("[ column   ] top settles %.6e m, theory %.6e m (%+.3f %%)\n", top_settlement, theory,
              100 * (top_settlement / theory - 1));
  // Linear elements in uniaxial stress are nodally exact for a load lumped per layer; what
  // remains is the neo-Hookean response at strain ≤ 1e-3 and the lateral variation of the
  // lumped load (0.1 %–1 %): 2 % would catch a factor in E, ρ, g or the lumping.
  EXPECT_NEAR(top_settlement, theory, 0.02 * theory);
}

TEST(ElasticPart, EnergyForcesAndStiffnessMatchFiniteDifferences) {
  const Eigen::Vector3d lo(0, 0, 0), hi(0.02, 0.01, 0.02);
  const TetMesh mesh = MakeTetGrid(lo, hi, Eigen::Vector3i(2, 1, 2));
  std::vector<bool> base(static_cast<size_t>(mesh.vertices.rows()));
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) base[v] = mesh.vertices(v, 1) < 1e-9;
  ElasticPartOptions options;
  options.density = 60;
  options.gravity = Eigen::Vector3d(0, -9.81, 0);
  const ElasticPart part = ElasticPart::Create(
      mesh, base, UniformMaterial(mesh.tets.rows(), 5e4, 0.3), options, "block");
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> jitter(-1e-3, 1e-3);
  Eigen::VectorXd u(part.size());
  for (Eigen::Index i = 0; i < u.size(); ++i) u[i] = jitter(rng);
  ElasticPart::Evaluation e;
  part.Evaluate(part.Positions(mesh.vertices, u), HessianKind::kExact, true, &e);
  const double scale = 5e4 * 0.01;  // E times an edge: force per metre of strain, N/m·m
  std::string report;
  const double gradient_error = testing::WorstGradientError(
      [&](const Eigen::VectorXd& v) { return part.Energy(part.Positions(mesh.vertices, v)); },
      part.FreeComponents(e.vertex_gradient), u, scale * 1e-3, testing::StepSweep(1e-4, 6), 6, 30,
      12, &report);
  EXPECT_LE(gradient_error, 1e-6) << report;
  const double hessian_error = testing::WorstJacobianError(
      [&](const Eigen::VectorXd& v) {
        ElasticPart::Evaluation at;
        part.Evaluate(part.Positions(mesh.vertices, v), HessianKind::kExact, false, &at);
        return part.FreeComponents(at.vertex_gradient);
      },
      DenseSymmetric(e.hessian), u, scale, testing::StepSweep(1e-4, 6), 6, 30, 13, &report);
  EXPECT_LE(hessian_error, 1e-6) << report;
  std::printf("[ FD       ] soft part: energy -> forces %.2e, forces -> stiffness %.2e\n",
              gradient_error, hessian_error);
}

TEST(ElasticPart, RestShapeAdjointMatchesFiniteDifferencesOfTheResidual) {
  // zᵀ G(X) at fixed deformed positions, G the free vertices' residual of a part rebuilt on
  // rest positions X: its X-gradient is RestShapeAdjoint(z), the weight's term included.
  const Eigen::Vector3d lo(0, 0, 0), hi(0.02, 0.01, 0.02);
  const TetMesh mesh = MakeTetGrid(lo, hi, Eigen::Vector3i(2, 1, 2));
  std::vector<bool> base(static_cast<size_t>(mesh.vertices.rows()));
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) base[v] = mesh.vertices(v, 1) < 1e-9;
  ElasticPartOptions options;
  options.density = 5e5;  // exaggerated so that the weight's term is a visible share
  options.gravity = Eigen::Vector3d(0.5, -9.81, 0.2);
  const TissueMaterial material = UniformMaterial(mesh.tets.rows(), 5e4, 0.35);
  const ElasticPart part = ElasticPart::Create(mesh, base, material, options, "block");
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> uniform(-1, 1);
  Vertices positions = mesh.vertices, z = Vertices::Zero(mesh.vertices.rows(), 3);
  for (Eigen::Index v : part.free_vertices()) {
    for (int c = 0; c < 3; ++c) {
      positions(v, c) += 1.5e-3 * uniform(rng);
      z(v, c) = uniform(rng);
    }
  }
  auto contracted_residual = [&](const Eigen::VectorXd& rest_vector) {
    TetMesh moved = mesh;
    moved.vertices = Eigen::Map<const Vertices>(rest_vector.data(), mesh.vertices.rows(), 3);
    const ElasticPart at = ElasticPart::Create(moved, base, material, options, "block");
    ElasticPart::Evaluation e;
    at.Evaluate(positions, HessianKind::kExact, false, &e);
    return at.FreeComponents(e.vertex_gradient).dot(at.FreeComponents(z));
  };
  const Vertices analytic = part.RestShapeAdjoint(positions, z);
  const Eigen::VectorXd rest_vector =
      Eigen::Map<const Eigen::VectorXd>(mesh.vertices.data(), mesh.vertices.size());
  const Eigen::VectorXd analytic_vector =
      Eigen::Map<const Eigen::VectorXd>(analytic.data(), analytic.size());
  std::string report;
  const double error = testing::WorstGradientError(contracted_residual, analytic_vector,
                                                   rest_vector, analytic_vector.norm() * 1e-3,
                                                   testing::StepSweep(1e-4, 6), 8, 60, 19, &report);
  EXPECT_LE(error, 1e-6) << report;
  std::printf("[ FD       ] soft part: rest-shape adjoint term %.2e\n", error);
}

TEST(ElasticPart, OnNewRestPositionsItIsThePartBuiltThere) {
  const Eigen::Vector3d lo(0, 0, 0), hi(0.02, 0.01, 0.02);
  const TetMesh mesh = MakeTetGrid(lo, hi, Eigen::Vector3i(2, 2, 2));
  std::vector<bool> base(static_cast<size_t>(mesh.vertices.rows()));
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) base[v] = mesh.vertices(v, 1) < 1e-9;
  ElasticPartOptions options;
  options.density = 60;
  options.gravity = Eigen::Vector3d(0, -9.81, 0);
  const TissueMaterial material = UniformMaterial(mesh.tets.rows(), 5e4, 0.3);
  const ElasticPart part = ElasticPart::Create(mesh, base, material, options, "block");
  TetMesh moved = mesh;
  for (Eigen::Index v = 0; v < moved.vertices.rows(); ++v)
    moved.vertices(v, 1) += 0.1 * moved.vertices(v, 1) * (1 + moved.vertices(v, 0) / 0.02);
  const ElasticPart rebuilt = part.WithRestPositions(moved.vertices);
  const ElasticPart fresh = ElasticPart::Create(moved, base, material, options, "block");
  EXPECT_EQ((rebuilt.vertex_mass() - fresh.vertex_mass()).norm(), 0.0);
  EXPECT_EQ((rebuilt.boundary().surface.vertices - fresh.boundary().surface.vertices).norm(), 0.0);
  Vertices x = moved.vertices;
  x.col(1) *= 0.97;
  ElasticPart::Evaluation a, b;
  rebuilt.Evaluate(x, HessianKind::kExact, true, &a);
  fresh.Evaluate(x, HessianKind::kExact, true, &b);
  EXPECT_EQ(a.energy, b.energy);
  EXPECT_EQ((a.vertex_gradient - b.vertex_gradient).norm(), 0.0);
  EXPECT_EQ(Eigen::MatrixXd(a.hessian - b.hessian).norm(), 0.0);
  // A move that flattens a tet is refused, naming it.
  Vertices flat = mesh.vertices;
  flat.col(1).setZero();
  EXPECT_THROW(part.WithRestPositions(flat), InputError);
}

TEST(ElasticPart, RefusesAPartWithNothingHeldAndNamesIt) {
  const TetMesh mesh = MakeTetGrid(Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(0.01),
                                   Eigen::Vector3i(1, 1, 1));
  const TissueMaterial material = UniformMaterial(mesh.tets.rows(), 5e4, 0.3);
  try {
    ElasticPart::Create(mesh, std::vector<bool>(mesh.vertices.rows(), false), material, {},
                        "cushion.msh");
    FAIL() << "accepted a part with no held vertex";
  } catch (const InputError& error) {
    EXPECT_EQ(error.source(), "cushion.msh");
    EXPECT_NE(std::string(error.what()).find("no vertex is held"), std::string::npos);
  }
  EXPECT_THROW(ElasticPart::Create(mesh, std::vector<bool>(3, true), material, {}, "cushion.msh"),
               InputError);
  TissueMaterial negative = material;
  negative.youngs_modulus[2] = -1;
  try {
    ElasticPart::Create(mesh, std::vector<bool>(mesh.vertices.rows(), true), negative, {},
                        "cushion.msh");
    FAIL() << "accepted a negative modulus";
  } catch (const InputError& error) {
    EXPECT_EQ(error.location(), "tet 2");
  }
}

// Each connected component must be held over an area: two cubes side by side with only the
// first's base held is refused naming the second (its first vertex), and so is a cube held
// along one edge (it would turn about it).
TEST(ElasticPart, RefusesAComponentHeldNowhereOrAlongALine) {
  const ElasticPartOptions none;
  const TetMesh cube = MakeTetGrid(Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(0.01),
                                   Eigen::Vector3i(2, 2, 2));
  const Eigen::Index n = cube.vertices.rows();
  TetMesh two = cube;
  two.vertices.conservativeResize(2 * n, 3);
  two.vertices.bottomRows(n) = cube.vertices.rowwise() + Eigen::RowVector3d(0.05, 0, 0);
  two.tets.conservativeResize(2 * cube.tets.rows(), 4);
  two.tets.bottomRows(cube.tets.rows()) = cube.tets.array() + static_cast<int>(n);
  const TetComponents components = LabelTetComponents(two);
  ASSERT_EQ(components.count, 2);
  EXPECT_EQ(components.vertex_component[0], 0);
  EXPECT_EQ(components.vertex_component[n], 1);
  EXPECT_EQ(components.vertex_component.head(n).maxCoeff(), 0);
  EXPECT_EQ(components.vertex_component.tail(n).minCoeff(), 1);

  std::vector<bool> held(static_cast<size_t>(2 * n), false);
  for (Eigen::Index v = 0; v < n; ++v) held[v] = cube.vertices(v, 1) < 1e-12;
  try {
    ElasticPart::Create(two, held, UniformMaterial(two.tets.rows(), 5e4, 0.3), none, "pair.msh");
    FAIL() << "accepted a component with nothing held";
  } catch (const InputError& error) {
    EXPECT_EQ(error.source(), "pair.msh");
    EXPECT_NE(error.location().find("component 1"), std::string::npos) << error.what();
    EXPECT_NE(error.location().find("from vertex " + std::to_string(n)), std::string::npos)
        << error.what();
  }
  std::vector<bool> edge(static_cast<size_t>(n), false);
  for (Eigen::Index v = 0; v < n; ++v)
    edge[v] = cube.vertices(v, 1) < 1e-12 && cube.vertices(v, 2) < 1e-12;
  try {
    ElasticPart::Create(cube, edge, UniformMaterial(cube.tets.rows(), 5e4, 0.3), none, "edge");
    FAIL() << "accepted a cube held along one edge";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("along a line"), std::string::npos) << error.what();
  }
}

// Join lays the parts side by side: vertices, tets, held flags and per-tet materials in
// order, the same energy as the parts' sum at any positions; parts of another density refused.
TEST(ElasticPart, JoinedPartsAreThePartsSideBySide) {
  ElasticPartOptions heavy;
  heavy.density = 50;
  heavy.gravity = Eigen::Vector3d(0, -9.81, 0);
  auto make = [&](const Eigen::Vector3d& lo, double modulus, const ElasticPartOptions& options) {
    const TetMesh mesh =
        MakeTetGrid(lo, lo + Eigen::Vector3d(0.02, 0.01, 0.02), Eigen::Vector3i(2, 1, 2));
    std::vector<bool> base(static_cast<size_t>(mesh.vertices.rows()));
    for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v)
      base[v] = mesh.vertices(v, 1) < lo.y() + 1e-12;
    return ElasticPart::Create(mesh, base, UniformMaterial(mesh.tets.rows(), modulus, 0.3), options,
                               "block");
  };
  const ElasticPart a = make(Eigen::Vector3d::Zero(), 5e4, heavy);
  const ElasticPart b = make(Eigen::Vector3d(0.1, 0, 0), 2e4, heavy);
  const ElasticPart joined = ElasticPart::Join({&a, &b}, "a+b");
  const Eigen::Index na = a.rest().vertices.rows(), nb = b.rest().vertices.rows();
  ASSERT_EQ(joined.rest().vertices.rows(), na + nb);
  EXPECT_EQ(joined.rest().tets(a.rest().tets.rows(), 0), b.rest().tets(0, 0) + na);
  EXPECT_EQ(joined.size(), a.size() + b.size());
  EXPECT_EQ(joined.material().youngs_modulus[a.rest().tets.rows()], 2e4);
  EXPECT_EQ(joined.boundary().surface.triangles.rows(),
            a.boundary().surface.triangles.rows() + b.boundary().surface.triangles.rows());
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> jitter(-5e-4, 5e-4);
  Vertices pa = a.rest().vertices, pb = b.rest().vertices;
  for (Vertices* p : {&pa, &pb})
    for (Eigen::Index i = 0; i < p->size(); ++i) p->data()[i] += jitter(rng);
  Vertices both(na + nb, 3);
  both << pa, pb;
  EXPECT_NEAR(joined.Energy(both), a.Energy(pa) + b.Energy(pb),
              1e-12 * std::abs(a.Energy(pa) + b.Energy(pb)));
  const ElasticPart light = make(Eigen::Vector3d(0.2, 0, 0), 5e4, ElasticPartOptions());
  try {
    ElasticPart::Join({&a, &light}, "a+light");
    FAIL() << "joined parts of different densities";
  } catch (const InputError& error) {
    EXPECT_EQ(error.location(), "soft support 2");
  }
}

}  // namespace
}  // namespace ergo
