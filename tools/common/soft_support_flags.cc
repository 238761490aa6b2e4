#include "tools/common/soft_support_flags.h"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string_view>
#include <utility>
#include <vector>

#include <gflags/gflags.h>

#include "ergo/body/support_solid.h"
#include "ergo/body/tissue_material.h"
#include "ergo/contact/support.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/mesh_io.h"
#include "ergo/mesh/split_list.h"
#include "ergo/mesh/text_reader.h"
#include "problems/soft_support_scenario.h"
#include "tools/common/flag_checks.h"

DEFINE_string(support_model, "rigid",
              "rigid: the support does not deform; soft: a foam part (a tet mesh of --support, "
              "or --support_tets) whose bottom plane is held, paper §4.3");
DEFINE_double(support_youngs_modulus, 5e4,
              "soft support: Young's modulus in Pa (seat foams: 2e4–1.25e5; the paper's chair "
              "cushions 25, 50, 125 kPa)");
DEFINE_double(support_poisson_ratio, 0.3, "soft support: Poisson's ratio, in (-1, 0.5)");
DEFINE_double(support_density, 0,
              "soft support: density in kg/m³ for its own weight (foam 30–80); 0 = weightless");
DEFINE_string(support_tets, "",
              "soft support: its tet mesh (.msh, or a TetGen .node/.ele pair, in --unit) instead "
              "of meshing the support surface; the vertices on its lowest plane are held. "
              "Several soft supports: a comma-separated list (one part, each mesh its own "
              "component with its own base)");
DEFINE_string(support_held, "",
              "soft support from --support_tets: a text file of the held vertices' 0-based "
              "indices (whitespace-separated, # comments) instead of its lowest plane; with "
              "several --support_tets, one file per mesh, comma-separated (empty: lowest plane)");
DEFINE_double(soft_support_edge_length, 0.01,
              "soft support meshed from the surface: tet edge length at its top, m");
DEFINE_double(soft_support_base_edge_length, 0.03,
              "soft support meshed from the surface: tet edge length at its base, m (>= the "
              "top's)");

