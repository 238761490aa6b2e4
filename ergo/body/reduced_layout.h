// ReducedLayout: the numbering of the reduced coordinates y = (u^F, q) restricted to
// unlocked core DOFs, and the maps between vertex space and y — the B matrix of Eq. 1
// (δp_a = B_a δq with B_a = [I  −[h_a]×], h_a = p_a − c) and its transpose.
//   y[3i .. 3i+2]            free vertex i's displacement
//   y[core_offset() + j]     core component FreeComponents()[j] (tx,ty,tz,rx,ry,rz)
#pragma once

#include <vector>

#include <Eigen/Core>

#include "ergo/body/body_state.h"
#include "ergo/body/layered_body.h"

namespace ergo {

class ReducedLayout {
 public:
  // Captures the body's lock at construction.
  explicit ReducedLayout(const LayeredBody& body);

  Eigen::Index size() const {
    return core_offset_ + static_cast<Eigen::Index>(core_components_.size());
  }
  Eigen::Index core_offset() const { return core_offset_; }
  int core_count() const { return static_cast<int>(core_components_.size()); }
  const std::vector<int>& core_components() const { return core_components_; }

  // B_a restricted to the unlocked core components: 3 x core_count(), for lever arm h.
  Eigen::MatrixXd CoreJacobian(const Eigen::Vector3d& lever_arm) const;

  // y-gradient from a vertex-space gradient (#V x 3): [g_F ; Σ_a B_aᵀ g_a].
  Eigen::VectorXd ReduceGradient(const LayeredBody& body, const BodyState& state,
                                 const Vertices& positions, const Vertices& vertex_gradient) const;

  // The state moved by a reduced step δy: u ← u + δu, c ← c + δc, R ← exp([δθ]×) R.
  BodyState Retract(const BodyState& state, const Eigen::VectorXd& step) const;

  // Vertex-space displacement field of a reduced step (linearised), #V x 3.
  Vertices VertexVelocity(const LayeredBody& body, const BodyState& state,
                          const Vertices& positions, const Eigen::VectorXd& step) const;

 private:
  Eigen::Index core_offset_ = 0;
  std::vector<int> core_components_;
};

}  // namespace ergo
