// The paper's scenes (chair, shoe sole, mouse) from flags: the preset, the negative-image
// start, resolution and lock overrides, a user's body or support, and each scene's own
// --chair_*, --shoe_*, --mouse_* flags. Used by scenario_flags.cc's table.
#pragma once

#include "problems/scenario.h"

namespace ergo {

Scenario MakeChairFromFlags();
Scenario MakeShoeFromFlags();
Scenario MakeMouseFromFlags();

}  // namespace ergo
