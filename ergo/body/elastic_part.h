// ElasticPart: a deformable tet-mesh part without a rigid core — a soft support (a foam
// cushion, an insole; paper §4.3) whose held vertices (its base) stay where they are put.
// The same neo-Hookean material as the body's tissue, lumped masses and optional gravity.
// Its degrees of freedom are the free vertices' positions; held vertices keep whatever
// positions the caller passes (their rest positions for a support's base).
//
// Besides energy, forces and the stiffness matrix, it gives the rest-shape term of a design
// gradient (paper Eq. 22–23): zᵀ ∂G/∂X for the part's equilibrium residual G = ∂E/∂x and an
// adjoint field z, when the design moves the rest positions X.
//
// Units: m, kg, Pa, N, J.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "ergo/body/tet_kernel.h"
#include "ergo/body/tissue_material.h"
#include "ergo/mesh/eigen_types.h"
#include "ergo/mesh/tet_boundary.h"
#include "ergo/mesh/tri_mesh.h"

namespace ergo {

struct ElasticPartOptions {
  double density = 0;  // kg/m³ (polyurethane foam: 30–80); 0: massless
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();  // m/s²; zero: no weight
};

class ElasticPart {
 public:
  struct Evaluation {
    double energy = 0;  // elastic + gravity, J
    // ∂E/∂x per vertex, N; at a held vertex, the force its holder must exert (the reaction).
    Vertices vertex_gradient;
    SparseMatrix hessian;  // over free DOFs 3i..3i+2, upper triangle, fixed pattern, N/m
    bool with_hessian = false;
  };

  // Validates and derives everything. Throws InputError (source = `name`) for an unusable
  // mesh or material, flags of the wrong size, or a connected component not held by at
  // least three non-collinear vertices (it could float away or turn about its held line).
  // One part may have several components: several soft supports in one scene (Join).
  static ElasticPart Create(TetMesh rest, std::vector<bool> held, TissueMaterial material,
                            const ElasticPartOptions& options, const std::string& name);

  // Several parts as one (their tet meshes side by side, vertex and tet indices offset in
  // order): the scene's soft supports, each keeping its own held base and material. They must
  // share density and gravity (one ElasticPartOptions) and the material's volume-term
  // constants. Throws InputError naming the part that differs.
  static ElasticPart Join(const std::vector<const ElasticPart*>& parts, const std::string& name);

  // The same part on other rest positions (a designed rest shape): topology, held set,
  // material and stiffness pattern kept; rest data, masses and the boundary's positions
  // recomputed. Throws InputError naming the first tet the move inverts or flattens.
  ElasticPart WithRestPositions(const Vertices& rest) const;

  const TetMesh& rest() const { return rest_; }
  const std::vector<bool>& held() const { return held_; }
  const TissueMaterial& material() const { return material_; }
  const ElasticPartOptions& options() const { return options_; }
  const Eigen::VectorXi& free_vertices() const { return free_vertices_; }
  // Vertex -> index among free vertices (its DOFs are 3i..3i+2), or -1 when held.
  const Eigen::VectorXi& free_index() const { return free_index_; }
  const Eigen::VectorXd& vertex_mass() const { return vertex_mass_; }
  // The outward boundary (where contact happens) with its maps to the tet vertices.
  const TetBoundary& boundary() const { return boundary_; }
  Eigen::Index size() const { return 3 * free_vertices_.size(); }
  const SparseMatrix& pattern() const { return pattern_; }

  // Positions with the free vertices displaced by `free_displacement` (3·#free) from `base`
  // (every vertex; held ones keep theirs).
  Vertices Positions(const Vertices& base, const Eigen::VectorXd& free_displacement) const;
  // The rows of a vertex field at the free vertices, as a 3·#free vector.
  Eigen::VectorXd FreeComponents(const Vertices& vertex_field) const;

  double Energy(const Vertices& positions) const;
  void Evaluate(const Vertices& positions, HessianKind kind, bool with_hessian,
                Evaluation* evaluation) const;

  // Per tet at `positions`: the von Mises equivalent of the Cauchy stress σ = P Fᵀ / det F,
  // Pa, and the volume change det F − 1 (for pictures of a support's stress and strain).
  Eigen::VectorXd VonMisesStress(const Vertices& positions) const;
  Eigen::VectorXd VolumeChange(const Vertices& positions) const;

  // The rest-shape derivative of the residual contracted with an adjoint field:
  // Σ_e (∂f_e/∂X_e)ᵀ z_e, plus the weight's change through the lumped masses. `z` is per
  // vertex (#V x 3; only free rows matter — held vertices have no residual). #V x 3, N.
  Vertices RestShapeAdjoint(const Vertices& positions, const Vertices& z) const;

 private:
  ElasticPart() = default;
  void BuildPattern();

  TetMesh rest_;
  std::vector<bool> held_;
  TissueMaterial material_;
  ElasticPartOptions options_;
  Eigen::VectorXi free_vertices_, free_index_;
  Eigen::VectorXd vertex_mass_;
  TetBoundary boundary_;
  std::shared_ptr<const TetKernel> kernel_;
  SparseMatrix pattern_;
  // Per tet and local corner pair (a, b) with both corners free and a's DOFs first: the value
  // index of the block's first row in each of its 3 columns; -1 otherwise.
  std::vector<std::array<std::array<int, 3>, 16>> plans_;
};

}  // namespace ergo
