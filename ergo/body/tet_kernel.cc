#include "ergo/body/tet_kernel.h"

#include <glog/logging.h>

namespace ergo {

TetKernel::TetKernel(const TetMesh& mesh, const TissueMaterial& tissue) {
  rest_.reserve(static_cast<size_t>(mesh.tets.rows()));
  materials_.reserve(static_cast<size_t>(mesh.tets.rows()));
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    TetPositions x;
    for (int k = 0; k < 4; ++k) x.col(k) = mesh.vertices.row(mesh.tets(t, k)).transpose();
    const auto rest = ComputeTetRestData(x);
    CHECK(rest) << "tet " << t << " has non-positive rest volume (ValidateTetMaterial refuses it)";
    rest_.push_back(*rest);
    NeoHookeanParameters parameters;
    parameters.youngs_modulus = tissue.youngs_modulus[t];
    parameters.poisson_ratio = tissue.poisson_ratio[t];
    parameters.compression_resistance = tissue.compression_resistance;
    parameters.inversion_threshold = tissue.inversion_threshold;
    parameters.stiffening_exponent = StiffeningExponentOf(tissue, t);
    materials_.emplace_back(parameters);
  }
}

}  // namespace ergo
