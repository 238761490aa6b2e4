#include "problems/scenario_parts.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "ergo/body/body_directory.h"
#include "ergo/body/layer_builder.h"
#include "ergo/body/recorded_anatomy.h"
#include "ergo/body/sample_interpolation.h"
#include "ergo/body/tissue_fields.h"
#include "ergo/contact/support.h"
#include "ergo/contact/support_validation.h"
#include "ergo/equilibrium/placement.h"
#include "ergo/mesh/axis_map.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/mesh_check.h"
#include "ergo/mesh/mesh_io.h"
#include "ergo/mesh/seconds_since.h"
#include "ergo/mesh/surface_geometry.h"
#include "ergo/mesh/tet_boundary.h"

namespace ergo {
namespace {

SampleInterpolant Field(const std::string& csv, double constant, LengthUnit unit, bool is_length,
                        const std::string& name, const std::string& value_unit) {
  if (csv.empty()) return SampleInterpolant::Constant(constant);
  SampleCsvOptions options;
  options.unit = unit;
  options.value_is_length = is_length;
  options.value_name = name;
  options.value_unit = value_unit;
  return SampleInterpolant::Fit(ReadPointSamplesCsv(csv, options));
}

// The mesh check's first finding that is more than a note, as an InputError naming `path`
// (`why` is appended to what is wrong).
void ThrowFirstProblem(const MeshCheckReport& report, const std::string& path,
                       const std::string& why) {
  for (const MeshIssue& issue : report.issues) {
    if (issue.severity == Severity::kNote) continue;
    std::string what = issue.what;
    if (!issue.examples.empty()) what += " (e.g. " + issue.examples.front() + ")";
    throw InputError(
        path, issue.location, what + why,
        issue.fix.empty() ? "repair the mesh (ergo_mesh check lists every finding)" : issue.fix);
  }
}

// The tissue mass option from a requested total mass (negative: keep the core's default).
void SetTotalMass(double total_mass, double layer_volume, const std::string& source,
                  LayeredBodyOptions* options) {
  if (total_mass < 0) return;
  const double tissue = options->tissue_density * layer_volume;
  options->core_mass = total_mass - tissue;
  if (!(options->core_mass > 0)) {
    throw InputError(
        source, "total mass",
        "the total mass is not above the tissue's own mass (" + std::to_string(tissue) + " kg)",
        "give a larger total mass");
  }
}

std::shared_ptr<LayeredBody> LoadUserTetMesh(const UserBodyInput& input,
                                             const LayeredBodyOptions& load) {
  if (!(input.youngs_modulus > 0) || !(input.poisson_ratio > -1 && input.poisson_ratio < 0.5)) {
    throw InputError(input.tet_mesh, "material",
                     "Young's modulus must be positive and Poisson's ratio in (-1, 0.5)",
                     "e.g. E 1e4 Pa, nu 0.45");
  }
  ReadOptions read;
  read.unit = input.unit;
  ReadDetails details;
  const TetMesh mesh = ReadTetMesh(input.tet_mesh, read, &details);
  MeshCheckOptions check;
  check.unit = input.unit;
  const MeshCheckReport report = CheckTetMesh(mesh, input.tet_mesh, check, &details);
  ThrowFirstProblem(report, input.tet_mesh, "");
  std::vector<bool> attached = AttachedFromInnerBoundary(mesh, input.tet_mesh);
  const SampleInterpolant stiffness =
      Field(input.stiffness_csv, input.youngs_modulus, input.unit, false, "Young's modulus", "Pa");
  TissueMaterial material;
  material.youngs_modulus.resize(mesh.tets.rows());
  double volume = 0;
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    Eigen::Vector3d corners[4];
    for (int k = 0; k < 4; ++k) corners[k] = mesh.vertices.row(mesh.tets(t, k)).transpose();
    material.youngs_modulus[t] =
        stiffness(0.25 * (corners[0] + corners[1] + corners[2] + corners[3]));
    volume +=
        (corners[1] - corners[0]).dot((corners[2] - corners[0]).cross(corners[3] - corners[0])) / 6;
  }
  material.poisson_ratio = Eigen::VectorXd::Constant(mesh.tets.rows(), input.poisson_ratio);
  LayeredBodyOptions options = load;
  SetTotalMass(input.total_mass, volume, input.tet_mesh, &options);
  return std::make_shared<LayeredBody>(
      LayeredBody::Create(mesh, std::move(attached), material, options, input.tet_mesh));
}

}  // namespace

