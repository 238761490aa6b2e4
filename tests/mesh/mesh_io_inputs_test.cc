// Inputs that once misbehaved (issue 19): a FIFO or a device given as a mesh is refused up
// front instead of blocking or reading forever; polygon lines longer than 1 MiB are read,
// while fixed-size records keep their bound; coordinates of 1e300 get their true size.

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "ergo/mesh/input_error.h"
#include "ergo/mesh/mesh_check.h"
#include "ergo/mesh/mesh_io.h"
#include "ergo/mesh/primitives.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

std::string Scratch(const std::string& name) {
  static const std::string dir = testing::MakeScratchDir("mesh_inputs");
  return dir + "/" + name;
}

// The InputError message of `read`, or "" when it does not throw.
std::string ErrorOf(const std::function<void()>& read) {
  try {
    read();
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(Mesh, ReadersRefuseAFifoUpFrontInsteadOfWaitingForAWriter) {
  const std::string fifo = Scratch("pipe.obj");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // Should a reader open the FIFO (and block), this writer hands it a valid mesh, so the
  // test fails on the verdict instead of hanging.
  std::atomic<bool> done{false};
  std::thread writer([&] {
    while (!done) {
      const int descriptor = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK);
      if (descriptor >= 0) {
        const std::string mesh = "v 0 0 0\nv 0.1 0 0\nv 0 0.1 0\nf 1 2 3\n";
        EXPECT_EQ(::write(descriptor, mesh.data(), mesh.size()), static_cast<ssize_t>(mesh.size()));
        ::close(descriptor);
        return;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  });
  const MeshCheckReport report = CheckMeshFile(fifo);
  done = true;
  writer.join();
  EXPECT_EQ(report.ExitCode(), 2) << report.FullReport();
  const std::string text = report.FullReport();
  EXPECT_NE(text.find(fifo + ": unusable: this is a named pipe (FIFO), not a regular file"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("cat " + fifo + " > mesh.stl"), std::string::npos) << text;
}

TEST(Mesh, ReadersRefuseDevicesAndDirectoriesNamingWhatTheyAre) {
  // /dev/null reads as an empty file (and /dev/zero would never end): no mesh file, also
  // under a mesh file's name.
  for (const char* device : {"/dev/null"}) {
    const std::string link = Scratch(std::string(device + 5) + ".stl");
    ASSERT_EQ(::symlink(device, link.c_str()), 0);
    const std::string message = ErrorOf([&] { ReadTriMesh(link); });
    EXPECT_NE(message.find(link + ": this is a character device, not a regular file"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("pass a regular mesh file"), std::string::npos) << message;
  }
  const std::string folder = Scratch("folder.stl");
  ASSERT_EQ(::mkdir(folder.c_str(), 0700), 0);
  EXPECT_NE(ErrorOf([&] { ReadTriMesh(folder); }).find("this is a directory"), std::string::npos);
  // A symbolic link to a regular file is a regular file.
  WriteTriMesh(Scratch("target.off"), MakeIcosphere(0.1, 0));
  ASSERT_EQ(::symlink(Scratch("target.off").c_str(), Scratch("link.off").c_str()), 0);
  EXPECT_EQ(ReadTriMesh(Scratch("link.off")).triangles.rows(), 20);
}

// A convex polygon of `corners` vertices on a circle (0.1 m radius), its face on one line.
std::string PolygonVertices(int corners, const std::string& prefix) {
  std::string text;
  for (int i = 0; i < corners; ++i) {
    const double angle = 2 * std::acos(-1.0) * i / corners;
    text += prefix + std::to_string(0.1 * std::cos(angle)) + " " +
            std::to_string(0.1 * std::sin(angle)) + " 0\n";
  }
  return text;
}

constexpr int kLongPolygon = 200000;  // its index list is about 1.3 MB on one line

TEST(Mesh, PolygonLinesLongerThanAMebibyteAreRead) {
  std::string obj = PolygonVertices(kLongPolygon, "v ");
  std::string face = "f";
  for (int i = 1; i <= kLongPolygon; ++i) face += " " + std::to_string(i);
  ASSERT_GT(face.size(), size_t{1} << 20);
  std::ofstream(Scratch("long.obj")) << obj << face << "\n";
  EXPECT_EQ(ReadTriMesh(Scratch("long.obj")).triangles.rows(), kLongPolygon - 2);

  std::string off = "OFF\n" + std::to_string(kLongPolygon) + " 1 0\n" +
                    PolygonVertices(kLongPolygon, "") + std::to_string(kLongPolygon);
  for (int i = 0; i < kLongPolygon; ++i) off += " " + std::to_string(i);
  std::ofstream(Scratch("long.off")) << off << "\n";
  EXPECT_EQ(ReadTriMesh(Scratch("long.off")).triangles.rows(), kLongPolygon - 2);

  std::string ply = "ply\nformat ascii 1.0\nelement vertex " + std::to_string(kLongPolygon) +
                    "\nproperty float x\nproperty float y\nproperty float z\nelement face 1\n"
                    "property list int int vertex_indices\nend_header\n" +
                    PolygonVertices(kLongPolygon, "") + std::to_string(kLongPolygon);
  for (int i = 0; i < kLongPolygon; ++i) ply += " " + std::to_string(i);
  std::ofstream(Scratch("long.ply")) << ply << "\n";
  EXPECT_EQ(ReadTriMesh(Scratch("long.ply")).triangles.rows(), kLongPolygon - 2);
}

TEST(Mesh, FixedSizeRecordsLongerThanAMebibyteAreStillRefused) {
  const std::string padding(2 << 20, '1');
  std::ofstream(Scratch("long_node.node")) << "1 3 0 0\n1 0 0 " << padding << "\n";
  std::ofstream(Scratch("long_node.ele")) << "0 4 0\n";
  const std::string node = ErrorOf([] { ReadTetMesh(Scratch("long_node.node")); });
  EXPECT_NE(node.find("long_node.node:line 2: line is longer than 1 MiB"), std::string::npos)
      << node.substr(0, 300);
  std::ofstream(Scratch("long_header.ply")) << "ply\ncomment " << padding << "\n";
  const std::string ply = ErrorOf([] { ReadTriMesh(Scratch("long_header.ply")); });
  EXPECT_NE(ply.find("long_header.ply:line 2"), std::string::npos) << ply.substr(0, 300);
  // A face whose declared corner count exceeds what the file holds is still refused early.
  std::ofstream(Scratch("count_lie.off")) << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n9 0 1 2\n";
  const std::string off = ErrorOf([] { ReadTriMesh(Scratch("count_lie.off")); });
  EXPECT_NE(off.find("9 vertices in face 0"), std::string::npos) << off;
}

TEST(Mesh, CheckReportsTheTrueSizeOfAMeshWithCoordinatesOf1e300) {
  TriMesh surface = MakeIcosphere(1.0, 1);
  surface.vertices *= 1e300;
  const MeshCheckReport report = CheckTriMesh(surface, "huge", {});
  const std::string text = report.FullReport();
  EXPECT_NEAR(report.bounding_box_diagonal / 1e300, 2 * std::sqrt(3.0), 0.5) << text;
  EXPECT_EQ(text.find("inf"), std::string::npos) << text;
  ASSERT_NE(report.Find("size-too-large"), nullptr) << text;
  EXPECT_NE(report.Find("size-too-large")->what.find("e+300 m across"), std::string::npos) << text;
  // Areas and volumes at that scale do not overflow into false findings either.
  EXPECT_EQ(report.Find("degenerate-triangles"), nullptr) << text;
  EXPECT_EQ(report.Find("inward-orientation"), nullptr) << text;
  EXPECT_EQ(report.issues.size(), 1u) << text;

  TetMesh volume = MakeTetGrid({0, 0, 0}, {0.2, 0.1, 0.1}, {2, 1, 1});
  volume.vertices *= 1e301;
  const MeshCheckReport tets = CheckTetMesh(volume, "huge tets", {});
  EXPECT_EQ(tets.Find("zero-volume-tets"), nullptr) << tets.FullReport();
  EXPECT_EQ(tets.issues.size(), 1u) << tets.FullReport();

  // Beyond the largest double the size is said to be so, not "inf".
  surface.vertices = MakeIcosphere(1.0, 1).vertices * 1.7e308;
  const std::string beyond = CheckTriMesh(surface, "beyond", {}).FullReport();
  EXPECT_NE(beyond.find("more than 1.798e+308 m across"), std::string::npos) << beyond;
  EXPECT_NE(beyond.find("e+308 m across (bounding-box diagonal)"), std::string::npos) << beyond;
}

}  // namespace
}  // namespace ergo
