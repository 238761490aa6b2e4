#include "ergo/body/layer_builder.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <numeric>
#include <sstream>
#include <utility>

#include <glog/logging.h>

#include "ergo/body/hole_filling.h"
#include "ergo/mesh/input_error.h"
#include "ergo/mesh/mesh_check.h"
#include "ergo/mesh/seconds_since.h"
#include "ergo/mesh/tet_boundary.h"

namespace ergo {
namespace {

using Clock = std::chrono::steady_clock;

std::string FormatPoint(const Eigen::Vector3d& p) {
  std::ostringstream out;
  out.precision(4);
  out << "(" << p.x() << ", " << p.y() << ", " << p.z() << ") m";
  return out.str();
}

std::string FormatLength(double metres) {
  std::ostringstream out;
  out.precision(4);
  out << metres << " m";
  return out.str();
}

void ValidateOptions(const BuilderOptions& options, const std::string& source) {
  if (!(options.edge_length > 0) || !std::isfinite(options.edge_length)) {
    throw InputError(source, "edge length", "the target edge length must be a positive length",
                     "give e.g. 0.005 (5 mm)");
  }
  if (!(options.facet_distance >= 0) || !std::isfinite(options.facet_distance)) {
    throw InputError(source, "facet distance", "must be >= 0 (0 = edge length / 10)", "");
  }
  if (!(options.facet_angle_degrees > 0 && options.facet_angle_degrees <= 30)) {
    throw InputError(source, "facet angle",
                     "must be in (0, 30] degrees (Mesh_3 may not terminate above 30)",
                     "use the default 25");
  }
  if (!(options.radius_edge_ratio >= 2)) {
    throw InputError(source, "radius-edge ratio", "must be >= 2 (Mesh_3 may not terminate below 2)",
                     "use the default 2");
  }
  if (!(options.relative_error_bound > 0 && options.relative_error_bound < 1e-2)) {
    throw InputError(source, "relative error bound", "must be in (0, 0.01)",
                     "use the default 1e-5");
  }
}

// The cheap look at the domain before meshing: labels on a regular grid, seeds on both
// surfaces found by bisection across labelled grid edges, and the layer volume estimate.
struct GridScan {
  int layer_nodes = 0, core_nodes = 0, outside_nodes = 0;
  double step = 0;            // target grid spacing
  double cell_volume = 0;     // volume per grid node
  bool core_outside = false;  // a core node outside the outer shape (untrusted input only)
  Eigen::Vector3d core_outside_at = Eigen::Vector3d::Zero();
  std::vector<SurfaceSeed> seeds;
};

// Farthest-point selection of up to `count` of `points`.
std::vector<size_t> SpreadSubset(const std::vector<Eigen::Vector3d>& points, int count) {
  std::vector<size_t> chosen;
  if (points.empty() || count <= 0) return chosen;
  std::vector<double> distance(points.size(), std::numeric_limits<double>::infinity());
  size_t next = 0;
  while (static_cast<int>(chosen.size()) < count) {
    chosen.push_back(next);
    const Eigen::Vector3d latest = points[next];
    double farthest = -1;
    for (size_t i = 0; i < points.size(); ++i) {
      distance[i] = std::min(distance[i], (points[i] - latest).squaredNorm());
      if (distance[i] > farthest) {
        farthest = distance[i];
        next = i;
      }
    }
    if (farthest <= 0) break;
  }
  return chosen;
}

GridScan ScanGrid(const ImplicitLayer& layer, const RegionFunction& region, bool check_core,
                  const BuilderOptions& options, double tolerance) {
  GridScan scan;
  const Eigen::Vector3d lo = layer.bounds.min(), extent = layer.bounds.sizes();
  scan.step = std::max(extent.maxCoeff() / 40.0, options.edge_length / 2);
  Eigen::Vector3i n;
  for (int a = 0; a < 3; ++a)
    n[a] = std::max(2, static_cast<int>(std::ceil(extent[a] / scan.step)) + 1);
  const auto node = [&](int i, int j, int k) {
    return Eigen::Vector3d(lo.x() + extent.x() * i / (n.x() - 1),
                           lo.y() + extent.y() * j / (n.y() - 1),
                           lo.z() + extent.z() * k / (n.z() - 1));
  };
  scan.cell_volume = extent.x() / (n.x() - 1) * extent.y() / (n.y() - 1) * extent.z() / (n.z() - 1);
  const auto index = [&](int i, int j, int k) {
    return (static_cast<size_t>(k) * n.y() + j) * n.x() + i;
  };
  std::vector<int> label(static_cast<size_t>(n.x()) * n.y() * n.z());
  for (int k = 0; k < n.z(); ++k) {
    for (int j = 0; j < n.y(); ++j) {
      for (int i = 0; i < n.x(); ++i) {
        const Eigen::Vector3d p = node(i, j, k);
        const int l = region(p);
        label[index(i, j, k)] = l;
        if (l == kLayerRegion) ++scan.layer_nodes;
        if (l == kCoreRegion) ++scan.core_nodes;
        if (l == kOutsideRegion) ++scan.outside_nodes;
        if (check_core && !scan.core_outside && layer.core(p) < 0 && !(layer.outer(p) < 0)) {
          scan.core_outside = true;
          scan.core_outside_at = p;
        }
      }
    }
  }
  // Grid edges from a layer node to a non-layer node cross the skin or the core surface.
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> crossings[2];
  std::vector<Eigen::Vector3d> midpoints[2];
  for (int k = 0; k < n.z(); ++k) {
    for (int j = 0; j < n.y(); ++j) {
      for (int i = 0; i < n.x(); ++i) {
        const int a = label[index(i, j, k)];
        const Eigen::Vector3i here(i, j, k);
        for (int axis = 0; axis < 3; ++axis) {
          Eigen::Vector3i there = here;
          if (++there[axis] >= n[axis]) continue;
          const int b = label[index(there.x(), there.y(), there.z())];
          if (a == b || (a != kLayerRegion && b != kLayerRegion)) continue;
          Eigen::Vector3d inside = node(i, j, k), other = node(there.x(), there.y(), there.z());
          const int other_label = a == kLayerRegion ? b : a;
          if (a != kLayerRegion) std::swap(inside, other);
          const int type = other_label == kCoreRegion ? 1 : 0;
          crossings[type].emplace_back(inside, other);
          midpoints[type].push_back((inside + other) / 2);
        }
      }
    }
  }
  for (int type = 0; type < 2; ++type) {
    for (size_t c : SpreadSubset(midpoints[type], options.max_seeds_per_surface)) {
      Eigen::Vector3d inside = crossings[type][c].first, other = crossings[type][c].second;
      int other_label = type == 1 ? kCoreRegion : kOutsideRegion;
      while ((inside - other).norm() > tolerance) {
        const Eigen::Vector3d mid = (inside + other) / 2;
        const int l = region(mid);
        if (l == kLayerRegion) {
          inside = mid;
        } else {
          other = mid;
          other_label = l;
        }
      }
      scan.seeds.push_back({(inside + other) / 2, other_label == kCoreRegion});
    }
  }
  return scan;
}

// Keeps the tets in `keep` and the vertices they use; returns old -> new vertex ids.
std::vector<int> CompactMesh(const std::vector<bool>& keep, TetMesh* mesh) {
  std::vector<int> new_id(static_cast<size_t>(mesh->vertices.rows()), -1);
  int vertices = 0, tets = 0;
  for (Eigen::Index t = 0; t < mesh->tets.rows(); ++t) {
    if (!keep[t]) continue;
    for (int k = 0; k < 4; ++k) {
      int& id = new_id[mesh->tets(t, k)];
      if (id < 0) id = vertices++;
    }
    ++tets;
  }
  TetMesh out;
  out.vertices.resize(vertices, 3);
  for (size_t v = 0; v < new_id.size(); ++v)
    if (new_id[v] >= 0) out.vertices.row(new_id[v]) = mesh->vertices.row(v);
  out.tets.resize(tets, 4);
  Eigen::Index row = 0;
  for (Eigen::Index t = 0; t < mesh->tets.rows(); ++t) {
    if (!keep[t]) continue;
    for (int k = 0; k < 4; ++k) out.tets(row, k) = new_id[mesh->tets(t, k)];
    ++row;
  }
  *mesh = std::move(out);
  return new_id;
}

// Vertex-connected components of the tets (union-find over tet corners).
std::vector<int> TetComponents(const TetMesh& mesh, int* count) {
  std::vector<int> parent(static_cast<size_t>(mesh.vertices.rows()));
  std::iota(parent.begin(), parent.end(), 0);
  const auto find = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t)
    for (int k = 1; k < 4; ++k) parent[find(mesh.tets(t, k))] = find(mesh.tets(t, 0));
  std::vector<int> label(parent.size(), -1), tet_component(static_cast<size_t>(mesh.tets.rows()));
  *count = 0;
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    const int root = find(mesh.tets(t, 0));
    if (label[root] < 0) label[root] = (*count)++;
    tet_component[t] = label[root];
  }
  return tet_component;
}

