// The body directory: the files `ergo_body build` writes and every later tool reads to get
// the body part of paper §3.1 back — the layer's tet mesh, its attached (core) vertices,
// per-tet Young's modulus and Poisson's ratio, densities and core mass, and the build
// summary. SI units. The format (version 1) is specified in ergo/body/README.md.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "ergo/body/layered_body.h"
#include "ergo/mesh/json.h"
#include "ergo/mesh/tri_mesh.h"
#include "ergo/mesh/vtu_writer.h"

namespace ergo {

inline constexpr int kBodyFormatVersion = 1;

// File names inside a body directory.
inline constexpr char kBodyJsonFile[] = "body.json";
inline constexpr char kBodyMeshFile[] = "body.msh";
inline constexpr char kBodyAttachedFile[] = "attached.txt";
inline constexpr char kBodyMaterialFile[] = "tet_material.csv";
inline constexpr char kBodyViewFile[] = "body.vtu";

// Everything a body directory holds.
struct BodyRecord {
  TetMesh rest;                    // metres, positively oriented
  std::vector<bool> attached;      // per vertex
  TissueMaterial material;         // per-tet E (Pa) and ν, compression resistance, ε
  double tissue_density = 1050.0;  // kg/m³
  double core_mass = -1.0;         // kg; negative = core volume × core_density
  double core_density = 1050.0;    // kg/m³
  Eigen::VectorXd vertex_depth;    // m per vertex for the VTU view; may be empty
  Json summary = Json::object();   // the builder's numbers (counts, volume, mass, quality)
  Json source = Json::object();    // how it was built (inputs, options, notes)
};

// Writes the directory (created if missing; existing body files are replaced), each file
// atomically: body.msh, attached.txt, tet_material.csv, body.vtu (in `view_encoding`), then
// body.json last, so a directory with a body.json is complete. Throws InputError when `dir`
// cannot be written.
void SaveBodyDirectory(const std::string& dir, const BodyRecord& body,
                       VtuEncoding view_encoding = VtuEncoding::kBinary);

// Reads a directory written by SaveBodyDirectory. Throws InputError naming the file (and
// line) for a missing or corrupt file, an unknown format version, or files that disagree
// (counts, index ranges).
BodyRecord ReadBodyDirectory(const std::string& dir);

// Values that replace the stored ones when loading.
struct BodyOverrides {
  std::optional<double> tissue_density, core_mass, core_density;
};

// Reads the directory and creates the LayeredBody: the scenario part of `scenario`
// (gravity, lock, external force and torque) is used as given; tissue density, core mass
// and core density come from body.json unless overridden.
LayeredBody LoadLayeredBody(const std::string& dir, const LayeredBodyOptions& scenario = {},
                            const BodyOverrides& overrides = {});

}  // namespace ergo
