#include "ergo/mesh/sparse_cholesky.h"

#include <random>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Dense>

namespace ergo {
namespace {

using Matrix = SparseCholesky::Matrix;

// A random sparse SPD matrix: B Bᵀ + n·I for a random sparse B (full symmetric storage).
Matrix RandomSpd(int n, unsigned seed, double shift) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-1, 1);
  std::uniform_int_distribution<int> index(0, n - 1);
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < n; ++i) {
    entries.emplace_back(i, i, uniform(rng));
    for (int k = 0; k < 3; ++k) entries.emplace_back(i, index(rng), uniform(rng));
  }
  Matrix b(n, n);
  b.setFromTriplets(entries.begin(), entries.end());
  Matrix identity(n, n);
  identity.setIdentity();
  Matrix a = Matrix(b * Matrix(b.transpose())) + shift * identity;
  a.makeCompressed();
  return a;
}

TEST(Mesh, CholeskySolveMatchesDenseSolve) {
  const Matrix a = RandomSpd(200, 1, 1.0);
  const Eigen::VectorXd rhs = Eigen::VectorXd::Random(200);
  SparseCholesky cholesky;
  cholesky.Analyze(a);
  ASSERT_TRUE(cholesky.Factorize(a).ok);
  const Eigen::VectorXd dense = Eigen::MatrixXd(a).llt().solve(rhs);
  // Both are backward stable; cond(a) here is ~1e2, so 1e-12 relative is ample.
  EXPECT_LT((cholesky.Solve(rhs) - dense).norm(), 1e-12 * dense.norm());
}

TEST(Mesh, CholeskyUsesOnlyTheUpperTriangle) {
  Matrix a = RandomSpd(50, 2, 1.0);
  const Eigen::VectorXd rhs = Eigen::VectorXd::Random(50);
  const Eigen::VectorXd expected = Eigen::MatrixXd(a).llt().solve(rhs);
  Matrix upper = a.triangularView<Eigen::Upper>();
  upper.makeCompressed();
  SparseCholesky cholesky;
  cholesky.Analyze(upper);
  ASSERT_TRUE(cholesky.Factorize(upper).ok);
  EXPECT_LT((cholesky.Solve(rhs) - expected).norm(), 1e-12 * expected.norm());
}

TEST(Mesh, CholeskyRefactorisesNewValuesOnTheSamePattern) {
  Matrix a = RandomSpd(100, 3, 1.0);
  SparseCholesky cholesky;
  cholesky.Analyze(a);
  ASSERT_TRUE(cholesky.Factorize(a).ok);
  // Same pattern, different values: scale and shift the diagonal.
  Matrix b = 2.0 * a;
  for (int i = 0; i < 100; ++i) b.coeffRef(i, i) += 5.0;
  b.makeCompressed();
  ASSERT_EQ(b.nonZeros(), a.nonZeros());
  ASSERT_TRUE(cholesky.Factorize(b).ok);
  const Eigen::VectorXd rhs = Eigen::VectorXd::Ones(100);
  const Eigen::VectorXd expected = Eigen::MatrixXd(b).llt().solve(rhs);
  EXPECT_LT((cholesky.Solve(rhs) - expected).norm(), 1e-12 * expected.norm());
}

TEST(Mesh, CholeskyReportsAnIndefiniteMatrixClearly) {
  // diag(1, 2, -3, 4) on a path pattern: the third leading minor is negative.
  Matrix a(4, 4);
  std::vector<Eigen::Triplet<double>> entries = {{0, 0, 1}, {1, 1, 2},   {2, 2, -3},
                                                 {3, 3, 4}, {0, 1, 0.1}, {1, 0, 0.1}};
  a.setFromTriplets(entries.begin(), entries.end());
  a.makeCompressed();
  SparseCholesky cholesky;
  cholesky.Analyze(a);
  const FactorizationStatus status = cholesky.Factorize(a);
  EXPECT_FALSE(status.ok);
  EXPECT_GE(status.failed_column, 0);
  EXPECT_NE(status.message.find("not positive definite"), std::string::npos) << status.message;
  EXPECT_FALSE(cholesky.factorized());
}

TEST(Mesh, CholeskyCopiesSolveIndependentlyFromSeveralThreads) {
  const Matrix a = RandomSpd(300, 4, 1.0);
  SparseCholesky analysed;
  analysed.Analyze(a);
  std::vector<SparseCholesky> copies(4, analysed);
  std::vector<Eigen::VectorXd> solutions(4);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&, t] {
      Matrix scaled = (1.0 + t) * a;
      scaled.makeCompressed();
      ASSERT_TRUE(copies[t].Factorize(scaled).ok);
      solutions[t] = copies[t].Solve(Eigen::VectorXd::Ones(300));
    });
  }
  for (auto& thread : threads) thread.join();
  const Eigen::VectorXd base = Eigen::MatrixXd(a).llt().solve(Eigen::VectorXd::Ones(300));
  for (int t = 0; t < 4; ++t)
    EXPECT_LT((solutions[t] * (1.0 + t) - base).norm(), 1e-11 * base.norm());
}

}  // namespace
}  // namespace ergo
