// Speed of the per-tet neo-Hookean element (ergo/material/tet_element.h): energy +
// gradient + Hessian (PSD-projected for Newton, exact for the adjoint) per element, on
// well-shaped tets under moderate strain and on compressed/inverted tets, where the
// projection and the extension below the inversion threshold are active. Measures only.
#include <random>
#include <vector>

#include <benchmark/benchmark.h>
#include <Eigen/Geometry>

#include "ergo/material/rotation_variant_svd.h"
#include "ergo/material/tet_element.h"

namespace ergo {
namespace {

constexpr int kElements = 1024;  // cycled through, so inputs are not loop-invariant

struct Element {
  TetRestData rest;
  TetPositions x;
};

Eigen::Matrix3d RandomRotation(std::mt19937& rng) {
  std::normal_distribution<double> normal;
  return Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng))
      .normalized()
      .toRotationMatrix();
}

// Random 1 cm tets; deformed by F = R1 diag(sigma) R2^T with sigma in [0.7, 1.3]
// (well-shaped) or with one stretch in [-0.2, 0.3] and another in [0.3, 0.9] (compressed).
std::vector<Element> MakeElements(bool compressed) {
  std::mt19937 rng(compressed ? 2 : 1);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<Element> elements;
  while (static_cast<int>(elements.size()) < kElements) {
    TetPositions rest;
    rest << 1, -1, -1, 1, 1, -1, 1, -1, 1, 1, -1, -1;
    rest = 0.005 * RandomRotation(rng) * rest;
    for (int i = 0; i < 12; ++i) rest(i) += 0.001 * (unit(rng) - 0.5);
    const std::optional<TetRestData> data = ComputeTetRestData(rest);
    if (!data) continue;
    Eigen::Vector3d sigma(0.7 + 0.6 * unit(rng), 0.7 + 0.6 * unit(rng), 0.7 + 0.6 * unit(rng));
    if (compressed) {
      sigma(1) = 0.3 + 0.6 * unit(rng);
      sigma(2) = -0.2 + 0.5 * unit(rng);
    }
    const Eigen::Matrix3d f = RandomRotation(rng) * sigma.asDiagonal() * RandomRotation(rng);
    elements.push_back({*data, f * rest});
  }
  return elements;
}

// alpha: the stretch term's exponent (2 neo-Hookean; 6.82 the heel pad's stiffening law).
void BM_ElementEnergyGradientHessian(benchmark::State& state, bool compressed, HessianKind kind,
                                     double alpha = 2.0) {
  NeoHookeanParameters parameters;
  parameters.stiffening_exponent = alpha;
  const NeoHookean material(parameters);
  const std::vector<Element> elements = MakeElements(compressed);
  double energy;
  Vector12d gradient;
  Matrix12d hessian;
  int i = 0;
  for (auto _ : state) {
    const Element& e = elements[i++ & (kElements - 1)];
    EvaluateElement(material, e.rest, e.x, kind, &energy, &gradient, &hessian);
    benchmark::DoNotOptimize(energy);
    benchmark::DoNotOptimize(gradient.data());
    benchmark::DoNotOptimize(hessian.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_ElementEnergyGradient(benchmark::State& state, bool compressed) {
  const NeoHookean material(NeoHookeanParameters{});
  const std::vector<Element> elements = MakeElements(compressed);
  double energy;
  Vector12d gradient;
  int i = 0;
  for (auto _ : state) {
    const Element& e = elements[i++ & (kElements - 1)];
    EvaluateElement(material, e.rest, e.x, HessianKind::kExact, &energy, &gradient, nullptr);
    benchmark::DoNotOptimize(energy);
    benchmark::DoNotOptimize(gradient.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_SignedSvd(benchmark::State& state, bool compressed) {
  const std::vector<Element> elements = MakeElements(compressed);
  std::vector<Eigen::Matrix3d> fs;
  for (const Element& e : elements) fs.push_back(DeformationGradient(e.rest, e.x));
  int i = 0;
  for (auto _ : state) {
    SignedSvd3 svd = RotationVariantSvd(fs[i++ & (kElements - 1)]);
    benchmark::DoNotOptimize(svd);
  }
  state.SetItemsProcessed(state.iterations());
}

BENCHMARK_CAPTURE(BM_ElementEnergyGradientHessian, well_shaped_psd, false,
                  HessianKind::kProjectedPsd);
BENCHMARK_CAPTURE(BM_ElementEnergyGradientHessian, well_shaped_exact, false, HessianKind::kExact);
BENCHMARK_CAPTURE(BM_ElementEnergyGradientHessian, compressed_psd, true,
                  HessianKind::kProjectedPsd);
BENCHMARK_CAPTURE(BM_ElementEnergyGradientHessian, compressed_exact, true, HessianKind::kExact);
BENCHMARK_CAPTURE(BM_ElementEnergyGradientHessian, well_shaped_psd_stiffening, false,
                  HessianKind::kProjectedPsd, 6.82);
BENCHMARK_CAPTURE(BM_ElementEnergyGradientHessian, compressed_psd_stiffening, true,
                  HessianKind::kProjectedPsd, 6.82);
BENCHMARK_CAPTURE(BM_ElementEnergyGradient, well_shaped, false);
BENCHMARK_CAPTURE(BM_ElementEnergyGradient, compressed, true);
BENCHMARK_CAPTURE(BM_SignedSvd, well_shaped, false);
BENCHMARK_CAPTURE(BM_SignedSvd, compressed, true);

}  // namespace
}  // namespace ergo

BENCHMARK_MAIN();
