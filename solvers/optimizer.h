// Optimizer: one interface for every outer optimiser of the design problem (paper §4.1 and
// DESIGN.md §3 "Outer optimisation"): the paper's NCG with eight parallel step probes, a
// steepest-descent baseline with the same probes, Ceres L-BFGS / NCG and NLopt MMA / CCSAQ /
// L-BFGS. Each takes an Objective, a start x₀ and a Budget and returns the best design it
// evaluated with a per-iteration history, so they can be compared on equal terms: the same
// φ, the same evaluation count (every φ evaluation, probes and failures included), the same
// Newton-iteration count and the same wall clock. See solvers/README.md.
//
//   std::unique_ptr<Optimizer> optimizer = MakeOptimizer("paper-ncg", {}, &error);
//   DesignObjective objective(scenario.MakeProblem());
//   Budget budget;  budget.max_evaluations = 200;
//   OptimizerResult result = optimizer->Minimize(objective, objective.problem().InitialDesign(),
//                                                budget, {});
//   std::cout << result.BriefReport() << "\n";
#pragma once

#include <atomic>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "solvers/objective.h"

namespace ergo {

// When to stop. Tolerances are on the scaled problem every optimiser sees: value φ/|φ(x₀)|,
// lengths in units of Objective::LengthScale() (1 mm of vertex travel).
struct Budget {
  int max_evaluations = 200;  // φ evaluations, including probes and failed ones
  double max_seconds = 0;     // wall clock; 0 = unlimited. An evaluation in flight finishes.
  // Converged when ‖∇φ‖∞ · LengthScale / |φ(x₀)| ≤ this (relative change of φ per mm).
  double gradient_tolerance = 1e-8;
  // Converged when an iteration lowers φ by less than this fraction of |φ|.
  double function_tolerance = 1e-10;
  // Converged when an iteration moves no vertex farther than this, mm (Ceres: relative).
  double parameter_tolerance = 1e-8;
};

// Per-iteration history entry: φ and its parts at the iterate, and the cost so far.
struct IterationRecord {
  int iteration = 0;           // 0 = the start x₀
  long evaluations = 0;        // φ evaluations so far (all of them)
  long newton_iterations = 0;  // equilibrium Newton iterations so far
  double seconds = 0;          // wall clock since Minimize began
  double phi = 0;              // as evaluated at the iterate (never interpolated)
  ObjectiveTerms terms;        // φ's named parts there
  double gradient_norm = -1;   // ‖∇φ‖₂ at the iterate; −1 where it was not evaluated
  double step = 0;             // largest vertex move from the previous iterate, m
  // The time split of every evaluation so far (cumulative like `evaluations`; zeros for
  // objectives that are not design problems).
  EvaluationTiming timing;
  // Runs in fresh rounds (solvers/fresh_rounds.h): the score afresh of the design kept when
  // this entry was recorded (φ₀ afresh until a round's check keeps a better one). NaN for
  // other runs.
  double kept_fresh_phi = std::numeric_limits<double>::quiet_NaN();
};

// How a caller watches and stops a run. Everything is optional.
struct RunControl {
  // Set to true (e.g. by a SIGINT handler) to stop cleanly with the best design so far;
  // evaluations already running finish first. The library installs no signal handler.
  const std::atomic<bool>* stop = nullptr;
  // Called on every history entry; return false to stop ("interrupted").
  std::function<bool(const IterationRecord&)> progress;
  // Called after every evaluation, successful or not, with the design evaluated (probes
  // included). Serialised: never called from two threads at once.
  std::function<void(const Eigen::VectorXd& x, const ObjectiveValue& value)> on_evaluation;
};

struct OptimizerResult {
  std::string optimizer;   // registry name
  bool ok = false;         // false only if not even x₀ could be evaluated
  Eigen::VectorXd best_x;  // the best design evaluated successfully
  double initial_phi = 0;  // φ(x₀)
  double best_phi = 0;     // φ(best_x), as evaluated
  // When best_phi is the score of best_x placed afresh (MinimizeInRounds): the optimiser's own
  // value there, on its path. NaN otherwise.
  double followed_phi = std::numeric_limits<double>::quiet_NaN();
  ObjectiveTerms best_terms;  // φ(best_x)'s named parts
  // A copy of the objective as it stood right after evaluating best_x. For a DesignProblem
  // it holds the equilibrium the optimiser saw there: re-evaluating best_x on it reproduces
  // best_phi (a fresh problem may settle into another equilibrium where several exist).
  std::shared_ptr<Objective> best_objective;
  // The best few distinct designs evaluated (best first, best_x among them) and their φ: a
  // caller may check them afresh (another placement, another mesh) before it keeps one.
  std::vector<Eigen::VectorXd> candidates;
  std::vector<double> candidate_phi;
  std::vector<IterationRecord> history;
  std::string stop_reason;      // e.g. "budget: 200 evaluations", "stalled: ..."
  long evaluations = 0;         // every φ evaluation made (probes, failures included)
  long failed_evaluations = 0;  // evaluations whose equilibrium (or value) failed
  long newton_iterations = 0;
  double seconds = 0;  // wall
  // The time split summed over every evaluation made (the same ones as `evaluations`); its
  // seconds are per evaluation, so parallel probes and placements sum beyond `seconds`.
  EvaluationTiming timing;