TriMesh FacesOf(const TetBoundary& boundary, const std::vector<bool>& face_selected) {
  TriMesh mesh;
  mesh.vertices = boundary.surface.vertices;
  const auto count = std::count(face_selected.begin(), face_selected.end(), true);
  mesh.triangles.resize(count, 3);
  Eigen::Index row = 0;
  for (Eigen::Index f = 0; f < boundary.surface.triangles.rows(); ++f)
    if (face_selected[f]) mesh.triangles.row(row++) = boundary.surface.triangles.row(f);
  return mesh;
}

// Messages that depend on the kind of input.
struct CoreMessages {
  std::string empty_what, empty_fix;
};

// Meshes, classifies the boundary, checks and measures. A given layer.region skips the
// core-inside-outer test (surface input: true by construction).
BuiltLayer MeshLayer(const ImplicitLayer& layer, const BuilderOptions& options,
                     const std::string& source, const CoreMessages& messages,
                     Clock::time_point start) {
  ValidateOptions(options, source);
  const double h = options.edge_length;
  const RegionFunction region =
      layer.region ? layer.region : RegionFunction([&layer](const Eigen::Vector3d& p) {
        if (!(layer.outer(p) < 0)) return static_cast<int>(kOutsideRegion);
        return static_cast<int>(layer.core(p) < 0 ? kCoreRegion : kLayerRegion);
      });
  const double radius = layer.bounds.diagonal().norm() / 2;
  LayerMesherCriteria criteria;
  criteria.facet_angle_degrees = options.facet_angle_degrees;
  criteria.facet_size = h / std::sqrt(3.0);
  criteria.facet_distance = options.facet_distance > 0 ? options.facet_distance : h / 10;
  criteria.cell_radius_edge_ratio = options.radius_edge_ratio;
  criteria.cell_size = h * std::sqrt(3.0 / 8.0);
  if (options.edge_length_field) {
    const auto field = options.edge_length_field;
    criteria.size_scale = [field, h](const Eigen::Vector3d& p) {
      return std::min(field(p), h) / h;
    };
  }
  criteria.relative_error_bound = options.relative_error_bound;
  criteria.exude = options.exude;
  criteria.perturb = options.perturb;
  criteria.sliver_bound_degrees = options.sliver_bound_degrees;
  criteria.seed = options.seed;

  auto say = [&options](const std::string& stage) {
    if (options.progress) options.progress(stage);
  };
  // 1. Look before meshing.
  say("scanning the layer on a grid");
  const GridScan scan =
      ScanGrid(layer, region, !layer.region, options, options.relative_error_bound * radius);
  if (scan.core_outside) {
    throw InputError(
        source, "",
        "the core is not inside the outer shape: " + FormatPoint(scan.core_outside_at) +
            " is inside the core but not inside the body",
        "shrink the core or grow the outer shape so the core is strictly inside");
  }
  if (scan.layer_nodes == 0) {
    throw InputError(source, "",
                     "the layer is empty or thinner than " + FormatLength(scan.step) +
                         " everywhere (no sample point of a " + FormatLength(scan.step) +
                         " grid over the bounding box lies in it)",
                     "check that the core is smaller than the outer shape and that the bounding "
                     "box contains the body");
  }
  if (scan.core_nodes == 0) throw InputError(source, "", messages.empty_what, messages.empty_fix);
  // A regular tet of edge h has volume h³/(6√2); the meshes have about 2.3× as many tets
  // as that volume ratio (measured on the spherical shell).
  const double estimated_tets =
      2.3 * scan.layer_nodes * scan.cell_volume / (std::pow(h, 3) / (6 * std::sqrt(2.0)));
  constexpr double kMaxTets = 5e6;
  if (estimated_tets > kMaxTets) {
    throw InputError(
        source, "edge length",
        "an edge length of " + FormatLength(h) + " would give about " +
            std::to_string(static_cast<long long>(estimated_tets / 1e6)) + " million tets",
        "use an edge length of at least " + FormatLength(h * std::cbrt(estimated_tets / kMaxTets)));
  }

  // 2. Mesh.
  say("meshing the layer with CGAL Mesh_3 (about " +
      std::to_string(static_cast<long long>(estimated_tets)) + " tets expected: refine, " +
      (options.perturb ? "perturb, " : "") + (options.exude ? "exude" : "") + ")");
  LayerMesherResult meshed = MeshImplicitLayer(region, layer.bounds, scan.seeds, criteria);
  BuiltLayer built;
  LayerBuildReport& report = built.report;
  report.edge_length = h;
  report.facet_distance = criteria.facet_distance;
  report.initial_points = meshed.initial_points;
  report.refine_seconds = meshed.refine_seconds;
  report.exude_seconds = meshed.exude_seconds;
  report.perturb_seconds = meshed.perturb_seconds;
  if (meshed.mesh.tets.rows() == 0) {
    throw InputError(source, "",
                     "Mesh_3 produced no tets: the layer is empty or much thinner "
                     "than the edge length",
                     "use a smaller edge length or a thicker layer");
  }
  TetMesh mesh = std::move(meshed.mesh);

  {
    char line[160];
    std::snprintf(line, sizeof line,
                  "meshed %lld tets (refine %.1f s, perturb %.1f s, exude %.1f s); classifying "
                  "the boundary",
                  static_cast<long long>(mesh.tets.rows()), meshed.refine_seconds,
                  meshed.perturb_seconds, meshed.exude_seconds);
    say(line);
  }
  // 3. Classify the boundary components by the surface Mesh_3 put their vertices on.
  TetBoundary boundary = ExtractBoundary(mesh);
  std::vector<int> votes_core(boundary.component_count, 0), votes_skin(boundary.component_count, 0);
  for (Eigen::Index f = 0; f < boundary.surface.triangles.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const uint8_t flags =
          meshed.surface_flags[boundary.surface_to_tet[boundary.surface.triangles(f, k)]];
      if (flags == 2) ++votes_core[boundary.face_component[f]];
      if (flags == 1) ++votes_skin[boundary.face_component[f]];
    }
  }
  std::vector<bool> component_is_core(boundary.component_count);
  for (int c = 0; c < boundary.component_count; ++c)
    component_is_core[c] = votes_core[c] > votes_skin[c];
  std::vector<bool> attached(static_cast<size_t>(mesh.vertices.rows()), false);
  std::vector<bool> on_skin(attached.size(), false);
  for (Eigen::Index f = 0; f < boundary.surface.triangles.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int v = boundary.surface_to_tet[boundary.surface.triangles(f, k)];
      (component_is_core[boundary.face_component[f]] ? attached : on_skin)[v] = true;
    }
  }

  // Pieces of the layer that touch no core would float free: drop them.
  int piece_count = 0;
  const std::vector<int> piece = TetComponents(mesh, &piece_count);
  if (piece_count > 1) {
    std::vector<bool> piece_attached(piece_count, false);
    for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t)
      for (int k = 0; k < 4; ++k)
        piece_attached[piece[t]] = piece_attached[piece[t]] || attached[mesh.tets(t, k)];
    std::vector<bool> keep(static_cast<size_t>(mesh.tets.rows()));
    int dropped_tets = 0, dropped_pieces = 0;
    for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
      keep[t] = piece_attached[piece[t]];
      dropped_tets += keep[t] ? 0 : 1;
    }
    for (int c = 0; c < piece_count; ++c) dropped_pieces += piece_attached[c] ? 0 : 1;
    if (dropped_pieces > 0) {
      const std::vector<int> new_id = CompactMesh(keep, &mesh);
      std::vector<bool> a(static_cast<size_t>(mesh.vertices.rows())), s(a.size());
      for (size_t v = 0; v < new_id.size(); ++v) {
        if (new_id[v] < 0) continue;
        a[new_id[v]] = attached[v];
        s[new_id[v]] = on_skin[v];
      }
      attached = std::move(a);
      on_skin = std::move(s);
      report.notes.push_back("dropped " + std::to_string(dropped_pieces) + " piece(s) of layer (" +
                             std::to_string(dropped_tets) +
                             " tets) that touch no core and would float free");
      boundary = ExtractBoundary(mesh);
      // Component ids changed; recompute which faces are core from the flags.
      component_is_core.assign(boundary.component_count, false);
      for (Eigen::Index f = 0; f < boundary.surface.triangles.rows(); ++f) {
        const int v = boundary.surface_to_tet[boundary.surface.triangles(f, 0)];
        if (attached[v]) component_is_core[boundary.face_component[f]] = true;
      }
    }
  }
  for (int c = 0; c < boundary.component_count; ++c)
    (component_is_core[c] ? report.core_components : report.skin_components)++;
  if (report.core_components == 0)
    throw InputError(source, "", messages.empty_what, messages.empty_fix);
  if (report.skin_components == 0) {
    throw InputError(source, "", "the meshed layer has no skin (every boundary is on the core)",
                     "check the outer shape");
  }
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
    if (attached[v] && on_skin[v]) {
      throw InputError(source, "",
                       "the core touches the skin at " +
                           FormatPoint(mesh.vertices.row(v).transpose()) +
                           ": the layer is thinner than the mesh resolution there",
                       "use a smaller edge length or a deeper layer");
    }
  }
  if (report.core_components > 1) {
    report.notes.push_back("the core has " + std::to_string(report.core_components) +
                           " separate pieces (the layer reaches through the body somewhere); "
                           "they move together as one rigid core");
  }
  if (report.skin_components > 1) {
    report.notes.push_back("the skin has " + std::to_string(report.skin_components) +
                           " separate pieces");
  }

  say("measuring the layer's thickness and depth");
  // 4. Measure: the skin and the core surface as meshes, thickness and depth.
  std::vector<bool> skin_face(boundary.surface.triangles.rows()), core_face(skin_face.size());
  for (size_t f = 0; f < skin_face.size(); ++f) {
    core_face[f] = component_is_core[boundary.face_component[f]];
    skin_face[f] = !core_face[f];
  }
  built.skin_surface = FacesOf(boundary, skin_face);
  std::unique_ptr<SurfaceDistance> core_surface;
  try {
    core_surface = std::make_unique<SurfaceDistance>(FacesOf(boundary, core_face));
  } catch (const InputError& error) {
    throw InputError(source, "core surface",
                     "the meshed core surface is not a manifold (" + error.problem() +
                         "): somewhere the core is thinner than the mesh resolves (a depth "
                         "near half the part's thickness)",
                     "use a smaller edge length, or a smaller depth where the part is thin");
  }
  const SurfaceDistance& core_distance = *core_surface;
  double thickness_sum = 0;
  report.min_thickness = std::numeric_limits<double>::infinity();
  Eigen::Vector3d thinnest = Eigen::Vector3d::Zero();
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
    if (on_skin[v]) {
      ++report.skin_vertex_count;
      const double t = core_distance.Nearest(mesh.vertices.row(v).transpose()).distance;
      thickness_sum += t;
      if (t < report.min_thickness) {
        report.min_thickness = t;
        thinnest = mesh.vertices.row(v).transpose();
      }
    }
    if (attached[v]) {
      ++report.attached_vertex_count;
      // First-order distance to {f_core = 0}: |f| / |∇f|, each gradient component the
      // smaller of the forward and backward differences (f may jump where the nearest
      // skin point does; a jump spoils only the difference that straddles it).
      const Eigen::Vector3d p = mesh.vertices.row(v).transpose();
      const double e = 1e-3 * criteria.facet_distance, f = layer.core(p);
      Eigen::Vector3d gradient;
      for (int a = 0; a < 3; ++a) {
        const Eigen::Vector3d d = Eigen::Vector3d::Unit(a) * e;
        const double forward = (layer.core(p + d) - f) / e, backward = (f - layer.core(p - d)) / e;
        gradient[a] = std::abs(forward) < std::abs(backward) ? forward : backward;
      }
      const double offset = std::abs(f) / std::max(gradient.norm(), 1e-300);
      report.max_attached_offset = std::max(report.max_attached_offset, offset);
    }
  }
  report.mean_thickness = thickness_sum / std::max(report.skin_vertex_count, 1);
  if (report.min_thickness < options.min_thickness_in_edges * h) {
    throw InputError(source, "",
                     "the layer is only " + FormatLength(report.min_thickness) + " thick at " +
                         FormatPoint(thinnest) + ", less than " +
                         std::to_string(options.min_thickness_in_edges) + " edge lengths (" +
                         FormatLength(h) + ")",
                     "use an edge length of at most " +
                         FormatLength(report.min_thickness / options.min_thickness_in_edges) +
                         " or a deeper layer");
  }
  report.vertex_count = static_cast<int>(mesh.vertices.rows());
  report.tet_count = static_cast<int>(mesh.tets.rows());
  report.quality = MeasureTetQuality(mesh);
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    const Eigen::Vector3d p0 = mesh.vertices.row(mesh.tets(t, 0));
    report.layer_volume +=
        (Eigen::Vector3d(mesh.vertices.row(mesh.tets(t, 1))) - p0)
            .dot((Eigen::Vector3d(mesh.vertices.row(mesh.tets(t, 2))) - p0)
                     .cross(Eigen::Vector3d(mesh.vertices.row(mesh.tets(t, 3))) - p0)) /
        6.0;
  }
  CHECK_EQ(report.quality.non_positive_count, 0) << "Mesh_3 produced a flat or inverted tet";
  built.mesh = std::move(mesh);
  built.attached = std::move(attached);
  // Depth under each vertex, measured: distance from its nearest skin point to the core.
  const auto skin = std::make_shared<SurfaceDistance>(built.skin_surface);
  built.vertex_depth.resize(built.mesh.vertices.rows());
  for (Eigen::Index v = 0; v < built.mesh.vertices.rows(); ++v) {
    const Eigen::Vector3d q = skin->Nearest(built.mesh.vertices.row(v).transpose()).point;
    built.vertex_depth[v] = core_distance.Nearest(q).distance;
  }
  built.skin = skin;
  report.total_seconds = SecondsSince(start);
  return built;
}

}  // namespace

