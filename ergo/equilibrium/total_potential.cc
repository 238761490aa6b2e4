#include "ergo/equilibrium/total_potential.h"

#include <algorithm>
#include <chrono>

#include <glog/logging.h>
#include <Eigen/Eigenvalues>

#include "ergo/mesh/seconds_since.h"
#include "ergo/mesh/surface_geometry.h"

namespace ergo {
namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

SurfaceContact MakeSurfaceContact(const LayeredBody& body, const SurfaceContactOptions& options) {
  const Skin& skin = body.skin();
  return SurfaceContact(skin.RestSurface(body.rest().vertices), skin.vertices, skin.rest_areas,
                        options);
}

// A soft support's contact is two-way: with the skin's springs alone, its vertices between
// the skin's would rise into the tissue unresisted (measured: a 10 kPa foam block under a
// 10 kPa cube scored 3.7e14 on its side against 1.5e9 on a rigid block).
SurfaceContactOptions TwoWay(SurfaceContactOptions options) {
  options.support_springs = true;
  return options;
}

Eigen::MatrixXd ProjectPsd(const Eigen::MatrixXd& block) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(block);
  return eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.0).asDiagonal() *
         eigen.eigenvectors().transpose();
}

// The reduced DOFs a body vertex moves with and ∂p/∂y on them (3 x dofs): its own three
// (identity) when free, the core's through B when attached.
struct BodyVertexDofs {
  std::vector<int> dofs;
  Eigen::MatrixXd jacobian;
};

BodyVertexDofs DofsOf(const ReducedSystem& system, const BodyState& state,
                      const Vertices& positions, int vertex) {
  BodyVertexDofs out;
  const int f = system.body().free_index()[vertex];
  if (f >= 0) {
    out.dofs = {3 * f, 3 * f + 1, 3 * f + 2};
    out.jacobian = Eigen::Matrix3d::Identity();
    return out;
  }
  const ReducedLayout& layout = system.layout();
  out.jacobian = layout.CoreJacobian(positions.row(vertex).transpose() - state.centre);
  for (int j = 0; j < layout.core_count(); ++j)
    out.dofs.push_back(static_cast<int>(layout.core_offset()) + j);
  return out;
}

// Adds block (3x3, rows of support vertex a, columns of support vertex b) to the support's
// DOFs at `offset`, upper triangle only; held vertices (free index −1) have none.
void AddSupportBlock(int offset, int free_a, int free_b, const Eigen::Matrix3d& block,
                     Triplets* out) {
  if (free_a < 0 || free_b < 0) return;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      const int row = offset + 3 * free_a + r, col = offset + 3 * free_b + c;
      if (row <= col) out->emplace_back(row, col, block(r, c));
    }
  }
}

// Adds Jᵀ H (body vertex rows through `dofs`, support vertex columns) above the diagonal:
// the support's DOFs come after the body's.
void AddCrossBlock(const BodyVertexDofs& body, int offset, int free_support,
                   const Eigen::Matrix3d& block, Triplets* out) {
  if (free_support < 0) return;
  const Eigen::MatrixXd cross = body.jacobian.transpose() * block;
  for (size_t i = 0; i < body.dofs.size(); ++i)
    for (int c = 0; c < 3; ++c)
      out->emplace_back(body.dofs[i], offset + 3 * free_support + c, cross(i, c));
}

}  // namespace

Eigen::MatrixXd SkinFeatureHessian(const Contact& support_spring, bool project_psd) {
  const int n = support_spring.anchor.feature.size();
  Eigen::MatrixXd block = support_spring.spring.hessian.block(3, 3, 3 * n, 3 * n);
  return project_psd ? ProjectPsd(block) : block;
}

Support SoftSupportSurface(const ElasticPart& part, const std::string& name) {
  return Support(part.boundary().surface, name);
}

TotalPotential::TotalPotential(const LayeredBody& body, const SurfaceContactOptions& options,
                               std::shared_ptr<const ElasticPart> soft_support)
    : system_(body, soft_support ? soft_support->size() : 0),
      contact_(MakeSurfaceContact(body, soft_support ? TwoWay(options) : options)),
      soft_support_(std::move(soft_support)) {
  double lever = 0;
  for (Eigen::Index a : body.attached_vertices())
    lever = std::max(lever, (body.rest().vertices.row(a).transpose() - body.core_centre()).norm());
  lever_length_ = lever > 0 ? lever : 1.0;
}

void TotalPotential::set_soft_support(std::shared_ptr<const ElasticPart> part) {
  CHECK(soft_support_ && part) << "a soft support replaces a soft support";
  CHECK_EQ(part->size(), soft_support_->size());
  CHECK_EQ(part->rest().vertices.rows(), soft_support_->rest().vertices.rows());
  soft_support_ = std::move(part);
  soft_surface_.reset();  // pinned to the new rest areas at the next evaluation
}

