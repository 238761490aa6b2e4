// Triangle-surface steps of the mesh check (see mesh_check_steps.h): faces with a repeated
// vertex, degenerate and duplicate faces, then the edge topology — boundary, non-manifold
// and inconsistently oriented edges, non-manifold vertices, inward-facing closed
// components — and finally self-intersections. Everything is sorting, hashing and
// union-find, O(n log n), except the self-intersection test, which has a work budget.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <unordered_map>

#include <Eigen/Geometry>

#include "ergo/mesh/mesh_check_steps.h"
#include "ergo/mesh/self_intersection.h"
#include "ergo/mesh/text_reader.h"

namespace ergo::check {

namespace {

// Twice the area below this fraction of the squared mesh size is zero to working precision
// (float data rounds at ~1e-7); the height's threshold is kDegenerateShape.
constexpr double kDegenerateArea = 1e-12;

const char kSelfIntersectionBudgetFix[] =
    "re-mesh with well-shaped triangles (e.g. MeshLab 'Remeshing: Isotropic Explicit "
    "Remeshing' or CGAL's isotropic_remeshing) and check again; ergo_mesh check "
    "--noself_intersections checks everything else";

class DisjointSets {
 public:
  explicit DisjointSets(size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  int Find(int x) {
    while (parent_[static_cast<size_t>(x)] != x) {
      parent_[static_cast<size_t>(x)] =
          parent_[static_cast<size_t>(parent_[static_cast<size_t>(x)])];
      x = parent_[static_cast<size_t>(x)];
    }
    return x;
  }
  void Union(int a, int b) {
    a = Find(a);
    b = Find(b);
    if (a != b) parent_[static_cast<size_t>(std::max(a, b))] = std::min(a, b);
  }

 private:
  std::vector<int> parent_;
};

// One side of an edge: the triangle using it and whether it runs from lo to hi.
struct EdgeUse {
  int lo, hi, face;
  bool forward;
  bool operator<(const EdgeUse& o) const {
    return lo != o.lo ? lo < o.lo : hi != o.hi ? hi < o.hi : face < o.face;
  }
};

std::string EdgeName(int a, int b) {
  return "edge (" + std::to_string(a) + ", " + std::to_string(b) + ")";
}

// Marks faces with a repeated vertex, degenerate faces and later copies of duplicate
// faces; returns which faces take part in the edge topology.
std::vector<bool> CheckFaces(const TriMesh& mesh, double diagonal, const Context& context,
                             MeshCheckReport* report) {
  const int faces = static_cast<int>(mesh.triangles.rows());
  const int examples = context.options.max_examples;
  std::vector<bool> valid(static_cast<size_t>(faces), true);
  Tally repeated(Severity::kProblem, "repeated-vertex-in-face", examples);
  Tally degenerate(Severity::kProblem, "degenerate-triangles", examples);
  for (int f = 0; f < faces; ++f) {
    const int a = mesh.triangles(f, 0), b = mesh.triangles(f, 1), c = mesh.triangles(f, 2);
    if (a == b || b == c || a == c) {
      valid[static_cast<size_t>(f)] = false;
      if (repeated.WantsExample()) {
        repeated.Add(context.Element("triangle", f) + " has vertices (" + std::to_string(a) + ", " +
                     std::to_string(b) + ", " + std::to_string(c) + ")");
      } else {
        repeated.Count();
      }
      continue;
    }
    const WideVector pa = WidePoint(mesh.vertices, a), pb = WidePoint(mesh.vertices, b),
                     pc = WidePoint(mesh.vertices, c);
    const long double twice_area = (pb - pa).cross(pc - pa).norm();
    const long double longest =
        std::max({(pb - pa).squaredNorm(), (pc - pb).squaredNorm(), (pa - pc).squaredNorm()});
    if (twice_area <= kDegenerateShape * longest ||
        twice_area <= kDegenerateArea * static_cast<long double>(diagonal) * diagonal) {
      if (degenerate.WantsExample()) {
        char area[32];
        std::snprintf(area, sizeof area, "%.3Lg", twice_area / 2);
        degenerate.Add(context.Element("triangle", f) + " has area " + area + " m² (corners " +
                       std::to_string(a) + ", " + std::to_string(b) + ", " + std::to_string(c) +
                       ")");
      } else {
        degenerate.Count();
      }
    }
  }
  repeated.Report(Counted(repeated.count(), "triangle uses", "triangles use") +
                      " the same vertex twice (they are lines or points)",
                  "remove these faces, or weld the mesh and remove degenerate faces", report);
  degenerate.Report(Counted(degenerate.count(), "triangle has", "triangles have") +
                        " zero area (collinear corners): normals and pressures are undefined "
                        "on them",
                    "remove degenerate faces (e.g. MeshLab 'Remove Zero Area Faces') or re-mesh",
                    report);

  // Duplicate faces: the same three vertices in any order, each copy against the first.
  std::unordered_map<std::array<int, 3>, int, VertexIdsHash> first_with;
  first_with.reserve(static_cast<size_t>(faces));
  Tally duplicate(Severity::kProblem, "duplicate-faces", examples);
  for (int f = 0; f < faces; ++f) {
    if (!valid[static_cast<size_t>(f)]) continue;
    std::array<int, 3> key = {mesh.triangles(f, 0), mesh.triangles(f, 1), mesh.triangles(f, 2)};
    std::sort(key.begin(), key.end());
    const auto [first, inserted] = first_with.emplace(key, f);
    if (inserted) continue;
    valid[static_cast<size_t>(f)] = false;
    if (duplicate.WantsExample()) {
      duplicate.Add(context.Element("triangle", f) + " repeats " +
                    context.Element("triangle", first->second));
    } else {
      duplicate.Count();
    }
  }
  duplicate.Report(Counted(duplicate.count(), "triangle repeats", "triangles repeat") +
                       " an earlier triangle (same three vertices); the copies are left out "
                       "of the edge checks",
                   "remove duplicate faces (e.g. MeshLab 'Remove Duplicate Faces')", report);
  return valid;
}

// Corner (0, 1 or 2) of face f at vertex v.
int CornerOf(const TriMesh& mesh, int f, int v) {
  return mesh.triangles(f, 0) == v ? 0 : mesh.triangles(f, 1) == v ? 1 : 2;
}

void CheckEdges(const TriMesh& mesh, const std::vector<bool>& valid, const Context& context,
                MeshCheckReport* report) {
  const int faces = static_cast<int>(mesh.triangles.rows());
  const int examples = context.options.max_examples;
  std::vector<EdgeUse> uses;
  uses.reserve(3 * static_cast<size_t>(faces));
  for (int f = 0; f < faces; ++f) {
    if (!valid[static_cast<size_t>(f)]) continue;
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles(f, k), b = mesh.triangles(f, (k + 1) % 3);
      uses.push_back({std::min(a, b), std::max(a, b), f, a < b});
    }
  }
  std::sort(uses.begin(), uses.end());

