// Placing a body over a support before the first solve: the paper starts the human
// "slightly above the supporting surface" (§3.4). Translating the body rigidly along the
// load to a small gap saves the free-fall Newton iterations and avoids starting deep inside.
#pragma once

#include "ergo/body/body_state.h"
#include "ergo/body/layered_body.h"
#include "ergo/contact/support.h"

namespace ergo {

struct PlacementResult {
  BodyState state;
  double moved = 0;    // signed distance moved along the load direction, m (> 0: down)
  bool found = false;  // false: the body meets the support nowhere along the load line
};

// Moves `state` rigidly along the load direction (weight + external force) so that its skin
// is `gap` metres short of first touching `support`, found by sphere tracing (steps of the
// smallest skin-to-support distance, to 1e-7 of the body's size). If the skin penetrates at
// the start, the body is lifted out first. found = false leaves the state unchanged.
PlacementResult PlaceAboveSupport(const LayeredBody& body, const BodyState& state,
                                  const Support& support, double gap);

}  // namespace ergo
