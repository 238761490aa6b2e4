// ergo_body: builds a body part (paper §3.1) — a tetrahedral soft-tissue layer around a
// rigid core — and writes it as a body directory (ergo/body/README.md).
//
//   ergo_body build --surface=leg.stl --unit=mm --depth_samples=depth.csv
//       --stiffness_samples=E.csv --edge_length=0.008 --out=leg_body
//   ergo_body build --shape=sphere_shell --outer_radius=0.1 --core_radius=0.07
//       --youngs_modulus=1e4 --edge_length=0.01 --out=shell
//
// Exit status: 0 success, 2 bad input (the message names the flag or file), 1 bad flags.

#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <gflags/gflags.h>
#include <glog/logging.h>

#include "ergo/body/body_build.h"
#include "ergo/body/body_directory.h"
#include "ergo/body/layered_body.h"
#include "ergo/contact/support_validation.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/length_unit.h"
#include "tools/common/flag_checks.h"
#include "tools/common/vtu_flags.h"

DEFINE_string(surface, "", "closed or open (flat-cut) skin surface: .obj .off .ply .stl .msh");
DEFINE_string(unit, "m", "unit of --surface and of the CSVs' x,y,z and depth: m or mm");
DEFINE_string(shape, "",
              "instead of --surface, an implicit test shape: sphere_shell or "
              "ellipsoid_shell");
DEFINE_double(outer_radius, 0, "sphere_shell: skin radius, m");
DEFINE_double(core_radius, 0, "sphere_shell: core radius, m");
DEFINE_string(semi_axes, "",
              "ellipsoid_shell: skin semi-axes a,b,c in m (core: each minus --depth)");
DEFINE_double(depth, 0, "constant layer depth, m (not scaled by --unit)");
DEFINE_string(depth_samples, "", "CSV x,y,z,depth (in --unit), interpolated over the skin");
DEFINE_double(youngs_modulus, 0, "constant Young's modulus, Pa (tissue: 5e3-15e3)");
DEFINE_string(stiffness_samples, "", "CSV x,y,z,E (x,y,z in --unit, E in Pa)");
DEFINE_string(anatomy, "none",
              "--surface only: anatomical priors for depth and E: foot, seat, hand or none "
              "(ergo/body/README.md; --depth_samples / --stiffness_samples replace them near "
              "the measured points)");
DEFINE_string(axes, "x,y,z",
              "--surface only: the scan's axes that become ergo's x, y (up) and z (the part's "
              "length), e.g. y,z,x for a scan with z up and its length along x");
DEFINE_string(heel_end, "auto", "--anatomy=foot: where the heel is: auto, min_z or max_z");
DEFINE_string(foot_side, "auto",
              "--anatomy=foot: left or right (auto: the medial side from the arch's height)");
DEFINE_double(poisson_ratio, 0.45, "Poisson's ratio of the tissue, in (-1, 0.5)");
DEFINE_double(density, 1050, "tissue density, kg/m^3");
DEFINE_double(core_mass, -1, "core mass, kg; negative = core volume times --core_density");
DEFINE_double(core_density, 1050, "core density for the automatic core mass, kg/m^3");
DEFINE_double(compression_resistance, 1.0, "dimensionless volume-term weight c (DESIGN §3)");
DEFINE_double(inversion_threshold, 0.1, "principal-stretch clamp of the invertible material");
DEFINE_double(edge_length, 0, "target tet edge length, m (required)");
DEFINE_double(facet_distance, 0, "surface approximation bound, m; 0 = edge_length/10");
DEFINE_int32(seed, 0, "random seed of the mesher (same seed, same mesh)");
DEFINE_string(out, "", "output body directory (required)");
DEFINE_bool(progress, true,
            "print each stage (reading, meshing, measuring) with the elapsed time to stderr");