  Tally boundary(context.options.require_closed ? Severity::kProblem : Severity::kNote,
                 "open-boundary", examples);
  Tally non_manifold(Severity::kProblem, "non-manifold-edges", examples);
  Tally inconsistent(Severity::kProblem, "inconsistent-orientation", examples);
  DisjointSets corners(3 * static_cast<size_t>(faces));  // fans around each vertex
  DisjointSets patches(static_cast<size_t>(faces));      // faces joined by manifold edges
  std::vector<bool> on_non_manifold_edge(static_cast<size_t>(mesh.vertices.rows()), false);
  bool orientable = true;
  for (size_t i = 0; i < uses.size();) {
    size_t j = i;
    while (j < uses.size() && uses[j].lo == uses[i].lo && uses[j].hi == uses[i].hi) ++j;
    const EdgeUse& e = uses[i];
    const size_t count = j - i;
    if (count == 1) {
      if (boundary.WantsExample()) {
        boundary.Add(EdgeName(e.lo, e.hi) + " of " + context.Element("triangle", e.face) +
                     " has no neighbour");
      } else {
        boundary.Count();
      }
    } else if (count == 2) {
      const EdgeUse& g = uses[i + 1];
      if (e.forward == g.forward) {
        orientable = false;
        if (inconsistent.WantsExample()) {
          inconsistent.Add(EdgeName(e.lo, e.hi) + ": " + context.Element("triangle", e.face) +
                           " and " + context.Element("triangle", g.face) +
                           " both run it in the same direction");
        } else {
          inconsistent.Count();
        }
      }
      patches.Union(e.face, g.face);
      for (int v : {e.lo, e.hi}) {
        corners.Union(3 * e.face + CornerOf(mesh, e.face, v),
                      3 * g.face + CornerOf(mesh, g.face, v));
      }
    } else {
      on_non_manifold_edge[static_cast<size_t>(e.lo)] = true;
      on_non_manifold_edge[static_cast<size_t>(e.hi)] = true;
      if (non_manifold.WantsExample()) {
        std::string example =
            EdgeName(e.lo, e.hi) + " is shared by " + std::to_string(count) + " triangles: ";
        for (size_t k = i; k < j && k < i + 4; ++k) {
          example += (k == i ? "" : ", ") + context.Element("triangle", uses[k].face);
        }
        non_manifold.Add(example + (count > 4 ? ", ..." : ""));
      } else {
        non_manifold.Count();
      }
    }
    i = j;
  }
  boundary.Report(Counted(boundary.count(), "edge belongs", "edges belong") +
                      " to only one triangle: the surface is open",
                  context.options.require_closed
                      ? "close the holes (e.g. MeshLab 'Close Holes') so the surface encloses "
                        "a volume"
                      : "",
                  report);
  non_manifold.Report(Counted(non_manifold.count(), "edge is", "edges are") +
                          " shared by more than two triangles (non-manifold)",
                      "separate or remove the extra sheets meeting at these edges", report);
  inconsistent.Report(Counted(inconsistent.count(), "edge is", "edges are") +
                          " used twice in the same direction: neighbouring triangles have "
                          "opposite orientations",
                      "orient the faces consistently (e.g. MeshLab 'Re-Orient all faces "
                      "coherently')",
                      report);

