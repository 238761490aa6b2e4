// ergo_calibrate: tissue calibration from indentation curves (paper §3.1). Each measured point
// of the body part has a force–indentation curve of a rigid sphere (--indentation=FILE,
// ergo/calibration/indentation_curves.h); its Young's modulus — and, with --fit_depth, its
// layer depth — is fitted by least squares on the layered indentation law
// (ergo/calibration/layered_indentation.h, Ceres). Writes, as one unit:
//   OUT/stiffness_samples.csv  x,y,z,E for `ergo_body build --stiffness_samples`
//   OUT/depth_samples.csv      x,y,z,depth for `--depth_samples` (the depths fitted or
//                              measured; not for a half-space)
//   OUT/calibration.json, calibration.md  every point's fit, its standard errors and warnings
//   OUT/fits.json, calibration.png  each curve, its fitted law and Hertz's law with the same
//                              E (tools/plot_calibration.py)
// x, y, z and depths are written in --unit, the unit ergo_body must then be given.
// Exit status: 0 every curve fitted, 1 a fit failed (which and why; nothing written),
// 2 unusable input.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <gflags/gflags.h>
#include <glog/logging.h>

#include "ergo/calibration/indentation_curves.h"
#include "ergo/calibration/indentation_fit.h"
#include "ergo/mesh/atomic_file.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/json.h"
#include "tools/common/child_process.h"
#include "tools/common/flag_checks.h"
#include "tools/common/output_directory.h"

DEFINE_string(indentation, "",
              "indentation curves, CSV: sample,x,y,z,indentation,force[,depth], one row per "
              "reading (ergo/calibration/README.md)");
DEFINE_string(unit, "m",
              "unit of the file's x, y, z, indentation and depth, and of the output "
              "CSVs' x, y, z and depth: m or mm");
DEFINE_double(indenter_radius, 0, "radius of the spherical indenter tip, m (required)");
DEFINE_double(poisson_ratio, 0.45,
              "Poisson's ratio of the tissue, in (-1, 0.5] (ergo_body's "
              "default 0.45)");
DEFINE_string(layer_base, "bonded",
              "how the layer sits on the bone: bonded (tissue on bone) or sliding");
DEFINE_bool(fit_depth, false,
            "fit the layer's depth too (else it is the file's depth column or --depth)");
DEFINE_double(depth, 0,
              "the layer's depth, m, for every point without a depth column (with --fit_depth: "
              "a first guess); 0 = none given");
DEFINE_bool(half_space, false,
            "treat the tissue as deep (the Hertz half-space): fit E alone, write no depths");
DEFINE_double(max_depth, 0.1, "--fit_depth: the largest depth the fit may reach, m");
DEFINE_bool(fit_contact_point, false,
            "fit where the tip first touched too (the logged indentation at contact, within "
            "± half the deepest travel); else the file's indentation 0 is first contact");
DEFINE_string(out, "", "output directory (required; replaced as a whole)");
DEFINE_bool(plot, true,
            "write calibration.png (each curve with its fit) with tools/plot_calibration.py "
            "(python3 + matplotlib)");

