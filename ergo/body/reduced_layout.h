// ReducedLayout: the numbering of the reduced coordinates y = (u^F, q, u^S) — q restricted
// to unlocked core DOFs, u^S a soft support's free displacements when there is one — and
// the maps between the body's vertex space and y: the B matrix of Eq. 1 (δp_a = B_a δq with
// B_a = [I  −[h_a]×], h_a = p_a − c) and its transpose.
//   y[3i .. 3i+2]                free body vertex i's displacement
//   y[core_offset() + j]         core component FreeComponents()[j] (tx,ty,tz,rx,ry,rz)
//   y[support_offset() + 3k ..]  the soft support's free vertex k's displacement
#pragma once

#include <vector>

#include <Eigen/Core>

#include "ergo/body/body_state.h"
#include "ergo/body/layered_body.h"

namespace ergo {

class ReducedLayout {
 public:
  // Captures the body's lock at construction. `support_size`: 3·#free vertices of a soft
  // support (0: rigid support).
  explicit ReducedLayout(const LayeredBody& body, Eigen::Index support_size = 0);

  Eigen::Index size() const { return support_offset() + support_size_; }
  // The body's part of y: u^F and q.
  Eigen::Index body_size() const { return support_offset(); }
  Eigen::Index support_offset() const {
    return core_offset_ + static_cast<Eigen::Index>(core_components_.size());
  }
  Eigen::Index support_size() const { return support_size_; }
  Eigen::Index core_offset() const { return core_offset_; }
  int core_count() const { return static_cast<int>(core_components_.size()); }
  const std::vector<int>& core_components() const { return core_components_; }

  // B_a restricted to the unlocked core components: 3 x core_count(), for lever arm h.
  Eigen::MatrixXd CoreJacobian(const Eigen::Vector3d& lever_arm) const;

  // y-gradient from a body vertex-space gradient (#V x 3): [g_F ; Σ_a B_aᵀ g_a ; 0].
  Eigen::VectorXd ReduceGradient(const LayeredBody& body, const BodyState& state,
                                 const Vertices& positions, const Vertices& vertex_gradient) const;

  // The state moved by a reduced step δy: u ← u + δu, c ← c + δc, R ← exp([δθ]×) R,
  // u^S ← u^S + δu^S.
  BodyState Retract(const BodyState& state, const Eigen::VectorXd& step) const;

  // The body's vertex-space displacement field of a reduced step (linearised), #V x 3.
  Vertices VertexVelocity(const LayeredBody& body, const BodyState& state,
                          const Vertices& positions, const Eigen::VectorXd& step) const;

 private:
  Eigen::Index core_offset_ = 0;
  std::vector<int> core_components_;
  Eigen::Index support_size_ = 0;
};

}  // namespace ergo
