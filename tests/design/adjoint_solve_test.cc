// SolveAdjoint (ergo/design/adjoint_solve.h) on a system whose solution is checked by its
// residual: a tridiagonal SPD matrix (upper triangle stored, as K̂ is). Preconditioned by the
// factor of a nearby matrix it takes the conjugate-gradient path without factorising; without
// a factor it factorises; both give the same z. An indefinite matrix is refused with a message.
#include "ergo/design/adjoint_solve.h"

#include <vector>

#include <gtest/gtest.h>
#include <Eigen/SparseCore>

namespace ergo {
namespace {

// Upper triangle of tridiag(−1, diagonal, −1), n × n.
SparseMatrix Tridiagonal(int n, double diagonal) {
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < n; ++i) {
    entries.emplace_back(i, i, diagonal);
    if (i + 1 < n) entries.emplace_back(i, i + 1, -1.0);
  }
  SparseMatrix m(n, n);
  m.setFromTriplets(entries.begin(), entries.end());
  m.makeCompressed();
  return m;
}

double Residual(const SparseMatrix& upper, const Eigen::VectorXd& z, const Eigen::VectorXd& r) {
  const Eigen::VectorXd kz = upper.selfadjointView<Eigen::Upper>() * z;
  return (kz - r).norm() / r.norm();
}

TEST(AdjointSolve, PreconditionedAndFactorisedPathsSolveTheSameSystem) {
  const int n = 50;
  const SparseMatrix k = Tridiagonal(n, 2.5);
  const Eigen::VectorXd r = Eigen::VectorXd::LinSpaced(n, -1, 2);
  SparseCholesky nearby;
  const SparseMatrix k_nearby = Tridiagonal(n, 2.5 * 1.01);
  nearby.Analyze(k_nearby);
  ASSERT_TRUE(nearby.Factorize(k_nearby).ok);
  SparseCholesky scratch;
  const AdjointSolution by_cg = SolveAdjoint(k, r, nearby, &scratch);
  ASSERT_TRUE(by_cg.ok) << by_cg.message;
  EXPECT_GT(by_cg.pcg_iterations, 0);
  EXPECT_EQ(by_cg.factorizations, 0);
  EXPECT_LT(Residual(k, by_cg.z, r), 1e-10);

  const SparseCholesky none;
  const AdjointSolution by_factor = SolveAdjoint(k, r, none, &scratch);
  ASSERT_TRUE(by_factor.ok) << by_factor.message;
  EXPECT_EQ(by_factor.factorizations, 1);
  EXPECT_LT(Residual(k, by_factor.z, r), 1e-12);
  EXPECT_LT((by_cg.z - by_factor.z).norm(), 1e-9 * by_factor.z.norm());

  // Not positive definite (diagonal 1 < 2|−1|·cos(π/(n+1))): refused, not a NaN solution.
  const AdjointSolution refused = SolveAdjoint(Tridiagonal(n, 1.0), r, none, &scratch);
  EXPECT_FALSE(refused.ok);
  EXPECT_NE(refused.message.find("not positive definite"), std::string::npos) << refused.message;
}

}  // namespace
}  // namespace ergo
