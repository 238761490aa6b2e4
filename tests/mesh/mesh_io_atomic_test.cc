// Atomic output: a writer that fails leaves neither a partial file nor its temporary file;
// a writer that succeeds replaces the old file in one step; an unwritable path is an
// InputError naming it.

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "ergo/mesh/atomic_file.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/mesh_io.h"
#include "ergo/mesh/primitives.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

namespace fs = std::filesystem;

int FilesIn(const std::string& dir) {
  int count = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++count;
  return count;
}

TEST(Mesh, AtomicWriteLeavesNothingWhenTheWriterFails) {
  const std::string dir = testing::MakeScratchDir("atomic");
  const std::string path = dir + "/out.txt";
  EXPECT_THROW(WriteFileAtomically(path,
                                   [](std::ostream& out) {
                                     out << "half of it";
                                     throw std::runtime_error("simulated failure");
                                   }),
               std::runtime_error);
  EXPECT_FALSE(fs::exists(path));
  EXPECT_EQ(FilesIn(dir), 0);
}

TEST(Mesh, AtomicWriteReplacesAnExistingFileCompletely) {
  const std::string dir = testing::MakeScratchDir("atomic");
  const std::string path = dir + "/sphere.off";
  std::ofstream(path) << "old content that is longer than nothing";
  WriteTriMesh(path, MakeIcosphere(0.1, 1));
  EXPECT_EQ(ReadTriMesh(path).triangles.rows(), 80);
  EXPECT_EQ(FilesIn(dir), 1);  // no temporary file left behind
}

TEST(Mesh, WritingIntoAMissingFolderIsAnInputErrorNamingThePath) {
  const std::string path = testing::MakeScratchDir("atomic") + "/missing/folder/mesh.obj";
  try {
    WriteTriMesh(path, MakeIcosphere(0.1, 0));
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.source(), path);
    EXPECT_NE(error.fix().find("directory"), std::string::npos);
  }
}

TEST(Mesh, WritersRefuseUnknownExtensions) {
  const std::string path = testing::MakeScratchDir("atomic") + "/mesh.3ds";
  EXPECT_THROW(WriteTriMesh(path, MakeIcosphere(0.1, 0)), InputError);
  EXPECT_THROW(WriteTetMesh(path, MakeTetGrid({0, 0, 0}, {1, 1, 1}, {1, 1, 1})), InputError);
}

}  // namespace
}  // namespace ergo
