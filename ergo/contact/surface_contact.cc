#include "ergo/contact/surface_contact.h"

#include <algorithm>

#include <glog/logging.h>

namespace ergo {

double ContactSkinShare(const Eigen::VectorXd& skin_areas, const Eigen::VectorXd& support_areas,
                        const std::vector<bool>& region) {
  CHECK(region.empty() || region.size() == static_cast<size_t>(support_areas.size()));
  auto median = [](std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
    return values[values.size() / 2];
  };
  std::vector<double> skin(skin_areas.data(), skin_areas.data() + skin_areas.size()), support;
  for (Eigen::Index j = 0; j < support_areas.size(); ++j)
    if ((region.empty() || region[j]) && support_areas[j] > 0) support.push_back(support_areas[j]);
  const double a_skin = median(skin), a_support = median(support);
  if (!(a_skin > 0) || !(a_support > 0)) return 0.5;
  // ½ up to support vertices four times the skin's (spacing twice the skin's), then the
  // support's share falls as 4ā_skin/(ā_support + 4ā_skin): continuous at ratio 4.
  const double ratio = a_support / a_skin;
  return std::clamp(ratio / (ratio + 4), 0.5, 0.99);
}

Eigen::Vector3d SurfaceContacts::TotalForceOnBody() const {
  return skin_force.colwise().sum().transpose();
}

namespace {

// The springs' share of κ·s/2 on each side.
double SkinShare(const SurfaceContactOptions& o) { return o.support_springs ? o.skin_share : 1.0; }
double SupportShare(const SurfaceContactOptions& o) {
  return o.support_springs ? 1 - o.skin_share : 0.5;
}

}  // namespace

int SurfaceContacts::skin_vertices_in_contact() const {
  int count = 0;
  for (Eigen::Index v = 0; v < skin_load.size(); ++v) count += skin_load[v] > 0;
  return count;
}

Eigen::Matrix3d SurfaceContacts::TranslationStiffness() const {
  // A rigid translation e moves the skin vertex of a skin spring, or all skin feature
  // vertices of a support spring; by translation invariance of E the summed feature block
  // equals the (point, point) block in both cases.
  Eigen::Matrix3d stiffness = Eigen::Matrix3d::Zero();
  for (const Contact& contact : skin.contacts)
    stiffness += contact.spring.hessian.topLeftCorner<3, 3>();
  if (support_springs) {
    for (const Contact& contact : support.contacts)
      stiffness += contact.spring.hessian.topLeftCorner<3, 3>();
  }
  return stiffness;
}

SurfaceContact::SurfaceContact(const TriMesh& skin_rest, Eigen::VectorXi body_ids,
                               Eigen::VectorXd skin_areas, const SurfaceContactOptions& options)
    : skin_(skin_rest, "body skin"),
      body_ids_(std::move(body_ids)),
      skin_areas_(std::move(skin_areas)),
      options_(options),
      skin_positions_(skin_rest.vertices) {
  CHECK_EQ(body_ids_.size(), skin_rest.vertices.rows());
  CHECK_EQ(skin_areas_.size(), skin_rest.vertices.rows());
  CHECK_GT(options.stiffness, 0.0);
  CHECK(options.skin_share >= 0 && options.skin_share < 1);
  body_vertex_count_ = body_ids_.size() > 0 ? body_ids_.maxCoeff() + 1 : 0;
}

SurfaceContact::SurfaceContact(const SurfaceContact& other)
    : skin_(other.skin_),
      body_ids_(other.body_ids_),
      skin_areas_(other.skin_areas_),
      options_(other.options_),
      body_vertex_count_(other.body_vertex_count_),
      clearance_(other.clearance_),
      skin_hints_(other.skin_hints_),
      skin_positions_(other.skin_positions_),
      support_positions_(other.support_positions_),
      support_shape_(other.support_shape_) {
  // The rebuilt tree has a new shape stamp: old hints seed searches but prove nothing.
}

void SurfaceContact::set_stiffness(double kappa) {
  CHECK_GT(kappa, 0.0);
  options_.stiffness = kappa;
}

void SurfaceContact::ChooseSkinShare(const Support& support) {
  if (options_.skin_share != 0) return;
  // The support's vertices near the body: inside the rest skin's box grown by its size.
  const TriMesh& rest = skin_.mesh();
  const Eigen::RowVector3d lo = rest.vertices.colwise().minCoeff(),
                           hi = rest.vertices.colwise().maxCoeff();
  const Eigen::RowVector3d margin = hi - lo;
  std::vector<bool> near(static_cast<size_t>(support.mesh().vertices.rows()));
  for (Eigen::Index j = 0; j < support.mesh().vertices.rows(); ++j) {
    const Eigen::RowVector3d x = support.mesh().vertices.row(j);
    near[j] =
        (x.array() >= (lo - margin).array()).all() && (x.array() <= (hi + margin).array()).all();
  }
  options_.skin_share = ContactSkinShare(skin_areas_, support.vertex_areas(), near);
}

void SurfaceContact::MoveSkin(const Vertices& body_positions, const Support& support) {
  CHECK_GE(body_positions.rows(), body_vertex_count_);
  ChooseSkinShare(support);
  Vertices positions(body_ids_.size(), 3);
  for (Eigen::Index l = 0; l < body_ids_.size(); ++l)
    positions.row(l) = body_positions.row(body_ids_[l]);
  const Vertices& support_positions = support.mesh().vertices;
  const Eigen::Index support_count = support_positions.rows();
  const bool support_changed = support.shape() != support_shape_;
  if (clearance_.size() != support_count || support_positions_.rows() != support_count) {
    clearance_ = Eigen::VectorXd::Zero(support_count);
    skin_hints_.assign(static_cast<size_t>(support_count), SupportPoint());
  } else {
    // Every point of the skin moved at most as far as its farthest vertex (the surface is
    // the vertices' piecewise-linear interpolation), so each bound shrinks by that much.
    const double moved = (positions - skin_positions_).rowwise().norm().maxCoeff();
    clearance_ = (clearance_.array() - moved).cwiseMax(0.0);
    // A changed support (same vertices, moved: a design step): each vertex's bound shrinks by
    // its own move too. The hints are points of the skin, which the support does not move.
    if (support_changed) {
      clearance_ =
          (clearance_ - (support_positions - support_positions_).rowwise().norm()).cwiseMax(0.0);
    }
  }
  if (support_changed) {
    support_positions_ = support_positions;
    support_shape_ = support.shape();
  }
  skin_positions_ = positions;
  skin_.UpdateVertices(positions);
}

ContactSet SurfaceContact::SupportSprings(const Support& support, bool with_hessian) {
  ContactSet set;
  const Vertices& x = support.mesh().vertices;
  const Eigen::VectorXd& areas = support.vertex_areas();
  const auto count = static_cast<Eigen::Index>(x.rows());
  auto stiffness = [&](Eigen::Index j) {
    return 0.5 * options_.stiffness * SupportShare(options_) * areas[j];
  };
  // First which vertices are inside the skin (queries only where the bounds allow), then the
  // springs of those alone: thousands of springs, not one slot per support vertex.
  std::vector<char> inside(static_cast<size_t>(count), 0);
#pragma omp parallel for schedule(dynamic, 256) if (count >= 1024)
  for (Eigen::Index j = 0; j < count; ++j) {
    const Eigen::Vector3d p = x.row(j).transpose();
    if (clearance_[j] > 0 || !skin_.InBoundingBox(p)) continue;
    if (!(stiffness(j) > 0)) continue;
    SupportPoint& hint = skin_hints_[j];
    hint = skin_.ClosestPoint(p, hint.triangle >= 0 ? &hint : nullptr);
    if (!hint.inside) {
      clearance_[j] = std::sqrt(hint.squared_distance);
      continue;
    }
    inside[j] = 1;
  }
  std::vector<int> points;
  for (Eigen::Index j = 0; j < count; ++j)
    if (inside[j]) points.push_back(static_cast<int>(j));
  set.contacts.resize(points.size());
  const auto springs = static_cast<int>(points.size());
#pragma omp parallel for schedule(dynamic, 64) if (springs >= 256)
  for (int i = 0; i < springs; ++i) {
    const int j = points[i];
    Contact& contact = set.contacts[i];
    contact.point = j;
    contact.anchor = skin_hints_[j];
    contact.stiffness = stiffness(j);
    contact.spring = EvaluateSlidingAnchor(contact.anchor.feature.type, x.row(j).transpose(),
                                           skin_.Positions(contact.anchor.feature),
                                           contact.stiffness, with_hessian);
  }
  for (const Contact& contact : set.contacts) {
    set.energy += contact.spring.energy;
    set.max_penetration = std::max(set.max_penetration, contact.penetration());
  }
  return set;
}

void SurfaceContact::Evaluate(const Vertices& body_positions, const Support& support,
                              bool with_hessian, std::vector<SupportPoint>* hints,
                              SurfaceContacts* out, bool with_support_samples) {
  SurfaceContacts& c = *out;
  ChooseSkinShare(support);
  Eigen::VectorXd stiffness = Eigen::VectorXd::Zero(body_positions.rows());
  for (Eigen::Index l = 0; l < body_ids_.size(); ++l)
    stiffness[body_ids_[l]] = 0.5 * options_.stiffness * SkinShare(options_) * skin_areas_[l];
  c.skin = EvaluateContacts(support, body_positions, body_ids_, stiffness, with_hessian, hints);
  c.support_springs = options_.support_springs;
  c.skin_share = SkinShare(options_);
  c.support_share = SupportShare(options_);

  // Per-vertex forces: each spring pushes its point and, oppositely, its feature's vertices.
  c.skin_force = Vertices::Zero(body_ids_.size(), 3);
  c.support_force = Vertices::Zero(support.mesh().vertices.rows(), 3);
  c.skin_load = Eigen::VectorXd::Zero(body_ids_.size());
  Eigen::VectorXi local_of = Eigen::VectorXi::Constant(body_positions.rows(), -1);
  for (Eigen::Index l = 0; l < body_ids_.size(); ++l) local_of[body_ids_[l]] = static_cast<int>(l);
  for (const Contact& contact : c.skin.contacts) {
    c.skin_load[local_of[contact.point]] = contact.force().norm() / c.skin_share;
    c.skin_force.row(local_of[contact.point]) -= contact.spring.gradient.segment<3>(0).transpose();
    for (int k = 0; k < contact.anchor.feature.size(); ++k)
      c.support_force.row(contact.anchor.feature.vertices[k]) -=
          contact.spring.gradient.segment<3>(3 + 3 * k).transpose();
  }
  c.support = ContactSet();
  c.support_load = Eigen::VectorXd::Zero(support.mesh().vertices.rows());
  c.support_sampled = false;
  if (c.support_springs || with_support_samples) {
    SampleSupport(body_positions, support, with_hessian, out);
  } else {
    c.energy = c.skin.energy;
    c.max_penetration = c.skin.max_penetration;
  }
}

void SurfaceContact::AddSupportSamples(const Vertices& body_positions, const Support& support,
                                       bool with_hessian, SurfaceContacts* out) {
  if (out->support_sampled) return;
  CHECK(!out->support_springs) << "support springs that push are sampled by Evaluate";
  SampleSupport(body_positions, support, with_hessian, out);
}

void SurfaceContact::SampleSupport(const Vertices& body_positions, const Support& support,
                                   bool with_hessian, SurfaceContacts* out) {
  SurfaceContacts& c = *out;
  MoveSkin(body_positions, support);
  c.support = SupportSprings(support, with_hessian);
  c.support_sampled = true;
  c.energy = c.skin.energy + (c.support_springs ? c.support.energy : 0.0);
  // What κ controls: one-way, the support's samples push nothing, so how far a convex support
  // pokes between skin vertices is geometry, not stiffness (a calibration could not reach it).
  c.max_penetration = c.support_springs
                          ? std::max(c.skin.max_penetration, c.support.max_penetration)
                          : c.skin.max_penetration;
  for (const Contact& contact : c.support.contacts) {
    c.support_load[contact.point] = contact.force().norm() / c.support_share;
    if (!c.support_springs) continue;  // sampled for the score only
    c.support_force.row(contact.point) -= contact.spring.gradient.segment<3>(0).transpose();
    for (int k = 0; k < contact.anchor.feature.size(); ++k)
      c.skin_force.row(contact.anchor.feature.vertices[k]) -=
          contact.spring.gradient.segment<3>(3 + 3 * k).transpose();
  }
}

double SurfaceContact::Energy(const Vertices& body_positions, const Support& support,
                              std::vector<SupportPoint>* hints) {
  ChooseSkinShare(support);
  // One-way, the support's samples hold no energy: the skin tree need not follow.
  if (options_.support_springs) MoveSkin(body_positions, support);
  Eigen::VectorXd stiffness = Eigen::VectorXd::Zero(body_positions.rows());
  for (Eigen::Index l = 0; l < body_ids_.size(); ++l)
    stiffness[body_ids_[l]] = 0.5 * options_.stiffness * SkinShare(options_) * skin_areas_[l];
  const double skin =
      EvaluateContacts(support, body_positions, body_ids_, stiffness, false, hints).energy;
  return options_.support_springs ? skin + SupportSprings(support, false).energy : skin;
}

}  // namespace ergo
