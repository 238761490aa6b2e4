#include "ergo/ergonomics/score_gradient.h"

#include <glog/logging.h>

#include "ergo/mesh/surface_geometry.h"

namespace ergo {
namespace {

// One spring variable: a body vertex (tet-mesh id and skin-local id) or a support vertex.
struct Variable {
  bool on_body = false;
  int vertex = -1;      // tet-mesh id on the body, support vertex id otherwise
  int skin_local = -1;  // on the body: its index in the skin
};

// The variables of a spring in the order of its gradient: the point, then the feature.
int SpringVariables(const Contact& contact, bool point_on_body, const Skin& skin,
                    Variable* variables) {
  const Feature& feature = contact.anchor.feature;
  if (point_on_body) {
    variables[0] = {true, contact.point, skin.local_of[contact.point]};
    for (int k = 0; k < feature.size(); ++k) variables[1 + k] = {false, feature.vertices[k], -1};
  } else {
    variables[0] = {false, contact.point, -1};
    for (int k = 0; k < feature.size(); ++k)
      variables[1 + k] = {true, skin.vertices[feature.vertices[k]], feature.vertices[k]};
  }
  return 1 + feature.size();
}

}  // namespace

ScorePartials PressureScorePartials(const ContactPressures& pressures, const LayeredBody& body,
                                    bool support_side) {
  const Skin& skin = body.skin();
  const SurfaceContacts& contacts = pressures.contacts;
  ScorePartials out;
  out.body = Vertices::Zero(body.rest().vertices.rows(), 3);
  out.support.position = Vertices::Zero(contacts.support_force.rows(), 3);
  // Σ s P̄^e and the denominators of P
  out.support.area = support_side ? pressures.support.d_area
                                  : Eigen::VectorXd::Zero(pressures.support.d_area.size());

  for (int side = 0; side < (support_side ? 2 : 1); ++side) {
    const bool point_on_body = side == 0;
    for (const Contact& contact : (point_on_body ? contacts.skin : contacts.support).contacts) {
      // The spring's point carries the load ‖f‖/share (p = κg there), f = −∂E/∂p.
      const int vertex = point_on_body ? skin.local_of[contact.point] : contact.point;
      const double weight = (point_on_body ? pressures.human : pressures.support)
                                .d_force_magnitude[vertex];  // ∂ζ/∂load
      const Eigen::Vector3d force = contact.force();
      const double magnitude = force.norm();
      if (weight == 0 || magnitude == 0) continue;
      const double share = point_on_body ? contacts.skin_share : contacts.support_share;
      // ∂(‖f‖/share)/∂z = −f̂ᵀ ∂²E/∂p∂z / share for every spring variable z.
      const Eigen::Matrix<double, 1, 12> row =
          -(weight / (share * magnitude)) * force.transpose() * contact.spring.hessian.topRows<3>();
      Variable variables[4];
      const int n = SpringVariables(contact, point_on_body, skin, variables);
      for (int b = 0; b < n; ++b) {
        const Eigen::Vector3d g = row.segment<3>(3 * b).transpose();
        if (variables[b].on_body) {
          out.body.row(variables[b].vertex) += g.transpose();
        } else {
          out.support.position.row(variables[b].vertex) += g.transpose();
        }
      }
      // A support spring's k = ½κ(1 − α)s_j, and its load with it: ∂load/∂s_j = load/s_j.
      if (!point_on_body) {
        const double area = pressures.support_areas[contact.point];
        CHECK_GT(area, 0.0);
        out.support.area[contact.point] += weight * magnitude / (share * area);
      }
    }
  }
  return out;
}

SupportShapeGradient ResidualShapeContraction(const SurfaceContacts& contacts,
                                              const LayeredBody& body,
                                              const Eigen::VectorXd& support_areas,
                                              const Vertices& body_velocity) {
  const Skin& skin = body.skin();
  SupportShapeGradient out;
  out.position = Vertices::Zero(contacts.support_force.rows(), 3);
  out.area = Eigen::VectorXd::Zero(contacts.support_force.rows());
  for (int side = 0; side < 2; ++side) {
    const bool point_on_body = side == 0;
    if (!point_on_body && !contacts.support_springs) break;  // score-only: not in G
    for (const Contact& contact : (point_on_body ? contacts.skin : contacts.support).contacts) {
      Variable variables[4];
      const int n = SpringVariables(contact, point_on_body, skin, variables);
      // zᵀ ∂G/∂x_m = Σ_{body variables b} v_bᵀ ∂²E/∂b∂x_m, and (support springs) through k.
      Eigen::Matrix<double, 1, 12> row = Eigen::Matrix<double, 1, 12>::Zero();
      double stiffness_part = 0;  // Σ_b v_b·∂E/∂b = k · ∂(zᵀG)/∂k
      for (int a = 0; a < n; ++a) {
        if (!variables[a].on_body) continue;
        const Eigen::Vector3d v = body_velocity.row(variables[a].vertex).transpose();
        row += v.transpose() * contact.spring.hessian.middleRows<3>(3 * a);
        stiffness_part += v.dot(contact.spring.gradient.segment<3>(3 * a));
      }
      for (int b = 0; b < n; ++b)
        if (!variables[b].on_body) out.position.row(variables[b].vertex) += row.segment<3>(3 * b);
      if (!point_on_body && stiffness_part != 0) {
        const double area = support_areas[contact.point];
        CHECK_GT(area, 0.0);
        out.area[contact.point] += stiffness_part / area;
      }
    }
  }
  return out;
}

Vertices ResidualShapeDerivative(const SurfaceContacts& contacts, const LayeredBody& body,
                                 const TriMesh& support, const Vertices& support_velocity) {
  const Skin& skin = body.skin();
  Vertices out = Vertices::Zero(body.rest().vertices.rows(), 3);
  // The rate of each support vertex's barycentric area.
  Eigen::VectorXd area_rate = Eigen::VectorXd::Zero(support.vertices.rows());
  Eigen::VectorXd areas;  // only the support's springs need them (one-way: none)
  if (contacts.support_springs && !contacts.support.contacts.empty()) {
    areas = BarycentricVertexAreas(support);
    for (Eigen::Index t = 0; t < support.triangles.rows(); ++t) {
      const Eigen::RowVector3i tri = support.triangles.row(t);
      const Eigen::Matrix3d gradient = TriangleAreaGradient(
          support.vertices.row(tri[0]), support.vertices.row(tri[1]), support.vertices.row(tri[2]));
      double rate = 0;
      for (int k = 0; k < 3; ++k) rate += gradient.row(k).dot(support_velocity.row(tri[k]));
      for (int k = 0; k < 3; ++k) area_rate[tri[k]] += rate / 3;
    }
  }
  for (int side = 0; side < 2; ++side) {
    const bool point_on_body = side == 0;
    if (!point_on_body && !contacts.support_springs) break;  // score-only: not in G
    for (const Contact& contact : (point_on_body ? contacts.skin : contacts.support).contacts) {
      Variable variables[4];
      const int n = SpringVariables(contact, point_on_body, skin, variables);
      Eigen::Matrix<double, 12, 1> velocity = Eigen::Matrix<double, 12, 1>::Zero();
      for (int b = 0; b < n; ++b)
        if (!variables[b].on_body)
          velocity.segment<3>(3 * b) = support_velocity.row(variables[b].vertex).transpose();
      const Eigen::Matrix<double, 12, 1> change = contact.spring.hessian * velocity;
      const double stiffness_rate = point_on_body || areas[contact.point] <= 0
                                        ? 0.0
                                        : area_rate[contact.point] / areas[contact.point];
      for (int a = 0; a < n; ++a) {
        if (!variables[a].on_body) continue;
        out.row(variables[a].vertex) +=
            (change.segment<3>(3 * a) + stiffness_rate * contact.spring.gradient.segment<3>(3 * a))
                .transpose();
      }
    }
  }
  return out;
}

Vertices ChainSupportAreas(const Eigen::VectorXd& area_weight, const TriMesh& support) {
  CHECK_EQ(area_weight.size(), support.vertices.rows());
  Vertices out = Vertices::Zero(support.vertices.rows(), 3);
  for (Eigen::Index t = 0; t < support.triangles.rows(); ++t) {
    const Eigen::RowVector3i tri = support.triangles.row(t);
    // s_j gets a third of each incident triangle's area.
    const double weight = (area_weight[tri[0]] + area_weight[tri[1]] + area_weight[tri[2]]) / 3;
    if (weight == 0) continue;
    const Eigen::Matrix3d gradient = TriangleAreaGradient(
        support.vertices.row(tri[0]), support.vertices.row(tri[1]), support.vertices.row(tri[2]));
    for (int k = 0; k < 3; ++k) out.row(tri[k]) += weight * gradient.row(k);
  }
  return out;
}

}  // namespace ergo
