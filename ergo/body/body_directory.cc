#include "ergo/body/body_directory.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string_view>
#include <system_error>

#include <glog/logging.h>

#include "ergo/mesh/atomic_file.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/mesh_io.h"
#include "ergo/mesh/text_reader.h"
#include "ergo/mesh/vtu_writer.h"

namespace ergo {
namespace {

namespace fs = std::filesystem;

constexpr char kFormatName[] = "ergo-body";
constexpr char kRegenerate[] = "rebuild the body with `ergo_body build`";

std::string PathIn(const std::string& dir, const std::string& file) {
  return (fs::path(dir) / file).string();
}

bool IsUniform(const Eigen::VectorXd& values) {
  return values.size() > 0 && values.maxCoeff() == values.minCoeff();
}

// A file name from body.json: a plain name inside the directory.
std::string FileName(const Json& files, const std::string& key, const std::string& json_path) {
  const std::string& name = GetString(files, key, json_path);
  if (name.empty() || name.find('/') != std::string::npos || name.find('\\') != std::string::npos ||
      name == "." || name == "..") {
    throw InputError(json_path, "member \"" + key + "\"",
                     "\"" + name + "\" is not a plain file name inside the body directory",
                     kRegenerate);
  }
  return name;
}

std::vector<bool> ReadAttached(const std::string& path, Eigen::Index vertex_count) {
  const std::string text = BytesToText(ReadFileBytes(path));
  TextReader reader(path, text);
  std::vector<bool> attached(static_cast<size_t>(vertex_count), false);
  std::vector<std::string_view> tokens;
  int64_t previous = -1;
  while (reader.NextTokens('#', &tokens)) {
    if (tokens.size() != 1) reader.Fail("expected one vertex id per line", kRegenerate);
    int64_t id = 0;
    if (!ParseInt64(tokens[0], &id)) {
      reader.Fail("vertex id " + Quote(tokens[0]) + " is not an integer", kRegenerate);
    }
    if (id < 0 || id >= vertex_count) {
      reader.Fail("vertex id " + std::to_string(id) + " is outside [0, " +
                      std::to_string(vertex_count) + ") (the mesh's vertices)",
                  kRegenerate);
    }
    if (id <= previous) reader.Fail("vertex ids must be strictly increasing", kRegenerate);
    previous = id;
    attached[static_cast<size_t>(id)] = true;
  }
  return attached;
}

void ReadMaterial(const std::string& path, Eigen::Index tet_count, TissueMaterial* material) {
  const std::string text = BytesToText(ReadFileBytes(path));
  TextReader reader(path, text);
  material->youngs_modulus.resize(tet_count);
  material->poisson_ratio.resize(tet_count);
  std::string_view line;
  Eigen::Index row = 0;
  bool header = false;
  size_t columns = 2;  // a third column, stiffening_exponent, is optional (2: neo-Hookean)
  while (reader.NextLine(&line)) {
    std::vector<std::string_view> fields;
    size_t start = 0;
    for (size_t i = 0; i <= line.size(); ++i) {
      if (i == line.size() || line[i] == ',') {
        std::string_view field = line.substr(start, i - start);
        while (!field.empty() && (field.front() == ' ' || field.front() == '\r'))
          field.remove_prefix(1);
        while (!field.empty() && (field.back() == ' ' || field.back() == '\r'))
          field.remove_suffix(1);
        fields.push_back(field);
        start = i + 1;
      }
    }
    if (fields.size() == 1 && fields[0].empty()) continue;
    if (!fields.empty() && !fields[0].empty() && fields[0][0] == '#') continue;
    if (!header) {
      header = true;
      columns = fields.size();
      if ((columns != 2 && columns != 3) || fields[0] != "youngs_modulus_pa" ||
          fields[1] != "poisson_ratio" || (columns == 3 && fields[2] != "stiffening_exponent")) {
        reader.Fail("expected the header youngs_modulus_pa,poisson_ratio[,stiffening_exponent]",
                    kRegenerate);
      }
      if (columns == 3) material->stiffening_exponent.resize(tet_count);
      continue;
    }
    if (fields.size() != columns) {
      reader.Fail("expected " + std::to_string(columns) + " comma-separated values", kRegenerate);
    }
    if (row >= tet_count) {
      reader.Fail("more rows than the mesh's " + std::to_string(tet_count) + " tets", kRegenerate);
    }
    double E = 0, nu = 0;
    if (!ParseDouble(fields[0], &E) || !std::isfinite(E) || !(E > 0)) {
      reader.Fail("Young's modulus " + Quote(fields[0]) + " is not a positive number", kRegenerate);
    }
    if (!ParseDouble(fields[1], &nu) || !(nu > -1 && nu < 0.5)) {
      reader.Fail("Poisson's ratio " + Quote(fields[1]) + " is not a number in (-1, 0.5)",
                  kRegenerate);
    }
    if (columns == 3) {
      double alpha = 0;
      if (!ParseDouble(fields[2], &alpha) || !(alpha >= 2 && alpha <= 30)) {
        reader.Fail("stiffening exponent " + Quote(fields[2]) + " is not a number in [2, 30]",
                    kRegenerate);
      }
      material->stiffening_exponent[row] = alpha;
    }
    material->youngs_modulus[row] = E;
    material->poisson_ratio[row] = nu;
    ++row;
  }
  if (row != tet_count) {
    throw InputError(path, "",
                     "has " + std::to_string(row) + " rows for the mesh's " +
                         std::to_string(tet_count) + " tets",
                     kRegenerate);
  }
}

double PositiveNumber(const Json& object, const std::string& key, const std::string& source) {
  const double value = GetNumber(object, key, source);
  if (!(value > 0) || !std::isfinite(value)) {
    throw InputError(source, "member \"" + key + "\"", "must be a positive number", kRegenerate);
  }
  return value;
}

}  // namespace

void SaveBodyDirectory(const std::string& dir, const BodyRecord& body, VtuEncoding view_encoding) {
  const Eigen::Index n = body.rest.vertices.rows(), tets = body.rest.tets.rows();
  CHECK_EQ(static_cast<Eigen::Index>(body.attached.size()), n);
  CHECK_EQ(body.material.youngs_modulus.size(), tets);
  CHECK_EQ(body.material.poisson_ratio.size(), tets);
  CHECK(body.vertex_depth.size() == 0 || body.vertex_depth.size() == n);
  std::error_code error;
  fs::create_directories(dir, error);
  if (error || !fs::is_directory(dir)) {
    throw InputError(
        dir, "",
        "cannot create the body directory" + (error ? ": " + error.message() : std::string()),
        "choose a writable --out directory");
  }

  WriteOptions msh;
  msh.msh_version = MshVersion::k41;
  WriteTetMesh(PathIn(dir, kBodyMeshFile), body.rest, msh);

  int attached_count = 0;
  WriteFileAtomically(PathIn(dir, kBodyAttachedFile), [&](std::ostream& out) {
    out << "# ergo body: attached (core) vertex ids of " << kBodyMeshFile
        << ", 0-based, increasing, one per line\n";
    for (Eigen::Index v = 0; v < n; ++v) {
      if (!body.attached[v]) continue;
      out << v << '\n';
      ++attached_count;
    }
  });

  WriteFileAtomically(PathIn(dir, kBodyMaterialFile), [&](std::ostream& out) {
    const bool stiffening = body.material.stiffening_exponent.size() != 0;
    out << "youngs_modulus_pa,poisson_ratio" << (stiffening ? ",stiffening_exponent" : "") << '\n';
    for (Eigen::Index t = 0; t < tets; ++t) {
      WriteDouble(out, body.material.youngs_modulus[t]);
      out << ',';
      WriteDouble(out, body.material.poisson_ratio[t]);
      if (stiffening) {
        out << ',';
        WriteDouble(out, body.material.stiffening_exponent[t]);
      }
      out << '\n';
    }
  });

  VtuFields fields;
  Eigen::VectorXd attached_field(n);
  for (Eigen::Index v = 0; v < n; ++v) attached_field[v] = body.attached[v] ? 1.0 : 0.0;
  fields.point_scalars.push_back({"attached", attached_field});
  if (body.vertex_depth.size() == n) fields.point_scalars.push_back({"depth_m", body.vertex_depth});
  fields.cell_scalars.push_back({"youngs_modulus_Pa", body.material.youngs_modulus});
  fields.cell_scalars.push_back({"poisson_ratio", body.material.poisson_ratio});
  if (body.material.stiffening_exponent.size() != 0)
    fields.cell_scalars.push_back({"stiffening_exponent", body.material.stiffening_exponent});
  WriteVtu(PathIn(dir, kBodyViewFile), body.rest, fields, view_encoding);

  Json json = Json::object();
  json["format"] = kFormatName;
  json["format_version"] = kBodyFormatVersion;
  Json& files = json["files"];
  files["mesh"] = kBodyMeshFile;
  files["attached"] = kBodyAttachedFile;
  files["material"] = kBodyMaterialFile;
  files["view"] = kBodyViewFile;
  Json& mesh = json["mesh"];
  mesh["unit"] = "m";
  mesh["vertices"] = static_cast<long long>(n);
  mesh["tets"] = static_cast<long long>(tets);
  mesh["attached_vertices"] = attached_count;
  Json& material = json["material"];
  material["tissue_density_kg_m3"] = body.tissue_density;
  material["core_mass_kg"] = body.core_mass >= 0 ? Json(body.core_mass) : Json();
  material["core_density_kg_m3"] = body.core_density;
  material["compression_resistance"] = body.material.compression_resistance;
  material["inversion_threshold"] = body.material.inversion_threshold;
  material["youngs_modulus_min_pa"] = body.material.youngs_modulus.minCoeff();
  material["youngs_modulus_max_pa"] = body.material.youngs_modulus.maxCoeff();
  material["poisson_ratio"] = IsUniform(body.material.poisson_ratio)
                                  ? Json(body.material.poisson_ratio[0])
                                  : Json("per tet");
  json["summary"] = body.summary;
  json["source"] = body.source;
  WriteJsonFile(PathIn(dir, kBodyJsonFile), json);
}

BodyRecord ReadBodyDirectory(const std::string& dir) {
  const std::string json_path = PathIn(dir, kBodyJsonFile);
  std::error_code error;
  if (!fs::is_directory(dir, error)) {
    throw InputError(dir, "", "is not a directory",
                     "pass the --out directory of `ergo_body build`");
  }
  if (!fs::exists(json_path, error)) {
    throw InputError(json_path, "", "missing: this is not a body directory (or it is incomplete)",
                     kRegenerate);
  }
  const Json json = ReadJsonFile(json_path);
  if (GetString(json, "format", json_path) != kFormatName) {
    throw InputError(json_path, "member \"format\"", "is not \"ergo-body\"",
                     "pass a body directory written by `ergo_body build`");
  }
  const long long version = GetInteger(json, "format_version", json_path, 1, 1 << 30);
  if (version > kBodyFormatVersion) {
    throw InputError(json_path, "member \"format_version\"",
                     "version " + std::to_string(version) + " is newer than this ergo reads (" +
                         std::to_string(kBodyFormatVersion) + ")",
                     "update ergo or rebuild the body with this version");
  }
  const Json& files = GetMember(json, "files", json_path);
  const Json& mesh_info = GetMember(json, "mesh", json_path);
  const Json& material = GetMember(json, "material", json_path);
  if (GetString(mesh_info, "unit", json_path) != "m") {
    throw InputError(json_path, "member \"unit\"", "must be \"m\"", kRegenerate);
  }

  BodyRecord body;
  const std::string mesh_path = PathIn(dir, FileName(files, "mesh", json_path));
  body.rest = ReadTetMesh(mesh_path);
  const long long vertices = GetInteger(mesh_info, "vertices", json_path, 0, 1LL << 31);
  const long long tets = GetInteger(mesh_info, "tets", json_path, 0, 1LL << 31);
  if (body.rest.vertices.rows() != vertices || body.rest.tets.rows() != tets) {
    throw InputError(mesh_path, "",
                     "has " + std::to_string(body.rest.vertices.rows()) + " vertices and " +
                         std::to_string(body.rest.tets.rows()) + " tets, but " + kBodyJsonFile +
                         " says " + std::to_string(vertices) + " and " + std::to_string(tets),
                     kRegenerate);
  }
  const std::string attached_path = PathIn(dir, FileName(files, "attached", json_path));
  body.attached = ReadAttached(attached_path, body.rest.vertices.rows());
  const long long attached = GetInteger(mesh_info, "attached_vertices", json_path, 0, 1LL << 31);
  const auto attached_read = std::count(body.attached.begin(), body.attached.end(), true);
  if (attached_read != attached) {
    throw InputError(attached_path, "",
                     "lists " + std::to_string(attached_read) + " vertices, but " + kBodyJsonFile +
                         " says " + std::to_string(attached),
                     kRegenerate);
  }
  ReadMaterial(PathIn(dir, FileName(files, "material", json_path)), body.rest.tets.rows(),
               &body.material);

  body.tissue_density = PositiveNumber(material, "tissue_density_kg_m3", json_path);
  body.core_density = PositiveNumber(material, "core_density_kg_m3", json_path);
  const Json& core_mass = GetMember(material, "core_mass_kg", json_path);
  if (core_mass.is_null()) {
    body.core_mass = -1;
  } else {
    body.core_mass = GetNumber(material, "core_mass_kg", json_path);
    if (!(body.core_mass >= 0) || !std::isfinite(body.core_mass)) {
      throw InputError(json_path, "member \"core_mass_kg\"", "must be >= 0 or null (automatic)",
                       kRegenerate);
    }
  }
  body.material.compression_resistance = GetNumber(material, "compression_resistance", json_path);
  body.material.inversion_threshold = GetNumber(material, "inversion_threshold", json_path);
  if (const Json* summary = FindMember(json, "summary")) body.summary = *summary;
  if (const Json* source = FindMember(json, "source")) body.source = *source;
  return body;
}

LayeredBody LoadLayeredBody(const std::string& dir, const LayeredBodyOptions& scenario,
                            const BodyOverrides& overrides) {
  BodyRecord body = ReadBodyDirectory(dir);
  LayeredBodyOptions options = scenario;
  options.tissue_density = overrides.tissue_density.value_or(body.tissue_density);
  options.core_mass = overrides.core_mass.value_or(body.core_mass);
  options.core_density = overrides.core_density.value_or(body.core_density);
  return LayeredBody::Create(std::move(body.rest), std::move(body.attached),
                             std::move(body.material), options, dir);
}

}  // namespace ergo
