#include "ergo/ergonomics/pressure_score.h"

namespace ergo {

PressureScore ScorePressures(const ContactPressures& pressures, const LayeredBody& body,
                             bool score_support_side, bool with_partials) {
  PressureScore out;
  out.human = pressures.human.cost;
  out.support = pressures.support.cost;
  out.value = out.human + (score_support_side ? out.support : 0.0);
  if (with_partials) {
    out.partials = PressureScorePartials(pressures, body, score_support_side);
    out.has_partials = true;
  }
  return out;
}

}  // namespace ergo
