// "nlopt-mma", "nlopt-ccsaq", "nlopt-lbfgs" and "nlopt-tnewton": NLopt's MMA, CCSA-quadratic,
// L-BFGS and preconditioned truncated Newton (LD_MMA, LD_CCSAQ, LD_LBFGS,
// LD_TNEWTON_PRECOND_RESTART, whose Hessian-vector products are gradient differences, one
// evaluation each) through its C++ API on the scaled problem (u in millimetres
// of vertex travel, value φ/|φ(x₀)|), with bound constraints on the vertex moves: a box of
// MoveLimits::total around x₀, and — since NLopt exposes no iteration boundary and MMA sizes
// its first steps by the box — runs in rounds whose box of MoveLimits::per_round is
// re-centred on the best design after each round (classic move limits; README).
#pragma once

#include <memory>

#include "solvers/optimizer.h"

namespace ergo {

enum class NloptMethod { kMma, kCcsaq, kLbfgs, kTnewton };

std::unique_ptr<Optimizer> MakeNloptOptimizer(NloptMethod method, const MoveLimits& limits);

}  // namespace ergo
