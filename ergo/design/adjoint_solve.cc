#include "ergo/design/adjoint_solve.h"

#include "ergo/mesh/preconditioned_cg.h"

namespace ergo {

AdjointSolution SolveAdjoint(const SparseMatrix& hessian, const Eigen::VectorXd& rhs,
                             const SparseCholesky& newton_factor, SparseCholesky* cholesky) {
  AdjointSolution out;
  if (newton_factor.factorized() && newton_factor.rows() == hessian.rows()) {
    const PcgResult cg = PreconditionedConjugateGradient(hessian, newton_factor, rhs, 1e-12, 30);
    out.pcg_iterations = cg.iterations;
    if (cg.converged) {
      out.z = cg.x;
      out.ok = true;
      out.message = "ok";
      return out;
    }
  }
  cholesky->AnalyzeIfChanged(hessian);
  const FactorizationStatus factor = cholesky->Factorize(hessian);
  ++out.factorizations;
  if (!factor.ok) {
    out.message = "the exact Hessian at the equilibrium is not positive definite (" +
                  factor.message +
                  "): the equilibrium is not a strict minimum, so its derivative is undefined";
    return out;
  }
  out.z = cholesky->Solve(rhs);
  out.ok = true;
  out.message = "ok";
  return out;
}

}  // namespace ergo
