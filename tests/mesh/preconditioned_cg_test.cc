#include "ergo/mesh/preconditioned_cg.h"

#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Dense>

namespace ergo {
namespace {

using Matrix = SparseCholesky::Matrix;

// A 1D Laplacian-like SPD tridiagonal matrix with diagonal d (upper storage).
Matrix Tridiagonal(int n, double diagonal) {
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < n; ++i) {
    entries.emplace_back(i, i, diagonal);
    if (i + 1 < n) entries.emplace_back(i, i + 1, -1.0);
  }
  Matrix m(n, n);
  m.setFromTriplets(entries.begin(), entries.end());
  m.makeCompressed();
  return m;
}

TEST(Mesh, PcgWithTheExactFactorConvergesInOneIteration) {
  const Matrix a = Tridiagonal(200, 2.5);
  SparseCholesky factor;
  factor.Analyze(a);
  ASSERT_TRUE(factor.Factorize(a).ok);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(200, -1, 1);
  const PcgResult r = PreconditionedConjugateGradient(a, factor, b, 1e-12, 10);
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.iterations, 1);
  EXPECT_LT((Eigen::MatrixXd(a).selfadjointView<Eigen::Upper>() * r.x - b).norm(),
            1e-12 * b.norm());
}

TEST(Mesh, PcgWithANearbyFactorSolvesTheNewMatrixToTolerance) {
  const Matrix old_matrix = Tridiagonal(300, 2.5), new_matrix = Tridiagonal(300, 2.6);
  SparseCholesky factor;
  factor.Analyze(old_matrix);
  ASSERT_TRUE(factor.Factorize(old_matrix).ok);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(300);
  const PcgResult r = PreconditionedConjugateGradient(new_matrix, factor, b, 1e-12, 50);
  EXPECT_TRUE(r.converged);
  EXPECT_LT(r.iterations, 15);
  const Eigen::VectorXd exact =
      Eigen::MatrixXd(new_matrix).selfadjointView<Eigen::Upper>().llt().solve(b);
  EXPECT_LT((r.x - exact).norm(), 1e-10 * exact.norm());
}

TEST(Mesh, PcgReportsNegativeCurvature) {
  const Matrix good = Tridiagonal(50, 2.5);
  Matrix bad = Tridiagonal(50, 2.5);
  bad.coeffRef(10, 10) = -5.0;  // indefinite
  SparseCholesky factor;
  factor.Analyze(good);
  ASSERT_TRUE(factor.Factorize(good).ok);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(50);
  b[10] = 1;
  const PcgResult r = PreconditionedConjugateGradient(bad, factor, b, 1e-12, 100);
  EXPECT_FALSE(r.converged);
  EXPECT_TRUE(r.negative_curvature);
}

}  // namespace
}  // namespace ergo
