#include "ergo/ergonomics/pressure_smoothing.h"

#include <cmath>

#include <glog/logging.h>

#include "ergo/mesh/cotangent_stiffness.h"
#include "ergo/mesh/surface_geometry.h"

namespace ergo {

struct PressureSmoothing::Filter {
  Eigen::SimplicialLDLT<SparseMatrix> factor;  // of A = M + R²K (symmetric positive definite)
  Eigen::VectorXd mass;                        // diag(M)
};

PressureSmoothing PressureSmoothing::Umbrella(const Triangles& triangles,
                                              Eigen::Index vertex_count) {
  PressureSmoothing smoothing;
  smoothing.size_ = vertex_count;
  smoothing.laplacian_ = UmbrellaLaplacian(triangles, vertex_count);
  return smoothing;
}

PressureSmoothing PressureSmoothing::Helmholtz(const TriMesh& surface, double radius) {
  CHECK(std::isfinite(radius) && radius > 0) << "smoothing radius must be positive";
  PressureSmoothing smoothing;
  const Eigen::Index n = surface.vertices.rows();
  smoothing.size_ = n;
  smoothing.radius_ = radius;
  auto filter = std::make_shared<Filter>();
  filter->mass = BarycentricVertexAreas(surface);
  const double r = radius / (2 * std::sqrt(3.0));
  SparseMatrix a = r * r * CotangentStiffness(surface.triangles, surface.vertices);
  // A vertex in no triangle (zero mass) keeps its value: unit mass, no stiffness.
  for (Eigen::Index v = 0; v < n; ++v)
    if (!(filter->mass[v] > 0)) filter->mass[v] = 0;
  Eigen::VectorXd diagonal = filter->mass;
  for (Eigen::Index v = 0; v < n; ++v)
    if (diagonal[v] == 0) diagonal[v] = 1;
  a += SparseMatrix(diagonal.asDiagonal());
  filter->factor.compute(a);
  CHECK(filter->factor.info() == Eigen::Success) << "M + R²K is not positive definite";
  for (Eigen::Index v = 0; v < n; ++v)
    if (filter->mass[v] == 0) filter->mass[v] = 1;
  smoothing.filter_ = std::move(filter);
  return smoothing;
}

Eigen::VectorXd PressureSmoothing::Apply(const Eigen::VectorXd& pressure, double lambda) const {
  CHECK_EQ(pressure.size(), size_);
  if (!filter_) return pressure - lambda * (laplacian_ * pressure);
  const Eigen::VectorXd smoothed = filter_->factor.solve(filter_->mass.cwiseProduct(pressure));
  return (1 - lambda) * pressure + lambda * smoothed;
}

Eigen::VectorXd PressureSmoothing::ApplyTransposed(const Eigen::VectorXd& gradient,
                                                   double lambda) const {
  CHECK_EQ(gradient.size(), size_);
  if (!filter_) return gradient - lambda * (laplacian_.transpose() * gradient);
  // Sᵀ = M A⁻¹ (A symmetric).
  const Eigen::VectorXd back = filter_->mass.cwiseProduct(filter_->factor.solve(gradient));
  return (1 - lambda) * gradient + lambda * back;
}

}  // namespace ergo
