#include "ergo/body/reduced_system.h"
#include "ergo/mesh/sparse_index.h"

#include <algorithm>
#include <limits>
#include <utility>

#include <glog/logging.h>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

namespace ergo {
namespace {

// Colours with fewer elements than this are assembled on one thread.
constexpr size_t kMinParallelColour = 512;

// Local corner pairs (a <= b) in a fixed order; kPair[a][b] is their slot.
constexpr int kPairs[10][2] = {{0, 0}, {0, 1}, {0, 2}, {0, 3}, {1, 1},
                               {1, 2}, {1, 3}, {2, 2}, {2, 3}, {3, 3}};

// Full B_a = [I  −[h]×] (3 x 6).
Eigen::Matrix<double, 3, 6> FullCoreJacobian(const Eigen::Vector3d& h) {
  Eigen::Matrix<double, 3, 6> b;
  b.leftCols<3>().setIdentity();
  b.rightCols<3>() << 0, h.z(), -h.y(), -h.z(), 0, h.x(), h.y(), -h.x(), 0;
  return b;
}

}  // namespace

ReducedSystem::ReducedSystem(const LayeredBody& body, Eigen::Index support_size)
    : body_(body), layout_(body, support_size), kernel_(body.rest(), body.material()) {
  BuildPattern();
  Colour();
}

void ReducedSystem::BuildPattern() {
  const Tetrahedra& tets = body_.rest().tets;
  const Eigen::VectorXi& free_index = body_.free_index();
  const int core_offset = static_cast<int>(layout_.core_offset());
  const int core_count = layout_.core_count();
  const auto n = static_cast<int>(layout_.size());

  std::vector<Eigen::Triplet<double>> entries;
  std::vector<char> touches_core(static_cast<size_t>(body_.free_vertices().size()), 0);
  for (Eigen::Index t = 0; t < tets.rows(); ++t) {
    bool has_attached = false;
    for (int k = 0; k < 4; ++k) has_attached |= free_index[tets(t, k)] < 0;
    for (int a = 0; a < 4; ++a) {
      const int fa = free_index[tets(t, a)];
      if (fa < 0) continue;
      if (has_attached) touches_core[fa] = 1;
      for (int b = 0; b < 4; ++b) {
        const int fb = free_index[tets(t, b)];
        if (fb < 0 || fb < fa) continue;
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c)
            if (fa != fb || r <= c) entries.emplace_back(3 * fa + r, 3 * fb + c, 0.0);
      }
    }
  }
  for (size_t f = 0; f < touches_core.size(); ++f) {
    if (!touches_core[f]) continue;
    for (int r = 0; r < 3; ++r)
      for (int j = 0; j < core_count; ++j)
        entries.emplace_back(3 * static_cast<int>(f) + r, core_offset + j, 0.0);
  }
  for (int i = 0; i < core_count; ++i)
    for (int j = i; j < core_count; ++j)
      entries.emplace_back(core_offset + i, core_offset + j, 0.0);
  pattern_.resize(n, n);
  pattern_.setFromTriplets(entries.begin(), entries.end());
  pattern_.makeCompressed();
  std::fill(pattern_.valuePtr(), pattern_.valuePtr() + pattern_.nonZeros(), 0.0);

