// The DesignProblem as an optimiser sees it: a ceres::FirstOrderFunction and an NLopt
// objective over scaled parameters u with x = x₀ + length_scale · u and value
// φ(x) / value_scale, so that tolerances written for O(1) problems mean something here
// (DESIGN.md §7: Ceres' defaults are relative to the problem's scale). A failed
// equilibrium is reported as a failure (Ceres: Evaluate returns false and the line search
// backs off; NLopt: +∞, which CCSA/MMA treat as "not conservative" and shrink the step).
#pragma once

#include <functional>

#include <ceres/first_order_function.h>
#include <Eigen/Core>

#include "ergo/design/design_problem.h"

namespace ergo {

struct DesignScaling {
  double value_scale = 1.0;   // φ is divided by this (e.g. φ(x₀))
  double length_scale = 1.0;  // x = x₀ + length_scale · u (e.g. 1e-3: u in millimetres)
};

// Observes every evaluation (x, evaluation) made through an adapter, e.g. to keep the best
// design and a history. Called on the evaluating thread.
using DesignObserver =
    std::function<void(const Eigen::VectorXd& x, const DesignEvaluation& evaluation)>;

class DesignFirstOrderFunction : public ceres::FirstOrderFunction {
 public:
  // Keeps a pointer to `problem` (must outlive this); x₀ is the origin of u.
  DesignFirstOrderFunction(DesignProblem* problem, Eigen::VectorXd origin, DesignScaling scaling,
                           DesignObserver observer = nullptr);
  bool Evaluate(const double* u, double* cost, double* gradient) const override;
  int NumParameters() const override { return static_cast<int>(origin_.size()); }
  Eigen::VectorXd DesignAt(const double* u) const;

 private:
  DesignProblem* problem_;
  Eigen::VectorXd origin_;
  DesignScaling scaling_;
  DesignObserver observer_;
};

// Data for NloptDesignObjective: pass a pointer to it as nlopt's f_data.
struct NloptDesignData {
  DesignProblem* problem = nullptr;
  Eigen::VectorXd origin;
  DesignScaling scaling;
  DesignObserver observer;
};

// nlopt::vfunc / nlopt_func signature: value (scaled) and, if grad is non-null, its gradient.
double NloptDesignObjective(unsigned n, const double* u, double* gradient, void* data);

}  // namespace ergo