  // Non-manifold vertices: the faces around a vertex form more than one fan.
  std::vector<std::pair<int, int>> vertex_fans;  // (vertex, fan root)
  vertex_fans.reserve(3 * static_cast<size_t>(faces));
  for (int f = 0; f < faces; ++f) {
    if (!valid[static_cast<size_t>(f)]) continue;
    for (int k = 0; k < 3; ++k)
      vertex_fans.emplace_back(mesh.triangles(f, k), corners.Find(3 * f + k));
  }
  std::sort(vertex_fans.begin(), vertex_fans.end());
  vertex_fans.erase(std::unique(vertex_fans.begin(), vertex_fans.end()), vertex_fans.end());
  Tally pinched(Severity::kProblem, "non-manifold-vertices", examples);
  for (size_t i = 0; i < vertex_fans.size();) {
    size_t j = i;
    while (j < vertex_fans.size() && vertex_fans[j].first == vertex_fans[i].first) ++j;
    const int v = vertex_fans[i].first;
    if (j - i > 1 && !on_non_manifold_edge[static_cast<size_t>(v)]) {
      if (pinched.WantsExample()) {
        pinched.Add(context.Vertex(v) + ": " + std::to_string(j - i) +
                    " separate fans of triangles meet only at this vertex");
      } else {
        pinched.Count();
      }
    }
    i = j;
  }
  pinched.Report(Counted(pinched.count(), "vertex joins", "vertices join") +
                     " surface pieces that share no edge there (non-manifold)",
                 "split these vertices or separate the pieces", report);

