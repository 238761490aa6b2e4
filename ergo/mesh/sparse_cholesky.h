// SparseCholesky: a supernodal sparse Cholesky factorisation (CHOLMOD, on OpenBLAS) of a
// symmetric positive-definite matrix whose sparsity pattern is fixed. Analyse the pattern
// once (fill-reducing ordering + symbolic factor), then refactorise numerically whenever
// only the values change — every Newton step, line-search probe and adjoint solve of a
// body reuses one analysis (DESIGN.md §6).
//
//   SparseCholesky cholesky;
//   cholesky.Analyze(K);                      // once per pattern
//   if (!cholesky.Factorize(K).ok) ...        // per step; reports a non-PD matrix
//   Eigen::VectorXd x = cholesky.Solve(b);
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace ergo {

struct FactorizationStatus {
  bool ok = false;
  // When not ok: why, e.g. "matrix is not positive definite: the leading minor of order
  // 1234 is not positive (pivot column 1233)".
  std::string message;
  // For a non-PD matrix: the column at which the factorisation broke down, else -1.
  Eigen::Index failed_column = -1;
};

class SparseCholesky {
 public:
  using Matrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

  SparseCholesky();
  ~SparseCholesky();
  // Copies share nothing: the copy gets its own CHOLMOD workspace and a copy of the
  // symbolic (and numeric, if any) factor, so copies can be used from different threads.
  SparseCholesky(const SparseCholesky& other);
  SparseCholesky& operator=(const SparseCholesky& other);
  SparseCholesky(SparseCholesky&&) noexcept;
  SparseCholesky& operator=(SparseCholesky&&) noexcept;

  // Symbolic analysis of the pattern of the upper triangle of `matrix` (square; entries
  // below the diagonal are ignored, so a full symmetric matrix is fine too).
  void Analyze(const Matrix& matrix);

  // Analyse only when `matrix`'s pattern (its compressed index arrays) differs from the one
  // analysed last, e.g. when a soft support's contact cross blocks change with the contact
  // set. Returns whether it analysed (a new analysis drops the numeric factor).
  bool AnalyzeIfChanged(const Matrix& matrix);
  // Numeric factorisation of a matrix with the analysed pattern (CHECKed by size and
  // non-zero count). Returns ok = false with a message for a non-PD matrix.
  FactorizationStatus Factorize(const Matrix& matrix);

  // x = A⁻¹ b using the last successful factorisation.
  Eigen::VectorXd Solve(const Eigen::VectorXd& rhs) const;

  bool analyzed() const;
  bool factorized() const;
  Eigen::Index rows() const { return rows_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  Eigen::Index rows_ = 0;
  Eigen::Index nonzeros_ = 0;
  bool factorized_ = false;
  std::vector<int> outer_, inner_;  // the analysed pattern, for AnalyzeIfChanged
};

}  // namespace ergo
