// Round trips through every mesh format ergo writes: write, read back, compare. ASCII
// formats and binary PLY (float64) must give back exactly the same doubles; binary STL
// stores float32, so it must give back the floats. Millimetre files must scale by 1000.

#include <filesystem>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "ergo/mesh/input_error.h"
#include "ergo/mesh/mesh_io.h"
#include "ergo/mesh/primitives.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

// An icosphere whose coordinates are perturbed so they have no short decimal form.
TriMesh AwkwardSurface() {
  TriMesh mesh = MakeIcosphere(0.1, 2, Eigen::Vector3d(0.31, -0.07, 1.0 / 3.0));
  std::mt19937 random(7);
  std::uniform_real_distribution<double> noise(-1e-3, 1e-3);
  for (Eigen::Index i = 0; i < mesh.vertices.size(); ++i) mesh.vertices.data()[i] += noise(random);
  return mesh;
}

TetMesh AwkwardVolume() {
  TetMesh mesh = MakeTetGrid({0.1, 0.2, 0.3}, {0.4, 0.5, 0.7}, {3, 2, 2});
  std::mt19937 random(11);
  std::uniform_real_distribution<double> noise(-1e-3, 1e-3);
  for (Eigen::Index i = 0; i < mesh.vertices.size(); ++i) mesh.vertices.data()[i] += noise(random);
  return mesh;
}

std::string Scratch(const std::string& name) {
  static const std::string dir = testing::MakeScratchDir("mesh_round_trip");
  return dir + "/" + name;
}

void ExpectSameSurface(const TriMesh& written, const std::string& path,
                       const WriteOptions& options = {}) {
  WriteTriMesh(path, written, options);
  ReadOptions read;
  read.unit = options.unit;
  const TriMesh read_back = ReadTriMesh(path, read);
  ASSERT_EQ(read_back.vertices.rows(), written.vertices.rows()) << path;
  ASSERT_EQ(read_back.triangles.rows(), written.triangles.rows()) << path;
  EXPECT_TRUE(read_back.triangles == written.triangles) << path;
  if (options.unit == LengthUnit::kMetre) {
    EXPECT_TRUE(read_back.vertices == written.vertices) << path;
  } else {
    // x / 1e-3 * 1e-3 may differ from x in the last bit.
    EXPECT_LE((read_back.vertices - written.vertices).cwiseAbs().maxCoeff(), 1e-15) << path;
  }
}

void ExpectSameVolume(const TetMesh& written, const std::string& path,
                      const WriteOptions& options = {}) {
  WriteTetMesh(path, written, options);
  ReadOptions read;
  read.unit = options.unit;
  const TetMesh read_back = ReadTetMesh(path, read);
  ASSERT_EQ(read_back.vertices.rows(), written.vertices.rows()) << path;
  ASSERT_EQ(read_back.tets.rows(), written.tets.rows()) << path;
  EXPECT_TRUE(read_back.tets == written.tets) << path;
  if (options.unit == LengthUnit::kMetre) {
    EXPECT_TRUE(read_back.vertices == written.vertices) << path;
  } else {
    EXPECT_LE((read_back.vertices - written.vertices).cwiseAbs().maxCoeff(), 1e-15) << path;
  }
}

// STL keeps no vertex list: compare each triangle's corner positions.
void ExpectSameStlCorners(const TriMesh& written, const TriMesh& read_back, bool as_float) {
  ASSERT_EQ(read_back.triangles.rows(), written.triangles.rows());
  EXPECT_EQ(read_back.vertices.rows(), written.vertices.rows());  // welded back
  for (Eigen::Index f = 0; f < written.triangles.rows(); ++f) {
    for (int c = 0; c < 3; ++c) {
      for (int k = 0; k < 3; ++k) {
        double expected = written.vertices(written.triangles(f, c), k);
        if (as_float) expected = static_cast<float>(expected);
        ASSERT_EQ(read_back.vertices(read_back.triangles(f, c), k), expected)
            << "triangle " << f << " corner " << c;
      }
    }
  }
}

TEST(Mesh, ObjRoundTripPreservesVerticesAndFaces) {
  ExpectSameSurface(AwkwardSurface(), Scratch("surface.obj"));
}