std::vector<bool> AttachedFromInnerBoundary(const TetMesh& mesh, const std::string& source) {
  const TetBoundary boundary = ExtractBoundary(mesh);
  std::vector<TriMesh> components(static_cast<size_t>(boundary.component_count));
  std::vector<std::vector<int>> faces(components.size());
  for (Eigen::Index f = 0; f < boundary.surface.triangles.rows(); ++f)
    faces[static_cast<size_t>(boundary.face_component[f])].push_back(static_cast<int>(f));
  std::vector<bool> attached(static_cast<size_t>(mesh.vertices.rows()), false);
  int outer = 0, inner = 0;
  for (size_t c = 0; c < faces.size(); ++c) {
    TriMesh part{boundary.surface.vertices, Triangles(faces[c].size(), 3)};
    for (size_t i = 0; i < faces[c].size(); ++i)
      part.triangles.row(static_cast<Eigen::Index>(i)) =
          boundary.surface.triangles.row(faces[c][i]);
    if (EnclosedVolume(part) > 0) {
      ++outer;
      continue;
    }
    ++inner;
    for (Eigen::Index i = 0; i < part.triangles.size(); ++i)
      attached[static_cast<size_t>(boundary.surface_to_tet[part.triangles(i / 3, i % 3)])] = true;
  }
  if (inner == 0) {
    throw InputError(source, "boundary",
                     "the tet mesh has no inner boundary: a body is a tissue layer around a "
                     "cavity where the rigid core sits",
                     "mesh the layer between the skin and the core's surface (or use --skin "
                     "with a depth to build one)");
  }
  if (outer != 1) {
    throw InputError(source, "boundary",
                     "the tet mesh has " + std::to_string(outer) + " outer boundaries",
                     "give one connected tissue layer");
  }
  return attached;
}

std::shared_ptr<const LayeredBody> MakeScenarioBody(const std::string& label,
                                                    const std::function<ImplicitBodySpec()>& spec,
                                                    double edge_length, double sliver_bound_degrees,
                                                    const UserBodyInput& user,
                                                    const LayeredBodyOptions& load,
                                                    ScenarioBuildReport* report) {
  if (!user.empty()) return LoadUserBody(user, edge_length, load, report);
  const auto start = std::chrono::steady_clock::now();
  BuilderOptions builder;
  builder.edge_length = edge_length;
  builder.sliver_bound_degrees = sliver_bound_degrees;
  const GeneratedBody generated = BuildImplicitBody(spec(), builder, load);
  report->body = label + ": " + DescribeGeneratedBody(generated);
  report->layer = generated.report;
  report->depth = generated.depth;
  report->body_seconds = SecondsSince(start);
  return generated.body;
}

