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
#include <string>
#include <vector>

#include <gflags/gflags.h>
#include <glog/logging.h>

#include "ergo/body/body_directory.h"
#include "ergo/body/layer_builder.h"
#include "ergo/body/layered_body.h"
#include "ergo/body/sample_interpolation.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/json.h"
#include "ergo/mesh/length_unit.h"
#include "ergo/mesh/mesh_io.h"
#include "ergo/mesh/split_list.h"
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

namespace ergo {
namespace {

constexpr char kUsage[] =
    "builds a body part and writes a body directory.\n"
    "  ergo_body build (--surface=FILE [--unit=mm] | --shape=sphere_shell|ellipsoid_shell ...)\n"
    "      (--depth=METRES | --depth_samples=CSV) (--youngs_modulus=PA | --stiffness_samples=CSV)\n"
    "      [--poisson_ratio=0.45] [--density=1050] [--core_mass=KG] --edge_length=METRES --out=DIR";

[[noreturn]] void FlagError(const std::string& flag, const std::string& what,
                            const std::string& fix) {
  throw InputError("--" + flag, "", what, fix);
}

void RequirePositive(const std::string& flag, double value, const std::string& example) {
  if (!(value > 0) || !std::isfinite(value)) {
    FlagError(flag, "must be a positive number (got " + std::to_string(value) + ")",
              "give e.g. --" + flag + "=" + example);
  }
}

bool Given(const char* name) { return !gflags::GetCommandLineFlagInfoOrDie(name).is_default; }

std::vector<double> ParseTriple(const std::string& flag, const std::string& text) {
  std::vector<double> values;
  for (const std::string& item : SplitList(text, ',')) {
    try {
      size_t used = 0;
      values.push_back(std::stod(item, &used));
      if (used != item.size()) values.push_back(NAN);
    } catch (const std::exception&) {
      values.push_back(NAN);
    }
  }
  if (values.size() != 3 || !(values[0] > 0 && values[1] > 0 && values[2] > 0)) {
    FlagError(flag, "expected three positive lengths a,b,c (got \"" + text + "\")",
              "give e.g. --" + flag + "=0.12,0.08,0.06");
  }
  return values;
}

SampleInterpolant DepthField(LengthUnit unit) {
  if (Given("depth") == !FLAGS_depth_samples.empty()) {
    FlagError("depth", "give exactly one of --depth and --depth_samples",
              "e.g. --depth=0.02 for a 2 cm layer");
  }
  if (!FLAGS_depth_samples.empty()) {
    SampleCsvOptions options;
    options.unit = unit;
    options.value_is_length = true;
    options.value_name = "depth";
    options.value_unit = unit == LengthUnit::kMillimetre ? "mm" : "m";
    return SampleInterpolant::Fit(ReadPointSamplesCsv(FLAGS_depth_samples, options));
  }
  RequirePositive("depth", FLAGS_depth, "0.02");
  return SampleInterpolant::Constant(FLAGS_depth);
}

SampleInterpolant StiffnessField(LengthUnit unit) {
  if (Given("youngs_modulus") == !FLAGS_stiffness_samples.empty()) {
    FlagError("youngs_modulus", "give exactly one of --youngs_modulus and --stiffness_samples",
              "e.g. --youngs_modulus=10000 (Pa)");
  }
  if (!FLAGS_stiffness_samples.empty()) {
    SampleCsvOptions options;
    options.unit = unit;
    options.value_is_length = false;
    options.value_name = "E";
    options.value_unit = "Pa";
    return SampleInterpolant::Fit(ReadPointSamplesCsv(FLAGS_stiffness_samples, options));
  }
  RequirePositive("youngs_modulus", FLAGS_youngs_modulus, "10000");
  return SampleInterpolant::Constant(FLAGS_youngs_modulus);
}

// The implicit test shapes; fills *source with what was built.
BuiltLayer BuildShape(const BuilderOptions& options, Json* source) {
  (*source)["mode"] = "implicit";
  (*source)["shape"] = FLAGS_shape;
  ImplicitLayer layer;
  if (FLAGS_shape == "sphere_shell") {
    RequirePositive("outer_radius", FLAGS_outer_radius, "0.1");
    RequirePositive("core_radius", FLAGS_core_radius, "0.07");
    if (!(FLAGS_core_radius < FLAGS_outer_radius)) {
      FlagError("core_radius", "must be smaller than --outer_radius", "e.g. 0.7 x outer radius");
    }
    if (Given("depth") || !FLAGS_depth_samples.empty()) {
      FlagError("depth", "sphere_shell takes its depth from the two radii",
                "drop --depth / --depth_samples");
    }
    const double R = FLAGS_outer_radius, r = FLAGS_core_radius;
    layer.outer = [R](const Eigen::Vector3d& p) { return p.norm() - R; };
    layer.core = [r](const Eigen::Vector3d& p) { return p.norm() - r; };
    layer.bounds = Eigen::AlignedBox3d(Eigen::Vector3d::Constant(-1.2 * R),
                                       Eigen::Vector3d::Constant(1.2 * R));
    (*source)["outer_radius_m"] = R;
    (*source)["core_radius_m"] = r;
  } else if (FLAGS_shape == "ellipsoid_shell") {
    const std::vector<double> a = ParseTriple("semi_axes", FLAGS_semi_axes);
    RequirePositive("depth", FLAGS_depth, "0.02");
    const Eigen::Vector3d outer(a[0], a[1], a[2]);
    const Eigen::Vector3d core = outer - Eigen::Vector3d::Constant(FLAGS_depth);
    if (!(core.minCoeff() > 0)) {
      FlagError("depth", "is not smaller than the smallest semi-axis", "use a thinner layer");
    }
    // Scaled so that |f| approximates the distance near the surface.
    layer.outer = [outer](const Eigen::Vector3d& p) {
      return (p.cwiseQuotient(outer).norm() - 1) * outer.minCoeff();
    };
    layer.core = [core](const Eigen::Vector3d& p) {
      return (p.cwiseQuotient(core).norm() - 1) * core.minCoeff();
    };
    layer.bounds = Eigen::AlignedBox3d(-1.2 * outer, 1.2 * outer);
    Json axes = Json::Array();
    for (double v : a) axes.Append(v);
    (*source)["semi_axes_m"] = axes;
    (*source)["depth_m"] = FLAGS_depth;
  } else {
    FlagError("shape", "unknown shape \"" + FLAGS_shape + "\"",
              "use sphere_shell or ellipsoid_shell");
  }
  return BuildLayerFromImplicit(layer, options, "--shape=" + FLAGS_shape);
}

int Build() {
  if (FLAGS_out.empty()) FlagError("out", "is required", "give the output directory, --out=DIR");
  RequirePositive("edge_length", FLAGS_edge_length, "0.01");
  if (!(FLAGS_facet_distance >= 0)) FlagError("facet_distance", "must be >= 0", "omit it");
  LengthUnit unit;
  if (!ParseLengthUnit(FLAGS_unit, &unit)) FlagError("unit", "must be m or mm", "--unit=mm");
  if (!(FLAGS_poisson_ratio > -1 && FLAGS_poisson_ratio < 0.5)) {
    FlagError("poisson_ratio", "must be in (-1, 0.5)", "tissue: 0.45");
  }
  RequirePositive("density", FLAGS_density, "1050");
  RequirePositive("core_density", FLAGS_core_density, "1050");
  if (!std::isfinite(FLAGS_core_mass)) FlagError("core_mass", "must be a number", "omit it");
  if (FLAGS_surface.empty() == FLAGS_shape.empty()) {
    FlagError("surface", "give exactly one of --surface and --shape", "e.g. --surface=leg.stl");
  }
  const VtuEncoding vtu_encoding = VtuEncodingFromFlags();

  BuilderOptions options;
  options.edge_length = FLAGS_edge_length;
  options.facet_distance = FLAGS_facet_distance;
  options.seed = static_cast<unsigned>(FLAGS_seed);
  const SampleInterpolant stiffness = StiffnessField(unit);

  Json source = Json::Object();
  BuiltLayer built;
  if (!FLAGS_surface.empty()) {
    const SampleInterpolant depth = DepthField(unit);
    ReadOptions read;
    read.unit = unit;
    const TriMesh skin = ReadTriMesh(FLAGS_surface, read);
    source["mode"] = "surface";
    source["surface"] = FLAGS_surface;
    source["unit"] = FLAGS_unit;
    source["depth"] = FLAGS_depth_samples.empty() ? Json(FLAGS_depth) : Json(FLAGS_depth_samples);
    source["depth_interpolation"] = depth.Describe();
    std::cout << "building from " << FLAGS_surface << " (" << skin.vertices.rows() << " vertices, "
              << skin.triangles.rows() << " triangles), depth " << depth.Describe() << " m\n";
    built = BuildLayerFromSurface(skin, depth, options, FLAGS_surface);
  } else {
    built = BuildShape(options, &source);
  }
  source["youngs_modulus"] =
      FLAGS_stiffness_samples.empty() ? Json(FLAGS_youngs_modulus) : Json(FLAGS_stiffness_samples);
  source["youngs_modulus_interpolation"] = stiffness.Describe();
  source["edge_length_m"] = FLAGS_edge_length;
  source["seed"] = FLAGS_seed;

  BodyRecord record;
  record.rest = built.mesh;
  record.attached = built.attached;
  record.material.youngs_modulus = InterpolateOntoTets(built, stiffness);
  record.material.poisson_ratio =
      Eigen::VectorXd::Constant(built.mesh.tets.rows(), FLAGS_poisson_ratio);
  record.material.compression_resistance = FLAGS_compression_resistance;
  record.material.inversion_threshold = FLAGS_inversion_threshold;
  record.tissue_density = FLAGS_density;
  record.core_mass = FLAGS_core_mass;
  record.core_density = FLAGS_core_density;
  record.vertex_depth = built.vertex_depth;

  // The LayeredBody validates the whole body and gives the masses.
  LayeredBodyOptions body_options;
  body_options.tissue_density = record.tissue_density;
  body_options.core_mass = record.core_mass;
  body_options.core_density = record.core_density;
  const LayeredBody body =
      LayeredBody::Create(record.rest, record.attached, record.material, body_options, FLAGS_out);
  Json summary = LayerBuildReportJson(built.report);
  summary["core_volume_m3"] = body.core_volume();
  summary["tissue_mass_kg"] = body.vertex_mass().sum();
  summary["core_mass_kg"] = body.core_mass();
  summary["mass_kg"] = body.total_mass();
  summary["youngs_modulus_min_pa"] = record.material.youngs_modulus.minCoeff();
  summary["youngs_modulus_max_pa"] = record.material.youngs_modulus.maxCoeff();
  record.summary = summary;
  record.source = source;
  SaveBodyDirectory(FLAGS_out, record, vtu_encoding);

  std::cout << DescribeLayerBuild(built.report);
  std::cout.precision(4);
  std::cout << "mass: " << body.total_mass() << " kg (tissue " << body.vertex_mass().sum()
            << " kg, core " << body.core_mass() << " kg"
            << (record.core_mass < 0 ? ", from the core volume" : "") << ")\n";
  std::cout << "Young's modulus: " << record.material.youngs_modulus.minCoeff() << " - "
            << record.material.youngs_modulus.maxCoeff() << " Pa; Poisson's ratio "
            << FLAGS_poisson_ratio << "\n";
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
