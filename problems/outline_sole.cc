// CGAL translation unit (2-D constrained Delaunay meshing of the outline).
#include "problems/outline_sole.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

#include <Eigen/Geometry>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "ergo/mesh/input_error.h"

namespace ergo {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_2<Kernel>;
using Fb = CGAL::Delaunay_mesh_face_base_2<Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;
using Point2 = Kernel::Point_2;  // (x, z)

// A binary raster over the ground plane: cell (i, j) has its centre at lo + (i + ½, j + ½)·h.
struct Raster {
  Eigen::Vector2d lo;
  double h = 0;
  int nx = 0, nz = 0;
  std::vector<double> value;
  double& at(int i, int j) { return value[static_cast<size_t>(j) * nx + i]; }
  double at(int i, int j) const { return value[static_cast<size_t>(j) * nx + i]; }
  Eigen::Vector2d Centre(int i, int j) const { return lo + h * Eigen::Vector2d(i + 0.5, j + 0.5); }
};

// Fills the cells whose centres lie in the triangle (a, b, c) of the ground plane.
void FillTriangle(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                  Raster* r) {
  const Eigen::Vector2d lo = a.cwiseMin(b).cwiseMin(c), hi = a.cwiseMax(b).cwiseMax(c);
  const int i0 = std::max(0, static_cast<int>(std::floor((lo.x() - r->lo.x()) / r->h)));
  const int i1 = std::min(r->nx - 1, static_cast<int>(std::ceil((hi.x() - r->lo.x()) / r->h)));
  const int j0 = std::max(0, static_cast<int>(std::floor((lo.y() - r->lo.y()) / r->h)));
  const int j1 = std::min(r->nz - 1, static_cast<int>(std::ceil((hi.y() - r->lo.y()) / r->h)));
  auto cross = [](const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
    return u.x() * v.y() - u.y() * v.x();
  };
  const double area = cross(b - a, c - a);
  if (area == 0) return;
  for (int j = j0; j <= j1; ++j) {
    for (int i = i0; i <= i1; ++i) {
      const Eigen::Vector2d p = r->Centre(i, j);
      const double u = cross(b - p, c - p) / area, v = cross(c - p, a - p) / area;
      if (u >= 0 && v >= 0 && u + v <= 1) r->at(i, j) = 1;
    }
  }
}

// Binary dilation (grow = true) or erosion by a disc of `radius` cells.
Raster Morph(const Raster& in, int radius, bool grow) {
  Raster out = in;
  for (int j = 0; j < in.nz; ++j) {
    for (int i = 0; i < in.nx; ++i) {
      bool any = !grow;
      for (int dj = -radius; dj <= radius && any != grow; ++dj) {
        for (int di = -radius; di <= radius; ++di) {
          if (di * di + dj * dj > radius * radius) continue;
          const int a = i + di, b = j + dj;
          const double v = (a < 0 || b < 0 || a >= in.nx || b >= in.nz) ? 0 : in.at(a, b);
          if (grow && v > 0.5) {
            any = true;
            break;
          }
          if (!grow && v < 0.5) {
            any = false;
            break;
          }
        }
      }
      out.at(i, j) = any ? 1 : 0;
    }
  }
  return out;
}

// Empty cells not connected to the raster's border are holes: filled.
void FillHoles(Raster* r) {
  std::vector<char> outside(r->value.size(), 0);
  std::vector<std::pair<int, int>> stack;
  for (int i = 0; i < r->nx; ++i) stack.insert(stack.end(), {{i, 0}, {i, r->nz - 1}});
  for (int j = 0; j < r->nz; ++j) stack.insert(stack.end(), {{0, j}, {r->nx - 1, j}});
  while (!stack.empty()) {
    const auto [i, j] = stack.back();
    stack.pop_back();
    if (i < 0 || j < 0 || i >= r->nx || j >= r->nz) continue;
    const size_t k = static_cast<size_t>(j) * r->nx + i;
    if (outside[k] || r->value[k] > 0.5) continue;
    outside[k] = 1;
    stack.insert(stack.end(), {{i + 1, j}, {i - 1, j}, {i, j + 1}, {i, j - 1}});
  }
  for (size_t k = 0; k < r->value.size(); ++k)
    if (!outside[k]) r->value[k] = 1;
}

// A 3 x 3 box blur, twice: a smooth field whose 0.5 level is a smooth outline.
Raster Blur(const Raster& in) {
  Raster a = in;
  for (int pass = 0; pass < 2; ++pass) {
    Raster b = a;
    for (int j = 0; j < a.nz; ++j) {
      for (int i = 0; i < a.nx; ++i) {
        double sum = 0;
        for (int dj = -1; dj <= 1; ++dj)
          for (int di = -1; di <= 1; ++di) {
            const int x = i + di, z = j + dj;
            sum += (x < 0 || z < 0 || x >= a.nx || z >= a.nz) ? 0 : a.at(x, z);
          }
        b.at(i, j) = sum / 9;
      }
    }
    a = b;
  }
  return a;
}

// The longest closed 0.5-contour of the field (marching squares on the cell centres).
std::vector<Eigen::Vector2d> TraceOutline(const Raster& f) {
  // Crossing point on the edge between two centres.
  auto crossing = [&](int i0, int j0, int i1, int j1) -> Eigen::Vector2d {
    const double a = f.at(i0, j0), b = f.at(i1, j1);
    const double t = (0.5 - a) / (b - a);
    return f.Centre(i0, j0) + t * (f.Centre(i1, j1) - f.Centre(i0, j0));
  };
  // Edges of a square keyed by a unique id; segments join edge ids.
  auto edge_id = [&](int i, int j, int horizontal) {
    return (static_cast<long>(j) * f.nx + i) * 2 + horizontal;
  };
  std::map<long, std::vector<long>> links;
  std::map<long, Eigen::Vector2d> points;
  for (int j = 0; j + 1 < f.nz; ++j) {
    for (int i = 0; i + 1 < f.nx; ++i) {
      // Corners: 0 (i,j), 1 (i+1,j), 2 (i+1,j+1), 3 (i,j+1); edges: bottom, right, top, left.
      const bool in[4] = {f.at(i, j) > 0.5, f.at(i + 1, j) > 0.5, f.at(i + 1, j + 1) > 0.5,
                          f.at(i, j + 1) > 0.5};
      const long ids[4] = {edge_id(i, j, 1), edge_id(i + 1, j, 0), edge_id(i, j + 1, 1),
                           edge_id(i, j, 0)};
      const int corner[4][2][2] = {{{i, j}, {i + 1, j}},
                                   {{i + 1, j}, {i + 1, j + 1}},
                                   {{i, j + 1}, {i + 1, j + 1}},
                                   {{i, j}, {i, j + 1}}};
      std::vector<int> crossed;
      for (int e = 0; e < 4; ++e) {
        const bool a = in[e], b = in[(e + 1) % 4];
        if (a != b) crossed.push_back(e);
      }
      for (int e : crossed) {
        points[ids[e]] =
            crossing(corner[e][0][0], corner[e][0][1], corner[e][1][0], corner[e][1][1]);
      }
      if (crossed.size() == 2) {
        links[ids[crossed[0]]].push_back(ids[crossed[1]]);
        links[ids[crossed[1]]].push_back(ids[crossed[0]]);
      } else if (crossed.size() == 4) {
        // Saddle: keep the inside corners apart (pair each inside corner's two edges).
        const int start = in[0] ? 0 : 1;
        for (int k : {start, start + 2}) {
          const int e0 = (k + 3) % 4, e1 = k % 4;
          links[ids[e0]].push_back(ids[e1]);
          links[ids[e1]].push_back(ids[e0]);
        }
      }
    }
  }
  std::vector<Eigen::Vector2d> best;
  std::map<long, bool> used;
  for (const auto& [start, next] : links) {
    if (used[start]) continue;
    std::vector<Eigen::Vector2d> loop;
    long previous = -1, current = start;
    while (!used[current]) {
      used[current] = true;
      loop.push_back(points[current]);
      const std::vector<long>& n = links[current];
      long step = -1;
      for (long candidate : n)
        if (candidate != previous && !used[candidate]) step = candidate;
      if (step < 0) break;
      previous = current;
      current = step;
    }
    if (loop.size() > best.size()) best = loop;
  }
  return best;
}

// The closed polyline resampled at about `spacing`, counter-clockwise in (x, z).
std::vector<Eigen::Vector2d> Resample(const std::vector<Eigen::Vector2d>& loop, double spacing) {
  double area = 0, length = 0;
  for (size_t k = 0; k < loop.size(); ++k) {
    const Eigen::Vector2d& a = loop[k];
    const Eigen::Vector2d& b = loop[(k + 1) % loop.size()];
    area += a.x() * b.y() - b.x() * a.y();
    length += (b - a).norm();
  }
  std::vector<Eigen::Vector2d> ordered = loop;
  if (area < 0) std::reverse(ordered.begin(), ordered.end());
  const int count = std::max(12, static_cast<int>(std::ceil(length / spacing)));
  const double step = length / count;
  std::vector<Eigen::Vector2d> out;
  double walked = 0, next = 0;
  for (size_t k = 0; k < ordered.size() && static_cast<int>(out.size()) < count; ++k) {
    const Eigen::Vector2d& a = ordered[k];
    const Eigen::Vector2d& b = ordered[(k + 1) % ordered.size()];
    const double piece = (b - a).norm();
    while (next <= walked + piece && static_cast<int>(out.size()) < count) {
      out.push_back(a + (piece > 0 ? (next - walked) / piece : 0) * (b - a));
      next += step;
    }
    walked += piece;
  }
  return out;
}

// True when two non-adjacent edges of the closed polygon cross.
bool SelfIntersects(const std::vector<Eigen::Vector2d>& polygon) {
  auto orient = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
    const double d = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
    return (d > 0) - (d < 0);
  };
  const size_t n = polygon.size();
  for (size_t i = 0; i < n; ++i) {
    for (size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // adjacent through the closing edge
      const Eigen::Vector2d &a = polygon[i], &b = polygon[(i + 1) % n];
      const Eigen::Vector2d &c = polygon[j], &d = polygon[(j + 1) % n];
      if (orient(a, b, c) * orient(a, b, d) < 0 && orient(c, d, a) * orient(c, d, b) < 0)
        return true;
    }
  }
  return false;
}

