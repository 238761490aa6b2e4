#include "ergo/body/support_solid.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <random>

#include "ergo/body/implicit_layer_mesher.h"
#include "ergo/body/surface_distance.h"
#include "ergo/mesh/input_error.h"

namespace ergo {
namespace {

std::string Millimetres(double metres) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g mm", metres * 1e3);
  return text;
}

}  // namespace

std::vector<bool> BottomVertices(const TetMesh& mesh, double tolerance) {
  const double bottom = mesh.vertices.col(1).minCoeff();
  std::vector<bool> base(static_cast<size_t>(mesh.vertices.rows()));
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v)
    base[v] = mesh.vertices(v, 1) <= bottom + tolerance;
  return base;
}

SupportSolid MeshSupportSolid(const TriMesh& surface, const SupportSolidOptions& options,
                              const std::string& source) {
  const double top = options.top_edge_length;
  const double bottom_edge = options.base_edge_length > 0 ? options.base_edge_length : top;
  if (!(top > 0) || !(bottom_edge >= top) || !std::isfinite(bottom_edge)) {
    throw InputError(source, "edge length",
                     "the support's edge lengths must be positive, the base's at least the top's "
                     "(got " +
                         Millimetres(top) + " and " + Millimetres(bottom_edge) + ")",
                     "e.g. 10 mm at the top and 30 mm at the base");
  }
  if (surface.vertices.rows() < 4 || surface.triangles.rows() < 4)
    throw InputError(source, "", "the support surface is empty", "give a closed surface");
  auto say = [&](const std::string& line) {
    if (options.progress) options.progress(line);
  };
  const SurfaceDistance distance(surface);  // throws for non-manifold or flipped surfaces
  const Eigen::Vector3d lo = surface.vertices.colwise().minCoeff();
  const Eigen::Vector3d hi = surface.vertices.colwise().maxCoeff();
  const double height = hi.y() - lo.y();
  if (!(top <= height)) {
    // Mesh_3 then keeps no tet, or a few flat ones on a base it cannot hold.
    throw InputError(source, "edge length",
                     "the support is " + Millimetres(height) + " tall, less than the top's " +
                         Millimetres(top) + " edges",
                     "use edges of at most a third of its height");
  }
  const double volume_estimate = (hi - lo).prod();
  const double mean_edge = 0.5 * (top + bottom_edge);
  // About 2.3 tets per regular-tet volume (layer_builder.cc measured it on shells).
  const double tets = 2.3 * volume_estimate / (std::pow(mean_edge, 3) / (6 * std::sqrt(2.0)));
  if (tets > 5e6) {
    throw InputError(source, "edge length",
                     "edge lengths of " + Millimetres(top) + "–" + Millimetres(bottom_edge) +
                         " would give about " + std::to_string(static_cast<long long>(tets / 1e6)) +
                         " million tets",
                     "use longer edges (at the base especially)");
  }

  LayerMesherCriteria criteria;
  criteria.facet_size = bottom_edge / std::sqrt(3.0);
  criteria.facet_distance = top / 10;
  criteria.cell_size = bottom_edge * std::sqrt(3.0 / 8.0);
  criteria.seed = options.seed;
  if (bottom_edge > top && height > 0) {
    // Linear in height: the top's length at the top, the base's at the bottom.
    criteria.size_scale = [=](const Eigen::Vector3d& p) {
      const double t = std::clamp((hi.y() - p.y()) / height, 0.0, 1.0);
      return (top + t * (bottom_edge - top)) / bottom_edge;
    };
  }
  // Seeds on the surface in a shuffled order: every prefix is spread over it.
  std::vector<int> order(static_cast<size_t>(surface.vertices.rows()));
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937(options.seed));
  std::vector<SurfaceSeed> seeds;
  for (int v : order) seeds.push_back({surface.vertices.row(v).transpose(), false});
  const Eigen::Vector3d margin = Eigen::Vector3d::Constant(2 * bottom_edge);
  say("meshing the support solid with CGAL Mesh_3 (about " +
      std::to_string(static_cast<long long>(tets)) + " tets expected)");
  const LayerMesherResult meshed = MeshImplicitLayer(
      [&distance](const Eigen::Vector3d& p) {
        return static_cast<int>(distance.Inside(p) ? kLayerRegion : kOutsideRegion);
      },
      Eigen::AlignedBox3d(lo - margin, hi + margin), seeds, criteria);
  if (meshed.mesh.tets.rows() == 0) {
    throw InputError(source, "",
                     "Mesh_3 produced no tets: the support is " + Millimetres(height) +
                         " tall, meshed with " + Millimetres(top) + "–" + Millimetres(bottom_edge) +
                         " edges",
                     "use edges of at most a third of its height");
  }
  SupportSolid solid;
  solid.mesh = meshed.mesh;
  // Surface vertices of the bottom face lie on its plane to Mesh_3's bisection accuracy.
  solid.base = BottomVertices(solid.mesh, 1e-3 * top);
  const long long held = std::count(solid.base.begin(), solid.base.end(), true);
  if (held < 3) {
    throw InputError(source, "",
                     "the support has no horizontal bottom face to hold (" + std::to_string(held) +
                         " vertices on its lowest plane)",
                     "give the support a flat base, or a tet mesh with the held vertices");
  }
  char line[160];
  std::snprintf(line, sizeof line,
                "support solid: %lld tets, %lld vertices, %lld held at the base (refine %.1f s, "
                "perturb %.1f s, exude %.1f s)",
                static_cast<long long>(solid.mesh.tets.rows()),
                static_cast<long long>(solid.mesh.vertices.rows()), held, meshed.refine_seconds,
                meshed.perturb_seconds, meshed.exude_seconds);
  say(line);
  return solid;
}

}  // namespace ergo
