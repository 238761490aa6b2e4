// The mesh check and the support validation on the crafted files of issue 19, at full size:
//   - 300k copies of one triangle (OBJ, 2.4 MB) and 300k copies of one tet (TetGen pair);
//   - 60k parallel triangles whose bounding boxes all overlap (binary STL, 3 MB);
//   - a closed double cone of 60k sliver triangles (binary STL, checked with --closed, and
//     read + validated as a support, as ergo_simulate does);
//   - for scale, a well-shaped closed icosphere of 327,680 triangles.
// Each runs once (they are seconds long); the label is the verdict. Run: mesh_check_benchmark
#include <filesystem>
#include <string>

#include <benchmark/benchmark.h>

#include "ergo/contact/support_validation.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/mesh_check.h"
#include "ergo/mesh/mesh_io.h"
#include "ergo/mesh/primitives.h"
#include "tests/support/crafted_meshes.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

const std::string& ScratchDir() {
  static const std::string dir = testing::MakeScratchDir("mesh_check_benchmark");
  return dir;
}

std::string Scratch(const std::string& name) { return ScratchDir() + "/" + name; }

std::string WriteStl(const std::string& name, const TriMesh& mesh) {
  WriteOptions options;
  options.encoding = Encoding::kBinary;
  const std::string path = Scratch(name);
  WriteTriMesh(path, mesh, options);
  return path;
}

void TimeCheck(benchmark::State& state, const std::string& path, bool closed) {
  MeshCheckOptions options;
  options.require_closed = closed;
  std::string verdict;
  for (auto _ : state) {
    const MeshCheckReport report = CheckMeshFile(path, options);
    verdict = report.BriefReport();
  }
  state.SetLabel(verdict.substr(verdict.find(": ") + 2));
}

void BM_CheckDuplicateTriangles(benchmark::State& state) {
  const std::string path = Scratch("duplicate_triangles.obj");
  testing::WriteDuplicateTrianglesObj(path, static_cast<int>(state.range(0)));
  TimeCheck(state, path, false);
}

void BM_CheckDuplicateTets(benchmark::State& state) {
  const std::string stem = Scratch("duplicate_tets");
  testing::WriteDuplicateTetsTetGen(stem, static_cast<int>(state.range(0)));
  TimeCheck(state, stem + ".ele", false);
}

void BM_CheckParallelTriangles(benchmark::State& state) {
  const std::string path = WriteStl(
      "parallel_triangles.stl", testing::ParallelTriangleStack(static_cast<int>(state.range(0))));
  TimeCheck(state, path, false);
}

void BM_CheckClosedSliverCone(benchmark::State& state) {
  const std::string path =
      WriteStl("sliver_cone.stl", testing::SliverDoubleCone(static_cast<int>(state.range(0)) / 2));
  TimeCheck(state, path, true);
}

// For scale: a well-shaped closed surface, whose test finishes well inside its budget.
void BM_CheckClosedIcosphere(benchmark::State& state) {
  const std::string path =
      WriteStl("icosphere.stl", MakeIcosphere(0.1, static_cast<int>(state.range(0))));
  TimeCheck(state, path, true);
}

void BM_ValidateSliverConeAsSupport(benchmark::State& state) {
  const std::string path = WriteStl(
      "sliver_cone_support.stl", testing::SliverDoubleCone(static_cast<int>(state.range(0)) / 2));
  std::string verdict;
  for (auto _ : state) {
    try {
      ValidateSupportMesh(ReadTriMesh(path), path);
      verdict = "accepted";
    } catch (const InputError& error) {
      verdict = "refused: " + error.problem();
    }
  }
  state.SetLabel(verdict);
}

BENCHMARK(BM_CheckDuplicateTriangles)->Arg(300000)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_CheckDuplicateTets)->Arg(300000)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_CheckParallelTriangles)->Arg(60000)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_CheckClosedSliverCone)->Arg(60000)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_CheckClosedIcosphere)->Arg(7)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_ValidateSliverConeAsSupport)->Arg(60000)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace
}  // namespace ergo

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  std::filesystem::remove_all(ergo::ScratchDir());  // the crafted files, tens of MB
  return 0;
}