TEST(Mesh, OffRoundTripPreservesVerticesAndFaces) {
  ExpectSameSurface(AwkwardSurface(), Scratch("surface.off"));
}

TEST(Mesh, PlyAsciiRoundTripPreservesVerticesAndFaces) {
  ExpectSameSurface(AwkwardSurface(), Scratch("surface_ascii.ply"));
}

TEST(Mesh, PlyBinaryRoundTripPreservesVerticesAndFaces) {
  WriteOptions options;
  options.encoding = Encoding::kBinary;
  ExpectSameSurface(AwkwardSurface(), Scratch("surface_binary.ply"), options);
}

TEST(Mesh, MshRoundTripPreservesTriangles) {
  ExpectSameSurface(AwkwardSurface(), Scratch("surface41.msh"));
  WriteOptions options;
  options.msh_version = MshVersion::k22;
  ExpectSameSurface(AwkwardSurface(), Scratch("surface22.msh"), options);
}

TEST(Mesh, StlAsciiRoundTripPreservesCornersExactly) {
  const TriMesh mesh = AwkwardSurface();
  WriteTriMesh(Scratch("surface_ascii.stl"), mesh);
  ExpectSameStlCorners(mesh, ReadTriMesh(Scratch("surface_ascii.stl")), false);
}

TEST(Mesh, StlBinaryRoundTripPreservesCornersAsFloats) {
  const TriMesh mesh = AwkwardSurface();
  WriteOptions options;
  options.encoding = Encoding::kBinary;
  WriteTriMesh(Scratch("surface_binary.stl"), mesh, options);
  EXPECT_EQ(std::filesystem::file_size(Scratch("surface_binary.stl")),
            84u + 50u * static_cast<uintmax_t>(mesh.triangles.rows()));
  ExpectSameStlCorners(mesh, ReadTriMesh(Scratch("surface_binary.stl")), true);
}

TEST(Mesh, TetMshRoundTripPreservesVerticesAndTets) {
  ExpectSameVolume(AwkwardVolume(), Scratch("volume41.msh"));
  WriteOptions options;
  options.msh_version = MshVersion::k22;
  ExpectSameVolume(AwkwardVolume(), Scratch("volume22.msh"), options);
}

TEST(Mesh, TetGenRoundTripPreservesVerticesAndTets) {
  ExpectSameVolume(AwkwardVolume(), Scratch("volume.node"));
  // Either file of the pair names the mesh.
  const TetMesh via_ele = ReadTetMesh(Scratch("volume.ele"));
  EXPECT_TRUE(via_ele.vertices == AwkwardVolume().vertices);
}

TEST(Mesh, MillimetreRoundTripScalesByAThousand) {
  const TriMesh mesh = AwkwardSurface();
  WriteOptions options;
  options.unit = LengthUnit::kMillimetre;
  for (const char* name : {"mm.obj", "mm.off", "mm.ply", "mm.msh"}) {
    ExpectSameSurface(mesh, Scratch(name), options);
    // Read as metres, the file's numbers are a thousand times the metres.
    const TriMesh as_metres = ReadTriMesh(Scratch(name));
    EXPECT_NEAR(as_metres.vertices(5, 1), 1000 * mesh.vertices(5, 1), 1e-12) << name;
  }
  ExpectSameVolume(AwkwardVolume(), Scratch("mm.node"), options);
  const TetMesh volume_as_metres = ReadTetMesh(Scratch("mm.ele"));
  EXPECT_NEAR(volume_as_metres.vertices(3, 2), 1000 * AwkwardVolume().vertices(3, 2), 1e-12);
}

TEST(Mesh, ReadAnyMeshTellsSurfacesFromVolumes) {
  WriteTriMesh(Scratch("any_surface.msh"), AwkwardSurface());
  WriteTetMesh(Scratch("any_volume.msh"), AwkwardVolume());
  EXPECT_FALSE(ReadAnyMesh(Scratch("any_surface.msh")).is_tet);
  EXPECT_TRUE(ReadAnyMesh(Scratch("any_volume.msh")).is_tet);
  EXPECT_THROW(ReadTetMesh(Scratch("any_surface.msh")), InputError);
}

}  // namespace
}  // namespace ergo