Vertices TotalPotential::SupportPositions(const BodyState& state) const {
  const Vertices& rest = soft_support_->rest().vertices;
  if (state.support_displacement.size() == 0) return rest;
  return soft_support_->Positions(rest, state.support_displacement);
}

const Support& TotalPotential::MoveSoftSurface(const Vertices& support_positions,
                                               const Support& support) const {
  const TetBoundary& boundary = soft_support_->boundary();
  CHECK_EQ(support.mesh().vertices.rows(), boundary.surface.vertices.rows())
      << "a soft support's evaluations take its boundary at rest (SoftSupportSurface)";
  if (!soft_surface_) {
    soft_surface_.emplace(support);
    soft_surface_->PinVertexAreas();  // rest areas: no area term in the springs' derivatives
  }
  Vertices moved(boundary.surface.vertices.rows(), 3);
  for (Eigen::Index i = 0; i < moved.rows(); ++i)
    moved.row(i) = support_positions.row(boundary.surface_to_tet[i]);
  if (moved != soft_surface_->mesh().vertices) soft_surface_->UpdateVertices(moved);
  return *soft_surface_;
}

const Support& TotalPotential::ContactSurface(const Support& support) const {
  return soft_support_ && soft_surface_ ? *soft_surface_ : support;
}

double TotalPotential::Energy(const BodyState& state, const Support& support,
                              std::vector<SupportPoint>* hints) const {
  const Vertices positions = DeformedPositions(body(), state);
  if (!soft_support_)
    return system_.Energy(state, positions) + contact_.Energy(positions, support, hints);
  const Vertices support_positions = SupportPositions(state);
  const Support& surface = MoveSoftSurface(support_positions, support);
  return system_.Energy(state, positions) + soft_support_->Energy(support_positions) +
         contact_.Energy(positions, surface, hints);
}

void TotalPotential::Evaluate(const BodyState& state, const Support& support, HessianKind kind,
                              bool with_hessian, std::vector<SupportPoint>* hints,
                              Evaluation* evaluation, bool with_support_samples) const {
  Evaluation& e = *evaluation;
  e.positions = DeformedPositions(body(), state);
  auto start = std::chrono::steady_clock::now();
  const Support* surface = &support;
  if (soft_support_) {
    e.support_positions = SupportPositions(state);
    surface = &MoveSoftSurface(e.support_positions, support);
  } else {
    e.support_positions.resize(0, 3);
  }
  contact_.Evaluate(e.positions, *surface, with_hessian, hints, &e.contacts, with_support_samples);
  e.contact_seconds = SecondsSince(start);
  start = std::chrono::steady_clock::now();
  system_.Evaluate(state, e.positions, kind, with_hessian, &e.body);
  Triplets soft_blocks;
  if (soft_support_) {
    soft_blocks = AddSoftSupportTerms(state, kind, with_hessian, &e);
  } else {
    for (const Contact& contact : e.contacts.skin.contacts) {
      e.body.vertex_gradient.row(contact.point) += contact.spring.gradient.head<3>().transpose();
      if (with_hessian) {
        // The skin vertex's block only: a rigid support does not move. It is positive
        // semi-definite in every Voronoi region (2k I, 2k(I − êêᵀ), 2k nnᵀ).
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
        system_.AddVertexBlockHessian(
            state, e.positions, vertices,
            SkinFeatureHessian(contact, kind == HessianKind::kProjectedPsd), &e.body);
      }
    }
  }
  e.body.energy += e.contacts.energy;
  e.gradient = system_.Finalize(state, e.positions, kind, &e.body);
  e.energy = e.body.energy;
  if (soft_support_) {
    e.energy += e.support.energy;
    e.gradient.tail(layout().support_size()) =
        soft_support_->FreeComponents(e.support.vertex_gradient);
    if (with_hessian) {
      SparseMatrix blocks(size(), size());
      blocks.setFromTriplets(soft_blocks.begin(), soft_blocks.end());
      e.coupled_hessian = e.body.hessian + blocks;
      e.coupled_hessian.makeCompressed();
    }
  }
  e.assembly_seconds = SecondsSince(start);
}

