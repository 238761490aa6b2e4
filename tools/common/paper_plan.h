// The runs behind `ergo_paper` (the paper's §5–§8 experiments on ergo's chair, shoe and
// mouse scenes) and which run fills which row of which table. A run is one ergo_optimize
// process; a run two tables need (the mouse's flat start is Table 1's row and Table 2's
// γ = 0 row) is planned once.
//
//   const PaperPlan plan = MakePaperPlan(PaperPreset::kQuick, {"table1", "baselines"});
//   for (const PaperRun& run : plan.runs) ... run.Arguments(plan.settings, flagfile)
//   for (size_t i : plan.table1) plan.runs[i] ...
#pragma once

#include <set>
#include <string>
#include <vector>

namespace ergo {

enum class PaperPreset { kQuick, kPaper };

// Parses --preset (quick or paper); throws InputError naming --preset otherwise.
PaperPreset ParsePaperPreset(const std::string& text);
std::string PaperPresetName(PaperPreset preset);

// What every run of a preset is given beyond its scene's flagfile.
struct PaperSettings {
  PaperPreset preset = PaperPreset::kQuick;
  int max_evals = 0;          // per optimisation
  int robust_placements = 1;  // the objective's placements (1, 3 or 5)
  bool placement_checks = false;
  std::vector<std::string> extra;  // the user's flags for every run (after `--`)
};

// The preset's defaults: quick = the scenes' quick meshes, 8 evaluations, one placement, no
// placement checks (inside a test's budget: about 4 minutes on 2 cores); paper = the
// paper-resolution meshes, 20 evaluations, no placement checks either.
PaperSettings DefaultPaperSettings(PaperPreset preset);

struct PaperRun {
  std::string scene;            // chair, shoe, mouse
  bool negative_image = false;  // start from the body's negative image
  double depth = 0;             // its depth, m; 0 = the scene's flagfile's
  bool smoothing = false;       // γ = κ·10^gamma_power; else γ = 0 (the flagfiles')
  int gamma_power = 0;
  bool raw_vertices = false;  // --parameterization=normal (the paper's design space)
  int exponent = 3;
  std::string designer = "ergo";        // ergo, sit-and-relax, pose-to-seat
  std::string start_designer = "none";  // ergo started from a baseline's design
  double baseline_depth = 0;            // the baselines' negative-image depth, m (0 = unused)

  // "chair__negative-image__depth=0.03": a directory name, unique per distinct run.
  std::string Name() const;
  // ergo_optimize's flags for this run (not --threads or --out).
  std::vector<std::string> Arguments(const PaperSettings& settings,
                                     const std::string& flagfile) const;
  // How the tables name the design: "ergo (flat start)", "Sit & Relax", ...
  std::string MethodLabel() const;
};

struct PaperPlan {
  PaperSettings settings;
  std::set<std::string> experiments;  // of kPaperExperiments
  std::vector<PaperRun> runs;         // distinct
  // Rows of each table, as indices into runs.
  std::vector<size_t> table1, table2, depth_sweep, exponents, baselines;
};

// table1, table2, depth_sweep, exponents, baselines.
const std::vector<std::string>& PaperExperiments();

// Throws InputError naming --experiments for a name not in PaperExperiments().
PaperPlan MakePaperPlan(const PaperSettings& settings, const std::set<std::string>& experiments);

// The γ sweep's values of j in γ = κ·10^j (κ = ζ(x₀)/ψ(x₀)), 100× apart like the paper's
// Table 2 (0, 1e11 … 1e17), centred on the paper's γ = 1e13, which ergo/design/README.md
// takes as κ·10^-1. The sweep runs in the paper's raw-vertex design space, where ψ is what
// keeps the design smooth (the filtered space needs no ψ).
const std::vector<int>& PaperGammaPowers();
// The paper's γ a value of PaperGammaPowers() stands for (1e11 for -3, …).
double PaperGammaFor(int gamma_power);
// The negative-image depths of the chair's sweep (§5.1: 1–6 cm), m.
const std::vector<double>& PaperChairDepths();

}  // namespace ergo