  double ReductionPercent() const;  // 100 (1 − best/initial)
  // The names of φ's terms in this run's records (best_terms' order first).
  std::vector<std::string> TermNames() const;
  std::string BriefReport() const;  // one line
  std::string FullReport() const;   // one line per history entry below the brief report
};

// The stop reason of a run that used up its wall-clock budget: "budget: 300 s wall".
std::string TimeBudgetReason(double max_seconds);

class Optimizer {
 public:
  virtual ~Optimizer() = default;
  virtual std::string name() const = 0;
  // Minimises `objective` from x0 within `budget`. Evaluates on `objective` and on clones of
  // it; never throws for numerical trouble (failures end up in stop_reason).
  virtual OptimizerResult Minimize(Objective& objective, const Eigen::VectorXd& x0,
                                   const Budget& budget, const RunControl& control) = 0;
};

// paper-ncg and steepest: the probe line search of paper §4.1.
struct ProbeOptions {
  // Largest vertex move of each trial step, metres (paper: 1 µm, 10 µm, 0.1, 0.2, 0.5, 0.7,
  // 1, 2 mm).
  std::vector<double> moves = {1e-6, 1e-5, 1e-4, 2e-4, 5e-4, 7e-4, 1e-3, 2e-3};
  // Worker threads for the probes; 0 = one per probe (the paper's eight).
  int threads = 0;
  // Probes are evaluated with their gradient, so the accepted one needs no further
  // evaluation (one adjoint solve per probe instead of one more equilibrium per iteration).
  // false: probes evaluate φ only and the accepted point is re-evaluated with ∇φ.
  bool gradient_at_probes = true;
  // paper-ncg: restart with −∇φ every this many iterations; 0 = the number of parameters.
  int restart_every = 0;
};

// nlopt-*: bounds on the vertex moves.
struct MoveLimits {
  double total = 0.02;  // no vertex moves farther than this from x₀, m
  // No vertex moves farther than this within one round (NLopt runs in rounds with the box
  // re-centred on the best design, see README), m; 0 = no per-round cap.
  double per_round = 0.002;
  int round_evaluations = 10;  // evaluations per round before re-centring
};

// Ceres: which GradientProblemSolver settings are not derived from the Budget.
struct CeresSettings {
  int max_lbfgs_rank = 20;
  // L-BFGS: scale the initial inverse Hessian by an eigenvalue estimate (Oren) instead of
  // the identity, so the method does not depend on how φ and the lengths are scaled.
  bool eigenvalue_scaling = true;
  // NCG flavour; Polak–Ribière like the paper's NCG (Ceres' default is Fletcher–Reeves).
  bool polak_ribiere = true;
};

struct OptimizerOptions {
  ProbeOptions probes;
  MoveLimits limits;
  CeresSettings ceres;
};

// "paper-ncg", "steepest", "ceres-lbfgs", "ceres-ncg", "nlopt-mma", "nlopt-ccsaq",
// "nlopt-lbfgs", "nlopt-tnewton".
std::vector<std::string> OptimizerNames();
// The optimiser called `name`, or nullptr with *error naming the valid names.
std::unique_ptr<Optimizer> MakeOptimizer(const std::string& name, const OptimizerOptions& options,
                                         std::string* error);

}  // namespace ergo