  // Scatter plans.
  plans_.resize(static_cast<size_t>(tets.rows()));
  for (Eigen::Index t = 0; t < tets.rows(); ++t) {
    ElementPlan& plan = plans_[t];
    bool has_attached = false;
    for (int k = 0; k < 4; ++k) {
      const int f = free_index[tets(t, k)];
      plan.free_dof[k] = f < 0 ? -1 : 3 * f;
      has_attached |= f < 0;
    }
    for (int p = 0; p < 10; ++p) {
      const int da = plan.free_dof[kPairs[p][0]], db = plan.free_dof[kPairs[p][1]];
      plan.transposed[p] = da > db;
      plan.block[p] = {-1, -1, -1};
      if (da < 0 || db < 0) continue;
      const int row = std::min(da, db), col = std::max(da, db);
      for (int c = 0; c < 3; ++c) plan.block[p][c] = ValueIndex(pattern_, row, col + c);
    }
    if (has_attached) plan.core_slot = core_slots_++;
  }
  free_core_index_.assign(touches_core.size(), {-1, -1, -1, -1, -1, -1});
  for (size_t f = 0; f < touches_core.size(); ++f) {
    if (!touches_core[f]) continue;
    for (int j = 0; j < core_count; ++j)
      free_core_index_[f][j] = ValueIndex(pattern_, 3 * static_cast<int>(f), core_offset + j);
  }
  for (auto& row : core_index_) row.fill(-1);
  for (int i = 0; i < core_count; ++i)
    for (int j = i; j < core_count; ++j)
      core_index_[i][j] = ValueIndex(pattern_, core_offset + i, core_offset + j);
}

void ReducedSystem::Colour() {
  // Greedy vertex-disjoint colouring: a tet takes the smallest colour not used by any tet
  // sharing one of its vertices. Deterministic (tets visited in index order).
  const Tetrahedra& tets = body_.rest().tets;
  const Eigen::Index vertex_count = body_.rest().vertices.rows();
  std::vector<std::vector<int>> vertex_tets(static_cast<size_t>(vertex_count));
  for (Eigen::Index t = 0; t < tets.rows(); ++t)
    for (int k = 0; k < 4; ++k) vertex_tets[tets(t, k)].push_back(static_cast<int>(t));
  std::vector<int> colour(static_cast<size_t>(tets.rows()), -1);
  std::vector<int> seen_by;  // colour -> last tet that saw it used
  for (Eigen::Index t = 0; t < tets.rows(); ++t) {
    for (int k = 0; k < 4; ++k) {
      for (int other : vertex_tets[tets(t, k)]) {
        const int c = colour[other];
        if (c >= 0) seen_by[c] = static_cast<int>(t);
      }
    }
    int c = 0;
    while (c < static_cast<int>(seen_by.size()) && seen_by[c] == t) ++c;
    if (c == static_cast<int>(seen_by.size())) {
      seen_by.push_back(-1);
      colours_.emplace_back();
    }
    colour[t] = c;
    colours_[c].push_back(static_cast<int>(t));
  }
  // Within a colour, visit tets in the order of their smallest DOF: the scatter then walks
  // the value array forwards instead of jumping around (the order does not change results
  // between thread counts: each colour's writes never overlap).
  const Eigen::VectorXi& free_index = body_.free_index();
  auto first_dof = [&](int t) {
    int smallest = std::numeric_limits<int>::max();
    for (int k = 0; k < 4; ++k) {
      const int f = free_index[tets(t, k)];
      if (f >= 0) smallest = std::min(smallest, f);
    }
    return smallest;
  };
  for (std::vector<int>& members : colours_) {
    std::stable_sort(members.begin(), members.end(),
                     [&](int a, int b) { return first_dof(a) < first_dof(b); });
  }
}

void ReducedSystem::ZeroHessian(SparseMatrix* hessian) const {
  if (hessian->rows() != pattern_.rows() || hessian->nonZeros() != pattern_.nonZeros() ||
      !hessian->isCompressed()) {
    *hessian = pattern_;
  } else {
    std::fill(hessian->valuePtr(), hessian->valuePtr() + hessian->nonZeros(), 0.0);
  }
}

double ReducedSystem::Energy(const BodyState& state, const Vertices& positions) const {
  const Tetrahedra& tets = body_.rest().tets;
  std::vector<double> element(static_cast<size_t>(tets.rows()));
#pragma omp parallel for schedule(static) if (tets.rows() >= Eigen::Index(kMinParallelColour))
  for (Eigen::Index t = 0; t < tets.rows(); ++t)
    element[t] = kernel_.Energy(t, TetCorners(positions, tets.row(t)));
  double energy = 0;
  for (double e : element) energy += e;  // fixed order: deterministic
  const Eigen::Vector3d& g = body_.gravity();
  for (Eigen::Index v = 0; v < positions.rows(); ++v)
    energy -= body_.vertex_mass()[v] * g.dot(positions.row(v).transpose());
  energy -= body_.core_mass() * g.dot(state.centre);
  energy -= body_.options().external_force.dot(state.centre);
  energy -= body_.options().external_torque.dot(state.torque_angle);
  return energy;
}

