#include "ergo/ergonomics/contact_pressures.h"

#include <glog/logging.h>

namespace ergo {

ContactPressureEvaluator::ContactPressureEvaluator(const LayeredBody& body, const TriMesh& support,
                                                   const PressureCostOptions& options)
    : body_(body),
      options_(options),
      skin_smoothing_(
          MakePressureSmoothing(body.skin().RestSurface(body.rest().vertices), options)),
      support_smoothing_(MakePressureSmoothing(support, options)) {}

ContactPressures ContactPressureEvaluator::Evaluate(SurfaceContacts contacts,
                                                    const Eigen::VectorXd& support_areas) const {
  const Skin& skin = body_.skin();
  CHECK_EQ(contacts.skin_load.size(), skin.vertices.size());
  CHECK_EQ(contacts.support_force.rows(), support_smoothing_.size());
  CHECK_EQ(support_areas.size(), support_smoothing_.size());
  ContactPressures out;
  out.contacts = std::move(contacts);
  out.support_areas = support_areas;
  out.human =
      EvaluateSurfacePressure(out.contacts.skin_load, skin.rest_areas, skin_smoothing_, options_);
  out.support = EvaluateSurfacePressure(out.contacts.support_load, support_areas,
                                        support_smoothing_, options_);
  return out;
}

}  // namespace ergo
