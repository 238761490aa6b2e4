// One static contact equilibrium of a body on a support, the whole job of `ergo_simulate`
// as a library call (paper §3.3–3.5): optionally place the body along its load just above
// the support, calibrate κ to a target penetration (or take it as given), solve, and
// evaluate both surfaces' pressures from the very springs of the final state. The tool and
// the Python bindings both call this, so they give the same numbers and messages.
//
//   StaticEquilibriumOptions options;
//   options.contact_stiffness = 0;  // calibrate to options.target_penetration
//   const StaticEquilibrium solved = SolveStaticEquilibrium(body, support_mesh, "seat.stl",
//                                                           options);
//   if (!solved.ok()) std::cerr << solved.message << "\n";
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "ergo/body/elastic_part.h"
#include "ergo/body/layered_body.h"
#include "ergo/body/tissue_compression.h"
#include "ergo/contact/stiffness_calibration.h"
#include "ergo/equilibrium/equilibrium_solver.h"
#include "ergo/ergonomics/contact_pressures.h"
#include "ergo/mesh/json.h"
#include "ergo/mesh/tri_mesh.h"

namespace ergo {

struct StaticEquilibriumOptions {
  // κ in Pa/m; 0 (the default) calibrates it so that the largest penetration at
  // equilibrium is `target_penetration` (paper §3.5), starting from a guess from the load.
  double contact_stiffness = 0;
  double target_penetration = 3e-4;  // m
  // The rest body turned by this rotation vector (rad) about its core's centre before it is
  // placed: a foot's roll about its length is (0, 0, roll).
  Eigen::Vector3d start_rotation = Eigen::Vector3d::Zero();
  // Move the body along its load to `gap` above the support before solving.
  bool place = true;
  double gap = 1e-3;                 // m
  double relative_tolerance = 1e-8;  // force residual relative to the load
  int max_iterations = 100;          // Newton iterations per solve
  int stall_iterations = 5;          // EquilibriumOptions::stall_iterations; 0 = strict only
  // EquilibriumOptions::contact_support_springs: the support's springs push too (always so
  // on a soft support).
  bool two_way_contact = false;
  // Wall-clock budget for the whole job, seconds; 0 = none. When it runs out the current
  // solve stops (EquilibriumStatus::kInterrupted) and the result says so.
  double max_seconds = 0;
  // One line per stage, Newton iteration and calibration step, elapsed time first
  // ("  12.3 s  Newton 4  residual 1.2e-3 N  ..."); none when empty.
  std::function<void(const std::string& line)> progress;
  // If set, checked before every Newton iteration: true stops (e.g. Ctrl-C).
  const std::atomic<bool>* stop = nullptr;
  // The support as a soft part (paper §4.3; null: rigid). Its boundary at rest must be the
  // `support_mesh` passed along (ElasticPart::boundary().surface), the contact surface.
  std::shared_ptr<const ElasticPart> soft_support;
};

struct StaticEquilibrium {
  EquilibriumResult result;                      // the final, reported solve
  std::optional<CalibrationResult> calibration;  // when κ was calibrated
  double contact_stiffness = 0;                  // κ used by `result`, Pa/m
  bool placed_found = true;       // false: the body meets the support nowhere along its load
  bool out_of_time = false;       // max_seconds ran out
  ContactPressures pressures;     // skin and support pressures and forces of `result`
  TissueCompression compression;  // how hard `result` squeezes the tissue
  Json summary;                   // EquilibriumSummary + calibration, contact, lock

  // Converged, touching the support, and (when calibrating) at the target penetration.
  bool ok() const;
  // Why not ok(), in words; "ok" otherwise.
  std::string message() const;
};

// `source` names the support in messages. Throws InputError for a support mesh that is
// unusable (not closed, not manifold, ...) or options out of range.
StaticEquilibrium SolveStaticEquilibrium(const LayeredBody& body, const TriMesh& support_mesh,
                                         const std::string& source,
                                         const StaticEquilibriumOptions& options);

}  // namespace ergo
