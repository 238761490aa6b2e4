// The data behind ergo_simulate's pictures (OUT/plot_data.json, drawn by
// tools/plot_simulation.py): the skin's contact pressure seen from the support, the centre of
// pressure, where the tissue is squeezed past its material law, and for a foot its length bands
// with their shares of the load.
#pragma once

#include "ergo/body/body_state.h"
#include "ergo/body/layered_body.h"
#include "ergo/body/tissue_compression.h"
#include "ergo/ergonomics/contact_pressures.h"
#include "ergo/mesh/json.h"
#include "tools/ergo_simulate/length_reading.h"

namespace ergo {

// `summary`: the run's summary.json, whose centre_of_pressure_m and region_shares (when
// present) the map marks. `title`: a line naming the run for the pictures.
Json SimulationPlotData(const LayeredBody& body, const BodyState& state,
                        const ContactPressures& pressures, const TissueCompression& compression,
                        const LengthReading& reading, const Json& summary,
                        const std::string& title);

}  // namespace ergo
