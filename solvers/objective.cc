#include "solvers/objective.h"

#include <algorithm>
#include <limits>

namespace ergo {

double TermValue(const ObjectiveTerms& terms, const std::string& name) {
  for (const ObjectiveTerm& term : terms)
    if (term.name == name) return term.value;
  return std::numeric_limits<double>::quiet_NaN();
}

void AddScaledTerms(const ObjectiveTerms& from, double scale, ObjectiveTerms* into) {
  for (const ObjectiveTerm& term : from) {
    auto same = std::find_if(into->begin(), into->end(),
                             [&](const ObjectiveTerm& t) { return t.name == term.name; });
    if (same == into->end()) same = into->insert(into->end(), {term.name, term.weight, 0.0});
    same->value += scale * term.value;
  }
}

}  // namespace ergo
