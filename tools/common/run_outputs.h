// What ergo_optimize writes for a run: for the initial and the optimised design the body
// and support as VTU (pressure, force, displacement fields) and the support as PLY and
// print-ready STL in millimetres; the data behind the pictures (plot_data.json, read by
// tools/plot_results.py); and the summary with the paper's Table 1 columns. Every file is
// written atomically.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "ergo/body/tissue_compression.h"
#include "ergo/design/centre_of_pressure.h"
#include "ergo/design/design_problem.h"
#include "ergo/ergonomics/contact_pressures.h"
#include "ergo/mesh/json.h"
#include "ergo/mesh/vtu_writer.h"
#include "problems/scenario.h"

namespace ergo {

// One design, evaluated, with the contact pressures of its equilibrium.
struct DesignReport {
  Eigen::VectorXd x;
  TriMesh support;
  DesignEvaluation evaluation;
  ContactPressures pressures;
  double peak_pressure = 0;  // skin side, Pa
  // The largest cell a 5 mm pressure plate under the skin would read (plate_reading.h), Pa; NaN
  // when the load is not seen along y.
  double plate_peak_pressure = std::numeric_limits<double>::quiet_NaN();
  double skin_contact_area = 0;         // Σ rest areas of skin vertices in contact, m²
  CentreOfPressure centre_of_pressure;  // of the skin's contact forces (centre_of_pressure.h)
  // The load's split over the scenario's regions (lengthwise_shares.h), one share per region;
  // empty without regions, equilibrium or contact.
  std::vector<double> region_shares;
  // How hard the equilibrium squeezes the tissue (ergo/body/tissue_compression.h).
  TissueCompression compression;
};

// Evaluates `x` on `problem` (φ only) and gathers its pressures. evaluation.ok tells
// whether the equilibrium converged.
// `regions`: the scenario's, for region_shares (none: no split).
DesignReport ReportDesign(DesignProblem& problem, const Eigen::VectorXd& x,
                          const LengthRegions& regions = {});
// The report of an evaluation already made of `x` on `problem`.
DesignReport ReportEvaluation(const DesignProblem& problem, const Eigen::VectorXd& x,
                              DesignEvaluation evaluation, const LengthRegions& regions = {});

// DIR/body_TAG.vtu and DIR/support_TAG.vtu (pressures; the support's displacement from
// `initial_support`), in `vtu_encoding`. A soft support's surface is written deformed, and its
// solid as DIR/support_solid_TAG.vtu (stress, volume change; design.h WriteSoftSupportVtu).
void WriteDesignVtus(const std::string& dir, const std::string& tag, const LayeredBody& body,
                     const DesignReport& report, const Vertices& initial_support,
                     VtuEncoding vtu_encoding);
// DIR/support_TAG.ply and DIR/support_TAG.stl (binary), in millimetres.
void WriteSupportMeshes(const std::string& dir, const std::string& tag, const TriMesh& support);
// Both: the VTUs, then the support's PLY and print-ready STL.
void WriteDesignFiles(const std::string& dir, const std::string& tag, const LayeredBody& body,
                      const DesignReport& report, const Vertices& initial_support,
                      VtuEncoding vtu_encoding);

// The data tools/plot_results.py draws: skin pressure seen along the load for both designs,
// the designed region's displacement.
Json PlotData(const Scenario& scenario, const DesignReport& initial, const DesignReport& optimized);

}  // namespace ergo
