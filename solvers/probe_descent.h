// The paper's outer optimiser (§4.1) and its plain baseline, both driven by the eight-probe
// line search: "paper-ncg" — nonlinear conjugate gradients with the Polak–Ribière+ β
// (restarted with −∇φ when β < 0, every n iterations, or when d is not a descent
// direction) — and "steepest" — d = −∇φ every iteration.
#pragma once

#include <memory>

#include "solvers/optimizer.h"

namespace ergo {

enum class ProbeDirection { kPolakRibiere, kSteepest };

std::unique_ptr<Optimizer> MakeProbeDescent(ProbeDirection direction, const ProbeOptions& options);

}  // namespace ergo
