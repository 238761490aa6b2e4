// Scenario: everything needed to pose one design problem — a body part, a support surface,
// where the body starts, which support vertices are designed, and the solver/cost options.
// Built by the scenario generators in problems/ (a soft ball on a bumpy plate; the paper's
// chair, shoe sole and mouse) or from a user's files; consumed by ergo_optimize,
// ergo_compare and the tests. SI units.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "ergo/body/body_state.h"
#include "ergo/body/layered_body.h"
#include "ergo/design/design_problem.h"
#include "ergo/mesh/tri_mesh.h"

namespace ergo {

// Bands along the body's rest length in which a pressure plate's masks would split its load
// (ergo/design/lengthwise_shares.h); the shoe's: rearfoot, midfoot, forefoot. Empty: none.
struct LengthRegions {
  std::vector<std::string> names;
  std::vector<double> ends;  // upper ends, fractions of the rest extent along z, the last 1
  bool from_min_z = true;    // the length runs from the smallest z (the generated foot's heel)
};

struct Scenario {
  std::string name;         // e.g. "bump", "chair"
  std::string description;  // one line for reports
  // Shared so that copies of a DesignProblem (which keep a reference) stay valid.
  std::shared_ptr<const LayeredBody> body;
  TriMesh support;        // closed, outward, metres
  BodyState start;        // the body's state before the first solve (above the support)
  DesignOptions design;   // equilibrium, cost, regulariser and the active-vertex mask
  LengthRegions regions;  // reported in summaries (region shares, centre of pressure)

  // A DesignProblem for this scenario.
  DesignProblem MakeProblem() const { return DesignProblem(*body, support, start, design); }
};

}  // namespace ergo
