// The contact pressures at an equilibrium (paper §4.1, Eq. 11–12, Fig. 4), from the very
// springs the equilibrium used (ergo/contact/surface_contact.h, both directions): at every
// skin vertex inside the support and every support vertex inside the skin the model's
// pressure p = κg (its load p·s over its barycentric area: the skin's at rest, the
// support's at its current shape), smoothed and costed per surface (pressure_cost.h); ζ of
// them is pressure_score.h. Shared by the design objective, ergo_simulate and ergo_optimize,
// so every output reports the forces the solver applied.
#pragma once

#include <Eigen/Core>

#include "ergo/body/layered_body.h"
#include "ergo/contact/surface_contact.h"
#include "ergo/ergonomics/pressure_cost.h"
#include "ergo/mesh/laplacian.h"

namespace ergo {

struct ContactPressures {
  SurfaceContacts contacts;       // the equilibrium's springs and per-vertex forces
  SurfacePressure human;          // per skin vertex, in LayeredBody::skin() order
  SurfacePressure support;        // per support vertex
  Eigen::VectorXd support_areas;  // barycentric, at the support's shape, m²
};

class ContactPressureEvaluator {
 public:
  // Keeps a reference to `body`. The pressure smoothing is built on the skin at rest and on
  // `support` (its initial shape: the operator does not move with the design).
  ContactPressureEvaluator(const LayeredBody& body, const TriMesh& support,
                           const PressureCostOptions& options);

  // Pressures and costs of both surfaces for the equilibrium's `contacts`, support vertex
  // areas `support_areas` (m²).
  ContactPressures Evaluate(SurfaceContacts contacts, const Eigen::VectorXd& support_areas) const;

  const PressureSmoothing& skin_smoothing() const { return skin_smoothing_; }
  const PressureSmoothing& support_smoothing() const { return support_smoothing_; }
  const PressureCostOptions& options() const { return options_; }

 private:
  const LayeredBody& body_;
  PressureCostOptions options_;
  PressureSmoothing skin_smoothing_, support_smoothing_;
};

}  // namespace ergo
