// Per-tet elastic energy, gradient and Hessian of a deformable part's neo-Hookean material
// (the body's tissue, a soft support's foam), through ergo/material: the one place the body
// stage calls the material.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "ergo/body/tissue_material.h"
#include "ergo/material/neo_hookean.h"
#include "ergo/material/tet_element.h"

namespace ergo {

// The corner positions of `tet` (columns = corners).
inline TetPositions TetCorners(const Vertices& positions, const Eigen::RowVector4i& tet) {
  TetPositions x;
  for (int k = 0; k < 4; ++k) x.col(k) = positions.row(tet[k]).transpose();
  return x;
}

// Rest data and material of every tet, precomputed once per part.
class TetKernel {
 public:
  // `rest` and `material` must have been validated (ValidateTetMaterial).
  TetKernel(const TetMesh& rest, const TissueMaterial& material);

  // Energy of tet t at corner positions x (columns = corners), J.
  double Energy(Eigen::Index t, const TetPositions& x) const {
    return ElementEnergy(materials_[t], rest_[t], x);
  }
  // Energy, gradient (12, corner-major, N) and Hessian (12 x 12, N/m) of tet t.
  double EnergyGradientHessian(Eigen::Index t, const TetPositions& x, HessianKind kind,
                               Vector12d* gradient, Matrix12d* hessian) const {
    double energy;
    EvaluateElement(materials_[t], rest_[t], x, kind, &energy, gradient, hessian);
    return energy;
  }
  // Energy and gradient only.
  double EnergyGradient(Eigen::Index t, const TetPositions& x, Vector12d* gradient) const {
    double energy;
    EvaluateElement(materials_[t], rest_[t], x, HessianKind::kExact, &energy, gradient, nullptr);
    return energy;
  }
  const NeoHookean& material(Eigen::Index t) const { return materials_[t]; }
  const TetRestData& rest(Eigen::Index t) const { return rest_[t]; }

 private:
  std::vector<TetRestData> rest_;
  std::vector<NeoHookean> materials_;
};

}  // namespace ergo
