#include "ergo/design/contact_pressures.h"

#include <glog/logging.h>

#include "ergo/mesh/surface_geometry.h"

namespace ergo {

ContactPressureEvaluator::ContactPressureEvaluator(const LayeredBody& body,
                                                   const Triangles& support_triangles,
                                                   Eigen::Index support_vertex_count,
                                                   const PressureCostOptions& options)
    : body_(body),
      support_triangles_(support_triangles),
      options_(options),
      skin_laplacian_(UmbrellaLaplacian(body.skin().RestSurface(body.rest().vertices).triangles,
                                        body.skin().vertices.size())),
      support_laplacian_(UmbrellaLaplacian(support_triangles, support_vertex_count)),
      skin_(body.skin().RestSurface(body.rest().vertices), "body skin") {}

ContactPressureEvaluator::ContactPressureEvaluator(const ContactPressureEvaluator& other)
    : body_(other.body_),
      support_triangles_(other.support_triangles_),
      options_(other.options_),
      skin_laplacian_(other.skin_laplacian_),
      support_laplacian_(other.support_laplacian_),
      skin_(body_.skin().RestSurface(body_.rest().vertices), "body skin") {}

ContactPressures ContactPressureEvaluator::Evaluate(const Vertices& positions,
                                                    ContactSet human_contacts,
                                                    const Vertices& support_positions,
                                                    double stiffness, bool with_hessian) {
  CHECK_EQ(support_positions.rows(), support_laplacian_.rows());
  const Skin& skin = body_.skin();
  ContactPressures out;
  out.human_contacts = std::move(human_contacts);
  Eigen::VectorXd human_force = Eigen::VectorXd::Zero(skin.vertices.size());
  for (const Contact& contact : out.human_contacts.contacts) {
    const int local = skin.local_of[contact.point];
    CHECK_GE(local, 0) << "contact on a vertex that is not on the skin";
    human_force[local] = contact.force().norm();
  }
  out.human = EvaluateSurfacePressure(human_force, skin.rest_areas, skin_laplacian_, options_);

  // Support vertices inside the deformed skin (the skin is closed: the layer's outside).
  Vertices skin_positions(skin.vertices.size(), 3);
  for (Eigen::Index i = 0; i < skin.vertices.size(); ++i)
    skin_positions.row(i) = positions.row(skin.vertices[i]);
  skin_.UpdateVertices(skin_positions);
  const auto count = static_cast<int>(support_positions.rows());
  out.support_contacts =
      EvaluateContacts(skin_, support_positions, Eigen::VectorXi::LinSpaced(count, 0, count - 1),
                       stiffness, with_hessian);
  out.support_areas = BarycentricVertexAreas(TriMesh{support_positions, support_triangles_});
  Eigen::VectorXd support_force = Eigen::VectorXd::Zero(count);
  for (const Contact& contact : out.support_contacts.contacts)
    support_force[contact.point] = contact.force().norm();
  out.support =
      EvaluateSurfacePressure(support_force, out.support_areas, support_laplacian_, options_);
  return out;
}

}  // namespace ergo
