// Self-intersections of a triangle surface: pairs of triangles that cross or overlap other
// than by sharing a vertex or an edge. Candidate pairs are the triangles whose bounding boxes
// overlap (CGAL's box intersection); each is decided with exact predicates. Kept in its own
// file so that the CGAL headers compile once. CGAL's orientation of the soup serves as the
// manifold test; other meshes are skipped with the reason, which the caller reports.
//
// The test has a work budget. A well-shaped mesh has a few candidates per triangle (its
// neighbours), but long slivers spanning the mesh or a stack of sheets make nearly every
// pair a candidate (60k such triangles: 1.8e9 pairs, minutes). The test then stops with
// `out_of_budget` set and BudgetReport() saying what it found, instead of running on.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "ergo/mesh/tri_mesh.h"

namespace ergo {

struct SelfIntersectionOptions {
  // Intersecting pairs listed at most; one more stops the test (stopped_at_limit).
  int max_pairs = 100;
  // Candidate pairs tested at most: this many per triangle (a well-shaped mesh has fewer than
  // 20; 200 leaves a margin for coarse or anisotropic ones), but at least min_pair_tests, so
  // small meshes are always tested completely. 10M tests take about 0.5 s here.
  double max_pair_tests_per_triangle = 200;
  int64_t min_pair_tests = 10'000'000;
  // Wall-clock limit in seconds (<= 0: none): a safety net for pairs whose exact predicates
  // are slow (near-coplanar triangles); the pair count above is the deterministic bound.
  double max_seconds = 5;
};

struct SelfIntersections {
  bool checked = false;                    // false: the test could not run, see skipped_because
  std::string skipped_because;             // e.g. "the surface is not manifold"
  std::vector<std::pair<int, int>> pairs;  // intersecting triangles (indices into the mesh)
  bool stopped_at_limit = false;           // more pairs than max_pairs exist
  // The budget ran out before every candidate pair was tested: `pairs` holds those found so
  // far and nothing is known about the rest. Only when checked.
  bool out_of_budget = false;
  bool stopped_by_time = false;     // out of time rather than out of pair tests
  int64_t triangles = 0;            // triangles tested (without repeated or collinear corners)
  int64_t pair_tests = 0;           // candidate pairs tested
  int64_t pair_test_limit = 0;      // the budget's pair tests for this mesh
  double seconds = 0;               // wall time of the whole test
  double estimated_candidates = 0;  // when out_of_budget: all candidate pairs, from a sample

  // When out_of_budget: "self-intersection test stopped after 0.52 s and 12,000,000
  // triangle-pair tests: the mesh has about 1.8e+09 pairs of triangles whose bounding boxes
  // overlap (...)". Empty otherwise.
  std::string BudgetReport() const;
};

// Finds up to `options.max_pairs` pairs of intersecting triangles within the budget.
// Vertices must already be welded (coincident vertices merged), or touching neighbours count
// as intersecting. Triangles with a repeated vertex and collinear (degenerate) triangles are
// ignored here: the mesh check reports them itself. Deterministic unless the time limit hits.
SelfIntersections FindSelfIntersections(const TriMesh& mesh,
                                        const SelfIntersectionOptions& options = {});

}  // namespace ergo
