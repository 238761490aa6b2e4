// The paper's Fig. 5 experiment: a body resting on a support with one bump of fixed height
// whose spatial frequency (1/width) varies; ζ for exponents 2, 3 and 4 at each frequency,
// each rescaled to agree at the lowest frequency. It shows that the cost discriminates
// spiky supports for every exponent (§4.1).
#pragma once

#include <string>
#include <vector>

#include "problems/bump_scenario.h"

namespace ergo {

struct BumpSweepPoint {
  double width = 0;                // Gaussian σ of the bump, m
  double frequency = 0;            // 1 / width, 1/m
  double zeta[3] = {0, 0, 0};      // ζ for e = 2, 3, 4
  double rescaled[3] = {0, 0, 0};  // ζ / ζ(lowest frequency) for each exponent
  int contact_vertices = 0;
  double max_penetration = 0;  // m
  double peak_pressure = 0;    // human side, Pa
  bool converged = false;
  std::string message;  // the equilibrium's report if it failed
};

// Solves the ball-on-bump scene for every width in `widths` (bump height and all else from
// `base`) and evaluates ζ for e = 2, 3, 4 from the one converged contact state. Points are
// returned in increasing frequency. The plate is meshed fine enough for the narrowest bump
// (cells of at most width/2 across the top) unless base.plate_cells is already finer.
std::vector<BumpSweepPoint> RunBumpFrequencySweep(const BumpScenarioOptions& base,
                                                  std::vector<double> widths);

}  // namespace ergo