namespace ergo {

namespace {

// The held-vertex file of --support_held: indices into the tet mesh, each checked.
std::vector<bool> ReadHeldVertices(const std::string& path, Eigen::Index vertex_count) {
  const std::string text = BytesToText(ReadFileBytes(path));
  TextReader reader(path, text);
  std::vector<bool> held(static_cast<size_t>(vertex_count), false);
  std::vector<std::string_view> tokens;
  while (reader.NextTokens('#', &tokens)) {
    for (std::string_view token : tokens) {
      const std::string word(token);
      char* end = nullptr;
      const long index = std::strtol(word.c_str(), &end, 10);
      if (end == word.c_str() || *end != '\0' || index < 0 || index >= vertex_count) {
        reader.Fail("'" + word + "' is not a vertex index of the support's tet mesh (0 to " +
                        std::to_string(vertex_count - 1) + ")",
                    "list 0-based indices of the vertices to hold");
      }
      held[index] = true;
    }
  }
  return held;
}

}  // namespace

bool SoftSupportRequested() {
  if (FLAGS_support_model != "rigid" && FLAGS_support_model != "soft") {
    throw InputError("--support_model", "", "'" + FLAGS_support_model + "' is not a model",
                     "use --support_model=rigid or --support_model=soft");
  }
  return FLAGS_support_model == "soft";
}

const std::string& SoftSupportTetFile() { return FLAGS_support_tets; }

void CheckSoftSupportFlags() {
  if (!SoftSupportRequested()) return;
  RequireInRange("support_youngs_modulus", FLAGS_support_youngs_modulus, 1.0, 1e11,
                 "Pa, e.g. 5e4 for a seat foam");
  if (!(FLAGS_support_poisson_ratio > -1 && FLAGS_support_poisson_ratio < 0.5)) {
    throw InputError("--support_poisson_ratio", "",
                     std::to_string(FLAGS_support_poisson_ratio) + " is outside (-1, 0.5)",
                     "e.g. 0.3 for a foam");
  }
  RequireInRange("support_density", FLAGS_support_density, 0, 1e4, "kg/m³, e.g. 50, or 0");
  if (!FLAGS_support_held.empty() && FLAGS_support_tets.empty()) {
    // A surface meshed here has its bottom plane held; its vertex numbers are not the user's.
    throw InputError("--support_held", "", "lists vertices of a tet mesh, but no --support_tets",
                     "give the tet mesh with --support_tets, or drop --support_held");
  }
  RequireInRange("soft_support_edge_length", FLAGS_soft_support_edge_length, 1e-4, 1.0,
                 "metres, e.g. 0.01");
  RequireInRange("soft_support_base_edge_length", FLAGS_soft_support_base_edge_length,
                 FLAGS_soft_support_edge_length, 1.0,
                 "metres, at least --soft_support_edge_length");
}

std::shared_ptr<const ElasticPart> SoftSupportFromFlags(const TriMesh& surface,
                                                        const std::string& source, LengthUnit unit,
                                                        const Eigen::Vector3d& gravity,
                                                        TriMesh* contact_surface) {
  CheckSoftSupportFlags();
  ElasticPartOptions options;
  options.density = FLAGS_support_density;
  options.gravity = FLAGS_support_density > 0 ? gravity : Eigen::Vector3d::Zero();
  if (!FLAGS_support_tets.empty()) {
    // One part per tet mesh, joined: several soft supports in one scene.
    const std::vector<std::string> files = SplitList(FLAGS_support_tets, ',');
    std::vector<std::string> held_files = SplitList(FLAGS_support_held, ',');
    if (!FLAGS_support_held.empty() && held_files.size() != files.size()) {
      throw InputError("--support_held", "",
                       std::to_string(held_files.size()) + " held-vertex files for " +
                           std::to_string(files.size()) + " --support_tets meshes",
                       "give one per mesh, comma-separated (empty for its lowest plane)");
    }
    held_files.resize(files.size());
    std::vector<ElasticPart> parts;
    for (size_t i = 0; i < files.size(); ++i) {
      TetMesh mesh = ReadTetMesh(files[i], ReadOptions{unit});
      // Meshers disagree on orientation: turn inverted tets, refuse flat ones (by name).
      for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t)
        if (TetVolume(mesh, t) < 0) std::swap(mesh.tets(t, 2), mesh.tets(t, 3));
      const double size =
          (mesh.vertices.colwise().maxCoeff() - mesh.vertices.colwise().minCoeff()).norm();
      std::vector<bool> held = held_files[i].empty()
                                   ? BottomVertices(mesh, 1e-6 * size)
                                   : ReadHeldVertices(held_files[i], mesh.vertices.rows());
      TissueMaterial material = UniformMaterial(mesh.tets.rows(), FLAGS_support_youngs_modulus,
                                                FLAGS_support_poisson_ratio);
      parts.push_back(ElasticPart::Create(std::move(mesh), std::move(held), std::move(material),
                                          options, files[i]));
    }
    std::vector<const ElasticPart*> pointers;
    for (const ElasticPart& part : parts) pointers.push_back(&part);
    auto part = std::make_shared<const ElasticPart>(
        parts.size() == 1 ? std::move(parts.front())
                          : ElasticPart::Join(pointers, FLAGS_support_tets));
    *contact_surface = part->boundary().surface;
    return part;
  }
  TetMesh mesh;
  std::vector<bool> held;
  {
    // The support check first (closed, manifold, outward): Mesh_3 of an open surface gives no
    // solid, and its message would blame the edge length.
    Support(surface, source);
    SupportSolidOptions options;
    options.top_edge_length = FLAGS_soft_support_edge_length;
    options.base_edge_length = FLAGS_soft_support_base_edge_length;
    options.progress = [](const std::string& line) { std::cerr << line << "\n"; };
    SupportSolid solid = MeshSupportSolid(surface, options, source);
    mesh = std::move(solid.mesh);
    held = std::move(solid.base);
  }
  TissueMaterial material =
      UniformMaterial(mesh.tets.rows(), FLAGS_support_youngs_modulus, FLAGS_support_poisson_ratio);
  auto part = std::make_shared<const ElasticPart>(
      ElasticPart::Create(std::move(mesh), std::move(held), std::move(material), options, source));
  *contact_surface = part->boundary().surface;
  return part;
}

void ApplySoftSupportFlags(Scenario* scenario) {
  if (!SoftSupportRequested()) return;
  TriMesh boundary;
  auto part = SoftSupportFromFlags(scenario->support, "--scenario=" + scenario->name + " support",
                                   LengthUnit::kMetre, scenario->body->gravity(), &boundary);
  UseSoftSupport(std::move(part), scenario);
}

std::string DescribeSoftSupportFlags() {
  std::ostringstream out;
  out << FLAGS_support_model;
  if (FLAGS_support_model == "soft") {
    out << " (E " << FLAGS_support_youngs_modulus << " Pa, nu " << FLAGS_support_poisson_ratio
        << ", density " << FLAGS_support_density << " kg/m3, "
        << (FLAGS_support_tets.empty() ? "meshed from the surface" : FLAGS_support_tets) << ")";
  }
  return out.str();
}

}  // namespace ergo
