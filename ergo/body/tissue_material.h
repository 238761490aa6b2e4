// Per-tet neo-Hookean parameters of a deformable part — the body's tissue or a soft
// support's foam — and the validation every part's tet mesh and material go through.
#pragma once

#include <string>

#include <Eigen/Core>

#include "ergo/mesh/tri_mesh.h"

namespace ergo {

// Per-tet neo-Hookean parameters (see ergo/material).
struct TissueMaterial {
  Eigen::VectorXd youngs_modulus;  // #T, Pa (tissue: 5–15 kPa; foam: 20–125 kPa)
  Eigen::VectorXd poisson_ratio;   // #T, in (−1, 0.5)
  // #T values of α in [2, 30] (NeoHookeanParameters::stiffening_exponent: 2 is neo-Hookean,
  // larger stiffens with stretch, as the plantar fat pads do), or empty: 2 everywhere.
  Eigen::VectorXd stiffening_exponent;
  double compression_resistance = 1.0;  // dimensionless c of the volume term (DESIGN §3)
  double inversion_threshold = 0.1;     // principal-stretch clamp ε
};

// Signed volume of tet t of `mesh` at its vertex positions, m³ (positive when oriented).
double TetVolume(const TetMesh& mesh, Eigen::Index t);

// α of tet t (2 when the material has none).
double StiffeningExponentOf(const TissueMaterial& material, Eigen::Index t);

// A material with the same E and ν on each of `tet_count` tets.
TissueMaterial UniformMaterial(Eigen::Index tet_count, double youngs_modulus, double poisson_ratio);

// Throws InputError (source = `name`, location = the tet) unless the mesh is non-empty, its
// indices are in range, every rest tet has positive volume and every material value is in
// range. `stiffness_hint` names a typical modulus for the fix ("tissue: 5e3–15e3 Pa").
void ValidateTetMaterial(const TetMesh& rest, const TissueMaterial& material,
                         const std::string& name, const std::string& stiffness_hint);

}  // namespace ergo
