// BodyState: the reduced coordinates y = (u^F, q, u^S) of the equilibrium (paper §3.3) —
// displacements of the body's free tet vertices, the rigid core's pose q = (centre c,
// rotation R), and, when the body rests on a soft support (paper §4.3), the displacements of
// that support's free vertices. Attached vertices follow the core: p_a = c + R (X_a − C₀).
// Rotations are updated multiplicatively, R ← exp([δθ]×) R (DESIGN.md §3).
#pragma once

#include <Eigen/Core>

#include "ergo/body/layered_body.h"

namespace ergo {

struct BodyState {
  Eigen::VectorXd free_displacement;                       // 3·#free, metres, free-vertex order
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();        // c: world position of C₀
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // R
  // Σ δθ over all updates: the angle the external torque works through (Eq. 9's linear
  // term). Exact for a single free rotation axis; a path integral otherwise.
  Eigen::Vector3d torque_angle = Eigen::Vector3d::Zero();
  // u^S: 3·#free displacements of a soft support's free vertices from its rest positions, m,
  // in ElasticPart::free_vertices() order. Empty: the support at rest (or rigid).
  Eigen::VectorXd support_displacement;
};

// The undeformed body at its rest pose.
BodyState RestState(const LayeredBody& body);

// The rest body translated rigidly by `offset` (e.g. lifted above a support).
BodyState TranslatedRestState(const LayeredBody& body, const Eigen::Vector3d& offset);

// `state` moved rigidly: turned by the rotation vector `rotation` (rad) about the core centre,
// then translated by `translation` (m). The external torque's work angle turns with it.
BodyState MovedRigidly(const LayeredBody& body, const BodyState& state,
                       const Eigen::Vector3d& translation, const Eigen::Vector3d& rotation);

// World positions of every tet-mesh vertex (#V x 3).
Vertices DeformedPositions(const LayeredBody& body, const BodyState& state);

// exp([θ]×) by Rodrigues' formula (accurate for small |θ|).
Eigen::Matrix3d RotationExp(const Eigen::Vector3d& theta);

}  // namespace ergo
