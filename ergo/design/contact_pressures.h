// The bi-directional contact pressures at an equilibrium (paper §4.1, Eq. 11–12, Fig. 4):
// on the human side each skin vertex's own penalty spring (the very forces the equilibrium
// used), on the support side the springs of support vertices inside the deformed skin,
// each turned into smoothed pressures and a cost by ergo/ergonomics. Shared by the design
// objective, ergo_simulate and ergo_optimize so every output reports the same forces.
#pragma once

#include <Eigen/Core>

#include "ergo/body/layered_body.h"
#include "ergo/contact/contact_set.h"
#include "ergo/contact/support.h"
#include "ergo/ergonomics/pressure_cost.h"
#include "ergo/mesh/laplacian.h"

namespace ergo {

struct ContactPressures {
  ContactSet human_contacts;      // skin vertices inside the support (point = tet-mesh vertex)
  ContactSet support_contacts;    // support vertices inside the skin (feature ids = skin-local)
  SurfacePressure human;          // per skin vertex, in LayeredBody::skin() order
  SurfacePressure support;        // per support vertex
  Eigen::VectorXd support_areas;  // barycentric, at the given support positions, m²
};

class ContactPressureEvaluator {
 public:
  // Keeps a reference to `body`; builds the skin's search tree once (rest shape).
  ContactPressureEvaluator(const LayeredBody& body, const Triangles& support_triangles,
                           Eigen::Index support_vertex_count, const PressureCostOptions& options);
  ContactPressureEvaluator(const ContactPressureEvaluator& other);

  // Pressures for body vertex positions `positions` whose skin springs against the support
  // are `human_contacts`, support vertices at `support_positions`, stiffness k.
  // with_hessian keeps the reverse springs' Hessians (for the adjoint).
  ContactPressures Evaluate(const Vertices& positions, ContactSet human_contacts,
                            const Vertices& support_positions, double stiffness, bool with_hessian);

  const SparseMatrix& skin_laplacian() const { return skin_laplacian_; }
  const SparseMatrix& support_laplacian() const { return support_laplacian_; }
  const PressureCostOptions& options() const { return options_; }

 private:
  const LayeredBody& body_;
  Triangles support_triangles_;
  PressureCostOptions options_;
  SparseMatrix skin_laplacian_, support_laplacian_;
  Support skin_;  // the body's skin, moved to the deformed positions per evaluation
};

}  // namespace ergo