void ReducedSystem::Evaluate(const BodyState& state, const Vertices& positions, HessianKind kind,
                             bool with_hessian, Evaluation* evaluation) const {
  const Tetrahedra& tets = body_.rest().tets;
  Evaluation& e = *evaluation;
  e.with_hessian = with_hessian;
  e.vertex_gradient = Vertices::Zero(positions.rows(), 3);
  e.core_gradient.setZero();
  e.core_block.setZero();
  if (with_hessian) ZeroHessian(&e.hessian);
  double* values = with_hessian ? e.hessian.valuePtr() : nullptr;

  std::vector<double> element_energy(static_cast<size_t>(tets.rows()));
  std::vector<Matrix6d> core_buffer(with_hessian ? static_cast<size_t>(core_slots_) : 0);
  const std::vector<int>& components = layout_.core_components();
  const int core_count = layout_.core_count();

  for (const std::vector<int>& colour : colours_) {
    // A barrier per colour costs more than a small colour's work (badly so when the
    // machine is busy): small colours run on one thread. The result does not change.
#pragma omp parallel for schedule(static) if (colour.size() >= kMinParallelColour)
    for (size_t i = 0; i < colour.size(); ++i) {
      const int t = colour[i];
      const ElementPlan& plan = plans_[t];
      const TetPositions x = TetCorners(positions, tets.row(t));
      Vector12d gradient;
      Matrix12d hessian;
      element_energy[t] = with_hessian
                              ? kernel_.EnergyGradientHessian(t, x, kind, &gradient, &hessian)
                              : kernel_.EnergyGradient(t, x, &gradient);
      for (int k = 0; k < 4; ++k)
        e.vertex_gradient.row(tets(t, k)) += gradient.segment<3>(3 * k).transpose();
      if (!with_hessian) continue;

      for (int p = 0; p < 10; ++p) {
        if (plan.block[p][0] < 0) continue;
        const int a = kPairs[p][0], b = kPairs[p][1];
        const Eigen::Matrix3d block = plan.transposed[p]
                                          ? Eigen::Matrix3d(hessian.block<3, 3>(3 * b, 3 * a))
                                          : Eigen::Matrix3d(hessian.block<3, 3>(3 * a, 3 * b));
        for (int c = 0; c < 3; ++c) {
          const int rows = a == b ? c + 1 : 3;  // diagonal blocks: upper triangle only
          for (int r = 0; r < rows; ++r) values[plan.block[p][c] + r] += block(r, c);
        }
      }
      if (plan.core_slot < 0) continue;
      // Corners on the core enter through B: K^FA B for free rows, Bᵀ K^AA B for q-q.
      std::array<Eigen::Matrix<double, 3, 6>, 4> jacobian;
      for (int k = 0; k < 4; ++k) {
        if (plan.free_dof[k] < 0) jacobian[k] = FullCoreJacobian(x.col(k) - state.centre);
      }
      Matrix6d core = Matrix6d::Zero();
      for (int a = 0; a < 4; ++a) {
        Eigen::Matrix<double, 3, 6> coupling = Eigen::Matrix<double, 3, 6>::Zero();
        for (int b = 0; b < 4; ++b) {
          if (plan.free_dof[b] >= 0) continue;
          coupling += hessian.block<3, 3>(3 * a, 3 * b) * jacobian[b];
        }
        if (plan.free_dof[a] >= 0) {
          const auto& index = free_core_index_[plan.free_dof[a] / 3];
          for (int j = 0; j < core_count; ++j)
            for (int r = 0; r < 3; ++r) values[index[j] + r] += coupling(r, components[j]);
        } else {
          core += jacobian[a].transpose() * coupling;
        }
      }
      core_buffer[plan.core_slot] = core;
    }
  }

  double energy = 0;
  for (double value : element_energy) energy += value;  // fixed order: deterministic
  for (const Matrix6d& block : core_buffer) e.core_block += block;
  const Eigen::Vector3d& g = body_.gravity();
  for (Eigen::Index v = 0; v < positions.rows(); ++v) {
    const double m = body_.vertex_mass()[v];
    energy -= m * g.dot(positions.row(v).transpose());
    e.vertex_gradient.row(v) -= m * g.transpose();
  }
  const Eigen::Vector3d& force = body_.options().external_force;
  const Eigen::Vector3d& torque = body_.options().external_torque;
  energy -= body_.core_mass() * g.dot(state.centre) + force.dot(state.centre) +
            torque.dot(state.torque_angle);
  e.core_gradient.head<3>() = -body_.core_mass() * g - force;
  e.core_gradient.tail<3>() = -torque;
  e.energy = energy;
}