BuiltLayer BuildLayerFromImplicit(const ImplicitLayer& layer, const BuilderOptions& options,
                                  const std::string& source) {
  CHECK(layer.outer && layer.core) << "ImplicitLayer needs both functions";
  if (layer.bounds.isEmpty() || !(layer.bounds.sizes().minCoeff() > 0)) {
    throw InputError(source, "bounding box", "the bounding box is empty",
                     "give a box around the body");
  }
  const CoreMessages messages{
      "the core is empty: no point of the bounding box is inside it (or it is thinner than "
      "the mesh resolution)",
      "give a core shape with a negative inside, strictly inside the outer shape"};
  return MeshLayer(layer, options, source, messages, Clock::now());
}

BuiltLayer BuildLayerFromSurface(const TriMesh& skin, const SampleInterpolant& depth,
                                 const BuilderOptions& options, const std::string& source) {
  const Clock::time_point start = Clock::now();
  ValidateOptions(options, source);
  if (options.progress) options.progress("checking the skin surface");
  // The mesh check, with the findings that matter for a skin.
  MeshCheckOptions check_options;
  check_options.require_closed = false;
  const MeshCheckReport check = CheckTriMesh(skin, source, check_options);
  for (const MeshIssue& issue : check.issues) {
    if (issue.severity == Severity::kNote || issue.code == "inward-orientation") continue;
    std::string what = issue.what;
    if (!issue.examples.empty()) what += " (e.g. " + issue.examples.front() + ")";
    throw InputError(source, issue.location, what, issue.fix);
  }
  if (!(depth.min_value() >= options.edge_length)) {
    throw InputError(source, "depth",
                     "the layer depth goes down to " + FormatLength(depth.min_value()) +
                         ", less than the edge length " + FormatLength(options.edge_length) +
                         ": the layer would be one element thick or less",
                     "use an edge length of at most " + FormatLength(depth.min_value()));
  }

  CappedSurface capped = CloseWithFlatCaps(skin, source);
  auto distance = std::make_shared<SurfaceDistance>(capped.surface);
  ImplicitLayer layer;
  const SurfaceDistance* d = distance.get();
  layer.outer = [d](const Eigen::Vector3d& p) { return d->Signed(p); };
  const ImplicitFunction limit = options.core_limit;
  layer.core = [d, &depth, limit](const Eigen::Vector3d& p) {
    SurfaceDistance::Closest closest;
    const double signed_distance = d->Signed(p, &closest);
    const double eroded = signed_distance + depth(closest.point);
    return limit ? std::max(eroded, limit(p)) : eroded;  // CSG intersection
  };
  const double max_depth = depth.max_value();
  layer.region = [d, &depth, max_depth, limit](const Eigen::Vector3d& p) {
    if (!d->Inside(p)) return static_cast<int>(kOutsideRegion);
    if (limit && limit(p) >= 0) return static_cast<int>(kLayerRegion);
    // Farther from the skin than the deepest depth: core, without a closest-point search.
    const std::optional<SurfaceDistance::Closest> closest = d->NearestWithin(p, max_depth);
    if (!closest) return static_cast<int>(kCoreRegion);
    return static_cast<int>(closest->distance > depth(closest->point) ? kCoreRegion : kLayerRegion);
  };
  const Eigen::Vector3d lo = capped.surface.vertices.colwise().minCoeff().transpose();
  const Eigen::Vector3d hi = capped.surface.vertices.colwise().maxCoeff().transpose();
  const double margin = std::max(2 * options.edge_length, 0.05 * (hi - lo).norm());
  layer.bounds = Eigen::AlignedBox3d(lo - Eigen::Vector3d::Constant(margin),
                                     hi + Eigen::Vector3d::Constant(margin));
  const CoreMessages messages{
      "the core vanishes: the depth (" + FormatLength(depth.min_value()) + " to " +
          FormatLength(depth.max_value()) +
          ") reaches beyond the middle of the body everywhere, so no tissue is deeper than it",
      "give depths smaller than half the body's thickness"};
  BuiltLayer built = MeshLayer(layer, options, source, messages, start);

  // Surface input: the depth field is the interpolated one, at each vertex's skin point.
  for (Eigen::Index v = 0; v < built.mesh.vertices.rows(); ++v)
    built.vertex_depth[v] = depth(distance->Nearest(built.mesh.vertices.row(v).transpose()).point);
  built.skin = distance;
  built.skin_surface = capped.surface;
  std::vector<std::string> notes = capped.notes;
  notes.insert(notes.end(), built.report.notes.begin(), built.report.notes.end());
  built.report.notes = std::move(notes);
  built.report.total_seconds = SecondsSince(start);
  return built;
}

