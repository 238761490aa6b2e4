// Placement checks: how a design scores when the body lands a little off the pose the
// optimiser saw — shifted a few millimetres across the support, held tilted by a degree — as a
// person never sits, stands or grips twice in exactly the same place (DESIGN.md §8). Each
// check places the body afresh (DesignPlacement::kFresh) from the moved start pose on its own
// copy of the problem. Units: m, rad.
#pragma once

#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "ergo/design/design_problem.h"

namespace ergo {

// A rigid change of the start pose: turned by `tilt` (rotation vector about the core
// centre) and shifted by `shift`.
struct Placement {
  std::string name;  // e.g. "x+3mm", "pitch-1deg", "centred"
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();
  Eigen::Vector3d tilt = Eigen::Vector3d::Zero();
};

// ±shift along the two world axes most nearly perpendicular to the body's load, and, when
// with_tilts, ±angle about each world axis across the load about which the core lock holds
// the rotation: a tilt about a free axis re-settles to the centred placement, so it is no
// check.
std::vector<Placement> PlacementChecks(const LayeredBody& body, double shift, double angle,
                                       bool with_tilts);

// The tilts alone: ±angle about each world axis across the load whose rotation the lock
// holds (none for angle 0).
std::vector<Placement> HeldTilts(const LayeredBody& body, double angle);

// A copy of `problem` whose evaluations place the body afresh from its start pose moved by
// `placement` (a zero placement: the centred pose).
DesignProblem PlacedProblem(const DesignProblem& problem, const Placement& placement);

// Design x placed afresh at every placement, each on its own copy of `problem`, in parallel
// threads. A placement not started because *stop became true fails with "interrupted".
std::vector<DesignEvaluation> EvaluatePlacements(const DesignProblem& problem,
                                                 const Eigen::VectorXd& x,
                                                 const std::vector<Placement>& placements,
                                                 const std::atomic<bool>* stop = nullptr);

// The mean φ of x over those placements (the robust objective's value placed afresh); NaN if
// any of their equilibria fails, and then *failure (when given) says which placement and why
// ("x+3mm: iteration cap: …"; empty otherwise). Adds their time splits to *timing when given.
double MeanPlacedPhi(const DesignProblem& problem, const Eigen::VectorXd& x,
                     const std::vector<Placement>& placements,
                     const std::atomic<bool>* stop = nullptr, EvaluationTiming* timing = nullptr,
                     std::string* failure = nullptr);

// Runs task(i) for i in [0, count) on min(count, cores) threads, sharing the cores among
// them (each thread's OpenMP regions get cores / threads).
void ForEachInParallel(int count, const std::function<void(int)>& task);

}  // namespace ergo