std::shared_ptr<LayeredBody> LoadUserBody(const UserBodyInput& input, double default_edge_length,
                                          const LayeredBodyOptions& load,
                                          ScenarioBuildReport* report) {
  const auto start = std::chrono::steady_clock::now();
  std::shared_ptr<LayeredBody> body;
  std::ostringstream line;
  if (!input.body_directory.empty()) {
    BodyOverrides overrides;
    if (input.total_mass >= 0) {
      throw InputError(input.body_directory, "total mass",
                       "a body directory carries its own masses",
                       "set the core mass when building it (ergo_body build --core_mass)");
    }
    body = std::make_shared<LayeredBody>(LoadLayeredBody(input.body_directory, load, overrides));
    const std::string record =
        (std::filesystem::path(input.body_directory) / kBodyJsonFile).string();
    const RecordedAnatomy recorded =
        ReadRecordedAnatomy(GetMember(ReadJsonFile(record), "source", record), record);
    if (report != nullptr && recorded.anatomy == Anatomy::kFoot) {
      report->scanned_foot = true;
      report->scanned_heel = recorded.heel;
    }
    line << "user body " << input.body_directory;
  } else if (!input.tet_mesh.empty()) {
    body = LoadUserTetMesh(input, load);
    line << "user tet mesh " << input.tet_mesh;
  } else {
    if (!(input.depth > 0) || !(input.youngs_modulus > 0) ||
        !(input.poisson_ratio > -1 && input.poisson_ratio < 0.5)) {
      throw InputError(
          input.skin_surface, "material",
          "depth and Young's modulus must be positive and Poisson's ratio in (-1, 0.5)",
          "e.g. depth 0.02 m, E 1e4 Pa, nu 0.45");
    }
    TissueFieldInputs inputs;
    inputs.anatomy = input.anatomy;
    const double edge_length = input.edge_length > 0 ? input.edge_length : default_edge_length;
    inputs.anatomy.min_depth = std::max(inputs.anatomy.min_depth, edge_length);
    if (input.anatomy.anatomy == Anatomy::kNone && input.depth_csv.empty())
      inputs.depth = input.depth;
    inputs.depth_samples = input.depth_csv;
    if (input.anatomy.anatomy == Anatomy::kNone && input.stiffness_csv.empty())
      inputs.youngs_modulus = input.youngs_modulus;
    inputs.stiffness_samples = input.stiffness_csv;
    inputs.unit = input.unit;
    inputs.axes = ParseAxisMap(input.axes, "--skin_axes");
    inputs.depth_flag = "skin_depth";
    inputs.depth_samples_flag = "depth_csv";
    inputs.modulus_flag = "skin_youngs_modulus";
    inputs.modulus_samples_flag = "stiffness_csv";
    ReadOptions read;
    read.unit = input.unit;
    TriMesh skin = ReadTriMesh(input.skin_surface, read);
    ApplyAxisMap(inputs.axes, &skin.vertices);
    const TissueFields fields = MakeTissueFields(skin, inputs, input.skin_surface);
    const SampleInterpolant& depth = fields.depth;
    const SampleInterpolant& stiffness = fields.youngs_modulus;
    BuilderOptions builder;
    builder.edge_length = edge_length;
    if (fields.priors) builder.core_limit = fields.priors->core_limit;
    const BuiltLayer built = BuildLayerFromSurface(skin, depth, builder, input.skin_surface);
    const TissueMaterial material =
        TissueMaterialOnLayer(built, stiffness, fields.stiffening_exponent, input.poisson_ratio);
    LayeredBodyOptions options = load;
    SetTotalMass(input.total_mass, built.report.layer_volume, input.skin_surface, &options);
    body = std::make_shared<LayeredBody>(
        LayeredBody::Create(built.mesh, built.attached, material, options, input.skin_surface));
    // As `ergo_body build`: a meshed skin that pinches or overlaps itself is refused with the
    // point and the edge lengths to try (--body_edge_length here).
    ValidateSkinForContact(body->skin().RestSurface(body->rest().vertices),
                           input.skin_surface + " (the built body's skin)");
    line << "user skin " << input.skin_surface << " (depth " << depth.Describe() << ", E "
         << stiffness.Describe() << ")";
    if (fields.priors) line << "; anatomical priors: " << fields.priors->summary;
    if (report != nullptr && fields.priors && input.anatomy.anatomy == Anatomy::kFoot) {
      report->scanned_foot = true;
      report->scanned_heel = fields.priors->heel;
    }
  }
  line << ": " << body->rest().vertices.rows() << " vertices, " << body->rest().tets.rows()
       << " tets, mass " << body->total_mass() << " kg";
  if (report != nullptr) {
    report->body = line.str();
    report->body_seconds = SecondsSince(start);
  }
  return body;
}

TriMesh LoadUserSupport(const UserSupportInput& input) {
  ReadOptions read;
  read.unit = input.unit;
  ReadDetails details;
  const TriMesh mesh = ReadTriMesh(input.path, read, &details);
  MeshCheckOptions check;
  check.unit = input.unit;
  check.require_closed = true;
  const MeshCheckReport report = CheckTriMesh(mesh, input.path, check, &details);
  ThrowFirstProblem(report, input.path,
                    "; a support must be a closed, manifold, outward surface without "
                    "self-intersections");
  return mesh;
}

std::vector<bool> ActiveByRule(const TriMesh& support, ActiveRule rule, double min_normal_y) {
  if (rule == ActiveRule::kAll) return std::vector<bool>(support.vertices.rows(), true);
  const Vertices normals = VertexNormals(support);
  std::vector<bool> active(static_cast<size_t>(support.vertices.rows()));
  for (Eigen::Index v = 0; v < support.vertices.rows(); ++v)
    active[v] = normals(v, 1) > min_normal_y;
  return active;
}

std::vector<bool> ActiveWhere(const TriMesh& support,
                              const std::function<bool(const Eigen::Vector3d&)>& designed) {
  std::vector<bool> active(static_cast<size_t>(support.vertices.rows()));
  for (Eigen::Index v = 0; v < support.vertices.rows(); ++v)
    active[v] = designed(support.vertices.row(v).transpose());
  return active;
}

BodyState StartAbove(const LayeredBody& body, const TriMesh& support, double gap,
                     const std::string& scenario) {
  return StartAbove(body, RestState(body), support, gap, scenario);
}

BodyState StartAbove(const LayeredBody& body, const BodyState& from, const TriMesh& support,
                     double gap, const std::string& scenario) {
  const Support surface(support, scenario + " support");
  const PlacementResult placed = PlaceAboveSupport(body, from, surface, gap);
  if (!placed.found) {
    throw InputError(scenario, "start",
                     "the body does not meet the support when moved along the load",
                     "place the body over the support (check the units and the body's position)");
  }
  return placed.state;
}

