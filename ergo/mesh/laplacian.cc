#include "ergo/mesh/laplacian.h"

#include <algorithm>
#include <vector>

#include <glog/logging.h>

namespace ergo {

SparseMatrix UmbrellaLaplacian(const Triangles& triangles, Eigen::Index vertex_count) {
  // Distinct undirected edges, via sorted (min, max) pairs.
  std::vector<std::pair<int, int>> edges;
  edges.reserve(static_cast<size_t>(triangles.rows()) * 3);
  for (Eigen::Index f = 0; f < triangles.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int a = triangles(f, k), b = triangles(f, (k + 1) % 3);
      CHECK(a >= 0 && a < vertex_count && b >= 0 && b < vertex_count) << "index out of range";
      if (a != b) edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::vector<int> degree(static_cast<size_t>(vertex_count), 0);
  for (const auto& [a, b] : edges) {
    ++degree[a];
    ++degree[b];
  }
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(edges.size() * 2 + static_cast<size_t>(vertex_count));
  for (Eigen::Index v = 0; v < vertex_count; ++v)
    if (degree[v] > 0) entries.emplace_back(v, v, 1.0);
  for (const auto& [a, b] : edges) {
    entries.emplace_back(a, b, -1.0 / degree[a]);
    entries.emplace_back(b, a, -1.0 / degree[b]);
  }
  SparseMatrix laplacian(vertex_count, vertex_count);
  laplacian.setFromTriplets(entries.begin(), entries.end());
  return laplacian;
}

SparseMatrix TaubinOperator(const SparseMatrix& laplacian, double lambda, double mu) {
  SparseMatrix identity(laplacian.rows(), laplacian.cols());
  identity.setIdentity();
  const SparseMatrix shrink = identity - lambda * laplacian;
  const SparseMatrix inflate = identity - mu * laplacian;
  return (inflate * shrink).pruned();
}

Eigen::MatrixXd ApplyTaubin(const SparseMatrix& laplacian, const TaubinParameters& parameters,
                            const Eigen::MatrixXd& values) {
  CHECK_EQ(values.rows(), laplacian.rows());
  Eigen::MatrixXd result = values;
  for (int i = 0; i < parameters.iterations; ++i) {
    result -= parameters.lambda * (laplacian * result);
    result -= parameters.mu * (laplacian * result);
  }
  return result;
}

Eigen::MatrixXd ApplyTaubinTransposed(const SparseMatrix& laplacian,
                                      const TaubinParameters& parameters,
                                      const Eigen::MatrixXd& values) {
  CHECK_EQ(values.rows(), laplacian.rows());
  // (T^m)ᵀ = (Tᵀ)^m and Tᵀ = (I − λLᵀ)(I − μLᵀ): the factors in reverse order.
  const SparseMatrix transposed = laplacian.transpose();
  Eigen::MatrixXd result = values;
  for (int i = 0; i < parameters.iterations; ++i) {
    result -= parameters.mu * (transposed * result);
    result -= parameters.lambda * (transposed * result);
  }
  return result;
}

TriMesh TaubinSmooth(const TriMesh& mesh, const TaubinParameters& parameters,
                     const std::vector<bool>& fixed) {
  CHECK(fixed.empty() || fixed.size() == static_cast<size_t>(mesh.vertices.rows()));
  const SparseMatrix laplacian = UmbrellaLaplacian(mesh.triangles, mesh.vertices.rows());
  TriMesh smoothed = mesh;
  Eigen::MatrixXd positions = mesh.vertices;
  for (int i = 0; i < parameters.iterations; ++i) {
    for (double step : {parameters.lambda, parameters.mu}) {
      positions -= step * (laplacian * positions);
      for (size_t v = 0; v < fixed.size(); ++v)
        if (fixed[v]) positions.row(static_cast<Eigen::Index>(v)) = mesh.vertices.row(v);
    }
  }
  smoothed.vertices = positions;
  return smoothed;
}

}  // namespace ergo
