#include "ergo/body/rest_extension.h"

#include <algorithm>
#include <set>
#include <utility>

#include <glog/logging.h>

namespace ergo {

RestExtension::RestExtension(const TetMesh& mesh, const std::vector<bool>& designed,
                             const std::vector<bool>& fixed) {
  const Eigen::Index n = mesh.vertices.rows();
  CHECK_EQ(static_cast<Eigen::Index>(designed.size()), n);
  CHECK_EQ(static_cast<Eigen::Index>(fixed.size()), n);
  interior_index_ = Eigen::VectorXi::Constant(n, -1);
  for (Eigen::Index v = 0; v < n; ++v) {
    CHECK(!(designed[v] && fixed[v])) << "vertex " << v << " both designed and fixed";
    if (designed[v]) {
      designed_.push_back(static_cast<int>(v));
    } else if (!fixed[v]) {
      interior_index_[v] = static_cast<int>(interior_.size());
      interior_.push_back(static_cast<int>(v));
    }
  }
  // The edges of the tets, once each.
  std::set<std::pair<int, int>> edges;
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t)
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) edges.insert(std::minmax(mesh.tets(t, a), mesh.tets(t, b)));
  // L = D − A (uniform weights): the interior block and its coupling to designed vertices.
  std::vector<Eigen::Triplet<double>> block, coupling;
  const auto m = static_cast<int>(interior_.size());
  Eigen::VectorXd degree = Eigen::VectorXd::Zero(m);
  for (const auto& [a, b] : edges) {
    const int ia = interior_index_[a], ib = interior_index_[b];
    if (ia >= 0) degree[ia] += 1;
    if (ib >= 0) degree[ib] += 1;
    if (ia >= 0 && ib >= 0) {
      block.emplace_back(std::min(ia, ib), std::max(ia, ib), -1.0);
    } else if (ia >= 0 && designed[b]) {
      coupling.emplace_back(ia, b, -1.0);
    } else if (ib >= 0 && designed[a]) {
      coupling.emplace_back(ib, a, -1.0);
    }
  }
  for (int i = 0; i < m; ++i) block.emplace_back(i, i, degree[i]);
  interior_block_.resize(m, m);
  interior_block_.setFromTriplets(block.begin(), block.end());
  interior_block_.makeCompressed();
  coupling_.resize(m, n);
  coupling_.setFromTriplets(coupling.begin(), coupling.end());
  if (m > 0) {
    cholesky_.Analyze(interior_block_);
    // Positive definite once each interior component touches a designed or fixed vertex.
    const FactorizationStatus status = cholesky_.Factorize(interior_block_);
    CHECK(status.ok) << "interior vertices without a path to the boundary: " << status.message;
  }
}

Vertices RestExtension::Extend(const Vertices& designed_displacement) const {
  Vertices out = Vertices::Zero(designed_displacement.rows(), 3);
  for (int v : designed_) out.row(v) = designed_displacement.row(v);
  if (interior_.empty()) return out;
  for (int c = 0; c < 3; ++c) {
    const Eigen::VectorXd rhs = -(coupling_ * out.col(c));
    const Eigen::VectorXd u = cholesky_.Solve(rhs);
    for (size_t i = 0; i < interior_.size(); ++i) out(interior_[i], c) = u[i];
  }
  return out;
}

Vertices RestExtension::PullBack(const Vertices& gradient) const {
  Vertices out = Vertices::Zero(gradient.rows(), 3);
  for (int v : designed_) out.row(v) = gradient.row(v);
  if (interior_.empty()) return out;
  for (int c = 0; c < 3; ++c) {
    Eigen::VectorXd interior(interior_.size());
    for (size_t i = 0; i < interior_.size(); ++i) interior[i] = gradient(interior_[i], c);
    // u_I = −L_II⁻¹ L_ID u_D, so the pull-back of g_I is −L_IDᵀ L_II⁻¹ g_I (L_II symmetric).
    const Eigen::VectorXd solved = cholesky_.Solve(interior);
    const Eigen::VectorXd back = -(coupling_.transpose() * solved);
    for (int v : designed_) out(v, c) += back[v];
  }
  return out;
}

}  // namespace ergo
