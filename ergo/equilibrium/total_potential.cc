#include "ergo/equilibrium/total_potential.h"

#include <chrono>

#include <glog/logging.h>
#include <Eigen/Eigenvalues>

#include "ergo/mesh/seconds_since.h"

namespace ergo {
namespace {

SurfaceContact MakeSurfaceContact(const LayeredBody& body, const SurfaceContactOptions& options) {
  const Skin& skin = body.skin();
  return SurfaceContact(skin.RestSurface(body.rest().vertices), skin.vertices, skin.rest_areas,
                        options);
}

}  // namespace

Eigen::MatrixXd SkinFeatureHessian(const Contact& support_spring, bool project_psd) {
  const int n = support_spring.anchor.feature.size();
  Eigen::MatrixXd block = support_spring.spring.hessian.block(3, 3, 3 * n, 3 * n);
  if (!project_psd) return block;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(block);
  return eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.0).asDiagonal() *
         eigen.eigenvectors().transpose();
}

TotalPotential::TotalPotential(const LayeredBody& body, const SurfaceContactOptions& options)
    : system_(body), contact_(MakeSurfaceContact(body, options)) {
  double lever = 0;
  for (Eigen::Index a : body.attached_vertices())
    lever = std::max(lever, (body.rest().vertices.row(a).transpose() - body.core_centre()).norm());
  lever_length_ = lever > 0 ? lever : 1.0;
}

double TotalPotential::Energy(const BodyState& state, const Support& support,
                              std::vector<SupportPoint>* hints) const {
  const Vertices positions = DeformedPositions(body(), state);
  return system_.Energy(state, positions) + contact_.Energy(positions, support, hints);
}

void TotalPotential::Evaluate(const BodyState& state, const Support& support, HessianKind kind,
                              bool with_hessian, std::vector<SupportPoint>* hints,
                              Evaluation* evaluation, bool with_support_samples) const {
  Evaluation& e = *evaluation;
  e.positions = DeformedPositions(body(), state);
  auto start = std::chrono::steady_clock::now();
  contact_.Evaluate(e.positions, support, with_hessian, hints, &e.contacts, with_support_samples);
  e.contact_seconds = SecondsSince(start);
  start = std::chrono::steady_clock::now();
  system_.Evaluate(state, e.positions, kind, with_hessian, &e.body);
  for (const Contact& contact : e.contacts.skin.contacts) {
    e.body.vertex_gradient.row(contact.point) += contact.spring.gradient.head<3>().transpose();
    if (with_hessian) {
      // The skin vertex's block only: the support is fixed during the equilibrium. It is
      // positive semi-definite in every Voronoi region (2k I, 2k(I − êêᵀ), 2k nnᵀ).
      system_.AddVertexHessian(state, e.positions, contact.point,
                               contact.spring.hessian.topLeftCorner<3, 3>(), &e.body);
    }
  }
  const Eigen::VectorXi& skin_vertices = body().skin().vertices;
  for (const Contact& contact : e.contacts.support.contacts) {
    if (!e.contacts.support_springs) break;  // score-only samples
    const Feature& feature = contact.anchor.feature;
    std::vector<int> vertices(static_cast<size_t>(feature.size()));
    for (int k = 0; k < feature.size(); ++k) {
      vertices[k] = skin_vertices[feature.vertices[k]];
      e.body.vertex_gradient.row(vertices[k]) +=
          contact.spring.gradient.segment<3>(3 + 3 * k).transpose();
    }
    if (with_hessian) {
      system_.AddVertexBlockHessian(state, e.positions, vertices,
                                    SkinFeatureHessian(contact, kind == HessianKind::kProjectedPsd),
                                    &e.body);
    }
  }
  e.body.energy += e.contacts.energy;
  e.energy = e.body.energy;
  e.gradient = system_.Finalize(state, e.positions, kind, &e.body);
  e.assembly_seconds = SecondsSince(start);
}

void TotalPotential::AddSupportSamples(const Support& support, bool with_hessian,
                                       Evaluation* evaluation) const {
  if (evaluation->contacts.support_sampled) return;
  const auto start = std::chrono::steady_clock::now();
  contact_.AddSupportSamples(evaluation->positions, support, with_hessian, &evaluation->contacts);
  evaluation->contact_seconds += SecondsSince(start);
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