Eigen::VectorXd InterpolateOntoTets(const BuiltLayer& layer, const SampleInterpolant& field) {
  CHECK(layer.skin != nullptr);
  const TetMesh& mesh = layer.mesh;
  Eigen::VectorXd values(mesh.tets.rows());
#pragma omp parallel for schedule(static)
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k) centroid += mesh.vertices.row(mesh.tets(t, k)).transpose() / 4;
    values[t] = field(layer.skin->Nearest(centroid).point);
  }
  return values;
}

std::string DescribeLayerBuild(const LayerBuildReport& r) {
  std::ostringstream out;
  out.precision(4);
  out << "layer mesh: " << r.vertex_count << " vertices, " << r.tet_count << " tets, "
      << r.skin_vertex_count << " skin vertices, " << r.attached_vertex_count
      << " attached (core) vertices\n";
  out << "layer volume: " << r.layer_volume << " m^3; thickness min " << r.min_thickness
      << " m, mean " << r.mean_thickness << " m\n";
  out << "edges: target " << r.edge_length << " m, mean " << r.quality.mean_edge_length
      << " m (min " << r.quality.min_edge_length << ", max " << r.quality.max_edge_length
      << "); facet distance " << r.facet_distance << " m\n";
  out << "quality: dihedral angles " << r.quality.min_dihedral_degrees << "-"
      << r.quality.max_dihedral_degrees << " deg, radius ratio min " << r.quality.min_radius_ratio
      << ", mean " << r.quality.mean_radius_ratio << "\n";
  out << "Mesh_3: " << r.initial_points << " seeds, refine " << r.refine_seconds << " s, exude "
      << r.exude_seconds << " s";
  if (r.perturb_seconds > 0) out << ", perturb " << r.perturb_seconds << " s";
  out << "; total " << r.total_seconds << " s\n";
  for (const std::string& note : r.notes) out << "note: " << note << "\n";
  return out.str();
}