Triplets TotalPotential::AddSoftSupportTerms(const BodyState& state, HessianKind kind,
                                             bool with_hessian, Evaluation* evaluation) const {
  Evaluation& e = *evaluation;
  const ElasticPart& part = *soft_support_;
  part.Evaluate(e.support_positions, kind, with_hessian, &e.support);
  Triplets blocks;
  const int offset = static_cast<int>(layout().support_offset());
  if (with_hessian) {
    // The support's elastic block, moved to its DOFs.
    for (int col = 0; col < e.support.hessian.outerSize(); ++col)
      for (SparseMatrix::InnerIterator it(e.support.hessian, col); it; ++it)
        blocks.emplace_back(offset + it.row(), offset + col, it.value());
  }
  const Eigen::VectorXi& surface_to_part = part.boundary().surface_to_tet;
  const Eigen::VectorXi& free_index = part.free_index();
  const Eigen::VectorXi& skin_vertices = body().skin().vertices;
  const bool project = kind == HessianKind::kProjectedPsd;

  // Skin vertex p inside the support, anchored on support feature vertices s_k.
  for (const Contact& contact : e.contacts.skin.contacts) {
    const Feature& feature = contact.anchor.feature;
    const int n = feature.size();
    e.body.vertex_gradient.row(contact.point) += contact.spring.gradient.head<3>().transpose();
    std::vector<int> support_free(static_cast<size_t>(n));
    for (int k = 0; k < n; ++k) {
      const int v = surface_to_part[feature.vertices[k]];
      support_free[k] = free_index[v];
      e.support.vertex_gradient.row(v) += contact.spring.gradient.segment<3>(3 + 3 * k).transpose();
    }
    if (!with_hessian) continue;
    const Eigen::MatrixXd whole = contact.spring.hessian.topLeftCorner(3 + 3 * n, 3 + 3 * n);
    const Eigen::MatrixXd h = project ? ProjectPsd(whole) : whole;
    system_.AddVertexHessian(state, e.positions, contact.point, h.topLeftCorner<3, 3>(), &e.body);
    const BodyVertexDofs dofs = DofsOf(system_, state, e.positions, contact.point);
    for (int k = 0; k < n; ++k) {
      AddCrossBlock(dofs, offset, support_free[k], h.block<3, 3>(0, 3 + 3 * k), &blocks);
      for (int l = 0; l < n; ++l)
        AddSupportBlock(offset, support_free[k], support_free[l],
                        h.block<3, 3>(3 + 3 * k, 3 + 3 * l), &blocks);
    }
  }
  // Support vertex s inside the skin, anchored on skin feature vertices (two-way contact).
  for (const Contact& contact : e.contacts.support.contacts) {
    if (!e.contacts.support_springs) break;  // score-only samples
    const Feature& feature = contact.anchor.feature;
    const int n = feature.size();
    const int v = surface_to_part[contact.point];
    e.support.vertex_gradient.row(v) += contact.spring.gradient.head<3>().transpose();
    std::vector<int> vertices(static_cast<size_t>(n));
    for (int k = 0; k < n; ++k) {
      vertices[k] = skin_vertices[feature.vertices[k]];
      e.body.vertex_gradient.row(vertices[k]) +=
          contact.spring.gradient.segment<3>(3 + 3 * k).transpose();
    }
    if (!with_hessian) continue;
    const Eigen::MatrixXd whole = contact.spring.hessian.topLeftCorner(3 + 3 * n, 3 + 3 * n);
    const Eigen::MatrixXd h = project ? ProjectPsd(whole) : whole;
    system_.AddVertexBlockHessian(state, e.positions, vertices, h.bottomRightCorner(3 * n, 3 * n),
                                  &e.body);
    AddSupportBlock(offset, free_index[v], free_index[v], h.topLeftCorner<3, 3>(), &blocks);
    for (int k = 0; k < n; ++k) {
      const BodyVertexDofs dofs = DofsOf(system_, state, e.positions, vertices[k]);
      AddCrossBlock(dofs, offset, free_index[v], h.block<3, 3>(3 + 3 * k, 0), &blocks);
    }
  }
  return blocks;
}