namespace ergo {
namespace {

struct PointResult {
  const IndentationCurve* curve = nullptr;
  IndentationFit fit;
  bool depth_measured = false;  // the file's depth column
};

std::string Number(double value) {
  std::ostringstream out;
  WriteDouble(out, value);
  return out.str();
}

// `value` to `digits` significant digits, as %g prints it.
std::string Significant(double value, int digits) {
  char text[64];
  std::snprintf(text, sizeof(text), "%.*g", digits, value);
  return text;
}

Json FitJson(const PointResult& result, double metres) {
  const IndentationFit& fit = result.fit;
  Json point = Json::object();
  point["sample"] = result.curve->name;
  point["line"] = result.curve->first_line;
  point["point"] = Json::array({result.curve->point.x() / metres, result.curve->point.y() / metres,
                                result.curve->point.z() / metres});
  point["readings"] = fit.readings;
  point["youngs_modulus_pa"] = fit.youngs_modulus;
  point["youngs_modulus_stderr_pa"] = fit.youngs_modulus_stderr;
  if (std::isinf(fit.depth)) {
    point["depth"] = "half-space";
  } else {
    point["depth"] = fit.depth / metres;
    point["depth_source"] = FLAGS_fit_depth         ? "fitted"
                            : result.depth_measured ? "measured"
                                                    : "--depth";
    point["depth_stderr"] = fit.depth_stderr / metres;
  }
  if (FLAGS_fit_contact_point) {
    point["contact_offset"] = fit.contact_offset / metres;
    point["contact_offset_stderr"] = fit.contact_offset_stderr / metres;
  }
  point["rms_residual_n"] = fit.rms_residual;
  point["relative_rms"] = fit.relative_rms;
  point["max_chi"] = fit.max_chi;
  point["max_strain"] = fit.max_strain;
  point["converged"] = fit.converged;
  point["note"] = fit.message;
  return point;
}

// The readings, the fitted law on a fine grid of δ and Hertz's law with the same E (what
// the layer adds), per point, in SI units: what the picture draws.
Json FitsJson(const std::vector<PointResult>& results, const SphericalIndenter& indenter) {
  Json fits = Json::array();
  for (const PointResult& result : results) {
    const IndentationCurve& curve = *result.curve;
    const IndentationFit& fit = result.fit;
    Json point = Json::object();
    point["sample"] = curve.name;
    point["indentation_m"] = curve.indentation;
    point["force_n"] = curve.force;
    point["youngs_modulus_pa"] = fit.youngs_modulus;
    point["youngs_modulus_stderr_pa"] = fit.youngs_modulus_stderr;
    point["depth_m"] = std::isinf(fit.depth) ? Json(nullptr) : Json(fit.depth);
    point["depth_stderr_m"] = fit.depth_stderr;
    point["contact_offset_m"] = fit.contact_offset;
    // From the first reading (or first contact) to the last, the law at δ − c.
    double first = fit.contact_offset, last = fit.contact_offset;
    for (double delta : curve.indentation) {
      first = std::min(first, delta);
      last = std::max(last, delta);
    }
    Json grid = Json::array(), law = Json::array(), hertz = Json::array();
    for (int k = 0; k <= 60; ++k) {
      const double delta = first + (last - first) * k / 60;
      const double travel = std::max(0.0, delta - fit.contact_offset);
      grid.push_back(delta);
      law.push_back(LayeredIndentationForce(indenter, fit.youngs_modulus, fit.depth, travel).force);
      hertz.push_back(LayeredIndentationForce(indenter, fit.youngs_modulus,
                                              std::numeric_limits<double>::infinity(), travel)
                          .force);
    }
    point["model_indentation_m"] = grid;
    point["model_force_n"] = law;
    point["hertz_force_n"] = hertz;
    point["note"] = fit.message;
    fits.push_back(point);
  }
  return fits;
}

void WriteSamples(const std::string& path, const std::vector<PointResult>& results, double metres,
                  bool depth, const std::string& unit) {
  WriteFileAtomically(path, [&](std::ostream& out) {
    out << "# ergo_calibrate from " << FLAGS_indentation << ": "
        << (depth ? "layer depth" : "Young's modulus (Pa)") << " per measured point; x, y, z"
        << (depth ? " and depth" : "") << " in " << unit << " (ergo_body build --unit=" << unit
        << ")\n";
    out << (depth ? "x,y,z,depth\n" : "x,y,z,youngs_modulus_pa\n");
    for (const PointResult& result : results) {
      const Eigen::Vector3d p = result.curve->point / metres;
      out << Number(p.x()) << "," << Number(p.y()) << "," << Number(p.z()) << ","
          << Number(depth ? result.fit.depth / metres : result.fit.youngs_modulus) << "\n";
    }
  });
}

std::string MarkdownReport(const std::vector<PointResult>& results, const std::string& unit,
                           double metres) {
  std::ostringstream md;
  md << "# Tissue calibration\n\n";
  md << "Curves: `" << FLAGS_indentation
     << "`; spherical indenter R = " << 1e3 * FLAGS_indenter_radius
     << " mm, ν = " << FLAGS_poisson_ratio << ", layer " << FLAGS_layer_base
     << " to the bone; law: Dimitriadis et al. 2002 (ergo/calibration/README.md); depth "
     << (FLAGS_half_space  ? "infinite (half-space)"
         : FLAGS_fit_depth ? "fitted"
                           : "given")
     << ".\n\n";
  md << "| sample | x, y, z (" << unit
     << ") | readings | E (kPa) | ± | depth (mm) | ± | contact at (mm) | rms (% of peak) "
        "| max χ | max δ/h | note |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const PointResult& result : results) {
    const IndentationFit& fit = result.fit;
    const Eigen::Vector3d p = result.curve->point / metres;
    md << "| " << result.curve->name << " | " << Significant(p.x(), 4) << ", "
       << Significant(p.y(), 4) << ", " << Significant(p.z(), 4) << " | " << fit.readings << " | "
       << Significant(1e-3 * fit.youngs_modulus, 4) << " | "
       << Significant(1e-3 * fit.youngs_modulus_stderr, 2) << " | "
       << (std::isinf(fit.depth) ? "∞" : Significant(1e3 * fit.depth, 4)) << " | "
       << (FLAGS_fit_depth ? Significant(1e3 * fit.depth_stderr, 2) : "–") << " | "
       << (FLAGS_fit_contact_point ? Significant(1e3 * fit.contact_offset, 3) + " ± " +
                                         Significant(1e3 * fit.contact_offset_stderr, 2)
                                   : "0 (given)")
       << " | " << Significant(100 * fit.relative_rms, 2) << " | " << Significant(fit.max_chi, 3)
       << " | " << Significant(fit.max_strain, 3) << " | " << fit.message << " |\n";
  }
  md << "\nThe law is small-strain linear elasticity; ergo's tissue is neo-Hookean. Readings with "
        "χ = √(Rδ)/h above 1 or δ/h above about 0.2 lie beyond where the two agree "
        "(ergo/calibration/README.md).\n";
  return md.str();
}

int Run() {
  RequireFlag(!FLAGS_indentation.empty(), "indentation", "is required",
              "give the curves' CSV, e.g. --indentation=curves.csv");
  RequireFlag(!FLAGS_out.empty(), "out", "is required",
              "name the output directory, e.g. --out=calib");
  LengthUnit unit = LengthUnit::kMetre;
  RequireFlag(ParseLengthUnit(FLAGS_unit, &unit), "unit", "'" + FLAGS_unit + "' is unknown",
              "use m or mm");
  RequireInRange("indenter_radius", FLAGS_indenter_radius, 1e-5, 0.5,
                 "the tip's radius in metres, e.g. 0.005 (required)");
  RequireFlag(FLAGS_poisson_ratio > -1 && FLAGS_poisson_ratio <= 0.5, "poisson_ratio",
              std::to_string(FLAGS_poisson_ratio) + " is outside (-1, 0.5]",
              "tissue is nearly incompressible: 0.45-0.5");
  RequireFlag(FLAGS_layer_base == "bonded" || FLAGS_layer_base == "sliding", "layer_base",
              "'" + FLAGS_layer_base + "' is unknown", "use bonded or sliding");
  RequireInRange("depth", FLAGS_depth, 0, 1, "metres, e.g. 0.017; 0 = not given");
  RequireInRange("max_depth", FLAGS_max_depth, 1e-4, 10, "metres, e.g. 0.1");
  RequireFlag(!(FLAGS_half_space && FLAGS_fit_depth), "half_space",
              "and --fit_depth are both given",
              "a half-space has no depth to fit: give one of them");
  RequireFlag(!(FLAGS_half_space && FLAGS_depth > 0), "half_space", "and --depth are both given",
              "give one of them");
  OutputDirectory output(FLAGS_out, "out");  // checks that it can be written, before any work

  const IndentationCurves curves = ReadIndentationCurvesCsv(FLAGS_indentation, unit);
  const double metres = MetresPerUnit(unit);
  if (!FLAGS_half_space && !FLAGS_fit_depth && !curves.has_depth && FLAGS_depth <= 0) {
    throw InputError("--depth", "", "the layer's depth is not known",
                     "give it (--depth=0.017, or a depth column in " + FLAGS_indentation +
                         "), fit it (--fit_depth) or treat the tissue as deep (--half_space)");
  }
  for (const std::string& column : curves.ignored_columns)
    std::cerr << "ergo_calibrate: " << FLAGS_indentation << ": column '" << column
              << "' is not read\n";

  IndentationFitOptions options;
  options.indenter.radius = FLAGS_indenter_radius;
  options.indenter.poisson_ratio = FLAGS_poisson_ratio;
  options.indenter.base = FLAGS_layer_base == "bonded" ? LayerBase::kBonded : LayerBase::kSliding;
  options.fit_depth = FLAGS_fit_depth;
  options.max_depth = FLAGS_max_depth;
  options.fit_contact_point = FLAGS_fit_contact_point;
  std::vector<PointResult> results;
  std::vector<std::string> failures;
  for (const IndentationCurve& curve : curves.curves) {
    PointResult result;
    result.curve = &curve;
    result.depth_measured = curve.measured_depth > 0;
    IndentationFitOptions point = options;
    point.depth = FLAGS_half_space        ? std::numeric_limits<double>::infinity()
                  : result.depth_measured ? curve.measured_depth
                  : FLAGS_depth > 0       ? FLAGS_depth
                                          : std::numeric_limits<double>::infinity();
    result.fit = FitIndentationCurve(curve.indentation, curve.force, point);
    std::cerr << "ergo_calibrate: " << curve.name << ": " << DescribeFit(result.fit) << "\n";
    if (!result.fit.converged)
      failures.push_back(FLAGS_indentation + ":line " + std::to_string(curve.first_line) +
                         ": sample '" + curve.name + "' " + result.fit.message);
    results.push_back(result);
  }
  if (!failures.empty()) {
    for (const std::string& failure : failures) std::cerr << "ergo_calibrate: " << failure << "\n";
    std::cerr << "ergo_calibrate: " << failures.size() << " of " << results.size()
              << " curves could not be fitted; nothing written (fix: give those points more "
                 "readings, or their depth)\n";
    return 1;
  }

  Json report = Json::object();
  report["indentation"] = FLAGS_indentation;
  report["unit"] = FLAGS_unit;
  report["indenter_radius_m"] = FLAGS_indenter_radius;
  report["poisson_ratio"] = FLAGS_poisson_ratio;
  report["layer_base"] = FLAGS_layer_base;
  report["depth_mode"] = FLAGS_half_space ? "half-space" : FLAGS_fit_depth ? "fitted" : "given";
  report["contact_point"] = FLAGS_fit_contact_point ? "fitted" : "indentation 0";
  report["points"] = Json::array();
  for (const PointResult& result : results) report["points"].push_back(FitJson(result, metres));
  WriteSamples(output.path() + "/stiffness_samples.csv", results, metres, false, FLAGS_unit);
  if (!FLAGS_half_space)
    WriteSamples(output.path() + "/depth_samples.csv", results, metres, true, FLAGS_unit);
  WriteJsonFile(output.path() + "/calibration.json", report);
  WriteFileAtomically(output.path() + "/calibration.md", [&](std::ostream& out) {
    out << MarkdownReport(results, FLAGS_unit, metres);
  });
  WriteJsonFile(output.path() + "/fits.json", FitsJson(results, options.indenter));
  const bool plotted =
      FLAGS_plot && RunPictureScript("ergo_calibrate", "plot_calibration.py", output.path());
  std::string error;
  if (!output.Commit(&error)) throw InputError("--out", "", error, "");
  std::cout << "ergo_calibrate: " << results.size() << " points fitted; " << FLAGS_out
            << "/stiffness_samples.csv" << (FLAGS_half_space ? "" : ", depth_samples.csv")
            << ", calibration.json, calibration.md, fits.json"
            << (plotted ? ", calibration.png" : "") << "\n";
  return 0;
}

}  // namespace
}  // namespace ergo

int main(int argc, char** argv) {
  gflags::SetUsageMessage(
      "fit tissue stiffness (and depth) from indentation curves\n"
      "  ergo_calibrate --indentation=curves.csv --indenter_radius=0.005 [--fit_depth | "
      "--depth=0.017 | --half_space] [--unit=mm] --out=DIR\n"
      "then: ergo_body build --surface=S --unit=U --stiffness_samples=DIR/stiffness_samples.csv "
      "--depth_samples=DIR/depth_samples.csv ...");
  try {
    ergo::CheckCommandLine(argc, argv);
  } catch (const ergo::InputError& error) {
    std::cerr << "ergo_calibrate: " << error.what() << "\n";
    return 2;
  }
  gflags::ParseCommandLineFlags(&argc, &argv, true);
  ergo::LogToStderrOnly();
  google::InitGoogleLogging(argv[0]);
  try {
    return ergo::Run();
  } catch (const ergo::InputError& error) {
    std::cerr << "ergo_calibrate: " << error.what() << "\n";
    return 2;
  }
}
