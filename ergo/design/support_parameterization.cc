#include "ergo/design/support_parameterization.h"

#include <cmath>

#include <glog/logging.h>

#include "ergo/design/spline_lattice.h"
#include "ergo/mesh/cotangent_stiffness.h"
#include "ergo/mesh/surface_geometry.h"

namespace ergo {

SupportParameterization::SupportParameterization(const TriMesh& initial, std::vector<bool> active,
                                                 DesignParameterization kind, double filter_radius,
                                                 bool l2_metric)
    : initial_(initial.vertices),
      normals_(VertexNormals(initial)),
      kind_(kind),
      l2_metric_(l2_metric && kind == DesignParameterization::kFiltered) {
  CHECK(active.empty() || active.size() == static_cast<size_t>(initial.vertices.rows()));
  std::vector<int> ids;
  for (Eigen::Index v = 0; v < initial.vertices.rows(); ++v)
    if (active.empty() || active[v]) ids.push_back(static_cast<int>(v));
  active_ = Eigen::Map<Eigen::VectorXi>(ids.data(), static_cast<Eigen::Index>(ids.size()));
  if (kind_ == DesignParameterization::kFiltered) {
    CHECK(filter_radius > 0 && std::isfinite(filter_radius))
        << "the filtered design space needs a filter radius > 0 m, got " << filter_radius;
    filter_radius_ = filter_radius;
    BuildFilter(initial);
  }
  if (kind_ == DesignParameterization::kSpline) {
    CHECK(filter_radius > 0 && std::isfinite(filter_radius))
        << "the spline design space needs a knot spacing > 0 m, got " << filter_radius;
    filter_radius_ = filter_radius;
    BuildSpline();
  }
}

void SupportParameterization::BuildSpline() {
  Eigen::MatrixXd points(active_.size(), 3);
  for (Eigen::Index i = 0; i < active_.size(); ++i) points.row(i) = initial_.row(active_[i]);
  // The lattice hangs from the whole support's lowest corner, not the designed vertices':
  // the same on every mesh of the support (spline_lattice.h).
  const Eigen::Vector3d origin =
      initial_.colwise().minCoeff().transpose() - Eigen::Vector3d::Constant(0.5 * filter_radius_);
  spline_basis_ = SplineLattice(points, filter_radius_, origin).basis();
}

void SupportParameterization::BuildFilter(const TriMesh& initial) {
  const Eigen::Index n = active_.size();
  if (n == 0) return;  // nothing to design, nothing to filter
  // Designed triangles in the active vertices' numbering.
  Eigen::VectorXi local = Eigen::VectorXi::Constant(initial.vertices.rows(), -1);
  for (Eigen::Index i = 0; i < n; ++i) local[active_[i]] = static_cast<int>(i);
  std::vector<int> designed;
  for (Eigen::Index f = 0; f < initial.triangles.rows(); ++f) {
    const int a = local[initial.triangles(f, 0)], b = local[initial.triangles(f, 1)],
              c = local[initial.triangles(f, 2)];
    if (a >= 0 && b >= 0 && c >= 0) designed.insert(designed.end(), {a, b, c});
  }
  TriMesh region;
  region.vertices.resize(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) region.vertices.row(i) = initial_.row(active_[i]);
  region.triangles =
      Eigen::Map<Triangles>(designed.data(), static_cast<Eigen::Index>(designed.size() / 3), 3);

  filter_mass_ = BarycentricVertexAreas(region);
  const Eigen::Index massive = (filter_mass_.array() > 0).count();
  const double stand_in = massive > 0 ? filter_mass_.sum() / static_cast<double>(massive) : 1.0;
  // A vertex without area has a zero row in M and K (degenerate triangles add nothing to
  // either): a positive M_ii makes A_ii = M_ii and so F's row the identity.
  for (Eigen::Index i = 0; i < n; ++i)
    if (!(filter_mass_[i] > 0)) filter_mass_[i] = stand_in;
  const double reference_area = std::pow(filter_radius_ / 2.5, 2);
  metric_weight_ = l2_metric_ ? (filter_mass_ / reference_area).cwiseSqrt().eval()
                              : Eigen::VectorXd::Ones(n).eval();

  const double R = filter_radius_ / (2.0 * std::sqrt(3.0));
  SparseMatrix mass(n, n);
  mass.reserve(Eigen::VectorXi::Ones(n));
  for (Eigen::Index i = 0; i < n; ++i) mass.insert(i, i) = filter_mass_[i];
  filter_matrix_ = mass + (R * R) * CotangentStiffness(region.triangles, region.vertices);
  filter_matrix_.makeCompressed();
  filter_cholesky_.Analyze(filter_matrix_);
  const FactorizationStatus status = filter_cholesky_.Factorize(filter_matrix_);
  // M > 0 and K ⪰ 0, so A is positive definite: a failure is a bug, not a user error.
  CHECK(status.ok) << "the Helmholtz filter matrix M + R²K: " << status.message;
}

Eigen::VectorXd SupportParameterization::Filter(const Eigen::VectorXd& theta) const {
  if (theta.size() == 0) return theta;
  return filter_cholesky_.Solve(filter_mass_.cwiseProduct(theta.cwiseQuotient(metric_weight_)));
}

Eigen::VectorXd SupportParameterization::FilterTransposed(const Eigen::VectorXd& g) const {
  if (g.size() == 0) return g;
  return filter_mass_.cwiseProduct(filter_cholesky_.Solve(g)).cwiseQuotient(metric_weight_);
}

int SupportParameterization::size() const {
  if (kind_ == DesignParameterization::kSpline) return static_cast<int>(spline_basis_.cols());
  return static_cast<int>(active_.size()) * (kind_ == DesignParameterization::kPositions ? 3 : 1);
}

Eigen::VectorXd SupportParameterization::InitialDesign() const {
  if (kind_ != DesignParameterization::kPositions) return Eigen::VectorXd::Zero(size());
  Eigen::VectorXd x(size());
  for (Eigen::Index i = 0; i < active_.size(); ++i)
    x.segment<3>(3 * i) = initial_.row(active_[i]).transpose();
  return x;
}

Vertices SupportParameterization::Positions(const Eigen::VectorXd& x) const {
  CHECK_EQ(x.size(), size());
  Vertices positions = initial_;
  if (kind_ == DesignParameterization::kPositions) {
    for (Eigen::Index i = 0; i < active_.size(); ++i)
      positions.row(active_[i]) = x.segment<3>(3 * i).transpose();
    return positions;
  }
  const Eigen::VectorXd along_normal = AlongNormal(x);
  for (Eigen::Index i = 0; i < active_.size(); ++i) {
    const int v = active_[i];
    positions.row(v) = initial_.row(v) + along_normal[i] * normals_.row(v);
  }
  return positions;
}

Eigen::VectorXd SupportParameterization::PullBack(const Vertices& position_gradient) const {
  CHECK_EQ(position_gradient.rows(), initial_.rows());
  // Per active vertex (3 numbers each for kPositions), then through the filter or spline.
  const Eigen::Index per_vertex = kind_ == DesignParameterization::kPositions ? 3 : 1;
  Eigen::VectorXd gradient(per_vertex * active_.size());
  for (Eigen::Index i = 0; i < active_.size(); ++i) {
    const int v = active_[i];
    if (kind_ == DesignParameterization::kPositions) {
      gradient.segment<3>(3 * i) = position_gradient.row(v).transpose();
    } else {
      gradient[i] = position_gradient.row(v).dot(normals_.row(v));
    }
  }
  if (kind_ == DesignParameterization::kSpline) return spline_basis_.transpose() * gradient;
  return kind_ == DesignParameterization::kFiltered ? FilterTransposed(gradient) : gradient;
}

Eigen::VectorXd SupportParameterization::VertexMoves(const Eigen::VectorXd& dx) const {
  CHECK_EQ(dx.size(), size());
  Eigen::VectorXd moves(active_.size());
  if (kind_ == DesignParameterization::kFiltered || kind_ == DesignParameterization::kSpline) {
    const Eigen::VectorXd displacement = AlongNormal(dx);
    for (Eigen::Index i = 0; i < active_.size(); ++i)
      moves[i] = std::abs(displacement[i]) * normals_.row(active_[i]).norm();
    return moves;
  }
  for (Eigen::Index i = 0; i < active_.size(); ++i)
    moves[i] =
        kind_ == DesignParameterization::kPositions ? dx.segment<3>(3 * i).norm() : std::abs(dx[i]);
  return moves;
}

double SupportParameterization::BoxHalfWidthForMove(double move) const {
  if (kind_ == DesignParameterization::kPositions) return move / std::sqrt(3.0);
  // B ≥ 0 with rows summing to 1: |Bc| ≤ max|c|.
  if (kind_ == DesignParameterization::kSpline) return move;
  // F averages (F·1 = 1, F ≥ 0 where A is an M-matrix, as on the scenes' grid tops), so
  // |Fθ| ≤ max|θ|: |θᵢ| ≤ move suffices.
  if (!l2_metric_ || metric_weight_.size() == 0) return move;
  return move * metric_weight_.minCoeff();
}

Eigen::VectorXd SupportParameterization::AlongNormal(const Eigen::VectorXd& x) const {
  switch (kind_) {
    case DesignParameterization::kFiltered:
      return Filter(x);
    case DesignParameterization::kSpline:
      return spline_basis_ * x;
    default:
      return x;
  }
}

Eigen::VectorXd SupportParameterization::NormalDisplacements(const Vertices& positions) const {
  Eigen::VectorXd displacement(active_.size());
  for (Eigen::Index i = 0; i < active_.size(); ++i) {
    const int v = active_[i];
    displacement[i] = (positions.row(v) - initial_.row(v)).dot(normals_.row(v));
  }
  return displacement;
}

Eigen::VectorXd SupportParameterization::DesignFor(const Vertices& positions) const {
  CHECK_EQ(positions.rows(), initial_.rows());
  switch (kind_) {
    case DesignParameterization::kPositions: {
      Eigen::VectorXd x(size());
      for (Eigen::Index i = 0; i < active_.size(); ++i)
        x.segment<3>(3 * i) = positions.row(active_[i]).transpose();
      return x;
    }
    case DesignParameterization::kNormalDisplacement:
      return NormalDisplacements(positions);
    case DesignParameterization::kFiltered:
      return (filter_matrix_ * NormalDisplacements(positions))
          .cwiseQuotient(filter_mass_)
          .cwiseProduct(metric_weight_);
    case DesignParameterization::kSpline: {
      if (size() == 0) return Eigen::VectorXd();
      SparseMatrix normal = spline_basis_.transpose() * spline_basis_;
      // ε: 1e-9 of the mean diagonal makes the redundant layers' normal matrix definite and
      // picks the minimum-norm controls among them; it also damps the fit along directions
      // the lattice reaches only through corner weights ~(1/48)³ (4e-6 of a move on the test
      // block), which matters for a start design, not for a gradient.
      const double epsilon = 1e-9 * normal.diagonal().mean();
      for (Eigen::Index c = 0; c < normal.rows(); ++c) normal.coeffRef(c, c) += epsilon;
      SparseCholesky cholesky;
      cholesky.Analyze(normal);
      const FactorizationStatus status = cholesky.Factorize(normal);
      // BᵀB ⪰ 0 plus ε > 0 is positive definite: a failure is a bug, not a user error.
      CHECK(status.ok) << "the spline's normal equations: " << status.message;
      return cholesky.Solve(spline_basis_.transpose() * NormalDisplacements(positions));
    }
  }
  LOG(FATAL) << "unknown parameterization";
  return {};
}

}  // namespace ergo
