#include "ergo/design/design_functions.h"

#include <cmath>
#include <limits>

#include <glog/logging.h>

namespace ergo {
namespace {

// Shared body of both adapters: evaluates and scales, false on failure.
bool EvaluateScaled(DesignProblem* problem, const Eigen::VectorXd& origin,
                    const DesignScaling& scaling, const DesignObserver& observer, const double* u,
                    double* cost, double* gradient) {
  const Eigen::Index n = origin.size();
  const Eigen::VectorXd x = origin + scaling.length_scale * Eigen::Map<const Eigen::VectorXd>(u, n);
  const DesignEvaluation e = problem->Evaluate(x, gradient != nullptr);
  if (observer) observer(x, e);
  if (!e.ok) return false;
  *cost = e.phi / scaling.value_scale;
  if (gradient) {
    Eigen::Map<Eigen::VectorXd>(gradient, n) =
        e.gradient * (scaling.length_scale / scaling.value_scale);
  }
  return std::isfinite(*cost);
}

}  // namespace

DesignFirstOrderFunction::DesignFirstOrderFunction(DesignProblem* problem, Eigen::VectorXd origin,
                                                   DesignScaling scaling, DesignObserver observer)
    : problem_(problem),
      origin_(std::move(origin)),
      scaling_(scaling),
      observer_(std::move(observer)) {
  CHECK(problem_);
  CHECK_EQ(origin_.size(), problem_->NumParameters());
  CHECK_GT(scaling_.value_scale, 0.0);
  CHECK_GT(scaling_.length_scale, 0.0);
}

bool DesignFirstOrderFunction::Evaluate(const double* u, double* cost, double* gradient) const {
  return EvaluateScaled(problem_, origin_, scaling_, observer_, u, cost, gradient);
}

Eigen::VectorXd DesignFirstOrderFunction::DesignAt(const double* u) const {
  return origin_ + scaling_.length_scale * Eigen::Map<const Eigen::VectorXd>(u, origin_.size());
}

double NloptDesignObjective(unsigned n, const double* u, double* gradient, void* data) {
  auto* d = static_cast<NloptDesignData*>(data);
  CHECK_EQ(static_cast<Eigen::Index>(n), d->origin.size());
  double cost = 0;
  if (!EvaluateScaled(d->problem, d->origin, d->scaling, d->observer, u, &cost, gradient)) {
    if (gradient) std::fill(gradient, gradient + n, 0.0);
    return std::numeric_limits<double>::infinity();
  }
  return cost;
}

}  // namespace ergo
