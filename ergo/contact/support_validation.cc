#include "ergo/contact/support_validation.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#include <glog/logging.h>
#include <Eigen/Geometry>

#include "ergo/contact/directed_edge_key.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/self_intersection.h"
#include "ergo/mesh/surface_geometry.h"

namespace ergo {
namespace {

// " (at (x, y, z) m)": where a finding is, for people to find it in their model.
std::string AtPoint(const Eigen::Vector3d& p) {
  char text[128];
  std::snprintf(text, sizeof text, " (at (%.4g, %.4g, %.4g) m)", p.x(), p.y(), p.z());
  return text;
}

std::string EdgeName(int a, int b) {
  return "edge (" + std::to_string(std::min(a, b)) + ", " + std::to_string(std::max(a, b)) + ")";
}

}  // namespace

void ValidateSupportMesh(const TriMesh& mesh, const std::string& source,
                         const SelfIntersectionOptions& self_intersection) {
  const Eigen::Index num_vertices = mesh.vertices.rows();
  const Eigen::Index num_triangles = mesh.triangles.rows();
  if (num_triangles < 4) {
    throw InputError(source, "",
                     "the support has " + std::to_string(num_triangles) +
                         " triangles; a closed surface needs at least 4",
                     "pass a closed triangle mesh that encloses the support's volume");
  }
  for (Eigen::Index v = 0; v < num_vertices; ++v) {
    if (!mesh.vertices.row(v).allFinite()) {
      throw InputError(source, "vertex " + std::to_string(v), "non-finite coordinate",
                       "check the file for NaN or infinite values");
    }
  }

  // Per triangle: valid, distinct vertex ids and a non-degenerate shape.
  for (Eigen::Index f = 0; f < num_triangles; ++f) {
    const std::string where = "triangle " + std::to_string(f);
    for (int c = 0; c < 3; ++c) {
      const int v = mesh.triangles(f, c);
      if (v < 0 || v >= num_vertices) {
        throw InputError(source, where,
                         "vertex id " + std::to_string(v) + " is out of range [0, " +
                             std::to_string(num_vertices) + ")",
                         "fix the triangle's vertex ids");
      }
    }
    const int a = mesh.triangles(f, 0), b = mesh.triangles(f, 1), c = mesh.triangles(f, 2);
    if (a == b || b == c || c == a) {
      throw InputError(source, where, "degenerate triangle: a vertex id is repeated",
                       "remove the triangle (and close the surface around it)");
    }
    const Eigen::Vector3d xa = mesh.vertices.row(a), xb = mesh.vertices.row(b),
                          xc = mesh.vertices.row(c);
    const double longest2 =
        std::max({(xb - xa).squaredNorm(), (xc - xb).squaredNorm(), (xa - xc).squaredNorm()});
    if (!((xb - xa).cross(xc - xa).norm() > kDegenerateTriangleRatio * longest2)) {
      throw InputError(source, where,
                       "degenerate triangle: zero area (its vertices are coincident or "
                       "collinear), so it has no normal",
                       "collapse or remove the triangle (and close the surface around it)");
    }
  }

  // Edges: each undirected edge must join exactly two triangles traversing it in
  // opposite directions (closed, edge-manifold, consistently oriented).
  std::unordered_map<std::uint64_t, std::vector<int>> incident;  // directed edge -> triangles
  incident.reserve(3 * num_triangles);
  for (Eigen::Index f = 0; f < num_triangles; ++f) {
    for (int c = 0; c < 3; ++c) {
      incident[DirectedEdgeKey(mesh.triangles(f, c), mesh.triangles(f, (c + 1) % 3))].push_back(
          static_cast<int>(f));
    }
  }
  for (Eigen::Index f = 0; f < num_triangles; ++f) {
    for (int c = 0; c < 3; ++c) {
      const int from = mesh.triangles(f, c), to = mesh.triangles(f, (c + 1) % 3);
      const std::vector<int>& same = incident[DirectedEdgeKey(from, to)];
      const auto reverse = incident.find(DirectedEdgeKey(to, from));
      const std::size_t opposite = reverse == incident.end() ? 0 : reverse->second.size();
      if (same.size() + opposite > 2) {
        throw InputError(
            source, EdgeName(from, to),
            "non-manifold edge: shared by " + std::to_string(same.size() + opposite) + " triangles",
            "make the surface 2-manifold: every edge must join exactly two "
            "triangles");
      }
      if (same.size() == 2) {
        throw InputError(source, EdgeName(from, to),
                         "inconsistent orientation: triangles " + std::to_string(same[0]) +
                             " and " + std::to_string(same[1]) + " both traverse it from vertex " +
                             std::to_string(from) + " to " + std::to_string(to),
                         "orient every triangle counter-clockwise seen from outside (flip one of "
                         "the two)");
      }
      if (opposite == 0) {
        throw InputError(source, EdgeName(from, to),
                         "open support: only triangle " + std::to_string(f) +
                             " uses this edge, so the surface has a hole and encloses no volume",
                         "close the surface so that every edge joins exactly two triangles");
      }
    }
  }

  // Vertices: the triangles around each vertex must form a single fan (no pinch points),
  // otherwise "inside" is ambiguous there. Walk the fan across edges and count.
  std::vector<int> valence(num_vertices, 0), first_corner(num_vertices, -1);
  for (Eigen::Index f = 0; f < num_triangles; ++f) {
    for (int c = 0; c < 3; ++c) {
      const int v = mesh.triangles(f, c);
      ++valence[v];
      if (first_corner[v] < 0) first_corner[v] = static_cast<int>(3 * f + c);
    }
  }
  for (Eigen::Index v = 0; v < num_vertices; ++v) {
    if (valence[v] == 0) continue;  // an unused vertex is harmless
    int corner = first_corner[v];
    int walked = 0;
    do {
      const int f = corner / 3, c = corner % 3;
      const int next = mesh.triangles(f, (c + 1) % 3);
      // The triangle across the outgoing edge (v, next) traverses it as (next, v).
      const int g = incident[DirectedEdgeKey(next, static_cast<int>(v))].front();
      int cg = 0;
      while (mesh.triangles(g, cg) != v) ++cg;
      corner = 3 * g + cg;
      ++walked;
    } while (corner != first_corner[v] && walked <= valence[v]);
    if (walked != valence[v]) {
      throw InputError(source, "vertex " + std::to_string(v),
                       "non-manifold vertex: its " + std::to_string(valence[v]) +
                           " triangles form more than one fan (the surface pinches there)" +
                           AtPoint(mesh.vertices.row(v).transpose()),
                       "give each sheet of the surface its own copy of the vertex, or separate "
                       "the sheets");
    }
  }

  // Orientation: counter-clockwise seen from outside encloses a positive volume.
  const double volume = EnclosedVolume(mesh);
  if (!(volume > 0)) {
    std::ostringstream what;
    what << "inside-out support: the enclosed volume is " << volume
         << " m^3 (not positive), i.e. the triangles are clockwise seen from outside";
    throw InputError(source, "", what.str(), "reverse the vertex order of every triangle");
  }

  // Self-intersections (the mesh foundation's exact CGAL check): a surface crossing itself
  // encloses no well-defined volume, and the inside test would contradict itself there.
  SelfIntersectionOptions budget = self_intersection;
  budget.max_pairs = 3;
  const SelfIntersections crossings = FindSelfIntersections(mesh, budget);
  if (crossings.checked && !crossings.pairs.empty()) {
    std::ostringstream what;
    const auto& corners = mesh.triangles.row(crossings.pairs[0].first);
    const Eigen::Vector3d centroid = (mesh.vertices.row(corners[0]) +
                                      mesh.vertices.row(corners[1]) + mesh.vertices.row(corners[2]))
                                         .transpose() /
                                     3;
    what << "self-intersecting support: triangles " << crossings.pairs[0].first << " and "
         << crossings.pairs[0].second << " intersect";
    if (crossings.pairs.size() > 1) {
      what << " (and " << (crossings.stopped_at_limit ? "more than " : "")
           << crossings.pairs.size() - 1 << " more pair" << (crossings.pairs.size() > 2 ? "s" : "")
           << ")";
    }
    what << AtPoint(centroid);
    throw InputError(source,
                     "triangles " + std::to_string(crossings.pairs[0].first) + " and " +
                         std::to_string(crossings.pairs[0].second),
                     what.str(),
                     "remove the overlap (e.g. union the parts with a mesh boolean) so the "
                     "surface bounds a single volume");
  }
  if (crossings.out_of_budget) {
    // Refused rather than used unverified: a crossing support gives wrong pressures without
    // any sign, and triangles whose boxes overlap this much would make every contact query
    // visit most of them as well.
    throw InputError(source, "",
                     crossings.BudgetReport() +
                         "; a support must be verified free of them (a surface crossing "
                         "itself gives wrong pressures), and contact queries would visit most "
                         "of these triangles too",
                     "re-mesh the support with well-shaped triangles (e.g. MeshLab "
                     "'Remeshing: Isotropic Explicit Remeshing' or CGAL's isotropic_remeshing)");
  }
  if (!crossings.checked) {
    LOG(WARNING) << source << ": self-intersection check skipped: " << crossings.skipped_because;
  }
}

void ValidateSkinForContact(const TriMesh& skin, const std::string& source) {
  try {
    ValidateSupportMesh(skin, source);
  } catch (const InputError& error) {
    throw InputError(error.source(), error.location(),
                     error.problem() +
                         "; the meshed skin touches or overlaps itself where two parts of the "
                         "surface (toes, fingers) come closer than the mesh resolves, and contact "
                         "cannot use it",
                     "try another edge length (ergo_body build's --edge_length, a scenario's "
                     "--body_edge_length; the shipped FIND foot builds at 0.005, 0.007, 0.008 "
                     "and 0.009 m but not at 0.006 or 0.010), or widen the gap between those "
                     "parts in the scan");
  }
}

}  // namespace ergo
