// The body directory (ergo/body/body_directory.h): build → save → load gives the same body,
// and damaged directories are refused with messages naming the file.
#include "ergo/body/body_directory.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "ergo/body/layer_builder.h"
#include "ergo/mesh/input_error.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

namespace fs = std::filesystem;

// A small built body: a spherical shell at 2 cm edges, E varying over the tets.
BodyRecord SmallBody() {
  ImplicitLayer layer;
  layer.outer = [](const Eigen::Vector3d& p) { return p.norm() - 0.1; };
  layer.core = [](const Eigen::Vector3d& p) { return p.norm() - 0.06; };
  layer.bounds =
      Eigen::AlignedBox3d(Eigen::Vector3d::Constant(-0.12), Eigen::Vector3d::Constant(0.12));
  BuilderOptions options;
  options.edge_length = 0.02;
  const BuiltLayer built = BuildLayerFromImplicit(layer, options, "shell");
  BodyRecord body;
  body.rest = built.mesh;
  body.attached = built.attached;
  const Eigen::Index tets = built.mesh.tets.rows();
  body.material.youngs_modulus = Eigen::VectorXd::LinSpaced(tets, 5e3 + 1.0 / 3.0, 15e3);
  body.material.poisson_ratio = Eigen::VectorXd::Constant(tets, 0.45);
  body.material.poisson_ratio[0] = 0.3;
  body.material.compression_resistance = 0.5;
  body.material.inversion_threshold = 0.2;
  body.tissue_density = 1010.5;
  body.core_density = 1900;
  body.vertex_depth = built.vertex_depth;
  body.summary = LayerBuildReportJson(built.report);
  body.source["mode"] = "test";
  return body;
}

const BodyRecord& Body() {
  static const BodyRecord body = SmallBody();
  return body;
}

std::string SavedCopy() {
  const std::string dir = testing::MakeScratchDir("body") + "/out";
  SaveBodyDirectory(dir, Body());
  return dir;
}

void Overwrite(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::trunc) << text;
}

std::string Slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

TEST(Body, BodyDirectoryRoundTripGivesTheSameBody) {
  const std::string dir = SavedCopy();
  for (const char* file :
       {kBodyJsonFile, kBodyMeshFile, kBodyAttachedFile, kBodyMaterialFile, kBodyViewFile}) {
    EXPECT_TRUE(fs::exists(fs::path(dir) / file)) << file;
  }
  // No temporary files left behind.
  int files = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    ++files;
    EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << entry.path();
  }
  EXPECT_EQ(files, 5);

  const BodyRecord read = ReadBodyDirectory(dir);
  const BodyRecord& body = Body();
  EXPECT_EQ(read.rest.vertices, body.rest.vertices);  // bit-identical
  EXPECT_EQ(read.rest.tets, body.rest.tets);
  EXPECT_EQ(read.attached, body.attached);
  EXPECT_EQ(read.material.youngs_modulus, body.material.youngs_modulus);
  EXPECT_EQ(read.material.poisson_ratio, body.material.poisson_ratio);
  EXPECT_EQ(read.material.compression_resistance, 0.5);
  EXPECT_EQ(read.material.inversion_threshold, 0.2);
  EXPECT_EQ(read.tissue_density, 1010.5);
  EXPECT_EQ(read.core_mass, -1);
  EXPECT_EQ(read.core_density, 1900);
  EXPECT_EQ(read.summary, body.summary);
  EXPECT_EQ(read.source, body.source);

  // The LayeredBody from the directory equals the one from the record.
  LayeredBodyOptions scenario;
  scenario.gravity = Eigen::Vector3d(0, 0, -9.81);
  const LayeredBody loaded = LoadLayeredBody(dir, scenario);
  LayeredBodyOptions options = scenario;
  options.tissue_density = body.tissue_density;
  options.core_density = body.core_density;
  const LayeredBody direct = LayeredBody::Create(body.rest, body.attached, body.material, options);
  EXPECT_EQ(loaded.vertex_mass(), direct.vertex_mass());
  EXPECT_EQ(loaded.core_mass(), direct.core_mass());
  EXPECT_EQ(loaded.core_volume(), direct.core_volume());
  EXPECT_EQ(loaded.core_centre(), direct.core_centre());
  EXPECT_EQ(loaded.core_inertia(), direct.core_inertia());
  EXPECT_EQ(loaded.layer_volume(), direct.layer_volume());
  EXPECT_EQ(loaded.skin().vertices, direct.skin().vertices);
  EXPECT_EQ(loaded.skin().rest_areas, direct.skin().rest_areas);
  EXPECT_EQ(loaded.gravity(), scenario.gravity);
  EXPECT_GT(loaded.core_mass(), 0);

  // Overrides replace the stored values.
  BodyOverrides overrides;
  overrides.core_mass = 3.0;
  overrides.tissue_density = 1000;
  const LayeredBody heavier = LoadLayeredBody(dir, scenario, overrides);
  EXPECT_EQ(heavier.core_mass(), 3.0);
  EXPECT_NEAR(heavier.vertex_mass().sum(), 1000 * heavier.layer_volume(), 1e-12);
}

