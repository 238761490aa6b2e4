#include "ergo/design/contact_pressures.h"

#include <glog/logging.h>

namespace ergo {

ContactPressureEvaluator::ContactPressureEvaluator(const LayeredBody& body,
                                                   const Triangles& support_triangles,
                                                   Eigen::Index support_vertex_count,
                                                   const PressureCostOptions& options)
    : body_(body),
      options_(options),
      skin_laplacian_(UmbrellaLaplacian(body.skin().RestSurface(body.rest().vertices).triangles,
                                        body.skin().vertices.size())),
      support_laplacian_(UmbrellaLaplacian(support_triangles, support_vertex_count)) {}

ContactPressures ContactPressureEvaluator::Evaluate(SurfaceContacts contacts,
                                                    const Eigen::VectorXd& support_areas) const {
  const Skin& skin = body_.skin();
  CHECK_EQ(contacts.skin_load.size(), skin.vertices.size());
  CHECK_EQ(contacts.support_force.rows(), support_laplacian_.rows());
  CHECK_EQ(support_areas.size(), support_laplacian_.rows());
  ContactPressures out;
  out.contacts = std::move(contacts);
  out.support_areas = support_areas;
  out.human =
      EvaluateSurfacePressure(out.contacts.skin_load, skin.rest_areas, skin_laplacian_, options_);
  out.support = EvaluateSurfacePressure(out.contacts.support_load, support_areas,
                                        support_laplacian_, options_);
  return out;
}

}  // namespace ergo
