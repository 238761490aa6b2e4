#include "ergo/equilibrium/total_potential.h"

#include <chrono>

#include <glog/logging.h>

namespace ergo {
namespace {

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

TotalPotential::TotalPotential(const LayeredBody& body, double contact_stiffness)
    : system_(body), stiffness_(contact_stiffness) {
  CHECK_GT(contact_stiffness, 0.0);
  double lever = 0;
  for (Eigen::Index a : body.attached_vertices())
    lever = std::max(lever, (body.rest().vertices.row(a).transpose() - body.core_centre()).norm());
  lever_length_ = lever > 0 ? lever : 1.0;
}

void TotalPotential::set_contact_stiffness(double k) {
  CHECK_GT(k, 0.0);
  stiffness_ = k;
}

double TotalPotential::Energy(const BodyState& state, const Support& support,
                              std::vector<SupportPoint>* hints) const {
  const Vertices positions = DeformedPositions(body(), state);
  const ContactSet contacts =
      EvaluateContacts(support, positions, body().skin().vertices, stiffness_, false, hints);
  return system_.Energy(state, positions) + contacts.energy;
}

void TotalPotential::Evaluate(const BodyState& state, const Support& support, HessianKind kind,
                              bool with_hessian, std::vector<SupportPoint>* hints,
                              Evaluation* evaluation) const {
  Evaluation& e = *evaluation;
  e.positions = DeformedPositions(body(), state);
  auto start = std::chrono::steady_clock::now();
  e.contacts = EvaluateContacts(support, e.positions, body().skin().vertices, stiffness_,
                                with_hessian, hints);
  e.contact_seconds = SecondsSince(start);
  start = std::chrono::steady_clock::now();
  system_.Evaluate(state, e.positions, kind, with_hessian, &e.body);
  for (const Contact& contact : e.contacts.contacts) {
    e.body.vertex_gradient.row(contact.point) += contact.spring.gradient.head<3>().transpose();
    if (with_hessian) {
      // Only the skin-vertex block: the support is fixed during the equilibrium.
      system_.AddVertexHessian(state, e.positions, contact.point,
                               contact.spring.hessian.topLeftCorner<3, 3>(), &e.body);
    }
  }
  e.body.energy += e.contacts.energy;
  e.energy = e.body.energy;
  e.gradient = system_.Finalize(state, e.positions, kind, &e.body);
  e.assembly_seconds = SecondsSince(start);
}

double TotalPotential::ResidualNorm(const Eigen::VectorXd& gradient) const {
  const ReducedLayout& layout = system_.layout();
  double squared = gradient.head(layout.core_offset()).squaredNorm();
  for (int j = 0; j < layout.core_count(); ++j) {
    const double value = gradient[layout.core_offset() + j];
    const bool rotation = layout.core_components()[j] >= 3;
    squared += rotation ? (value / lever_length_) * (value / lever_length_) : value * value;
  }
  return std::sqrt(squared);
}

}  // namespace ergo
