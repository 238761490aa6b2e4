// ReducedSystem: the body's total potential (elastic + gravity + external wrench, Eq. 9),
// its gradient in the reduced coordinates y = (u^F, q) and its Hessian K̂ (Eq. 7), exact or
// with every element block projected to positive semi-definite (for Newton).
//
// The exact Hessian includes the term from rotating the attached vertices' lever arms:
// with p_a = c + exp([δθ]×) h_a, ∂²E/∂δθ² gains Σ_a ½(g_a h_aᵀ + h_a g_aᵀ) − (g_a·h_a) I,
// g_a = ∂E/∂p_a (DESIGN.md §3); without it the adjoint gradient is wrong whenever the core
// may rotate. The sparsity pattern (upper triangle, free DOFs first, core DOFs last) is
// fixed per body: contact against a rigid support only adds blocks within it; a soft
// support's blocks and the contact's cross blocks are TotalPotential's.
//
// Assembly is parallel over elements of one colour at a time (colours share no vertex),
// so the result is bitwise identical for any number of threads.
//
// Usage per Newton step:
//   ReducedSystem::Evaluation e;
//   system.Evaluate(state, positions, kind, /*with_hessian=*/true, &e);
//   ... add other vertex-space terms: e.energy, e.vertex_gradient, AddVertexHessian(...)
//   Eigen::VectorXd gradient = system.Finalize(state, positions, kind, &e);
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "ergo/body/body_state.h"
#include "ergo/body/layered_body.h"
#include "ergo/body/reduced_layout.h"
#include "ergo/body/tet_kernel.h"
#include "ergo/mesh/eigen_types.h"

namespace ergo {

class ReducedSystem {
 public:
  struct Evaluation {
    double energy = 0;                          // J, relative to the rest pose's gravity reference
    Vertices vertex_gradient;                   // ∂E/∂x per tet-mesh vertex, #V x 3
    Vector6d core_gradient = Vector6d::Zero();  // direct terms on q (core weight, wrench)
    Matrix6d core_block = Matrix6d::Zero();     // q-q Hessian block, all 6 DOFs
    SparseMatrix hessian;                       // reduced, upper triangle, fixed pattern
    bool with_hessian = false;
  };

  // Keeps a reference to `body`, which must outlive the system. `support_size`: a soft
  // support's DOF count, appended to y (its rows stay empty here: TotalPotential adds them).
  explicit ReducedSystem(const LayeredBody& body, Eigen::Index support_size = 0);

  const LayeredBody& body() const { return body_; }
  const ReducedLayout& layout() const { return layout_; }
  Eigen::Index size() const { return layout_.size(); }
  // The fixed pattern with zero values (upper triangle, compressed).
  const SparseMatrix& pattern() const { return pattern_; }
  int colour_count() const { return static_cast<int>(colours_.size()); }

  // Total potential of the body alone: elastic + gravity − F·c − τ·θ, J.
  double Energy(const BodyState& state, const Vertices& positions) const;

  // Starts an evaluation: body energy, vertex-space gradient, and (with_hessian) the
  // elastic reduced Hessian. Other stages then add their vertex-space terms.
  void Evaluate(const BodyState& state, const Vertices& positions, HessianKind kind,
                bool with_hessian, Evaluation* evaluation) const;

  // Adds a symmetric 3x3 Hessian block acting on one vertex (e.g. a contact spring):
  // into its diagonal block if free, into the core block (Bᵀ H B) if attached.
  void AddVertexHessian(const BodyState& state, const Vertices& positions, int vertex,
                        const Eigen::Matrix3d& block, Evaluation* evaluation) const;

  // Adds a symmetric Hessian block over up to four vertices (e.g. a contact spring whose
  // anchor slides on a skin triangle): block (3n x 3n) in the order of `vertices`. Free
  // pairs go into the pattern (they must share a tet, as a skin triangle's corners do),
  // attached vertices through B.
  void AddVertexBlockHessian(const BodyState& state, const Vertices& positions,
                             const std::vector<int>& vertices, const Eigen::MatrixXd& block,
                             Evaluation* evaluation) const;

  // Completes the evaluation from the total vertex gradient: returns the reduced gradient
  // and (with_hessian) adds the lever-arm term (projected PSD for kProjectedPsd) and
  // writes the core block into the sparse Hessian.
  Eigen::VectorXd Finalize(const BodyState& state, const Vertices& positions, HessianKind kind,
                           Evaluation* evaluation) const;

  // Adds α·M̂ (the reduced lumped mass: m_i I on free vertices, Bᵀ M_A B plus the core's
  // mass and inertia on q) to a finalized Hessian: the "K + αM" of paper §3.4.
  void AddScaledMass(double alpha, const BodyState& state, const Vertices& positions,
                     SparseMatrix* hessian) const;

  // The reduced gradient of a vertex-space gradient field (no direct core terms).
  Eigen::VectorXd ReduceVertexGradient(const BodyState& state, const Vertices& positions,
                                       const Vertices& vertex_gradient) const {
    return layout_.ReduceGradient(body_, state, positions, vertex_gradient);
  }

 private:
  // Where one element's entries go in the pattern's value array.
  struct ElementPlan {
    std::array<int, 4> free_dof;  // 3·free index, or -1 for attached corners
    // For local corner pairs (a <= b, both free): value index of the first row of the
    // block in each of its 3 columns; `transposed` when a's DOFs come after b's.
    std::array<std::array<int, 3>, 10> block;
    std::array<bool, 10> transposed;
    int core_slot = -1;  // index into the per-element core buffers, -1 if no attached corner
  };

  void BuildPattern();
  void Colour();
  void AddCoreBlockToHessian(const Matrix6d& block, SparseMatrix* hessian) const;
  void ZeroHessian(SparseMatrix* hessian) const;

  const LayeredBody& body_;
  ReducedLayout layout_;
  TetKernel kernel_;
  SparseMatrix pattern_;
  std::vector<ElementPlan> plans_;
  std::vector<std::vector<int>> colours_;            // tets per colour
  std::vector<std::array<int, 6>> free_core_index_;  // per free vertex: value index of (3f, q_j)
  std::array<std::array<int, 6>, 6> core_index_{};   // value index of (q_i, q_j), i <= j
  int core_slots_ = 0;
};

}  // namespace ergo