TEST(Body, BodyDirectoryKeepsAnExplicitCoreMass) {
  BodyRecord body = Body();
  body.core_mass = 2.5;
  const std::string dir = testing::MakeScratchDir("body_mass");
  SaveBodyDirectory(dir, body);
  EXPECT_EQ(ReadBodyDirectory(dir).core_mass, 2.5);
  EXPECT_EQ(LoadLayeredBody(dir).core_mass(), 2.5);
}

// The InputError's source file name for reading `dir`, or "no error".
std::string LoadError(const std::string& dir, std::string* location = nullptr) {
  try {
    ReadBodyDirectory(dir);
  } catch (const InputError& error) {
    if (location) *location = error.location();
    return fs::path(error.source()).filename().string();
  }
  return "no error";
}

TEST(Body, BodyDirectoryKeepsStiffeningExponentsAndOmitsThemForNeoHookeanTissue) {
  // Neo-Hookean bodies keep the two-column file older directories have; a stiffening one
  // writes a third column and reads it back bit for bit, with its material law.
  BodyRecord body = Body();
  const std::string plain = testing::MakeScratchDir("body_neo");
  SaveBodyDirectory(plain, body);
  EXPECT_EQ(Slurp(plain + "/tet_material.csv").rfind("youngs_modulus_pa,poisson_ratio\n", 0), 0u);
  EXPECT_EQ(ReadBodyDirectory(plain).material.stiffening_exponent.size(), 0);
  const Eigen::Index tets = body.rest.tets.rows();
  body.material.stiffening_exponent = Eigen::VectorXd::LinSpaced(tets, 2.0, 6.82 + 1.0 / 3.0);
  const std::string dir = testing::MakeScratchDir("body_alpha");
  SaveBodyDirectory(dir, body);
  EXPECT_EQ(Slurp(dir + "/tet_material.csv")
                .rfind("youngs_modulus_pa,poisson_ratio,stiffening_exponent\n", 0),
            0u);
  EXPECT_EQ(ReadBodyDirectory(dir).material.stiffening_exponent, body.material.stiffening_exponent);
  std::string location;
  Overwrite(dir + "/tet_material.csv",
            "youngs_modulus_pa,poisson_ratio,stiffening_exponent\n1e4,0.45,1.5\n");
  EXPECT_EQ(LoadError(dir, &location), "tet_material.csv");
  EXPECT_EQ(location, "line 2");
}

TEST(Body, DamagedBodyDirectoriesAreRefusedNamingTheFile) {
  std::string location;
  {
    const std::string dir = testing::MakeScratchDir("empty");
    EXPECT_EQ(LoadError(dir), "body.json");
    EXPECT_EQ(LoadError(dir + "/nonexistent"), "nonexistent");
  }
  {
    const std::string dir = SavedCopy();
    fs::remove(fs::path(dir) / kBodyAttachedFile);
    EXPECT_EQ(LoadError(dir), "attached.txt");
  }
  {
    const std::string dir = SavedCopy();
    Overwrite(dir + "/attached.txt", "# ids\n3\n2\n");
    EXPECT_EQ(LoadError(dir, &location), "attached.txt");
    EXPECT_EQ(location, "line 3");
    Overwrite(dir + "/attached.txt", "0\n999999\n");
    EXPECT_EQ(LoadError(dir, &location), "attached.txt");
    EXPECT_EQ(location, "line 2");
    Overwrite(dir + "/attached.txt", "0\n1\n");
    EXPECT_EQ(LoadError(dir), "attached.txt");  // count disagrees with body.json
  }
  {
    const std::string dir = SavedCopy();
    std::string csv = Slurp(dir + "/tet_material.csv");
    csv.replace(csv.find('\n') + 1, 0, "-5,0.45\n");
    Overwrite(dir + "/tet_material.csv", csv);
    EXPECT_EQ(LoadError(dir, &location), "tet_material.csv");
    EXPECT_EQ(location, "line 2");
    Overwrite(dir + "/tet_material.csv", "youngs_modulus_pa,poisson_ratio\n1e4,0.45\n");
    EXPECT_EQ(LoadError(dir, &location), "tet_material.csv");  // too few rows
  }
  {
    const std::string dir = SavedCopy();
    std::string json = Slurp(dir + "/body.json");
    Overwrite(dir + "/body.json", json.substr(0, json.size() / 2));
    EXPECT_EQ(LoadError(dir, &location), "body.json");
    EXPECT_EQ(location.rfind("line ", 0), 0u) << location;
    json.replace(json.find("\"format_version\": 1"), 19, "\"format_version\": 7");
    Overwrite(dir + "/body.json", json);
    EXPECT_EQ(LoadError(dir, &location), "body.json");
    EXPECT_EQ(location, "member \"format_version\"");
  }
  {
    const std::string dir = SavedCopy();
    Overwrite(dir + "/body.msh", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n");
    EXPECT_EQ(LoadError(dir), "body.msh");
  }
}

}  // namespace
}  // namespace ergo
