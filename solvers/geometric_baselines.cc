#include "solvers/geometric_baselines.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <ceres/ceres.h>
#include <glog/logging.h>

#include "ergo/mesh/input_error.h"
#include "ergo/mesh/surface_geometry.h"

namespace ergo {
namespace {

// The body's underside over the designed support, the body resting on the support.
struct Underside {
  Eigen::Vector3d up;           // against the load
  Eigen::VectorXd gap;          // per support vertex: skin height above it at rest on it, m
  Eigen::VectorXi skin_vertex;  // per support vertex: the skin vertex giving it (-1: none)
  Vertices positions;           // tet-mesh vertices at the start pose
  TriMesh skin;                 // skin triangles over `positions`
};

Underside MeasureUnderside(const DesignProblem& problem, const BodyState& start) {
  const LayeredBody& body = problem.body();
  const TriMesh& support = problem.initial_support();
  const Eigen::VectorXi& active = problem.parameterization().active_vertices();
  Underside u;
  u.up = -body.TotalLoad().normalized();
  u.positions = DeformedPositions(body, start);
  u.skin = TriMesh{u.positions, body.skin().triangles};
  // The search disc: 1.5 skin edges, so every support vertex under the body finds the
  // skin vertices above it.
  double edges = 0;
  for (Eigen::Index f = 0; f < u.skin.triangles.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      edges += (u.positions.row(u.skin.triangles(f, k)) -
                u.positions.row(u.skin.triangles(f, (k + 1) % 3)))
                   .norm();
  const double radius = 1.5 * edges / (3.0 * std::max<Eigen::Index>(1, u.skin.triangles.rows()));
  const Eigen::VectorXi& skin = body.skin().vertices;
  u.gap = Eigen::VectorXd::Constant(support.vertices.rows(), std::nan(""));
  u.skin_vertex = Eigen::VectorXi::Constant(support.vertices.rows(), -1);
  double lowest = std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 0; i < active.size(); ++i) {
    const int v = active[i];
    const Eigen::Vector3d p = support.vertices.row(v);
    double best = std::numeric_limits<double>::infinity();
    for (Eigen::Index s = 0; s < skin.size(); ++s) {
      const Eigen::Vector3d q = u.positions.row(skin[s]);
      const Eigen::Vector3d off = q - p;
      const double along = off.dot(u.up);
      if ((off - along * u.up).norm() > radius || along >= best) continue;
      best = along;
      u.skin_vertex[v] = skin[s];
    }
    if (u.skin_vertex[v] >= 0) {
      u.gap[v] = best;
      lowest = std::min(lowest, best);
    }
  }
  if (!std::isfinite(lowest)) {
    throw InputError("baseline", "", "no designed support vertex lies under the body",
                     "check the scene: the body must start above the designed region");
  }
  // Rest the body on the support: the smallest gap becomes zero.
  for (Eigen::Index v = 0; v < u.gap.size(); ++v)
    if (u.skin_vertex[v] >= 0) u.gap[v] -= lowest;
  return u;
}

BaselineDesign Finish(const DesignProblem& problem, const Underside& underside,
                      const Eigen::VectorXd& weight, const BaselineOptions& options,
                      BaselineDesign design) {
  const TriMesh& support = problem.initial_support();
  // Targets: raise each weighted vertex to the skin above it.
  Eigen::VectorXd target = Eigen::VectorXd::Zero(support.vertices.rows());
  for (Eigen::Index v = 0; v < target.size(); ++v)
    if (weight[v] > 0) target[v] = underside.gap[v];
  design.weighted_vertices = static_cast<int>((weight.array() > 0).count());
  design.fit = FitSupport(support, problem.parameterization().active_vertices(), target, weight,
                          underside.up, options.fit);
  design.x = problem.parameterization().DesignFor(design.fit.positions);
  return design;
}

}  // namespace

BalanceResidual::BalanceResidual(Eigen::MatrixXd B, Eigen::VectorXd b)
    : B_(std::move(B)), b_(std::move(b)) {
  set_num_residuals(static_cast<int>(B_.rows()));
  for (Eigen::Index k = 0; k < B_.cols(); ++k) mutable_parameter_block_sizes()->push_back(1);
}

bool BalanceResidual::Evaluate(double const* const* parameters, double* residuals,
                               double** jacobians) const {
  Eigen::Map<Eigen::VectorXd> r(residuals, B_.rows());
  r = b_;
  for (Eigen::Index k = 0; k < B_.cols(); ++k) r += B_.col(k) * parameters[k][0];
  if (jacobians) {
    for (Eigen::Index k = 0; k < B_.cols(); ++k) {
      if (!jacobians[k]) continue;
      for (Eigen::Index row = 0; row < B_.rows(); ++row) jacobians[k][row] = B_(row, k);
    }
  }
  return true;
}

std::string BaselineDesign::Describe() const {
  std::ostringstream line;
  line << method << ": " << weighted_vertices << " support vertices fitted to the body"
       << " (rms misfit " << fit.rms_misfit * 1e3 << " mm)";
  if (method == "pose-to-seat")
    line << ", " << contact_vertices << " skin vertices assumed in contact, balance residual "
         << balance_residual << " of the load";
  return line.str();
}

BaselineDesign SitAndRelaxDesign(const DesignProblem& problem, const BodyState& start,
                                 const BaselineOptions& options) {
  if (!(options.negative_image_depth > 0))
    throw InputError("--negative_image_depth", "", "must be positive for Sit & Relax",
                     "e.g. 0.05 (the paper's 5 cm)");
  const Underside underside = MeasureUnderside(problem, start);
  // The negative image: the rigid skin pushed `depth` into the flat support; a vertex's
  // pressure is κ times its penetration (κ cancels in the fit's weights).
  Eigen::VectorXd weight = Eigen::VectorXd::Zero(underside.gap.size());
  for (Eigen::Index v = 0; v < weight.size(); ++v)
    if (underside.skin_vertex[v] >= 0)
      weight[v] = std::max(0.0, options.negative_image_depth - underside.gap[v]);
  if (weight.maxCoeff() > 0) weight /= weight.maxCoeff();
  BaselineDesign design;
  design.method = "sit-and-relax";
  return Finish(problem, underside, weight, options, std::move(design));
}

BaselineDesign PoseToSeatDesign(const DesignProblem& problem, const BodyState& start,
                                const BaselineOptions& options) {
  const LayeredBody& body = problem.body();
  const Underside underside = MeasureUnderside(problem, start);
  const Vertices normals = VertexNormals(underside.skin);
  const Eigen::VectorXd areas = BarycentricVertexAreas(underside.skin);
  // The contact set: downward-facing skin vertices (within contact_distance of the support
  // when given; the gap is measured over the support vertices below them).
  Eigen::VectorXd skin_gap = Eigen::VectorXd::Constant(underside.positions.rows(), INFINITY);
  for (Eigen::Index v = 0; v < underside.gap.size(); ++v) {
    const int s = underside.skin_vertex[v];
    if (s >= 0) skin_gap[s] = std::min(skin_gap[s], underside.gap[v]);
  }
  std::vector<int> contact;
  for (Eigen::Index i = 0; i < body.skin().vertices.size(); ++i) {
    const int s = body.skin().vertices[i];
    if (normals.row(s).dot(underside.up) >= 0) continue;
    if (options.contact_distance > 0 && !(skin_gap[s] <= options.contact_distance)) continue;
    contact.push_back(s);
  }
  if (contact.empty())
    throw InputError("--contact_distance", "", "no skin vertex is in the assumed contact set",
                     "raise it, or 0 for every downward-facing skin vertex");

  // Balance on the free degrees of freedom: Σ f_i + load = 0 and Σ (x_i − c) × f_i + M = 0,
  // f_i = p_i a_i (−n_i), each row scaled by the load (moments also by the body's size).
  const Eigen::Vector3d load = body.TotalLoad();
  const Eigen::Vector3d c = start.centre;
  Eigen::Vector3d moment = body.options().external_torque;
  for (Eigen::Index v = 0; v < underside.positions.rows(); ++v)
    moment +=
        (underside.positions.row(v).transpose() - c).cross(body.vertex_mass()[v] * body.gravity());
  const double size =
      (underside.positions.colwise().maxCoeff() - underside.positions.colwise().minCoeff()).norm();
  const std::vector<int> free = body.lock().FreeComponents();
  double area_sum = 0;
  for (int s : contact) area_sum += areas[s];
  const double p_mean = load.norm() / area_sum;
  Eigen::MatrixXd B(free.size(), contact.size());
  Eigen::VectorXd b(free.size());
  for (size_t row = 0; row < free.size(); ++row) {
    const int k = free[row];
    const double scale =
        std::sqrt(options.balance_weight) / (k < 3 ? load.norm() : load.norm() * size);
    b[row] = scale * (k < 3 ? load[k] : moment[k - 3]);
    for (size_t col = 0; col < contact.size(); ++col) {
      const int s = contact[col];
      // Per unit of p / p_mean, so the unknowns are of order one.
      const Eigen::Vector3d f = -p_mean * areas[s] * normals.row(s).transpose();
      const Eigen::Vector3d arm = underside.positions.row(s).transpose() - c;
      B(row, col) = scale * (k < 3 ? f[k] : arm.cross(f)[k - 3]);
    }
  }
  Eigen::VectorXd p = Eigen::VectorXd::Ones(contact.size());  // p / p_mean
  ceres::Problem problem_ls;
  std::vector<double*> blocks;
  for (size_t col = 0; col < contact.size(); ++col) {
    double* block = p.data() + col;
    blocks.push_back(block);
    // As even as the balance allows: area-weighted deviation from the mean pressure.
    problem_ls.AddResidualBlock(new TargetResidual(areas[contact[col]] / area_sum, 1.0), nullptr,
                                block);
    problem_ls.SetParameterLowerBound(block, 0, 0.0);
  }
  if (!free.empty()) problem_ls.AddResidualBlock(new BalanceResidual(B, b), nullptr, blocks);
  ceres::Solver::Options solver_options;
  solver_options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  solver_options.max_num_iterations = 200;
  solver_options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(solver_options, &problem_ls, &summary);

  BaselineDesign design;
  design.method = "pose-to-seat";
  design.contact_vertices = static_cast<int>(contact.size());
  design.balance_residual =
      free.empty() ? 0.0 : (B * p + b).norm() / std::sqrt(options.balance_weight);
  Eigen::VectorXd skin_pressure = Eigen::VectorXd::Zero(underside.positions.rows());
  for (size_t col = 0; col < contact.size(); ++col) skin_pressure[contact[col]] = p[col];
  Eigen::VectorXd weight = Eigen::VectorXd::Zero(underside.gap.size());
  for (Eigen::Index v = 0; v < weight.size(); ++v)
    if (underside.skin_vertex[v] >= 0) weight[v] = skin_pressure[underside.skin_vertex[v]];
  if (weight.maxCoeff() > 0) weight /= weight.maxCoeff();
  return Finish(problem, underside, weight, options, std::move(design));
}

}  // namespace ergo
