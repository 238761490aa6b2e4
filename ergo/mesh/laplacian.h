// The umbrella (graph) Laplacian L = I − A of a triangle surface, where A averages each
// vertex's 1-ring (DESIGN.md §3: the convention of the paper's Eq. 12 and Eq. 14), and
// Taubin smoothing T = (I − μL)(I − λL) (Taubin 1995; paper Eq. 14, λ = 0.5, μ = −0.53).
#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "ergo/mesh/eigen_types.h"
#include "ergo/mesh/tri_mesh.h"

namespace ergo {

// L = I − A, #V x #V, A_ij = 1/deg(i) for each edge neighbour j of i (deg = number of
// distinct neighbours). Rows sum to zero. A vertex with no neighbours has an all-zero
// row (it averages to itself), so smoothing leaves it unchanged.
SparseMatrix UmbrellaLaplacian(const Triangles& triangles, Eigen::Index vertex_count);

struct TaubinParameters {
  double lambda = 0.5;  // shrinking step, > 0
  double mu = -0.53;    // inflating step, < −λ
  int iterations = 1;   // m in Eq. 14
};

// One Taubin step T = (I − μL)(I − λL) as a sparse matrix.
SparseMatrix TaubinOperator(const SparseMatrix& laplacian, double lambda, double mu);

// T^m X for X with one column per coordinate (or any number of columns).
Eigen::MatrixXd ApplyTaubin(const SparseMatrix& laplacian, const TaubinParameters& parameters,
                            const Eigen::MatrixXd& values);

// (T^m)ᵀ X: the adjoint, for gradients of functions of T^m x.
Eigen::MatrixXd ApplyTaubinTransposed(const SparseMatrix& laplacian,
                                      const TaubinParameters& parameters,
                                      const Eigen::MatrixXd& values);

// The mesh after m Taubin iterations (vertices only; the connectivity is unchanged).
// Vertices flagged in `fixed` (if non-empty, size #V) keep their position.
TriMesh TaubinSmooth(const TriMesh& mesh, const TaubinParameters& parameters,
                     const std::vector<bool>& fixed = {});

}  // namespace ergo
