// "ceres-lbfgs" and "ceres-ncg": Ceres' GradientProblemSolver (LBFGS and
// NONLINEAR_CONJUGATE_GRADIENT with a Wolfe line search) on the scaled design problem
// u = (x − x₀) / LengthScale (millimetres of vertex travel), value φ / |φ(x₀)|, so that
// Ceres' relative tolerances and its unit first step mean something (DESIGN.md §7).
#pragma once

#include <memory>

#include "solvers/optimizer.h"

namespace ergo {

enum class CeresDirection { kLbfgs, kNonlinearConjugateGradient };

std::unique_ptr<Optimizer> MakeCeresOptimizer(CeresDirection direction,
                                              const CeresSettings& settings);

}  // namespace ergo
