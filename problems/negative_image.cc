#include "problems/negative_image.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include <Eigen/Geometry>

#include "ergo/body/surface_distance.h"
#include "ergo/contact/support.h"
#include "ergo/contact/support_validation.h"
#include "ergo/equilibrium/placement.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/laplacian.h"
#include "ergo/mesh/seconds_since.h"
#include "problems/mesh_booleans.h"

namespace ergo {
namespace {

using Segment = std::pair<Eigen::Vector3d, Eigen::Vector3d>;

double SegmentDistance(const Eigen::Vector3d& p, const Segment& s) {
  const Eigen::Vector3d d = s.second - s.first;
  const double length2 = d.squaredNorm();
  const double t = length2 > 0 ? std::clamp((p - s.first).dot(d) / length2, 0.0, 1.0) : 0.0;
  return (p - s.first - t * d).norm();
}

// Distance from each vertex to the nearest segment, capped at `cap` (farther is not needed).
std::vector<double> DistanceToCut(const Vertices& points, const std::vector<Segment>& cut,
                                  double cap) {
  Eigen::AlignedBox3d box;
  for (const Segment& s : cut) box.extend(s.first), box.extend(s.second);
  std::vector<double> distance(static_cast<size_t>(points.rows()), cap);
  for (Eigen::Index v = 0; v < points.rows(); ++v) {
    const Eigen::Vector3d p = points.row(v).transpose();
    if (box.exteriorDistance(p) >= cap) continue;
    for (const Segment& s : cut) distance[v] = std::min(distance[v], SegmentDistance(p, s));
  }
  return distance;
}

}  // namespace

std::string NegativeImage::BriefReport() const {
  std::ostringstream out;
  out << "negative image: " << support.vertices.rows() << " vertices, " << cut_segments
      << " cut edges, remeshed at " << edge_length * 1e3 << " mm, " << smoothed_vertices
      << " rim vertices smoothed (largest move " << rim_rounding * 1e3 << " mm), " << seconds
      << " s";
  return out.str();
}

NegativeImage MakeNegativeImage(const LayeredBody& body, const BodyState& contact,
                                const TriMesh& support, const NegativeImageOptions& o,
                                const std::string& scenario) {
  const auto start = std::chrono::steady_clock::now();
  const std::string source = scenario + " negative image";
  if (!(o.depth > 0) || !(o.smoothing_radius >= 0) || o.smoothing_iterations < 0 ||
      !(o.smoothing_lambda > 0 && o.smoothing_lambda <= 1) || o.remesh_iterations < 1 ||
      !(o.edge_length >= 0) || !(o.gap >= 0)) {
    throw InputError(source, "options",
                     "depth must be positive, smoothing radius, iterations and edge length "
                     "non-negative, λ in (0, 1], remeshing iterations ≥ 1",
                     "e.g. depth 0.05 m, radius 0.015 m, 10 iterations, λ 0.5");
  }
  const Eigen::Vector3d load = body.TotalLoad();
  if (!(load.norm() > 0)) {
    throw InputError(source, "", "the body has no load to push it into the support",
                     "give gravity or an external force");
  }
  const Eigen::Vector3d down = load.normalized();
  TriMesh skin = body.skin().RestSurface(DeformedPositions(body, contact));
  skin.vertices.rowwise() += (o.depth * down).transpose();
  const BooleanResult carved = MeshDifference(support, skin, source);
  if (carved.cut.empty()) {
    throw InputError(source, "", "the pushed-in body does not cut the support",
                     "start from a state that touches the support, or increase the depth");
  }

  // Triangles to remesh: the cavity (not on the original support) and a band around the cut.
  NegativeImage image;
  image.cut_segments = static_cast<int>(carved.cut.size());
  const SurfaceDistance original(support);
  double edge = o.edge_length;
  if (edge == 0) {
    // The median edge of the original triangles near the cut.
    const std::vector<double> near = DistanceToCut(support.vertices, carved.cut, 1.0);
    std::vector<double> lengths;
    for (Eigen::Index f = 0; f < support.triangles.rows(); ++f) {
      const int a = support.triangles(f, 0), b = support.triangles(f, 1),
                c = support.triangles(f, 2);
      if (std::min({near[a], near[b], near[c]}) > std::max(o.smoothing_radius, 1e-3)) continue;
      for (const auto& [i, j] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}})
        lengths.push_back((support.vertices.row(i) - support.vertices.row(j)).norm());
    }
    if (lengths.empty()) {
      for (Eigen::Index f = 0; f < support.triangles.rows(); ++f)
        lengths.push_back((support.vertices.row(support.triangles(f, 0)) -
                           support.vertices.row(support.triangles(f, 1)))
                              .norm());
    }
    std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
    edge = lengths[lengths.size() / 2];
  }
  image.edge_length = edge;
  const std::vector<double> before =
      DistanceToCut(carved.mesh.vertices, carved.cut, o.smoothing_radius + 2 * edge);
  std::vector<bool> remesh(static_cast<size_t>(carved.mesh.triangles.rows()), false);
  for (Eigen::Index f = 0; f < carved.mesh.triangles.rows(); ++f) {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    bool near_cut = false;
    for (int k = 0; k < 3; ++k) {
      const int v = carved.mesh.triangles(f, k);
      centroid += carved.mesh.vertices.row(v).transpose() / 3;
      near_cut = near_cut || before[v] < o.smoothing_radius + 2 * edge;
    }
    remesh[f] = near_cut || original.Nearest(centroid).distance > 1e-7;
  }
  TriMesh result = RemeshIsotropic(carved.mesh, remesh, edge, o.remesh_iterations);

  // Laplacian smoothing of the rim: vertices within the radius of the cut move, others stay.
  const std::vector<double> distance =
      DistanceToCut(result.vertices, carved.cut, o.smoothing_radius);
  std::vector<Eigen::Index> band;
  for (Eigen::Index v = 0; v < result.vertices.rows(); ++v)
    if (distance[v] < o.smoothing_radius) band.push_back(v);
  image.smoothed_vertices = static_cast<int>(band.size());
  const Vertices unsmoothed = result.vertices;
  if (!band.empty() && o.smoothing_iterations > 0) {
    const SparseMatrix laplacian = UmbrellaLaplacian(result.triangles, result.vertices.rows());
    for (int it = 0; it < o.smoothing_iterations; ++it) {
      const Eigen::MatrixXd step = laplacian * Eigen::MatrixXd(result.vertices);
      for (Eigen::Index v : band) result.vertices.row(v) -= o.smoothing_lambda * step.row(v);
    }
  }
  for (Eigen::Index v : band)
    image.rim_rounding =
        std::max(image.rim_rounding, (result.vertices.row(v) - unsmoothed.row(v)).norm());
  ValidateSupportMesh(result, source);

  const PlacementResult placed = PlaceAboveSupport(body, contact, Support(result, source), o.gap);
  if (!placed.found) {
    throw InputError(source, "start", "the body cannot be placed above the carved support",
                     "use a smaller depth");
  }
  image.support = std::move(result);
  image.start = placed.state;
  image.seconds = SecondsSince(start);
  return image;
}

}  // namespace ergo