namespace ergo {
namespace {

constexpr char kUsage[] =
    "builds a body part and writes a body directory.\n"
    "  ergo_body build (--surface=FILE [--unit=mm] | --shape=sphere_shell|ellipsoid_shell ...)\n"
    "      (--depth=METRES | --depth_samples=CSV) (--youngs_modulus=PA | --stiffness_samples=CSV)\n"
    "      or, for a scan, --anatomy=foot|seat|hand [--axes=y,z,x] [--heel_end=..] "
    "[--foot_side=..]\n"
    "      [--poisson_ratio=0.45] [--density=1050] [--core_mass=KG] --edge_length=METRES --out=DIR";

[[noreturn]] void FlagError(const std::string& flag, const std::string& what,
                            const std::string& fix) {
  throw InputError("--" + flag, "", what, fix);
}

bool Given(const char* name) { return !gflags::GetCommandLineFlagInfoOrDie(name).is_default; }

Eigen::Vector3d ParseTriple(const std::string& flag, const std::string& text) {
  const Eigen::Vector3d values = ParseThreeNumbers(flag, text, "0.12,0.08,0.06");
  if (!(values.minCoeff() > 0)) {
    FlagError(flag, "expected three positive lengths a,b,c (got \"" + text + "\")",
              "give e.g. --" + flag + "=0.12,0.08,0.06");
  }
  return values;
}

// A body no tool could use is not written: contact refuses a skin that pinches or overlaps
// itself (ValidateSkinForContact).
void RequireSkinUsableForContact(const BodyRecord& record, const std::string& source) {
  const LayeredBody body = LayeredBody::Create(record.rest, record.attached, record.material, {});
  ValidateSkinForContact(body.skin().RestSurface(record.rest.vertices),
                         source + " (the built body's skin)");
}

int Build() {
  if (FLAGS_out.empty()) FlagError("out", "is required", "give the output directory, --out=DIR");
  const VtuEncoding vtu_encoding = VtuEncodingFromFlags();
  BodyBuildOptions options;
  if (!ParseLengthUnit(FLAGS_unit, &options.unit))
    FlagError("unit", "must be m or mm", "--unit=mm");
  options.surface = FLAGS_surface;
  options.shape = FLAGS_shape;
  options.outer_radius = FLAGS_outer_radius;
  options.core_radius = FLAGS_core_radius;
  if (FLAGS_shape == "ellipsoid_shell")
    options.semi_axes = ParseTriple("semi_axes", FLAGS_semi_axes);
  if (Given("depth")) options.depth = FLAGS_depth;
  options.depth_samples = FLAGS_depth_samples;
  if (Given("youngs_modulus")) options.youngs_modulus = FLAGS_youngs_modulus;
  options.stiffness_samples = FLAGS_stiffness_samples;
  options.anatomy.anatomy = ParseAnatomy(FLAGS_anatomy, "--anatomy");
  options.anatomy.heel_end = ParseHeelEnd(FLAGS_heel_end, "--heel_end");
  options.anatomy.foot_side = ParseFootSide(FLAGS_foot_side, "--foot_side");
  options.axes = FLAGS_axes;
  options.poisson_ratio = FLAGS_poisson_ratio;
  options.density = FLAGS_density;
  options.core_mass = FLAGS_core_mass;
  options.core_density = FLAGS_core_density;
  options.compression_resistance = FLAGS_compression_resistance;
  options.inversion_threshold = FLAGS_inversion_threshold;
  options.edge_length = FLAGS_edge_length;
  options.facet_distance = FLAGS_facet_distance;
  options.seed = FLAGS_seed;
  if (FLAGS_progress) {
    options.progress = [](const std::string& line) {
      std::cerr << line << "\n";
      std::cerr.flush();
    };
  }
  const BuiltBody built = BuildBody(options);
  RequireSkinUsableForContact(built.record, FLAGS_surface.empty() ? FLAGS_shape : FLAGS_surface);
  SaveBodyDirectory(FLAGS_out, built.record, vtu_encoding);
  std::cout << built.report;
  std::cout << "wrote " << FLAGS_out << "/{" << kBodyJsonFile << ", " << kBodyMeshFile << ", "
            << kBodyAttachedFile << ", " << kBodyMaterialFile << ", " << kBodyViewFile << "}\n";
  return 0;
}

}  // namespace
}  // namespace ergo

int main(int argc, char** argv) {
  gflags::SetUsageMessage(ergo::kUsage);
  try {
    ergo::CheckCommandLine(argc, argv, /*positional=*/1);  // the subcommand
  } catch (const ergo::InputError& error) {
    std::cerr << "ergo_body: " << error.what() << "\nusage: " << ergo::kUsage << "\n";
    return 2;
  }
  gflags::ParseCommandLineFlags(&argc, &argv, true);
  ergo::LogToStderrOnly();
  google::InitGoogleLogging(argv[0]);
  if (argc != 2 || std::string(argv[1]) != "build") {
    std::cerr << "ergo_body: expected the subcommand `build`"
              << (argc > 1 ? ", got `" + std::string(argv[1]) + "`" : "")
              << "\nusage: " << ergo::kUsage << "\n";
    return 2;
  }
  try {
    return ergo::Build();
  } catch (const ergo::InputError& error) {
    std::cerr << "ergo_body: " << error.what() << "\n";
    return 2;
  }
}