Json LayerBuildReportJson(const LayerBuildReport& r) {
  Json json = Json::object();
  json["vertices"] = r.vertex_count;
  json["tets"] = r.tet_count;
  json["skin_vertices"] = r.skin_vertex_count;
  json["attached_vertices"] = r.attached_vertex_count;
  json["skin_components"] = r.skin_components;
  json["core_components"] = r.core_components;
  json["layer_volume_m3"] = r.layer_volume;
  json["min_layer_thickness_m"] = r.min_thickness;
  json["mean_layer_thickness_m"] = r.mean_thickness;
  json["max_attached_offset_m"] = r.max_attached_offset;
  json["min_dihedral_deg"] = r.quality.min_dihedral_degrees;
  json["max_dihedral_deg"] = r.quality.max_dihedral_degrees;
  json["radius_ratio_min"] = r.quality.min_radius_ratio;
  json["radius_ratio_mean"] = r.quality.mean_radius_ratio;
  json["edge_length_target_m"] = r.edge_length;
  json["edge_length_mean_m"] = r.quality.mean_edge_length;
  json["edge_length_min_m"] = r.quality.min_edge_length;
  json["edge_length_max_m"] = r.quality.max_edge_length;
  json["facet_distance_m"] = r.facet_distance;
  json["mesh_seconds"] = r.refine_seconds + r.perturb_seconds + r.exude_seconds;
  json["total_seconds"] = r.total_seconds;
  Json notes = Json::array();
  for (const std::string& note : r.notes) notes.push_back(note);
  json["notes"] = notes;
  return json;
}

}  // namespace ergo
