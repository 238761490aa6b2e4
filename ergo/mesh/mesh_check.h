// The mesh check behind `ergo_mesh check`: reads a mesh file (or takes a mesh) and reports
// everything that would make it unusable or wrong as a body or support surface, each finding
// with its file, the elements or lines concerned, what is wrong and the fix.
//
// Triangle surfaces: coincident vertices, degenerate (zero-area) triangles, repeated vertex
// in a face, duplicate faces, non-manifold edges and vertices, open boundary (a problem only
// when a closed surface is required), inconsistent or inward orientation, self-intersections
// (CGAL), unreferenced vertices. Tetrahedral meshes: inverted and zero-volume tets, repeated
// vertex in a tet, duplicate tets, faces shared by more than two tets, unreferenced and
// coincident vertices. Both: a size that suggests the wrong unit (bounding-box diagonal above
// 3 m or below 1 cm). Every check is O(n log n) (duplicates by hashing) except the
// self-intersection test, which has a work budget (self_intersection.h) and reports a
// problem when it runs out rather than running for minutes.
//
//   MeshCheckOptions options;
//   options.require_closed = true;
//   const MeshCheckReport report = CheckMeshFile("support.off", options);
//   std::cout << report.FullReport();
//   return report.ExitCode();  // 0 clean, 1 problems, 2 unusable
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ergo/mesh/length_unit.h"
#include "ergo/mesh/mesh_io.h"
#include "ergo/mesh/self_intersection.h"
#include "ergo/mesh/tri_mesh.h"

namespace ergo {

// note: worth knowing, the mesh is fine; problem: the mesh is wrong for ergo but could be
// read; unusable: the file could not be read at all.
enum class Severity { kNote = 0, kProblem = 1, kUnusable = 2 };

const char* SeverityName(Severity severity);

// One kind of finding, with how many elements have it and a few of them as examples.
struct MeshIssue {
  Severity severity = Severity::kNote;
  std::string code;                   // stable short name, e.g. "non-manifold-edge"
  std::string location;               // where, for findings about one place ("line 12"); often ""
  std::string file;                   // the file `location` is in, if not the checked one
                                      // (the other file of a TetGen pair); usually ""
  std::string what;                   // e.g. "12 edges are shared by more than two triangles"
  std::string fix;                    // what to do about it; "" for plain notes
  int64_t count = 0;                  // elements concerned (0 for whole-file findings)
  std::vector<std::string> examples;  // e.g. "edge (3, 4) (line 17): in triangles 5, 6, 9"
};

struct MeshCheckOptions {
  LengthUnit unit = LengthUnit::kMetre;  // unit of the file's coordinates
  bool require_closed = false;           // open boundary edges are problems, not notes
  bool check_self_intersections = true;
  // Its work budget; a test that runs out is a problem ("self-intersection-test-incomplete").
  SelfIntersectionOptions self_intersection;
  int max_examples = 5;  // examples listed per kind of finding
};

struct MeshCheckReport {
  std::string file;
  std::string format;  // as the reader named it; "" when unreadable
  bool is_tet = false;
  int64_t vertices = 0, triangles = 0, tets = 0;
  double bounding_box_diagonal = 0;  // metres
  std::vector<MeshIssue> issues;

  Severity Worst() const;  // kNote when there are no issues
  // 0 clean (notes allowed), 1 problems, 2 unusable.
  int ExitCode() const { return static_cast<int>(Worst()); }
  // The finding with `code`, or nullptr.
  const MeshIssue* Find(const std::string& code) const;
  // One line: file, verdict, counts of problems.
  std::string BriefReport() const;
  // Summary line, then each finding with its examples and fix, then the verdict.
  std::string FullReport() const;
};

// Reads `path` (any format ReadAnyMesh knows) and checks it. Never throws for bad input:
// an unreadable file is reported as an unusable finding.
MeshCheckReport CheckMeshFile(const std::string& path, const MeshCheckOptions& options = {});

// Checks a mesh already in memory (metres). `source` names it in messages; `details` from
// the reader (optional) add the reader's notes and the source lines of elements.
MeshCheckReport CheckTriMesh(const TriMesh& mesh, const std::string& source,
                             const MeshCheckOptions& options = {},
                             const ReadDetails* details = nullptr);
MeshCheckReport CheckTetMesh(const TetMesh& mesh, const std::string& source,
                             const MeshCheckOptions& options = {},
                             const ReadDetails* details = nullptr);

}  // namespace ergo