void UseNegativeImage(const NegativeImageOptions& options, double gap, Scenario* scenario,
                      ScenarioBuildReport* report) {
  const LayeredBody& body = *scenario->body;
  const Eigen::Vector3d lower = gap * body.TotalLoad().normalized();
  BodyState contact = scenario->start;
  contact.centre += lower;
  for (Eigen::Index i = 0; i < body.free_vertices().size(); ++i)
    contact.free_displacement.segment<3>(3 * i) += lower;
  const NegativeImage image =
      MakeNegativeImage(body, contact, scenario->support, options, scenario->name);
  scenario->support = image.support;
  scenario->start = image.start;
  if (report != nullptr) {
    report->negative_image = image.BriefReport();
    report->negative_image_seconds = image.seconds;
  }
}

double SkinEdgeNearDesign(const LayeredBody& body, const BodyState& state, const TriMesh& support,
                          const std::vector<bool>& active) {
  const Vertices positions = DeformedPositions(body, state);
  const Triangles& triangles = body.skin().triangles;
  double total = 0;
  long count = 0;
  for (Eigen::Index f = 0; f < triangles.rows(); ++f)
    for (int c = 0; c < 3; ++c, ++count)
      total += (positions.row(triangles(f, c)) - positions.row(triangles(f, (c + 1) % 3))).norm();
  const double mean = count > 0 ? total / static_cast<double>(count) : 0;
  Eigen::AlignedBox3d box;
  for (Eigen::Index v = 0; v < support.vertices.rows(); ++v)
    if (active.empty() || active[v]) box.extend(support.vertices.row(v).transpose());
  if (box.isEmpty()) return mean;
  box.min().array() -= 2 * mean;
  box.max().array() += 2 * mean;
  double near_total = 0;
  long near_count = 0;
  for (Eigen::Index f = 0; f < triangles.rows(); ++f) {
    for (int c = 0; c < 3; ++c) {
      const Eigen::Vector3d a = positions.row(triangles(f, c)),
                            b = positions.row(triangles(f, (c + 1) % 3));
      if (!box.contains(0.5 * (a + b))) continue;
      near_total += (a - b).norm();
      ++near_count;
    }
  }
  return near_count > 0 ? near_total / static_cast<double>(near_count) : mean;
}

void FinishScenario(const std::string& description, const std::string& support_summary,
                    double contact_stiffness, double free_fall_mass_scale,
                    const DesignSpaceOptions& design_space, std::vector<bool> active,
                    Scenario* scenario, ScenarioBuildReport* report) {
  ScenarioBuildReport& r = *report;
  const LayeredBody& body = *scenario->body;
  r.body_vertices = static_cast<int>(body.rest().vertices.rows());
  r.skin_vertices = static_cast<int>(body.skin().vertices.size());
  r.support_vertices = static_cast<int>(scenario->support.vertices.rows());
  r.active_vertices = static_cast<int>(std::count(active.begin(), active.end(), true));
  r.total_mass = body.total_mass();
  r.load = body.TotalLoad();
  std::ostringstream support;
  support << support_summary << ": " << r.support_vertices << " vertices (" << r.active_vertices
          << " designed)";
  r.support = support.str();
  std::ostringstream line;
  line << description << ": " << r.body_vertices << " body vertices, " << r.total_mass
       << " kg, load " << r.load.norm() << " N, " << r.support_vertices << " support vertices ("
       << r.active_vertices << " designed), κ " << contact_stiffness << " Pa/m";
  scenario->description = line.str();
  DesignOptions& design = scenario->design;
  design.equilibrium.contact_stiffness = contact_stiffness;
  design.equilibrium.free_fall_mass_scale = free_fall_mass_scale;
  design.active = std::move(active);
  r.skin_edge = SkinEdgeNearDesign(body, scenario->start, scenario->support, design.active);
  design.parameterization = design_space.parameterization;
  design.filter_radius =
      design_space.filter_radius > 0 ? design_space.filter_radius : 2.5 * r.skin_edge;
  design.pressure.smoothing_radius = design_space.pressure_smoothing_radius >= 0
                                         ? design_space.pressure_smoothing_radius
                                         : std::sqrt(3.0) * r.skin_edge;
  std::ostringstream space;
  space << "; skin edge near the design " << r.skin_edge * 1e3 << " mm";
  if (design.parameterization == DesignParameterization::kFiltered)
    space << ", design filter radius " << design.filter_radius * 1e3 << " mm";
  if (design.parameterization == DesignParameterization::kSpline)
    space << ", design spline knot spacing " << design.filter_radius * 1e3 << " mm";
  if (design.pressure.smoothing_radius > 0) {
    space << ", pressure smoothing radius " << design.pressure.smoothing_radius * 1e3 << " mm";
  } else {
    space << ", umbrella pressure smoothing";
  }
  r.support += space.str();
}

}  // namespace ergo
