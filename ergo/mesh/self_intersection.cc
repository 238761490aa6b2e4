#include "ergo/mesh/self_intersection.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include "ergo/mesh/seconds_since.h"

namespace ergo {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Corners = std::array<size_t, 3>;
using Box =
    CGAL::Box_intersection_d::Box_with_info_d<double, 3, int,
                                              CGAL::Box_intersection_d::ID_FROM_BOX_ADDRESS>;
using Clock = std::chrono::steady_clock;

// Thrown from the box callback to end the sweep early.
struct EnoughPairs {};
struct OutOfBudget {};

// Triangles sampled to estimate the candidate pairs of a mesh that ran out of budget, and
// the box comparisons that estimate may cost at most.
constexpr int kSampledTriangles = 64;
constexpr double kMaxSampleWork = 1e8;
// Below this many boxes the sweep compares them all instead of splitting further (the value
// CGAL's own self_intersections() uses; the default, 10, splits far deeper).
constexpr std::ptrdiff_t kBoxCutoff = 2000;
// Pairs tested between two looks at the clock.
constexpr int64_t kTestsPerClockCheck = 4096;

// Whether triangles t and u meet other than in the corners and edges they share.
bool TrianglesIntersect(const Corners& t, const Corners& u, const std::vector<Point>& points) {
  int shared_in_t[3], shared_in_u[3];
  int shared = 0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (t[i] != u[j]) continue;
      shared_in_t[shared] = i;
      shared_in_u[shared] = j;
      ++shared;
    }
  }
  const auto corner = [&](const Corners& c, int k) -> const Point& { return points[c[k % 3]]; };
  if (shared == 3) return true;  // the same triangle twice
  if (shared == 2) {
    // Along a shared edge they overlap only when coplanar, with the third corners on the same
    // side of the edge (a fold); otherwise they just meet at the edge.
    const Point& a = corner(t, shared_in_t[0]);
    const Point& b = corner(t, shared_in_t[1]);
    const Point& r = corner(t, 3 - shared_in_t[0] - shared_in_t[1]);
    const Point& s = corner(u, 3 - shared_in_u[0] - shared_in_u[1]);
    return CGAL::coplanar(a, b, r, s) && CGAL::coplanar_orientation(a, b, r, s) == CGAL::POSITIVE;
  }
  const Kernel::Triangle_3 tt(corner(t, 0), corner(t, 1), corner(t, 2));
  const Kernel::Triangle_3 uu(corner(u, 0), corner(u, 1), corner(u, 2));
  if (shared == 1) {
    // T ∩ U is convex and holds the shared corner; it holds more exactly when the edge of one
    // opposite the shared corner meets the other triangle.
    const int i = shared_in_t[0], j = shared_in_u[0];
    const Kernel::Segment_3 t_opposite(corner(t, i + 1), corner(t, i + 2));
    const Kernel::Segment_3 u_opposite(corner(u, j + 1), corner(u, j + 2));
    return CGAL::do_intersect(tt, u_opposite) || CGAL::do_intersect(uu, t_opposite);
  }
  return CGAL::do_intersect(tt, uu);
}

bool BoxesOverlap(const Box& a, const Box& b) {
  for (int k = 0; k < 3; ++k) {
    if (a.max_coord(k) < b.min_coord(k) || b.max_coord(k) < a.min_coord(k)) return false;
  }
  return true;
}

// Candidate pairs of the whole mesh from the boxes overlapping a few evenly spaced ones.
double EstimateCandidatePairs(const std::vector<Box>& boxes) {
  if (boxes.empty()) return 0;
  const double n = static_cast<double>(boxes.size());
  const int samples =
      static_cast<int>(std::clamp(kMaxSampleWork / n, 1.0, 1.0 * kSampledTriangles));
  double overlaps = 0;
  for (int s = 0; s < samples; ++s) {
    const Box& sample = boxes[static_cast<size_t>(n * s / samples)];
    for (const Box& box : boxes) overlaps += &box != &sample && BoxesOverlap(sample, box);
  }
  return overlaps / samples * n / 2;
}

// 12345678 -> "12,345,678".
std::string Grouped(int64_t value) {
  std::string digits = std::to_string(value);
  for (int i = static_cast<int>(digits.size()) - 3; i > (digits[0] == '-' ? 1 : 0); i -= 3) {
    digits.insert(static_cast<size_t>(i), ",");
  }
  return digits;
}

}  // namespace