void ReducedSystem::AddVertexHessian(const BodyState& state, const Vertices& positions, int vertex,
                                     const Eigen::Matrix3d& block, Evaluation* evaluation) const {
  CHECK(evaluation->with_hessian);
  const int f = body_.free_index()[vertex];
  if (f >= 0) {
    double* values = evaluation->hessian.valuePtr();
    // Diagonal block of free vertex f: upper triangle of columns 3f..3f+2.
    for (int c = 0; c < 3; ++c) {
      const int base = ValueIndex(evaluation->hessian, 3 * f, 3 * f + c);
      for (int r = 0; r <= c; ++r) values[base + r] += block(r, c);
    }
    return;
  }
  const Eigen::Matrix<double, 3, 6> b =
      FullCoreJacobian(positions.row(vertex).transpose() - state.centre);
  evaluation->core_block += b.transpose() * block * b;
}

void ReducedSystem::AddVertexBlockHessian(const BodyState& state, const Vertices& positions,
                                          const std::vector<int>& vertices,
                                          const Eigen::MatrixXd& block,
                                          Evaluation* evaluation) const {
  CHECK(evaluation->with_hessian);
  const auto n = static_cast<int>(vertices.size());
  CHECK(block.rows() == 3 * n && block.cols() == 3 * n);
  const Eigen::VectorXi& free_index = body_.free_index();
  const std::vector<int>& components = layout_.core_components();
  double* values = evaluation->hessian.valuePtr();
  std::vector<Eigen::Matrix<double, 3, 6>> jacobian(static_cast<size_t>(n));
  for (int a = 0; a < n; ++a)
    if (free_index[vertices[a]] < 0)
      jacobian[a] = FullCoreJacobian(positions.row(vertices[a]).transpose() - state.centre);
  for (int a = 0; a < n; ++a) {
    const int fa = free_index[vertices[a]];
    for (int b = 0; b < n; ++b) {
      const int fb = free_index[vertices[b]];
      const Eigen::Matrix3d h = block.block<3, 3>(3 * a, 3 * b);
      if (fa >= 0 && fb >= 0) {
        // Upper triangle: each unordered free pair once (from its row-major side).
        if (fa > fb) continue;
        for (int c = 0; c < 3; ++c) {
          const int base = ValueIndex(evaluation->hessian, 3 * fa, 3 * fb + c);
          const int rows = fa == fb ? c + 1 : 3;
          for (int r = 0; r < rows; ++r) values[base + r] += h(r, c);
        }
      } else if (fa >= 0) {
        // Free row, core column: K^FA B (its transpose is the lower triangle).
        const Eigen::Matrix<double, 3, 6> coupling = h * jacobian[b];
        const auto& index = free_core_index_[fa];
        for (int j = 0; j < layout_.core_count(); ++j) {
          CHECK_GE(index[j], 0) << "free vertex " << vertices[a] << " shares no tet with the core";
          for (int r = 0; r < 3; ++r) values[index[j] + r] += coupling(r, components[j]);
        }
      } else if (fb < 0) {
        evaluation->core_block += jacobian[a].transpose() * h * jacobian[b];
      }
    }
  }
}

