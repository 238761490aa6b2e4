#include "ergo/ergonomics/biharmonic_interpolation.h"

#include <cmath>
#include <map>
#include <sstream>
#include <vector>

#include <glog/logging.h>
#include <Eigen/Cholesky>
#include <Eigen/SVD>

#include "ergo/ergonomics/linearly_precise_laplacian.h"
#include "ergo/mesh/cotangent_stiffness.h"
#include "ergo/mesh/sparse_cholesky.h"
#include "ergo/mesh/surface_geometry.h"

namespace ergo {
namespace {

// S = B A⁻¹ Bᵀ is positive definite in exact arithmetic whenever B has full row rank; a
// reciprocal condition number below this means two handles (nearly) share a point and the
// weights would amplify the difference of their values without bound.
constexpr double kMinHandleConditioning = 1e-12;
// Handles whose spread across their best-fit line is below this fraction of their spread
// along it are on one line: the field across the line would be unconstrained (E vanishes on
// the linear function that is zero on the line), and a factorisation of the nearly singular
// A might not notice in round-off.
constexpr double kMinHandleSpreadRatio = 1e-6;

int Root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// Every edge-connected part of the surface must hold three handles not on one line, or E's
// null space (constants and linear functions on each part) is not pinned. "" when it holds.
std::string CheckHandleLayout(const TriMesh& surface, const std::vector<SurfacePoint>& handles) {
  const Eigen::Index n = surface.vertices.rows();
  std::vector<int> parent(static_cast<size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) parent[i] = static_cast<int>(i);
  for (Eigen::Index f = 0; f < surface.triangles.rows(); ++f)
    for (int k = 1; k < 3; ++k)
      parent[Root(parent, surface.triangles(f, k))] = Root(parent, surface.triangles(f, 0));
  std::map<int, std::vector<Eigen::Vector3d>> points_of_part;
  for (Eigen::Index f = 0; f < surface.triangles.rows(); ++f)
    points_of_part[Root(parent, surface.triangles(f, 0))];  // every part, with or without handles
  for (const SurfacePoint& handle : handles) {
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k)
      point += handle.barycentric[k] *
               surface.vertices.row(surface.triangles(handle.triangle, k)).transpose();
    points_of_part[Root(parent, surface.triangles(handle.triangle, 0))].push_back(point);
  }
  for (const auto& [root, points] : points_of_part) {
    std::ostringstream where;
    where << "the part of the surface around vertex (" << surface.vertices.row(root) << ") m";
    if (points.size() < 3) {
      return where.str() + " holds " + std::to_string(points.size()) +
             " handles: each part needs at least three, not on one line";
    }
    Eigen::MatrixXd centred(static_cast<Eigen::Index>(points.size()), 3);
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& p : points) mean += p / static_cast<double>(points.size());
    for (size_t i = 0; i < points.size(); ++i)
      centred.row(static_cast<Eigen::Index>(i)) = (points[i] - mean).transpose();
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(centred);
    const Eigen::VectorXd spread = svd.singularValues();
    if (!(spread[1] > kMinHandleSpreadRatio * spread[0])) {
      return "the handles on " + where.str() +
             " lie on one line: the field across it would be undetermined";
    }
  }
  return "";
}

}  // namespace

Eigen::VectorXd BiharmonicWeights::Interpolate(const Eigen::VectorXd& handle_values) const {
  CHECK(ok) << message;
  CHECK_EQ(handle_values.size(), weights.cols());
  return weights * handle_values;
}

BiharmonicWeights ComputeBiharmonicWeights(const TriMesh& surface,
                                           const std::vector<SurfacePoint>& handles,
                                           const BiharmonicOptions& options) {
  BiharmonicWeights result;
  const Eigen::Index n = surface.vertices.rows();
  const auto h = static_cast<Eigen::Index>(handles.size());
  if (h < 3) {
    result.message = "fewer than three handles (" + std::to_string(h) +
                     "): a surface field needs at least three points not on one line";
    return result;
  }
  for (size_t j = 0; j < handles.size(); ++j) {
    CHECK(handles[j].triangle >= 0 && handles[j].triangle < surface.triangles.rows())
        << "handle " << j << " has no triangle";
  }
  const std::string layout = CheckHandleLayout(surface, handles);
  if (!layout.empty()) {
    result.message = layout;
    return result;
  }
  const SparseMatrix laplacian =
      options.linearly_precise
          ? LinearlyPreciseLaplacian(surface)
          : SparseMatrix(-CotangentStiffness(surface.triangles, surface.vertices));
  const Eigen::VectorXd mass = BarycentricVertexAreas(surface);
  Eigen::VectorXd inverse_mass(n);
  for (Eigen::Index i = 0; i < n; ++i) inverse_mass[i] = mass[i] > 0 ? 1 / mass[i] : 0;
  const SparseMatrix energy =
      SparseMatrix(laplacian.transpose()) * inverse_mass.asDiagonal() * laplacian;

  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index j = 0; j < h; ++j) {
    const SurfacePoint& point = handles[static_cast<size_t>(j)];
    for (int k = 0; k < 3; ++k)
      entries.emplace_back(j, surface.triangles(point.triangle, k), point.barycentric[k]);
  }
  SparseMatrix constraints(h, n);
  constraints.setFromTriplets(entries.begin(), entries.end());
  const SparseMatrix normal = SparseMatrix(constraints.transpose()) * constraints;
  // Any ρ > 0 gives the same minimiser; ρ = tr Q / tr BᵀB keeps both terms of one size.
  double energy_trace = 0, normal_trace = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    energy_trace += energy.coeff(i, i);
    normal_trace += normal.coeff(i, i);
  }
  const double rho = energy_trace > 0 ? energy_trace / normal_trace : 1.0;
  const SparseMatrix system = energy + rho * normal;

  SparseCholesky cholesky;
  cholesky.Analyze(system);
  const FactorizationStatus status = cholesky.Factorize(system);
  if (!status.ok) {
    result.message =
        "the handles do not determine the field: they lie on one line, or a part of the "
        "surface holds none (" +
        status.message + ")";
    return result;
  }
  const Eigen::MatrixXd dense_constraints_t = Eigen::MatrixXd(constraints.transpose());
  Eigen::MatrixXd z(n, h);
  for (Eigen::Index j = 0; j < h; ++j) z.col(j) = cholesky.Solve(dense_constraints_t.col(j));
  Eigen::MatrixXd schur = constraints * z;
  schur = 0.5 * (schur + schur.transpose());  // symmetric in exact arithmetic
  const Eigen::LLT<Eigen::MatrixXd> llt(schur);
  if (llt.info() != Eigen::Success || !(llt.rcond() > kMinHandleConditioning)) {
    std::ostringstream message;
    message << "two handles (nearly) coincide: the interpolation would not be stable "
               "(reciprocal condition "
            << (llt.info() == Eigen::Success ? llt.rcond() : 0.0) << ")";
    result.message = message.str();
    return result;
  }
  // W = Z S⁻¹ = (S⁻¹ Zᵀ)ᵀ with S symmetric.
  result.weights = llt.solve(z.transpose()).transpose();
  result.ok = true;
  result.message = "ok";
  return result;
}

}  // namespace ergo