Vertices TotalPotential::RestShapeAdjoint(const BodyState& state, const Eigen::VectorXd& z,
                                          const Evaluation& e) const {
  CHECK(soft_support_) << "RestShapeAdjoint needs a soft support";
  CHECK_EQ(z.size(), size());
  const ElasticPart& part = *soft_support_;
  const Eigen::Index offset = layout().support_offset();
  // z as displacements of the foam's vertices (0 on the held ones) and of the body's.
  Vertices z_support = Vertices::Zero(part.rest().vertices.rows(), 3);
  for (Eigen::Index k = 0; k < part.free_vertices().size(); ++k)
    z_support.row(part.free_vertices()[k]) = z.segment<3>(offset + 3 * k).transpose();
  const Vertices z_body = layout().VertexVelocity(body(), state, e.positions, z);
  Vertices out = part.RestShapeAdjoint(e.support_positions, z_support);

  // A support spring's k = ½κ(1 − α)A_j: ∂(zᵀG)/∂A_j = (z · its forces' gradient)/A_j, and
  // A_j = Σ_{f ∋ j} area(f)/3 at rest.
  if (!e.contacts.support_springs || e.contacts.support.contacts.empty()) return out;
  const TetBoundary& boundary = part.boundary();
  const Eigen::VectorXi& surface_to_part = boundary.surface_to_tet;
  const Eigen::VectorXi& skin_vertices = body().skin().vertices;
  const Eigen::VectorXd rest_areas = BarycentricVertexAreas(boundary.surface);
  Eigen::VectorXd d_area = Eigen::VectorXd::Zero(rest_areas.size());
  for (const Contact& contact : e.contacts.support.contacts) {
    const int j = contact.point;
    double change = z_support.row(surface_to_part[j]).dot(contact.spring.gradient.head<3>());
    for (int k = 0; k < contact.anchor.feature.size(); ++k)
      change += z_body.row(skin_vertices[contact.anchor.feature.vertices[k]])
                    .dot(contact.spring.gradient.segment<3>(3 + 3 * k));
    d_area[j] = change / rest_areas[j];
  }
  const Triangles& triangles = boundary.surface.triangles;
  const Vertices& rest = boundary.surface.vertices;
  for (Eigen::Index f = 0; f < triangles.rows(); ++f) {
    const double weight =
        (d_area[triangles(f, 0)] + d_area[triangles(f, 1)] + d_area[triangles(f, 2)]) / 3;
    if (weight == 0) continue;
    const Eigen::Matrix3d gradient = TriangleAreaGradient(rest.row(triangles(f, 0)).transpose(),
                                                          rest.row(triangles(f, 1)).transpose(),
                                                          rest.row(triangles(f, 2)).transpose());
    for (int c = 0; c < 3; ++c)
      out.row(surface_to_part[triangles(f, c)]) += weight * gradient.row(c);
  }
  return out;
}

void TotalPotential::AddSupportSamples(const Support& support, bool with_hessian,
                                       Evaluation* evaluation) const {
  if (evaluation->contacts.support_sampled) return;
  const auto start = std::chrono::steady_clock::now();
  contact_.AddSupportSamples(evaluation->positions, ContactSurface(support), with_hessian,
                             &evaluation->contacts);
  evaluation->contact_seconds += SecondsSince(start);
}

double TotalPotential::LargestMove(const BodyState& state, const Vertices& positions,
                                   const Eigen::VectorXd& step) const {
  double body_move =
      layout().VertexVelocity(body(), state, positions, step).rowwise().norm().maxCoeff();
  double support_move = 0;
  const Eigen::Index offset = layout().support_offset();
  for (Eigen::Index k = 0; 3 * k < layout().support_size(); ++k)
    support_move = std::max(support_move, step.segment<3>(offset + 3 * k).norm());
  return body_move + support_move;
}

SparseMatrix TotalPotential::Mass(const BodyState& state, const Vertices& positions) const {
  SparseMatrix mass = system_.pattern();
  system_.AddScaledMass(1.0, state, positions, &mass);
  if (!soft_support_) return mass;
  Triplets diagonal;
  const Eigen::Index offset = layout().support_offset();
  const Eigen::VectorXi& free = soft_support_->free_vertices();
  for (Eigen::Index k = 0; k < free.size(); ++k)
    for (int c = 0; c < 3; ++c)
      diagonal.emplace_back(offset + 3 * k + c, offset + 3 * k + c,
                            soft_support_->vertex_mass()[free[k]]);
  SparseMatrix support_mass(size(), size());
  support_mass.setFromTriplets(diagonal.begin(), diagonal.end());
  SparseMatrix total = mass + support_mass;
  total.makeCompressed();
  return total;
}

void TotalPotential::AddScaledMass(double alpha, const BodyState& state, const Vertices& positions,
                                   SparseMatrix* hessian) const {
  if (!soft_support_) {
    system_.AddScaledMass(alpha, state, positions, hessian);
    return;
  }
  // The sum keeps K̂'s pattern: M̂'s entries are on the body's pattern and the support's
  // diagonal, both inside it.
  const Eigen::Index nonzeros = hessian->nonZeros();
  *hessian = *hessian + alpha * Mass(state, positions);
  hessian->makeCompressed();
  CHECK_EQ(hessian->nonZeros(), nonzeros);
}

double TotalPotential::ResidualNorm(const Eigen::VectorXd& gradient) const {
  const ReducedLayout& layout = system_.layout();
  double squared = gradient.head(layout.core_offset()).squaredNorm();
  for (int j = 0; j < layout.core_count(); ++j) {
    const double value = gradient[layout.core_offset() + j];
    const bool rotation = layout.core_components()[j] >= 3;
    squared += rotation ? (value / lever_length_) * (value / lever_length_) : value * value;
  }
  squared += gradient.tail(layout.support_size()).squaredNorm();
  return std::sqrt(squared);
}

}  // namespace ergo
