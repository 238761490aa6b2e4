// SupportParameterization: the design vector x of paper §4 and how it moves the support.
// Either the positions of an active subset of support vertices (3 numbers each; e.g. only
// the chair's top face moves), or their displacement along the initial vertex normals (one
// number each) — one interface for both. Units: metres.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "ergo/mesh/tri_mesh.h"

namespace ergo {

enum class DesignParameterization { kPositions, kNormalDisplacement };

class SupportParameterization {
 public:
  // `active` flags support vertices that may move (empty = all). Normals are the
  // area-weighted vertex normals of `initial`.
  SupportParameterization(const TriMesh& initial, std::vector<bool> active,
                          DesignParameterization kind);

  DesignParameterization kind() const { return kind_; }
  int size() const;  // number of design variables
  const Eigen::VectorXi& active_vertices() const { return active_; }
  // x₀: the initial support's design vector.
  Eigen::VectorXd InitialDesign() const;
  // Support vertex positions for design x.
  Vertices Positions(const Eigen::VectorXd& x) const;
  // dφ/dx from dφ/d(vertex positions) (#V x 3): chain rule through Positions().
  Eigen::VectorXd PullBack(const Vertices& position_gradient) const;
  // Per active vertex, the largest displacement a design step dx causes, m: for the
  // paper-NCG step sizes (largest vertex move) and move limits.
  Eigen::VectorXd VertexMoves(const Eigen::VectorXd& dx) const;

 private:
  Vertices initial_;
  Vertices normals_;
  Eigen::VectorXi active_;
  DesignParameterization kind_;
};

}  // namespace ergo