  // Closed, consistently oriented pieces must enclose positive volume (outward normals).
  if (boundary.count() > 0 || non_manifold.count() > 0 || !orientable) return;
  std::vector<long double> volume(static_cast<size_t>(faces), 0.0);
  std::vector<int> size(static_cast<size_t>(faces), 0);
  for (int f = 0; f < faces; ++f) {
    if (!valid[static_cast<size_t>(f)]) continue;
    const WideVector a = WidePoint(mesh.vertices, mesh.triangles(f, 0));
    const WideVector b = WidePoint(mesh.vertices, mesh.triangles(f, 1));
    const WideVector c = WidePoint(mesh.vertices, mesh.triangles(f, 2));
    const int root = patches.Find(f);
    volume[static_cast<size_t>(root)] += a.dot(b.cross(c)) / 6;
    ++size[static_cast<size_t>(root)];
  }
  Tally inward(Severity::kProblem, "inward-orientation", examples);
  for (int f = 0; f < faces; ++f) {
    if (size[static_cast<size_t>(f)] == 0 || volume[static_cast<size_t>(f)] >= 0) continue;
    char text[48];
    std::snprintf(text, sizeof text, "%.3Lg m³", volume[static_cast<size_t>(f)]);
    inward.Add("the closed piece containing " + context.Element("triangle", f) + " (" +
               std::to_string(size[static_cast<size_t>(f)]) + " triangles) encloses " + text);
  }
  inward.Report(Counted(inward.count(), "closed piece has", "closed pieces have") +
                    " inward-pointing normals (negative enclosed volume; ergo expects "
                    "counter-clockwise faces seen from outside)",
                "reverse the orientation of every face (swap two vertices of each), unless "
                "the piece bounds a cavity",
                report);
}

void CheckSelfIntersections(const TriMesh& mesh, const std::vector<int>& weld,
                            const std::vector<bool>& valid, const Context& context,
                            MeshCheckReport* report) {
  TriMesh welded;
  welded.vertices = mesh.vertices;
  std::vector<int> welded_to_mesh;
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    if (valid[static_cast<size_t>(f)]) welded_to_mesh.push_back(static_cast<int>(f));
  }
  welded.triangles.resize(static_cast<Eigen::Index>(welded_to_mesh.size()), 3);
  for (size_t i = 0; i < welded_to_mesh.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      welded.triangles(static_cast<Eigen::Index>(i), k) =
          weld[static_cast<size_t>(mesh.triangles(welded_to_mesh[i], k))];
    }
  }
  const SelfIntersections found = FindSelfIntersections(welded, context.options.self_intersection);
  if (!found.checked) {
    MeshIssue issue;
    issue.severity = Severity::kNote;
    issue.code = "self-intersection-not-checked";
    issue.what = "self-intersections were not checked: " + found.skipped_because;
    issue.fix = "fix the problems above, then check again";
    report->issues.push_back(issue);
    return;
  }
  if (found.out_of_budget) {
    // Not knowing is not clean: a surface that may cross itself cannot be a support.
    MeshIssue issue;
    issue.severity = Severity::kProblem;
    issue.code = "self-intersection-test-incomplete";
    issue.what = found.BudgetReport();
    issue.fix = kSelfIntersectionBudgetFix;
    report->issues.push_back(issue);
  }
  Tally intersecting(Severity::kProblem, "self-intersections", context.options.max_examples);
  for (const auto& [a, b] : found.pairs) {
    if (intersecting.WantsExample()) {
      intersecting.Add(context.Element("triangle", welded_to_mesh[static_cast<size_t>(a)]) +
                       " intersects " +
                       context.Element("triangle", welded_to_mesh[static_cast<size_t>(b)]));
    } else {
      intersecting.Count();
    }
  }
  intersecting.Report((found.stopped_at_limit || found.out_of_budget ? "at least " : "") +
                          Counted(intersecting.count(), "pair of triangles intersects",
                                  "pairs of triangles intersect") +
                          " (self-intersecting surface)",
                      "remove the overlapping parts (e.g. MeshLab 'Select Self Intersecting "
                      "Faces', or CGAL's autorefine) or re-mesh",
                      report);
}

}  // namespace

void CheckSurface(const TriMesh& mesh, const std::vector<int>& weld, const Context& context,
                  MeshCheckReport* report) {
  const std::vector<bool> valid = CheckFaces(mesh, report->bounding_box_diagonal, context, report);
  CheckEdges(mesh, valid, context, report);
  if (context.options.check_self_intersections) {
    CheckSelfIntersections(mesh, weld, valid, context, report);
  }
}

}  // namespace ergo::check
