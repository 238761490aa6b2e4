// ergo_bump: the paper's Fig. 5 — how the ergonomic cost ζ reacts to the spatial frequency
// of a bump under a soft body, for exponents 2, 3 and 4. Prints a table and writes a CSV
// (width, frequency, ζ₂, ζ₃, ζ₄ and each rescaled to agree at the lowest frequency).
#include <cstdio>
#include <iostream>

#include <gflags/gflags.h>
#include <glog/logging.h>

#include "ergo/mesh/atomic_file.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/split_list.h"
#include "problems/bump_experiment.h"
#include "tools/common/flag_checks.h"

DEFINE_string(widths, "0.03,0.02,0.014,0.01,0.007,0.005", "bump widths (Gaussian σ) to sweep, m");
DEFINE_double(bump_height, 0.004, "bump height, m (fixed over the sweep)");
DEFINE_double(ball_radius, 0.05, "ball radius, m");
DEFINE_double(core_radius, 0.03, "rigid core radius, m");
DEFINE_double(youngs_modulus, 1e4, "tissue Young's modulus, Pa");
DEFINE_double(edge_length, 0.01, "ball mesh edge length, m");
DEFINE_double(contact_stiffness, 1e7,
              "contact stiffness κ, Pa/m (1e7: ≈ 0.3 mm on a flat plate)");
DEFINE_string(out, "bump_sweep.csv", "CSV output file");

namespace ergo {
namespace {

std::vector<double> ParseList(const std::string& text, const std::string& flag) {
  std::vector<double> values;
  for (const std::string& item : SplitList(text, ',')) {
    char* end = nullptr;
    const double value = std::strtod(item.c_str(), &end);
    if (end == item.c_str() || *end != '\0' || !(value > 0)) {
      throw InputError("--" + flag, "", "'" + item + "' is not a positive number",
                       "e.g. --widths=0.03,0.01,0.005");
    }
    values.push_back(value);
  }
  if (values.size() < 2)
    throw InputError("--" + flag, "", "needs at least two widths", "e.g. --widths=0.03,0.01");
  return values;
}

int Run() {
  RequireInRange("bump_height", FLAGS_bump_height, 0, 0.019, "metres below the 2 cm plate, e.g. 0.004");
  RequireInRange("ball_radius", FLAGS_ball_radius, 0.01, 0.5, "metres, e.g. 0.05");
  RequireInRange("core_radius", FLAGS_core_radius, 1e-3, FLAGS_ball_radius * 0.95,
                 "metres, below the ball radius, e.g. 0.03");
  RequireInRange("youngs_modulus", FLAGS_youngs_modulus, 1, 1e9, "Pa, e.g. 1e4");
  RequireInRange("edge_length", FLAGS_edge_length, 2e-3, 0.1, "metres, e.g. 0.01");
  RequireInRange("contact_stiffness", FLAGS_contact_stiffness, 1e3, 1e14, "Pa/m, e.g. 1e7");
  BumpScenarioOptions options;
  options.bump_height = FLAGS_bump_height;
  options.ball_radius = FLAGS_ball_radius;
  options.core_radius = FLAGS_core_radius;
  options.youngs_modulus = FLAGS_youngs_modulus;
  options.edge_length = FLAGS_edge_length;
  options.contact_stiffness = FLAGS_contact_stiffness;
  const std::vector<BumpSweepPoint> points =
      RunBumpFrequencySweep(options, ParseList(FLAGS_widths, "widths"));
  std::printf("%10s %12s %12s %12s %12s %9s %9s %9s %8s\n", "width_mm", "freq_1/m", "zeta_e2",
              "zeta_e3", "zeta_e4", "rel_e2", "rel_e3", "rel_e4", "contacts");
  bool all_converged = true;
  for (const BumpSweepPoint& p : points) {
    all_converged = all_converged && p.converged;
    std::printf("%10.2f %12.1f %12.4g %12.4g %12.4g %9.3f %9.3f %9.3f %8d%s\n", p.width * 1e3,
                p.frequency, p.zeta[0], p.zeta[1], p.zeta[2], p.rescaled[0], p.rescaled[1],
                p.rescaled[2], p.contact_vertices,
                p.converged ? "" : ("  FAILED: " + p.message).c_str());
  }
  WriteFileAtomically(FLAGS_out, [&](std::ostream& out) {
    out << "width_m,frequency_per_m,zeta_e2,zeta_e3,zeta_e4,rescaled_e2,rescaled_e3,rescaled_e4,"
           "contact_vertices,"
           "max_penetration_m,peak_pressure_Pa,converged\n";
    for (const BumpSweepPoint& p : points) {
      for (double v : {p.width, p.frequency, p.zeta[0], p.zeta[1], p.zeta[2], p.rescaled[0],
                       p.rescaled[1], p.rescaled[2]}) {
        WriteDouble(out, v);
        out << ",";
      }
      out << p.contact_vertices << ",";
      WriteDouble(out, p.max_penetration);
      out << ",";
      WriteDouble(out, p.peak_pressure);
      out << "," << (p.converged ? 1 : 0) << "\n";
    }
  });
  std::cout << "wrote " << FLAGS_out << "\n";
  return all_converged ? 0 : 1;
}

}  // namespace
}  // namespace ergo

int main(int argc, char** argv) {
  gflags::SetUsageMessage(
      "ζ against the spatial frequency of a bump under a soft ball (paper Fig. 5)");
  try {
    ergo::CheckCommandLine(argc, argv);
  } catch (const ergo::InputError& error) {
    std::cerr << "ergo_bump: " << error.what() << "\n";
    return 2;
  }
  gflags::ParseCommandLineFlags(&argc, &argv, true);
  ergo::LogToStderrOnly();
  google::InitGoogleLogging(argv[0]);
  try {
    return ergo::Run();
  } catch (const ergo::InputError& error) {
    std::cerr << "ergo_bump: " << error.what() << "\n";
    return 2;
  }
}
