#include "ergo/contact/contact_set.h"

#include <optional>

#include <glog/logging.h>

namespace ergo {

Eigen::Vector3d ContactSet::TotalForce() const {
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  for (const Contact& contact : contacts) total += contact.force();
  return total;
}

ContactSet EvaluateContacts(const Support& surface, const Vertices& points,
                            const Eigen::VectorXi& indices, double stiffness, bool with_hessian,
                            std::vector<SupportPoint>* hints) {
  CHECK_GT(stiffness, 0.0);
  return EvaluateContacts(surface, points, indices, Eigen::VectorXd::Constant(points.rows(), stiffness),
                          with_hessian, hints);
}

ContactSet EvaluateContacts(const Support& surface, const Vertices& points,
                            const Eigen::VectorXi& indices, const Eigen::VectorXd& stiffness,
                            bool with_hessian, std::vector<SupportPoint>* hints) {
  CHECK_EQ(stiffness.size(), points.rows());
  CHECK(!hints || hints->size() == static_cast<size_t>(points.rows()));
  const auto count = static_cast<Eigen::Index>(indices.size());
  std::vector<std::optional<Contact>> found(static_cast<size_t>(count));
#pragma omp parallel for schedule(dynamic, 256) if (count >= 1024)
  for (Eigen::Index i = 0; i < count; ++i) {
    const int point = indices[i];
    const double k = stiffness[point];
    if (!(k > 0)) continue;
    const Eigen::Vector3d p = points.row(point).transpose();
    const SupportPoint* hint = nullptr;
    if (hints && (*hints)[point].triangle >= 0) hint = &(*hints)[point];
    const std::optional<SupportPoint> anchor = surface.Penetration(p, hint);
    if (!anchor) continue;
    Contact contact;
    contact.point = point;
    contact.anchor = *anchor;
    contact.stiffness = k;
    contact.spring = EvaluateSlidingAnchor(anchor->feature.type, p,
                                           surface.Positions(anchor->feature), k, with_hessian);
    found[i] = contact;
  }
  ContactSet set;
  for (Eigen::Index i = 0; i < count; ++i) {
    if (!found[i]) continue;
    const Contact& contact = *found[i];
    set.energy += contact.spring.energy;
    set.max_penetration = std::max(set.max_penetration, contact.penetration());
    if (hints) (*hints)[contact.point] = contact.anchor;
    set.contacts.push_back(contact);
  }
  return set;
}

}  // namespace ergo
