// Objective: what an outer optimiser (paper §4.1) minimises — x ↦ φ(x) with its gradient,
// plus the two facts about the design space the optimisers need: how far a step moves the
// support's vertices (the paper's probe lengths and the move limits are in metres of vertex
// travel) and what length counts as "1" for scaled solvers. DesignObjective wraps a
// DesignProblem; the analytic objectives let the same optimisers be tested on functions
// with a known minimum.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "ergo/design/evaluation_timing.h"

namespace ergo {

// A named part of φ: φ = Σ weight · value over an objective's terms (a design problem's
// "zeta" and "psi" with weights 1 and γ; an analytic function's single "f"). The optimisers
// minimise φ; the terms are what they log and report, whatever the objective is made of.
struct ObjectiveTerm {
  std::string name;
  double weight = 1;
  double value = 0;
};
using ObjectiveTerms = std::vector<ObjectiveTerm>;

// The value of the term called `name`, NaN if there is none.
double TermValue(const ObjectiveTerms& terms, const std::string& name);
// Adds scale · value of every term of `from` to the term of the same name in *into (appended,
// with from's weight, when *into has none): averages of objectives made of the same terms.
void AddScaledTerms(const ObjectiveTerms& from, double scale, ObjectiveTerms* into);

// One evaluation. A failed one (ok = false) carries a message and never a number.
struct ObjectiveValue {
  bool ok = false;
  std::string message;        // why not ok, or "ok"
  double phi = 0;             // the value minimised
  ObjectiveTerms terms;       // φ's named parts, in the objective's TermNames() order
  Eigen::VectorXd gradient;   // ∇φ, when requested and ok
  int newton_iterations = 0;  // equilibrium Newton iterations spent (also when failed)
  double seconds = 0;         // wall time of this evaluation
  // Where the time went, summed over the equilibria the evaluation solved (also when it
  // failed); all zeros for objectives that are not design problems (analytic ones).
  EvaluationTiming timing;
};

class Objective {
 public:
  virtual ~Objective() = default;

  virtual int NumParameters() const = 0;
  // The names of φ's terms, as every successful evaluation fills ObjectiveValue::terms.
  virtual std::vector<std::string> TermNames() const = 0;
  // φ(x) and, if with_gradient, ∇φ(x). Not thread-safe on one object: Clone per thread.
  virtual ObjectiveValue Evaluate(const Eigen::VectorXd& x, bool with_gradient) = 0;
  // An independent copy that may be evaluated on another thread, carrying this object's
  // warm-start state (a DesignProblem copy keeps its equilibrium cache).
  virtual std::unique_ptr<Objective> Clone() const = 0;
  // The largest displacement of any support vertex caused by the design step dx, metres.
  virtual double LargestMove(const Eigen::VectorXd& dx) const = 0;
  // Half-width of a per-coordinate box around x that keeps every vertex's move ≤ move
  // (move / √3 where a vertex has three free coordinates).
  virtual double BoxHalfWidthForMove(double move) const = 0;
  // The design-space length that scaled solvers treat as 1 (Ceres, NLopt): 1 mm of
  // vertex travel.
  virtual double LengthScale() const = 0;
  // One line for reports.
  virtual std::string Describe() const = 0;
};

}  // namespace ergo
