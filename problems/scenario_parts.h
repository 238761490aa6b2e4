// What every scenario builder shares: a user's body or support in place of the generated one
// (a body directory from `ergo_body build`, or a skin surface with depth and stiffness
// samples; a support mesh file with a rule for its designed vertices), the start placement
// just above the support (paper §3.4: the human starts slightly above the support), and the
// build report. Files are refused with the mesh check's and the readers' messages. SI units.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ergo/body/anatomical_priors.h"
#include "ergo/body/body_state.h"
#include "ergo/body/layered_body.h"
#include "ergo/mesh/length_unit.h"
#include "ergo/mesh/tri_mesh.h"
#include "problems/implicit_body.h"
#include "problems/negative_image.h"
#include "problems/scenario.h"

namespace ergo {

// A user's body instead of the generated one.
struct UserBodyInput {
  std::string body_directory;  // written by `ergo_body build`; used as it is (its masses)
  // Or a tet mesh of the tissue layer (.msh, .node/.ele): its outer boundary is the skin,
  // its inner boundaries (cavities) the core's surface, whose vertices are attached.
  std::string tet_mesh;
  // Otherwise a skin surface (.obj .off .ply .stl .msh; open scans are capped) meshed here:
  std::string skin_surface;
  LengthUnit unit = LengthUnit::kMetre;  // of the surface and of the CSV coordinates and depths
  std::string depth_csv;                 // x,y,z,depth samples; empty = constant `depth`
  std::string stiffness_csv;    // x,y,z,E (Pa) samples (surface or tet mesh); empty = constant
  double depth = 0.02;          // m
  double youngs_modulus = 1e4;  // Pa
  double poisson_ratio = 0.45;
  double edge_length = 0;  // m; 0 = the scenario's body edge length
  double total_mass = -1;  // kg; negative = core volume × 1050 kg/m³
  // Skin surface only: anatomical priors instead of the constants `depth` and
  // `youngs_modulus` (the CSVs then replace them near their points), and the rotation from
  // the scan's axes to ergo's (ergo/mesh/axis_map.h).
  AnatomyOptions anatomy;
  std::string axes = "x,y,z";
  bool empty() const { return body_directory.empty() && tet_mesh.empty() && skin_surface.empty(); }
};

// Which vertices of a user's support are designed.
enum class ActiveRule {
  kAll,           // every vertex
  kUpwardFacing,  // vertices whose unit normal has y above `min_normal_y` (the top side)
};

// A user's support mesh instead of the generated one.
struct UserSupportInput {
  std::string path;  // closed surface: .obj .off .ply .stl .msh
  LengthUnit unit = LengthUnit::kMetre;
  ActiveRule active = ActiveRule::kUpwardFacing;
  double min_normal_y = 0.5;
  bool empty() const { return path.empty(); }
};

// The design space and the score's smoothing, as a scene chooses them (DESIGN.md §8).
struct DesignSpaceOptions {
  DesignParameterization parameterization = DesignParameterization::kFiltered;
  // Radius r of the design filter, m; 0 = 2.5 × the skin's mean edge near the designed
  // region (SkinEdgeNearDesign).
  double filter_radius = 0;
  // Radius of the Helmholtz pressure smoothing, m; 0 = the paper's umbrella Laplacian;
  // negative = √3 × the skin's mean edge near the designed region (the umbrella's reach on
  // the skin, kept when the support is refined).
  double pressure_smoothing_radius = -1;
};

// Numbers of one scenario build, for reports and the README.
struct ScenarioBuildReport {
  std::string body;        // one line about the body (vertices, mass, layer, quality)
  LayerBuildReport layer;  // the builder's report (generated bodies only; else zeros)
  DepthAgreement depth;    // requested vs meshed depth (generated bodies only)
  std::string support;     // one line about the support
  int body_vertices = 0, skin_vertices = 0, support_vertices = 0, active_vertices = 0;
  double total_mass = 0;                           // kg
  Eigen::Vector3d load = Eigen::Vector3d::Zero();  // weight + external force, N
  double body_seconds = 0, support_seconds = 0, negative_image_seconds = 0, start_seconds = 0;
  std::string negative_image;  // one line when a negative image was made
  std::string roll;            // one line when the shoe's roll was balanced or stood
  double roll_radians = 0;     // the body's start roll about its length axis (z)
  double skin_edge = 0;        // mean skin edge near the designed region, m
  // A user's scan read as a foot (a skin with --anatomy=foot, or a body directory built so),
  // and, when it was measured, its heel's bisector on the scan as read, before meshing.
  bool scanned_foot = false;
  std::optional<ScannedHeel> scanned_heel;
};

// The scenario's body: the user's when `user` is set, else `spec()` meshed by the body
// builder with the edge length and sliver bound (`label` starts the report's body line).
// Fills the report's body line, layer and depth reports and seconds.
std::shared_ptr<const LayeredBody> MakeScenarioBody(const std::string& label,
                                                    const std::function<ImplicitBodySpec()>& spec,
                                                    double edge_length, double sliver_bound_degrees,
                                                    const UserBodyInput& user,
                                                    const LayeredBodyOptions& load,
                                                    ScenarioBuildReport* report);

// Loads or builds the user's body with the scenario's load and lock (`load`). Throws
// InputError (the readers', the builder's or the body's) for anything unusable.
std::shared_ptr<LayeredBody> LoadUserBody(const UserBodyInput& input, double default_edge_length,
                                          const LayeredBodyOptions& load,
                                          ScenarioBuildReport* report);

// Attached vertices of a tissue-layer tet mesh: those on its inner boundary components (the
// cavities left by the core: enclosed volume < 0 with outward-from-tissue faces). Throws
// InputError naming `source` when there is no inner boundary or more than one outer one.
std::vector<bool> AttachedFromInnerBoundary(const TetMesh& mesh, const std::string& source);

// Reads the user's support (metres after the unit) and refuses it with the mesh check's
// first problem (open, non-manifold, self-intersecting, degenerate, wrongly oriented).
TriMesh LoadUserSupport(const UserSupportInput& input);

// Per-vertex designed flags by the rule.
std::vector<bool> ActiveByRule(const TriMesh& support, ActiveRule rule, double min_normal_y);

// Per-vertex designed flags from a predicate on the position.
std::vector<bool> ActiveWhere(const TriMesh& support,
                              const std::function<bool(const Eigen::Vector3d&)>& designed);

// The body moved rigidly from its rest pose along the load until its skin is `gap` above the
// support. Throws InputError naming `scenario` when the body misses the support.
BodyState StartAbove(const LayeredBody& body, const TriMesh& support, double gap,
                     const std::string& scenario);
// The same from another pose (`from`, e.g. the rest pose turned).
BodyState StartAbove(const LayeredBody& body, const BodyState& from, const TriMesh& support,
                     double gap, const std::string& scenario);

// Replaces scenario->support by its negative image and scenario->start by the body just
// above it: the body is lowered from its start (`gap` above the support) to contact and
// carved `options.depth` further in. Throws InputError as MakeNegativeImage.
void UseNegativeImage(const NegativeImageOptions& options, double gap, Scenario* scenario,
                      ScenarioBuildReport* report);

// The mean length of the skin's edges near the designed support vertices (`active`, all if
// empty) with the body at `state`: edges whose midpoints lie within the designed vertices'
// bounding box grown by twice the skin's mean edge; the skin's mean edge if there are none.
double SkinEdgeNearDesign(const LayeredBody& body, const BodyState& state, const TriMesh& support,
                          const std::vector<bool>& active);

// Fills the report's counts and one-line support summary, the scenario's description
// (prefix + counts) and its design options (stiffness, free-fall scale, design space with
// its radii resolved, designed vertices).
void FinishScenario(const std::string& description, const std::string& support_summary,
                    double contact_stiffness, double free_fall_mass_scale,
                    const DesignSpaceOptions& design_space, std::vector<bool> active,
                    Scenario* scenario, ScenarioBuildReport* report);

}  // namespace ergo
