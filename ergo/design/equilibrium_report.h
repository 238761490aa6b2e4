// Output files describing one equilibrium on one support, for ParaView and for scripts:
// the deformed body and the support as VTU with pressure, force and displacement fields,
// and the numbers a designer reads as JSON. Every value comes from the contact evaluation
// the equilibrium used (DESIGN.md §6). SI units; files written atomically.
#pragma once

#include <string>

#include "ergo/body/body_state.h"
#include "ergo/body/elastic_part.h"
#include "ergo/body/tissue_compression.h"
#include "ergo/equilibrium/equilibrium_solver.h"
#include "ergo/ergonomics/contact_pressures.h"
#include "ergo/ergonomics/plate_reading.h"
#include "ergo/mesh/json.h"
#include "ergo/mesh/vtu_writer.h"

namespace ergo {

// Writes the deformed tet mesh: point fields pressure_Pa, smoothed_pressure_Pa (skin
// vertices, 0 elsewhere), attached, displacement_m, contact_force_N; cell field
// youngs_modulus_Pa.
void WriteDeformedBodyVtu(const std::string& path, const LayeredBody& body, const BodyState& state,
                          const ContactPressures& pressures,
                          VtuEncoding encoding = VtuEncoding::kBinary);

// Writes the support surface: point fields pressure_Pa and smoothed_pressure_Pa (support
// vertices inside the skin), contact_force_N, and displacement_m from `initial` (optional:
// pass an empty matrix to skip).
void WriteSupportVtu(const std::string& path, const TriMesh& support,
                     const ContactPressures& pressures, const Vertices& initial,
                     VtuEncoding encoding = VtuEncoding::kBinary);

// A soft support's deformed vertices at `state` (its rest positions plus the state's support
// displacement; the rest shape where the state has none).
Vertices SoftSupportPositions(const ElasticPart& part, const BodyState& state);
// The soft support's contact surface `surface` (vertex i is the part's
// boundary().surface_to_tet[i]) moved to the part's `positions`.
TriMesh SoftSupportSurface(const ElasticPart& part, const TriMesh& surface,
                           const Vertices& positions);

// Writes a soft support's deformed tet mesh: point fields displacement_m, held; cell fields
// von_mises_stress_Pa (Cauchy), volume_change (det F − 1), youngs_modulus_Pa.
void WriteSoftSupportVtu(const std::string& path, const ElasticPart& part,
                         const Vertices& positions, VtuEncoding encoding = VtuEncoding::kBinary);

// "tissue_compression" of an equilibrium's summary: min_volume_ratio, min_principal_stretch,
// inversion_threshold, tets_beyond_inversion_threshold, inverted_tets, worst_point_m.
Json TissueCompressionJson(const TissueCompression& compression);
// One warning line for people when tets are compressed beyond the material's inversion
// threshold (where they are, what it means); "" otherwise.
std::string DescribeTissueCompression(const TissueCompression& compression);

// "plate_peak" of a summary: pressure_Pa, pitch_m, cell_centre_xz_m (plate_reading.h).
Json PlatePeakJson(const PlatePeak& peak, const PlatePeakOptions& options = {});

// The summary of an equilibrium: converged, status, reason, iterations, residual_N,
// contact_vertices, max_penetration_m, total_contact_force_N, load_N, peak_pressure_Pa,
// contact_area_m2, mean_pressure_Pa, p95_pressure_Pa, contact_stiffness_Pa_per_m (κ),
// centre_of_pressure_m and centre_of_pressure_z_fraction (centre_of_pressure.h), plate_peak
// (the largest cell a 5 mm pressure plate under the skin would read; when the load acts within
// 10° of −y),
// tissue_compression (`compression`, of result.state: tissue_compression.h), energy_J, the time
// split, and the support side's peak pressure and contact vertex count.
Json EquilibriumSummary(const LayeredBody& body, const EquilibriumResult& result,
                        const ContactPressures& pressures, double contact_stiffness,
                        const TissueCompression& compression);

}  // namespace ergo