Eigen::VectorXd ReducedSystem::Finalize(const BodyState& state, const Vertices& positions,
                                        HessianKind kind, Evaluation* evaluation) const {
  Evaluation& e = *evaluation;
  Eigen::VectorXd gradient = layout_.ReduceGradient(body_, state, positions, e.vertex_gradient);
  const std::vector<int>& components = layout_.core_components();
  for (int j = 0; j < layout_.core_count(); ++j)
    gradient[layout_.core_offset() + j] += e.core_gradient[components[j]];
  if (!e.with_hessian) return gradient;

  // Lever-arm term: second derivative of p_a = c + exp([θ]×) h_a contracted with g_a.
  Eigen::Matrix3d lever = Eigen::Matrix3d::Zero();
  for (Eigen::Index a : body_.attached_vertices()) {
    const Eigen::Vector3d g = e.vertex_gradient.row(a).transpose();
    const Eigen::Vector3d h = positions.row(a).transpose() - state.centre;
    lever += 0.5 * (g * h.transpose() + h * g.transpose()) - g.dot(h) * Eigen::Matrix3d::Identity();
  }
  std::vector<int> rotations;
  for (int c : components)
    if (c >= 3) rotations.push_back(c - 3);
  if (kind == HessianKind::kProjectedPsd && !rotations.empty()) {
    // Project the term restricted to the free rotation axes.
    const auto k = static_cast<Eigen::Index>(rotations.size());
    Eigen::MatrixXd restricted(k, k);
    for (Eigen::Index i = 0; i < k; ++i)
      for (Eigen::Index j = 0; j < k; ++j) restricted(i, j) = lever(rotations[i], rotations[j]);
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(restricted);
    const Eigen::MatrixXd projected = eigen.eigenvectors() *
                                      eigen.eigenvalues().cwiseMax(0.0).asDiagonal() *
                                      eigen.eigenvectors().transpose();
    lever.setZero();
    for (Eigen::Index i = 0; i < k; ++i)
      for (Eigen::Index j = 0; j < k; ++j) lever(rotations[i], rotations[j]) = projected(i, j);
  }
  e.core_block.bottomRightCorner<3, 3>() += lever;
  AddCoreBlockToHessian(e.core_block, &e.hessian);
  return gradient;
}

void ReducedSystem::AddCoreBlockToHessian(const Matrix6d& block, SparseMatrix* hessian) const {
  const std::vector<int>& components = layout_.core_components();
  double* values = hessian->valuePtr();
  for (int i = 0; i < layout_.core_count(); ++i)
    for (int j = i; j < layout_.core_count(); ++j)
      values[core_index_[i][j]] += block(components[i], components[j]);
}

void ReducedSystem::AddScaledMass(double alpha, const BodyState& state, const Vertices& positions,
                                  SparseMatrix* hessian) const {
  CHECK_EQ(hessian->nonZeros(), pattern_.nonZeros());
  double* values = hessian->valuePtr();
  const Eigen::VectorXi& free = body_.free_vertices();
  for (Eigen::Index f = 0; f < free.size(); ++f) {
    const double m = alpha * body_.vertex_mass()[free[f]];
    for (int c = 0; c < 3; ++c)
      values[ValueIndex(*hessian, 3 * static_cast<int>(f) + c, 3 * static_cast<int>(f) + c)] += m;
  }
  Matrix6d core = Matrix6d::Zero();
  for (Eigen::Index a : body_.attached_vertices()) {
    const Eigen::Matrix<double, 3, 6> b =
        FullCoreJacobian(positions.row(a).transpose() - state.centre);
    core += body_.vertex_mass()[a] * b.transpose() * b;
  }
  core.topLeftCorner<3, 3>() += body_.core_mass() * Eigen::Matrix3d::Identity();
  core.bottomRightCorner<3, 3>() +=
      state.rotation * body_.core_inertia() * state.rotation.transpose();
  AddCoreBlockToHessian(alpha * core, hessian);
}

}  // namespace ergo