std::string SelfIntersections::BudgetReport() const {
  if (!out_of_budget) return "";
  char text[512];
  const double per_triangle = triangles > 0 ? 2 * estimated_candidates / triangles : 0;
  std::snprintf(text, sizeof text,
                "self-intersection test stopped after %.2g s and %s triangle-pair tests (%s): "
                "the mesh has about %.2g pairs of triangles whose bounding boxes overlap, %.0f "
                "per triangle, where a well-shaped mesh has fewer than 20 (long thin triangles "
                "spanning the mesh, or many stacked sheets); %s",
                seconds, Grouped(pair_tests).c_str(),
                stopped_by_time ? "its time limit" : "its limit for a mesh of this size",
                estimated_candidates, per_triangle,
                pairs.empty() ? "none of the tested pairs intersect, the rest are unknown"
                              : "the intersections listed are some of them");
  return text;
}

SelfIntersections FindSelfIntersections(const TriMesh& mesh,
                                        const SelfIntersectionOptions& options) {
  namespace pmp = CGAL::Polygon_mesh_processing;
  const Clock::time_point start = Clock::now();
  SelfIntersections result;
  std::vector<Point> points;
  points.reserve(static_cast<size_t>(mesh.vertices.rows()));
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
    points.emplace_back(mesh.vertices(v, 0), mesh.vertices(v, 1), mesh.vertices(v, 2));
  }
  // The soup CGAL sees: triangles without a repeated corner, with their mesh indices.
  std::vector<Corners> soup;
  std::vector<int> soup_to_mesh;
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    const int a = mesh.triangles(f, 0), b = mesh.triangles(f, 1), c = mesh.triangles(f, 2);
    if (a == b || b == c || a == c) continue;
    soup.push_back({static_cast<size_t>(a), static_cast<size_t>(b), static_cast<size_t>(c)});
    soup_to_mesh.push_back(static_cast<int>(f));
  }
  try {
    // Orientation does not change which triangles intersect; it tells whether the surface is a
    // manifold (CGAL would otherwise duplicate vertices).
    if (!pmp::orient_polygon_soup(points, soup)) {
      result.skipped_because =
          "the surface is not a manifold (CGAL would have to split vertices to orient it)";
      return result;
    }
    std::vector<Box> boxes;
    boxes.reserve(soup.size());
    for (size_t i = 0; i < soup.size(); ++i) {
      const Point& p = points[soup[i][0]];
      const Point& q = points[soup[i][1]];
      const Point& r = points[soup[i][2]];
      if (CGAL::collinear(p, q, r)) continue;  // reported as degenerate by the caller
      boxes.emplace_back(p.bbox() + q.bbox() + r.bbox(), static_cast<int>(i));
    }
    std::vector<const Box*> box_pointers;
    box_pointers.reserve(boxes.size());
    for (const Box& box : boxes) box_pointers.push_back(&box);
    result.triangles = static_cast<int64_t>(boxes.size());
    result.pair_test_limit =
        std::max(options.min_pair_tests,
                 static_cast<int64_t>(options.max_pair_tests_per_triangle * result.triangles));
    const bool timed = options.max_seconds > 0;
    const Clock::time_point deadline =
        start + std::chrono::duration_cast<Clock::duration>(
                    std::chrono::duration<double>(timed ? options.max_seconds : 0));
    const auto test = [&](const Box* a, const Box* b) {
      if (result.pair_tests == result.pair_test_limit) throw OutOfBudget();
      if (timed && result.pair_tests % kTestsPerClockCheck == 0 && Clock::now() > deadline) {
        result.stopped_by_time = true;
        throw OutOfBudget();
      }
      ++result.pair_tests;
      const Corners& t = soup[static_cast<size_t>(a->info())];
      const Corners& u = soup[static_cast<size_t>(b->info())];
      if (!TrianglesIntersect(t, u, points)) return;
      if (static_cast<int>(result.pairs.size()) == options.max_pairs) throw EnoughPairs();
      int first = soup_to_mesh[static_cast<size_t>(a->info())];
      int second = soup_to_mesh[static_cast<size_t>(b->info())];
      if (first > second) std::swap(first, second);
      result.pairs.emplace_back(first, second);
    };
    try {
      CGAL::box_self_intersection_d<CGAL::Sequential_tag>(box_pointers.begin(), box_pointers.end(),
                                                          test, kBoxCutoff);
    } catch (const EnoughPairs&) {
      result.stopped_at_limit = true;
    } catch (const OutOfBudget&) {
      result.out_of_budget = true;
      result.estimated_candidates = EstimateCandidatePairs(boxes);
    }
    result.checked = true;
  } catch (const std::exception& error) {
    result = SelfIntersections();
    result.skipped_because = std::string("CGAL failed: ") + error.what();
  }
  std::sort(result.pairs.begin(), result.pairs.end());
  result.seconds = SecondsSince(start);
  return result;
}

}  // namespace ergo
