#include "ergo/mesh/sparse_cholesky.h"

#include <algorithm>
#include <string>

#include <cholmod.h>
#include <glog/logging.h>

#include "ergo/mesh/blas_threads.h"

namespace ergo {

struct SparseCholesky::Impl {
  cholmod_common common;
  cholmod_factor* factor = nullptr;

  Impl() {
    ApplyDefaultBlasThreads();  // one OpenBLAS thread unless told otherwise (blas_threads.h)
    cholmod_start(&common);
    common.supernodal = CHOLMOD_SUPERNODAL;
    common.final_ll = 1;                    // keep an LLᵀ factor
    common.quick_return_if_not_posdef = 1;  // stop at the first non-positive pivot
    common.print = 0;
    common.error_handler = nullptr;
  }
  ~Impl() {
    if (factor) cholmod_free_factor(&factor, &common);
    cholmod_finish(&common);
  }
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;

  void CopyFactorFrom(const Impl& other) {
    if (factor) cholmod_free_factor(&factor, &common);
    if (other.factor) {
      factor = cholmod_copy_factor(other.factor, const_cast<cholmod_common*>(&common));
      CHECK(factor) << "CHOLMOD could not copy a factor (out of memory?)";
    }
  }
};

namespace {

// A non-owning CHOLMOD view of an Eigen compressed column matrix, upper triangle used.
cholmod_sparse View(const SparseCholesky::Matrix& matrix) {
  CHECK(matrix.isCompressed()) << "call makeCompressed() before factorising";
  cholmod_sparse view{};
  view.nrow = static_cast<size_t>(matrix.rows());
  view.ncol = static_cast<size_t>(matrix.cols());
  view.nzmax = static_cast<size_t>(matrix.nonZeros());
  view.p = const_cast<int*>(matrix.outerIndexPtr());
  view.i = const_cast<int*>(matrix.innerIndexPtr());
  view.x = const_cast<double*>(matrix.valuePtr());
  view.stype = 1;  // symmetric, upper triangle stored/used
  view.itype = CHOLMOD_INT;
  view.xtype = CHOLMOD_REAL;
  view.dtype = CHOLMOD_DOUBLE;
  view.sorted = 1;
  view.packed = 1;
  return view;
}

}  // namespace

SparseCholesky::SparseCholesky() : impl_(std::make_unique<Impl>()) {}
SparseCholesky::~SparseCholesky() = default;
SparseCholesky::SparseCholesky(SparseCholesky&&) noexcept = default;
SparseCholesky& SparseCholesky::operator=(SparseCholesky&&) noexcept = default;

SparseCholesky::SparseCholesky(const SparseCholesky& other) : impl_(std::make_unique<Impl>()) {
  *this = other;
}

SparseCholesky& SparseCholesky::operator=(const SparseCholesky& other) {
  if (this == &other) return *this;
  if (!impl_) impl_ = std::make_unique<Impl>();
  impl_->CopyFactorFrom(*other.impl_);
  rows_ = other.rows_;
  nonzeros_ = other.nonzeros_;
  factorized_ = other.factorized_;
  outer_ = other.outer_;
  inner_ = other.inner_;
  return *this;
}

void SparseCholesky::Analyze(const Matrix& matrix) {
  CHECK_EQ(matrix.rows(), matrix.cols());
  if (impl_->factor) cholmod_free_factor(&impl_->factor, &impl_->common);
  cholmod_sparse view = View(matrix);
  impl_->factor = cholmod_analyze(&view, &impl_->common);
  CHECK(impl_->factor) << "CHOLMOD analysis failed (status " << impl_->common.status << ")";
  rows_ = matrix.rows();
  nonzeros_ = matrix.nonZeros();
  factorized_ = false;
  CHECK(matrix.isCompressed());
  outer_.assign(matrix.outerIndexPtr(), matrix.outerIndexPtr() + matrix.outerSize() + 1);
  inner_.assign(matrix.innerIndexPtr(), matrix.innerIndexPtr() + matrix.nonZeros());
}

bool SparseCholesky::AnalyzeIfChanged(const Matrix& matrix) {
  CHECK(matrix.isCompressed());
  const bool same = impl_->factor && matrix.rows() == rows_ && matrix.nonZeros() == nonzeros_ &&
                    std::equal(outer_.begin(), outer_.end(), matrix.outerIndexPtr()) &&
                    std::equal(inner_.begin(), inner_.end(), matrix.innerIndexPtr());
  if (same) return false;
  Analyze(matrix);
  return true;
}

FactorizationStatus SparseCholesky::Factorize(const Matrix& matrix) {
  CHECK(impl_->factor) << "Analyze() before Factorize()";
  CHECK_EQ(matrix.rows(), rows_) << "matrix size differs from the analysed pattern";
  CHECK_EQ(matrix.nonZeros(), nonzeros_) << "sparsity pattern differs from the analysed one";
  FactorizationStatus status;
  cholmod_sparse view = View(matrix);
  const int ok = cholmod_factorize(&view, impl_->factor, &impl_->common);
  factorized_ = false;
  if (!ok || impl_->common.status < CHOLMOD_OK) {
    status.message = "CHOLMOD factorisation failed (status " +
                     std::to_string(impl_->common.status) + ", out of memory?)";
    return status;
  }
  if (impl_->common.status == CHOLMOD_NOT_POSDEF) {
    status.failed_column = static_cast<Eigen::Index>(impl_->factor->minor);
    status.message = "matrix is not positive definite: the leading minor of order " +
                     std::to_string(status.failed_column + 1) + " is not positive (column " +
                     std::to_string(status.failed_column) + " of " + std::to_string(rows_) + ")";
    return status;
  }
  factorized_ = true;
  status.ok = true;
  return status;
}

Eigen::VectorXd SparseCholesky::Solve(const Eigen::VectorXd& rhs) const {
  CHECK(factorized_) << "Solve() needs a successful Factorize()";
  CHECK_EQ(rhs.size(), rows_);
  cholmod_dense b{};
  b.nrow = static_cast<size_t>(rows_);
  b.ncol = 1;
  b.nzmax = b.nrow;
  b.d = b.nrow;
  b.x = const_cast<double*>(rhs.data());
  b.xtype = CHOLMOD_REAL;
  b.dtype = CHOLMOD_DOUBLE;
  cholmod_common* common = &impl_->common;
  cholmod_dense* x = cholmod_solve(CHOLMOD_A, impl_->factor, &b, common);
  CHECK(x) << "CHOLMOD solve failed (status " << common->status << ")";
  Eigen::VectorXd solution = Eigen::Map<const Eigen::VectorXd>(static_cast<double*>(x->x), rows_);
  cholmod_free_dense(&x, common);
  return solution;
}

bool SparseCholesky::analyzed() const { return impl_ && impl_->factor; }
bool SparseCholesky::factorized() const { return factorized_; }

}  // namespace ergo
