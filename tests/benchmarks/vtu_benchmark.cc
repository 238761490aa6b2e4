// The VTU writer's two encodings on a body of the paper presets' size: the Kuhn tet grid of a
// 0.2 m box with 22 x 22 x 22 = 10,648 vertices and 55,566 tets, carrying the fields
// ergo_simulate writes for the deformed body (pressure, smoothed pressure, attached,
// displacement, contact force per vertex; Young's modulus per tet) with full-precision
// values. Reports the write time (atomic write included) and the file size (counter
// "bytes"). Run: vtu_benchmark
#include <filesystem>
#include <random>
#include <string>

#include <benchmark/benchmark.h>

#include "ergo/mesh/primitives.h"
#include "ergo/mesh/vtu_writer.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

const std::string& ScratchDir() {
  static const std::string dir = testing::MakeScratchDir("vtu_benchmark");
  return dir;
}

struct Body {
  TetMesh mesh;
  VtuFields fields;
};

const Body& TenThousandVertexBody() {
  static const Body body = [] {
    Body b;
    b.mesh = MakeTetGrid({-0.1, -0.1, -0.1}, {0.1, 0.1, 0.1}, {21, 21, 21});
    const Eigen::Index n = b.mesh.vertices.rows(), tets = b.mesh.tets.rows();
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0, 1);
    auto values = [&](Eigen::Index rows, int cols, double scale) {
      Eigen::MatrixXd m(rows, cols);
      for (Eigen::Index i = 0; i < m.size(); ++i) m.data()[i] = scale * unit(random);
      return m;
    };
    Eigen::VectorXd attached(n);
    for (Eigen::Index v = 0; v < n; ++v) attached[v] = unit(random) < 0.3 ? 1.0 : 0.0;
    b.fields.point_scalars = {{"pressure_Pa", values(n, 1, 2e4)},
                              {"smoothed_pressure_Pa", values(n, 1, 2e4)},
                              {"attached", attached}};
    b.fields.point_vectors = {{"displacement_m", values(n, 3, 1e-2)},
                              {"contact_force_N", values(n, 3, 0.1)}};
    b.fields.cell_scalars = {{"youngs_modulus_Pa", values(tets, 1, 1e4)}};
    return b;
  }();
  return body;
}

void BM_WriteBodyVtu(benchmark::State& state, VtuEncoding encoding) {
  const Body& body = TenThousandVertexBody();
  const std::string path = ScratchDir() + "/body_" + VtuEncodingName(encoding) + ".vtu";
  for (auto _ : state) WriteVtu(path, body.mesh, body.fields, encoding);
  state.counters["bytes"] = static_cast<double>(std::filesystem::file_size(path));
  state.counters["vertices"] = static_cast<double>(body.mesh.vertices.rows());
  state.SetLabel(VtuEncodingName(encoding));
}

BENCHMARK_CAPTURE(BM_WriteBodyVtu, ascii, VtuEncoding::kAscii)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_WriteBodyVtu, binary, VtuEncoding::kBinary)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace ergo

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  std::filesystem::remove_all(ergo::ScratchDir());
  return 0;
}
