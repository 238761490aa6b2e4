#include "ergo/body/body_build.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "ergo/body/layer_builder.h"
#include "ergo/body/layered_body.h"
#include "ergo/body/sample_interpolation.h"
#include "ergo/body/tissue_fields.h"
#include "ergo/mesh/axis_map.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/mesh_io.h"
#include "ergo/mesh/seconds_since.h"

namespace ergo {
namespace {

[[noreturn]] void OptionError(const std::string& option, const std::string& what,
                              const std::string& fix) {
  throw InputError("--" + option, "", what, fix);
}

void RequirePositive(const std::string& option, double value, const std::string& example) {
  if (!(value > 0) || !std::isfinite(value)) {
    OptionError(option, "must be a positive number (got " + std::to_string(value) + ")",
                "give e.g. --" + option + "=" + example);
  }
}

SampleInterpolant StiffnessField(const BodyBuildOptions& options) {
  if (options.youngs_modulus.has_value() == !options.stiffness_samples.empty()) {
    OptionError("youngs_modulus", "give exactly one of --youngs_modulus and --stiffness_samples",
                "e.g. --youngs_modulus=10000 (Pa)");
  }
  if (!options.stiffness_samples.empty()) {
    SampleCsvOptions csv;
    csv.unit = options.unit;
    csv.value_is_length = false;
    csv.value_name = "E";
    csv.value_unit = "Pa";
    return SampleInterpolant::Fit(ReadPointSamplesCsv(options.stiffness_samples, csv));
  }
  RequirePositive("youngs_modulus", *options.youngs_modulus, "10000");
  return SampleInterpolant::Constant(*options.youngs_modulus);
}

// The implicit test shapes; fills *source with what was built.
BuiltLayer BuildShape(const BodyBuildOptions& body, const BuilderOptions& options, Json* source) {
  (*source)["mode"] = "implicit";
  (*source)["shape"] = body.shape;
  ImplicitLayer layer;
  if (body.shape == "sphere_shell") {
    RequirePositive("outer_radius", body.outer_radius, "0.1");
    RequirePositive("core_radius", body.core_radius, "0.07");
    if (!(body.core_radius < body.outer_radius)) {
      OptionError("core_radius", "must be smaller than --outer_radius", "e.g. 0.7 x outer radius");
    }
    if (body.depth || !body.depth_samples.empty()) {
      OptionError("depth", "sphere_shell takes its depth from the two radii",
                  "drop --depth / --depth_samples");
    }
    const double R = body.outer_radius, r = body.core_radius;
    layer.outer = [R](const Eigen::Vector3d& p) { return p.norm() - R; };
    layer.core = [r](const Eigen::Vector3d& p) { return p.norm() - r; };
    layer.bounds = Eigen::AlignedBox3d(Eigen::Vector3d::Constant(-1.2 * R),
                                       Eigen::Vector3d::Constant(1.2 * R));
    (*source)["outer_radius_m"] = R;
    (*source)["core_radius_m"] = r;
  } else if (body.shape == "ellipsoid_shell") {
    const Eigen::Vector3d outer = body.semi_axes;
    if (!(outer.minCoeff() > 0) || !outer.allFinite()) {
      OptionError("semi_axes", "expected three positive lengths a,b,c",
                  "give e.g. --semi_axes=0.12,0.08,0.06");
    }
    if (!body.depth) OptionError("depth", "is required for ellipsoid_shell", "e.g. --depth=0.02");
    RequirePositive("depth", *body.depth, "0.02");
    const Eigen::Vector3d core = outer - Eigen::Vector3d::Constant(*body.depth);
    if (!(core.minCoeff() > 0)) {
      OptionError("depth", "is not smaller than the smallest semi-axis", "use a thinner layer");
    }
    // Scaled so that |f| approximates the distance near the surface.
    layer.outer = [outer](const Eigen::Vector3d& p) {
      return (p.cwiseQuotient(outer).norm() - 1) * outer.minCoeff();
    };
    layer.core = [core](const Eigen::Vector3d& p) {
      return (p.cwiseQuotient(core).norm() - 1) * core.minCoeff();
    };
    layer.bounds = Eigen::AlignedBox3d(-1.2 * outer, 1.2 * outer);
    Json axes = Json::array();
    for (int k = 0; k < 3; ++k) axes.push_back(outer[k]);
    (*source)["semi_axes_m"] = axes;
    (*source)["depth_m"] = *body.depth;
  } else {
    OptionError("shape", "unknown shape \"" + body.shape + "\"",
                "use sphere_shell or ellipsoid_shell");
  }
  return BuildLayerFromImplicit(layer, options, "--shape=" + body.shape);
}

}  // namespace

BuiltBody BuildBody(const BodyBuildOptions& body) {
  RequirePositive("edge_length", body.edge_length, "0.01");
  if (!(body.facet_distance >= 0)) OptionError("facet_distance", "must be >= 0", "omit it");
  if (!(body.poisson_ratio > -1 && body.poisson_ratio < 0.5)) {
    OptionError("poisson_ratio", "must be in (-1, 0.5)", "tissue: 0.45");
  }
  RequirePositive("density", body.density, "1050");
  RequirePositive("core_density", body.core_density, "1050");
  if (!std::isfinite(body.core_mass)) OptionError("core_mass", "must be a number", "omit it");
  if (body.surface.empty() == body.shape.empty()) {
    OptionError("surface", "give exactly one of --surface and --shape", "e.g. --surface=leg.stl");
  }
  const auto begin = std::chrono::steady_clock::now();
  auto say = [&](const std::string& line) {
    if (!body.progress) return;
    char elapsed[32];
    std::snprintf(elapsed, sizeof elapsed, "%7.1f s  ", SecondsSince(begin));
    body.progress(elapsed + line);
  };

  BuilderOptions options;
  options.edge_length = body.edge_length;
  options.facet_distance = body.facet_distance;
  options.seed = static_cast<unsigned>(body.seed);
  options.progress = say;
  Json source = Json::object();
  BuiltLayer built;
  std::ostringstream report;
  std::optional<SampleInterpolant> stiffness, stiffening_exponent;
  if (!body.surface.empty()) {
    TissueFieldInputs inputs;
    inputs.anatomy = body.anatomy;
    inputs.anatomy.min_depth = std::max(inputs.anatomy.min_depth, body.edge_length);
    inputs.depth = body.depth;
    inputs.depth_samples = body.depth_samples;
    inputs.youngs_modulus = body.youngs_modulus;
    inputs.stiffness_samples = body.stiffness_samples;
    inputs.unit = body.unit;
    inputs.axes = ParseAxisMap(body.axes, "--axes");
    say("reading " + body.surface);
    ReadOptions read;
    read.unit = body.unit;
    TriMesh skin = ReadTriMesh(body.surface, read);
    ApplyAxisMap(inputs.axes, &skin.vertices);
    TissueFields fields = MakeTissueFields(skin, inputs, body.surface);
    stiffness = fields.youngs_modulus;
    stiffening_exponent = fields.stiffening_exponent;
    source["mode"] = "surface";
    source["surface"] = body.surface;
    source["unit"] = body.unit == LengthUnit::kMillimetre ? "mm" : "m";
    source["axes"] = body.axes;
    source["depth"] = body.depth ? Json(*body.depth) : Json(fields.depth_description);
    source["depth_interpolation"] = fields.depth.Describe();
    if (fields.priors) {
      source["anatomy"] = AnatomyName(body.anatomy.anatomy);
      source["anatomy_summary"] = fields.priors->summary;
      Json landmarks = Json::array();
      for (const Landmark& mark : fields.priors->landmarks) {
        Json entry = Json::object();
        entry["name"] = mark.name;
        entry["point_m"] = Json::array({mark.point.x(), mark.point.y(), mark.point.z()});
        entry["depth_m"] = mark.depth;
        entry["youngs_modulus_pa"] = mark.youngs_modulus;
        entry["stiffening_exponent"] = mark.stiffening_exponent;
        landmarks.push_back(entry);
      }
      source["landmarks"] = landmarks;
      if (const std::optional<ScannedHeel>& heel = fields.priors->heel) {
        source["heel_eversion_deg"] = heel->eversion * 180 / M_PI;
        source["medial_side"] = heel->medial_sign > 0 ? "+x" : "-x";
      }
      report << "anatomical priors: " << fields.priors->summary << "\n";
    }
    report << "building from " << body.surface << " (" << skin.vertices.rows() << " vertices, "
           << skin.triangles.rows() << " triangles), depth " << fields.depth.Describe() << " m\n";
    if (fields.priors) options.core_limit = fields.priors->core_limit;
    built = BuildLayerFromSurface(skin, fields.depth, options, body.surface);
    source["youngs_modulus"] =
        body.youngs_modulus ? Json(*body.youngs_modulus) : Json(fields.modulus_description);
  } else {
    if (body.anatomy.anatomy != Anatomy::kNone || body.axes != "x,y,z")
      OptionError("anatomy", "--anatomy and --axes need a scanned --surface", "drop them");
    stiffness = StiffnessField(body);
    built = BuildShape(body, options, &source);
    source["youngs_modulus"] =
        body.stiffness_samples.empty() ? Json(*body.youngs_modulus) : Json(body.stiffness_samples);
  }
  source["youngs_modulus_interpolation"] = stiffness->Describe();
  source["edge_length_m"] = body.edge_length;
  source["seed"] = body.seed;

  BuiltBody result;
  BodyRecord& record = result.record;
  record.rest = built.mesh;
  record.attached = built.attached;
  record.material =
      TissueMaterialOnLayer(built, *stiffness, stiffening_exponent, body.poisson_ratio);
  record.material.compression_resistance = body.compression_resistance;
  record.material.inversion_threshold = body.inversion_threshold;
  record.tissue_density = body.density;
  record.core_mass = body.core_mass;
  record.core_density = body.core_density;
  record.vertex_depth = built.vertex_depth;

  // The LayeredBody validates the whole body and gives the masses.
  say("checking the body (" + std::to_string(built.mesh.tets.rows()) + " tets)");
  LayeredBodyOptions body_options;
  body_options.tissue_density = record.tissue_density;
  body_options.core_mass = record.core_mass;
  body_options.core_density = record.core_density;
  const LayeredBody layered =
      LayeredBody::Create(record.rest, record.attached, record.material, body_options,
                          body.surface.empty() ? "--shape=" + body.shape : body.surface);
  Json summary = LayerBuildReportJson(built.report);
  summary["core_volume_m3"] = layered.core_volume();
  summary["tissue_mass_kg"] = layered.vertex_mass().sum();
  summary["core_mass_kg"] = layered.core_mass();
  summary["mass_kg"] = layered.total_mass();
  summary["youngs_modulus_min_pa"] = record.material.youngs_modulus.minCoeff();
  summary["youngs_modulus_max_pa"] = record.material.youngs_modulus.maxCoeff();
  if (record.material.stiffening_exponent.size() != 0) {
    summary["stiffening_exponent_min"] = record.material.stiffening_exponent.minCoeff();
    summary["stiffening_exponent_max"] = record.material.stiffening_exponent.maxCoeff();
  }
  record.summary = summary;
  record.source = source;

  report << DescribeLayerBuild(built.report);
  report.precision(4);
  report << "mass: " << layered.total_mass() << " kg (tissue " << layered.vertex_mass().sum()
         << " kg, core " << layered.core_mass() << " kg"
         << (record.core_mass < 0 ? ", from the core volume" : "") << ")\n";
  report << "Young's modulus: " << record.material.youngs_modulus.minCoeff() << " - "
         << record.material.youngs_modulus.maxCoeff() << " Pa; Poisson's ratio "
         << body.poisson_ratio << "\n";
  if (record.material.stiffening_exponent.size() != 0) {
    report << "stiffening exponent: " << record.material.stiffening_exponent.minCoeff() << " - "
           << record.material.stiffening_exponent.maxCoeff() << " (2: neo-Hookean)\n";
  }
  result.report = report.str();
  return result;
}

}  // namespace ergo
