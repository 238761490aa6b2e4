#include "ergo/design/support_parameterization.h"

#include <glog/logging.h>

#include "ergo/mesh/surface_geometry.h"

namespace ergo {

SupportParameterization::SupportParameterization(const TriMesh& initial, std::vector<bool> active,
                                                 DesignParameterization kind)
    : initial_(initial.vertices), normals_(VertexNormals(initial)), kind_(kind) {
  CHECK(active.empty() || active.size() == static_cast<size_t>(initial.vertices.rows()));
  std::vector<int> ids;
  for (Eigen::Index v = 0; v < initial.vertices.rows(); ++v)
    if (active.empty() || active[v]) ids.push_back(static_cast<int>(v));
  active_ = Eigen::Map<Eigen::VectorXi>(ids.data(), static_cast<Eigen::Index>(ids.size()));
}

int SupportParameterization::size() const {
  return static_cast<int>(active_.size()) * (kind_ == DesignParameterization::kPositions ? 3 : 1);
}

Eigen::VectorXd SupportParameterization::InitialDesign() const {
  if (kind_ == DesignParameterization::kNormalDisplacement) return Eigen::VectorXd::Zero(size());
  Eigen::VectorXd x(size());
  for (Eigen::Index i = 0; i < active_.size(); ++i)
    x.segment<3>(3 * i) = initial_.row(active_[i]).transpose();
  return x;
}

Vertices SupportParameterization::Positions(const Eigen::VectorXd& x) const {
  CHECK_EQ(x.size(), size());
  Vertices positions = initial_;
  for (Eigen::Index i = 0; i < active_.size(); ++i) {
    const int v = active_[i];
    if (kind_ == DesignParameterization::kPositions) {
      positions.row(v) = x.segment<3>(3 * i).transpose();
    } else {
      positions.row(v) = initial_.row(v) + x[i] * normals_.row(v);
    }
  }
  return positions;
}

Eigen::VectorXd SupportParameterization::PullBack(const Vertices& position_gradient) const {
  CHECK_EQ(position_gradient.rows(), initial_.rows());
  Eigen::VectorXd gradient(size());
  for (Eigen::Index i = 0; i < active_.size(); ++i) {
    const int v = active_[i];
    if (kind_ == DesignParameterization::kPositions) {
      gradient.segment<3>(3 * i) = position_gradient.row(v).transpose();
    } else {
      gradient[i] = position_gradient.row(v).dot(normals_.row(v));
    }
  }
  return gradient;
}

Eigen::VectorXd SupportParameterization::VertexMoves(const Eigen::VectorXd& dx) const {
  CHECK_EQ(dx.size(), size());
  Eigen::VectorXd moves(active_.size());
  for (Eigen::Index i = 0; i < active_.size(); ++i)
    moves[i] =
        kind_ == DesignParameterization::kPositions ? dx.segment<3>(3 * i).norm() : std::abs(dx[i]);
  return moves;
}

}  // namespace ergo
