#include "ergo/body/tissue_material.h"

#include <cmath>

#include <Eigen/Geometry>

#include "ergo/mesh/input_error.h"

namespace ergo {
double TetVolume(const TetMesh& mesh, Eigen::Index t) {
  const Eigen::Vector3d p0 = mesh.vertices.row(mesh.tets(t, 0));
  const Eigen::Vector3d e1 = Eigen::Vector3d(mesh.vertices.row(mesh.tets(t, 1))) - p0;
  const Eigen::Vector3d e2 = Eigen::Vector3d(mesh.vertices.row(mesh.tets(t, 2))) - p0;
  const Eigen::Vector3d e3 = Eigen::Vector3d(mesh.vertices.row(mesh.tets(t, 3))) - p0;
  return e1.dot(e2.cross(e3)) / 6.0;
}

double StiffeningExponentOf(const TissueMaterial& material, Eigen::Index t) {
  return material.stiffening_exponent.size() == 0 ? 2.0 : material.stiffening_exponent[t];
}

TissueMaterial UniformMaterial(Eigen::Index tet_count, double youngs_modulus,
                               double poisson_ratio) {
  TissueMaterial material;
  material.youngs_modulus = Eigen::VectorXd::Constant(tet_count, youngs_modulus);
  material.poisson_ratio = Eigen::VectorXd::Constant(tet_count, poisson_ratio);
  return material;
}

void ValidateTetMaterial(const TetMesh& rest, const TissueMaterial& material,
                         const std::string& name, const std::string& stiffness_hint) {
  const Eigen::Index n = rest.vertices.rows(), tet_count = rest.tets.rows();
  if (n == 0 || tet_count == 0)
    throw InputError(name, "", "the tet mesh is empty", "give a non-empty tetrahedral mesh");
  if (material.youngs_modulus.size() != tet_count || material.poisson_ratio.size() != tet_count) {
    throw InputError(
        name, "",
        "material arrays do not have one value per tet (" + std::to_string(tet_count) + " tets)",
        "give Young's modulus and Poisson's ratio per tet");
  }
  if (material.stiffening_exponent.size() != 0 &&
      material.stiffening_exponent.size() != tet_count) {
    throw InputError(
        name, "",
        "the stiffening exponents are not one per tet (" + std::to_string(tet_count) + " tets)",
        "give one per tet, or none for neo-Hookean tissue");
  }
  for (Eigen::Index t = 0; t < tet_count; ++t) {
    for (int k = 0; k < 4; ++k) {
      if (rest.tets(t, k) < 0 || rest.tets(t, k) >= n) {
        throw InputError(name, "tet " + std::to_string(t), "vertex index out of range",
                         "repair the tet mesh");
      }
    }
    const double E = material.youngs_modulus[t], nu = material.poisson_ratio[t];
    if (!(E > 0) || !std::isfinite(E)) {
      throw InputError(name, "tet " + std::to_string(t),
                       "Young's modulus " + std::to_string(E) + " Pa is not positive",
                       "give a positive stiffness (" + stiffness_hint + ")");
    }
    if (!(nu > -1.0 && nu < 0.5)) {
      throw InputError(name, "tet " + std::to_string(t),
                       "Poisson's ratio " + std::to_string(nu) + " is outside (-1, 0.5)",
                       "use a value below 0.5, such as 0.45 for nearly incompressible tissue");
    }
    const double alpha = StiffeningExponentOf(material, t);
    if (!(alpha >= 2.0 && alpha <= 30.0)) {
      throw InputError(name, "tet " + std::to_string(t),
                       "stiffening exponent " + std::to_string(alpha) + " is outside [2, 30]",
                       "use 2 for neo-Hookean tissue, about 7 for the heel's fat pad");
    }
    if (!(TetVolume(rest, t) > 0)) {
      throw InputError(name, "tet " + std::to_string(t),
                       "rest volume is not positive (degenerate or inverted element)",
                       "re-mesh, or swap two vertices of inverted tets");
    }
  }
  if (!(material.inversion_threshold > 0 && material.inversion_threshold < 1) ||
      !(material.compression_resistance >= 0)) {
    throw InputError(name, "",
                     "inversion threshold must be in (0,1) and compression resistance >= 0",
                     "use the defaults 0.1 and 1");
  }
}

}  // namespace ergo
