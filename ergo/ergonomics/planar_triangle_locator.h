// Point location among triangles projected onto the plane (x, z) seen along y: which
// triangles hold a point, and its barycentric coordinates there. A uniform bucket grid over
// the triangles' bounding boxes (about one triangle per bucket) makes a query cost a few
// triangle tests. Used to evaluate a piecewise-linear pressure map at any point of the plane
// and to put measured sensor locations onto the support. Metres.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "ergo/mesh/tri_mesh.h"

namespace ergo {

using PlanarPoints = Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor>;

// One triangle holding a query point: q = Σ_k barycentric[k] · point(triangles(triangle, k)).
struct PlanarHit {
  int triangle = -1;
  Eigen::Vector3d barycentric = Eigen::Vector3d::Zero();
};

class PlanarTriangleLocator {
 public:
  // `points`: #V x 2 (x, z); `triangles`: #F x 3 indices into them. Triangles whose projected
  // area is below 1e-12 of the bounding box's (seen edge-on) are never returned.
  PlanarTriangleLocator(PlanarPoints points, Triangles triangles);

  // Every triangle that holds `q` (on an edge or a corner counts, to a relative tolerance of
  // 1e-10 in the barycentric coordinates), in increasing triangle order; empty outside.
  void Locate(const Eigen::Vector2d& q, std::vector<PlanarHit>* hits) const;

  const PlanarPoints& points() const { return points_; }
  const Triangles& triangles() const { return triangles_; }
  // The bounding box of the triangles' corners.
  const Eigen::Vector2d& lower() const { return lower_; }
  const Eigen::Vector2d& upper() const { return upper_; }

 private:
  int BucketIndex(int i, int j) const { return j * columns_ + i; }

  PlanarPoints points_;
  Triangles triangles_;
  Eigen::Vector2d lower_ = Eigen::Vector2d::Zero(), upper_ = Eigen::Vector2d::Zero();
  double bucket_size_ = 1;
  int columns_ = 0, rows_ = 0;
  std::vector<int> bucket_start_;  // CSR: triangles of bucket b are in [start[b], start[b+1])
  std::vector<int> bucket_triangles_;
};

}  // namespace ergo
