// ζ of one equilibrium (paper Eq. 11–12) as value plus gradient: both surfaces' halves, the
// value a design is scored by, and on request its explicit partials ∂ζ/∂(body positions) and
// ∂ζ/∂(support shape) (score_gradient.h), which the design stage's adjoints chain through
// the equilibrium. One place decides which halves ζ holds, so value and gradient agree.
//
//   const ContactPressures pressures = evaluator.Evaluate(e.contacts, support_areas);
//   const PressureScore zeta = ScorePressures(pressures, body, true, /*with_partials=*/true);
#pragma once

#include "ergo/body/layered_body.h"
#include "ergo/ergonomics/contact_pressures.h"
#include "ergo/ergonomics/score_gradient.h"

namespace ergo {

struct PressureScore {
  double human = 0;    // ζ of the skin's side, Pa^e·m²
  double support = 0;  // ζ of the support's side, Pa^e·m²
  double value = 0;    // human + support, or human alone when the support side is not scored
  bool has_partials = false;
  ScorePartials partials;  // ∂value/∂(body positions, support shape) when has_partials
};

// `score_support_side` false: ζ is the skin's side alone (DesignOptions::score_support_side),
// in the value and the partials; the support's half is reported either way. `pressures`'
// contact springs must carry their Hessians when `with_partials`.
PressureScore ScorePressures(const ContactPressures& pressures, const LayeredBody& body,
                             bool score_support_side, bool with_partials);

}  // namespace ergo