bool InsidePolygon(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& p) {
  bool inside = false;
  for (size_t a = 0, b = polygon.size() - 1; a < polygon.size(); b = a++) {
    const Eigen::Vector2d& u = polygon[a];
    const Eigen::Vector2d& v = polygon[b];
    if ((u.y() > p.y()) != (v.y() > p.y()) &&
        p.x() < (v.x() - u.x()) * (p.y() - u.y()) / (v.y() - u.y()) + u.x())
      inside = !inside;
  }
  return inside;
}

}  // namespace

OutlineSole MakeOutlineSole(const TriMesh& foot, const OutlineSoleOptions& o) {
  if (!(o.margin >= 0) || !(o.footprint_height > 0) || !(o.thickness > 0) || !(o.top_spacing > 0) ||
      !(o.wall_spacing >= o.top_spacing) || !(o.raster > 0)) {
    throw InputError("outline sole", "options",
                     "margin must be non-negative; height, thickness, spacings and raster "
                     "positive, the wall spacing at least the top's",
                     "check the sole options");
  }
  if (foot.triangles.rows() == 0)
    throw InputError("outline sole", "foot", "the foot's skin is empty", "");
  // 1. The footprint: skin triangles touching the lowest `footprint_height`, on the ground.
  const double floor_y = foot.vertices.col(1).minCoeff();
  const double closing = 0.006;  // bridges gaps narrower than 12 mm (between toes, arch)
  const double reach = o.margin + closing + 3 * o.raster;
  Raster r;
  r.h = o.raster;
  const Eigen::Vector2d lo(foot.vertices.col(0).minCoeff(), foot.vertices.col(2).minCoeff());
  const Eigen::Vector2d hi(foot.vertices.col(0).maxCoeff(), foot.vertices.col(2).maxCoeff());
  r.lo = lo - Eigen::Vector2d::Constant(reach);
  r.nx = static_cast<int>(std::ceil((hi.x() - lo.x() + 2 * reach) / r.h));
  r.nz = static_cast<int>(std::ceil((hi.y() - lo.y() + 2 * reach) / r.h));
  r.value.assign(static_cast<size_t>(r.nx) * r.nz, 0.0);
  auto ground = [&](int v) -> Eigen::Vector2d {
    return Eigen::Vector2d(foot.vertices(v, 0), foot.vertices(v, 2));
  };
  for (Eigen::Index f = 0; f < foot.triangles.rows(); ++f) {
    const Eigen::Vector3i t = foot.triangles.row(f);
    const double lowest =
        std::min({foot.vertices(t[0], 1), foot.vertices(t[1], 1), foot.vertices(t[2], 1)});
    if (lowest - floor_y > o.footprint_height) continue;
    FillTriangle(ground(t[0]), ground(t[1]), ground(t[2]), &r);
  }
  // 2. Closed, holes filled, grown by the margin, smoothed.
  const int close_cells = static_cast<int>(std::round(closing / r.h));
  r = Morph(Morph(r, close_cells, true), close_cells, false);
  FillHoles(&r);
  if (o.margin > 0) r = Morph(r, static_cast<int>(std::round(o.margin / r.h)), true);
  const std::vector<Eigen::Vector2d> traced = TraceOutline(Blur(r));
  if (traced.size() < 8) {
    throw InputError("outline sole", "footprint",
                     "the foot's skin has no footprint within " +
                         std::to_string(o.footprint_height) + " m of its lowest point",
                     "check the foot (y up)");
  }
  std::vector<Eigen::Vector2d> ring;
  for (const Eigen::Vector2d& p : Resample(traced, o.top_spacing))
    if (ring.empty() || (p - ring.back()).norm() > 1e-3 * o.top_spacing) ring.push_back(p);
  while (ring.size() > 3 && (ring.front() - ring.back()).norm() <= 1e-3 * o.top_spacing)
    ring.pop_back();
  if (ring.size() < 8 || SelfIntersects(ring)) {
    throw InputError("outline sole", "footprint",
                     "the footprint's outline could not be traced as one simple loop (" +
                         std::to_string(ring.size()) + " points)",
                     "use the rectangular sole (--shoe_sole_outline=rectangle)");
  }

  // 3. The top: a constrained Delaunay mesh of the outline, edges about top_spacing.
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> handles;
  for (const Eigen::Vector2d& p : ring) handles.push_back(cdt.insert(Point2(p.x(), p.y())));
  for (size_t k = 0; k < handles.size(); ++k)
    cdt.insert_constraint(handles[k], handles[(k + 1) % handles.size()]);
  CGAL::refine_Delaunay_mesh_2(cdt, Criteria(0.125, o.top_spacing));

  OutlineSole sole;
  sole.outline.resize(static_cast<Eigen::Index>(ring.size()), 2);
  for (size_t k = 0; k < ring.size(); ++k) sole.outline.row(static_cast<Eigen::Index>(k)) = ring[k];
  std::map<Cdt::Vertex_handle, int> index;
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> triangles;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    index[v] = static_cast<int>(vertices.size());
    vertices.emplace_back(v->point().x(), o.top_y, v->point().y());
  }
  const int top_count = static_cast<int>(vertices.size());
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_in_domain()) continue;
    triangles.emplace_back(index[f->vertex(0)], index[f->vertex(1)], index[f->vertex(2)]);
  }
  // The top's boundary in order: the constrained vertices, by their place along the ring.
  std::vector<std::pair<double, int>> boundary;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    if (!cdt.are_there_incident_constraints(v)) continue;
    const Eigen::Vector2d p(v->point().x(), v->point().y());
    double best = std::numeric_limits<double>::infinity(), place = 0;
    for (size_t k = 0; k < ring.size(); ++k) {
      const Eigen::Vector2d& a = ring[k];
      const Eigen::Vector2d& b = ring[(k + 1) % ring.size()];
      const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
      const double d = (a + t * (b - a) - p).norm();
      if (d < best) {
        best = d;
        place = k + t;
      }
    }
    boundary.emplace_back(place, index[v]);
  }
  std::sort(boundary.begin(), boundary.end());
  std::vector<int> top_ring;
  for (const auto& [place, v] : boundary) top_ring.push_back(v);

  // 4. The flat bottom: a copy of the top's mesh (its refined triangles are well shaped,
  //    where a bare triangulation of the ring would make slivers of its collinear points).
  const double bottom_y = o.top_y - o.thickness;
  const size_t top_triangles = triangles.size();
  for (int v = 0; v < top_count; ++v)
    vertices.emplace_back(vertices[v].x(), bottom_y, vertices[v].z());
  for (size_t f = 0; f < top_triangles; ++f)
    triangles.push_back(triangles[f] + Eigen::Vector3i::Constant(top_count));
  // 5. Walls in rows of about wall_spacing, from the top's ring down to the bottom's.
  const int rows = std::max(1, static_cast<int>(std::ceil(o.thickness / o.wall_spacing)));
  std::vector<int> previous = top_ring;
  for (int row = 1; row <= rows; ++row) {
    std::vector<int> current;
    for (int v : top_ring) {
      if (row == rows) {
        current.push_back(v + top_count);
        continue;
      }
      current.push_back(static_cast<int>(vertices.size()));
      vertices.emplace_back(vertices[v].x(), o.top_y - o.thickness * row / rows, vertices[v].z());
    }
    for (size_t k = 0; k < current.size(); ++k) {
      const size_t n = (k + 1) % current.size();
      triangles.emplace_back(previous[k], current[k], current[n]);
      triangles.emplace_back(previous[k], current[n], previous[n]);
    }
    previous = current;
  }
  // 6. Outward orientation: the top up, the bottom down, the walls away from the outline's
  //    inside (the ring is counter-clockwise in (x, z), so outward is (Δz, −Δx)).
  sole.mesh.vertices.resize(static_cast<Eigen::Index>(vertices.size()), 3);
  for (size_t v = 0; v < vertices.size(); ++v)
    sole.mesh.vertices.row(static_cast<Eigen::Index>(v)) = vertices[v].transpose();
  sole.mesh.triangles.resize(static_cast<Eigen::Index>(triangles.size()), 3);
  for (size_t f = 0; f < triangles.size(); ++f) {
    Eigen::Vector3i t = triangles[f];
    const Eigen::Vector3d a = vertices[t[0]], b = vertices[t[1]], c = vertices[t[2]];
    const Eigen::Vector3d normal = (b - a).cross(c - a);
    const Eigen::Vector3d mid = (a + b + c) / 3;
    Eigen::Vector3d outward;
    if (std::abs(mid.y() - o.top_y) < 1e-12 && std::abs(normal.normalized().y()) > 0.5) {
      outward = Eigen::Vector3d::UnitY();
    } else if (std::abs(mid.y() - (o.top_y - o.thickness)) < 1e-12 &&
               std::abs(normal.normalized().y()) > 0.5) {
      outward = -Eigen::Vector3d::UnitY();
    } else {
      // A wall: outward is away from the outline near this facet (its two ring neighbours).
      const Eigen::Vector3d edge = (b - a).y() == 0 ? b - a : (c - a).y() == 0 ? c - a : c - b;
      outward = Eigen::Vector3d(edge.z(), 0, -edge.x());
      if (InsidePolygon(ring, Eigen::Vector2d(mid.x(), mid.z()) +
                                  1e-4 * Eigen::Vector2d(outward.x(), outward.z()).normalized()))
        outward = -outward;
    }
    if (normal.dot(outward) < 0) std::swap(t[1], t[2]);
    sole.mesh.triangles.row(static_cast<Eigen::Index>(f)) = t.transpose();
  }
  sole.top.assign(vertices.size(), false);
  for (int v = 0; v < top_count; ++v) sole.top[v] = true;
  return sole;
}

}  // namespace ergo
