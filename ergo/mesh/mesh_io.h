// Mesh files in and out, chosen by extension. Triangle meshes: .obj, .off, .ply (ASCII and
// binary), .stl (ASCII and binary), .msh (gmsh v2 / v4 triangles). Tetrahedral meshes: .msh
// (gmsh v2 / v4) and TetGen .node/.ele pairs. Readers scale coordinates to metres by the
// unit they are given and throw ergo::InputError (file, line or element, what, fix) on any
// file they cannot use; writers write a temporary file and rename it, so no partial output.
#pragma once

#include <string>
#include <vector>

#include "ergo/mesh/length_unit.h"
#include "ergo/mesh/tri_mesh.h"

namespace ergo {

struct ReadOptions {
  LengthUnit unit = LengthUnit::kMetre;  // unit of the file's coordinates
};

// Something a reader noticed that does not stop the mesh from being used: a note
// ("12 quads were split into triangles") or, when is_problem, a fault of the file that the
// reader worked around ("2 faces with fewer than 3 vertices were skipped").
struct ReadNote {
  bool is_problem = false;
  std::string location;  // "line 12", "element 7", or "" for the whole file
  std::string what;
  std::string fix;  // "" for plain notes
};

// Optional extra output of a reader.
struct ReadDetails {
  std::vector<ReadNote> notes;
  std::string format;              // e.g. "OFF", "PLY binary little-endian", "gmsh 4.1 ASCII"
  std::vector<int> vertex_lines;   // 1-based source line of each vertex; empty for binary files
  std::vector<int> element_lines;  // source line of each triangle / tet; empty for binary files
  // For a TetGen pair, the files those lines are in (the .node and the .ele); "" otherwise.
  std::string vertex_file, element_file;
};

// Reads a triangle mesh (.obj .off .ply .stl .msh); polygons are fan-triangulated.
TriMesh ReadTriMesh(const std::string& path, const ReadOptions& options = {},
                    ReadDetails* details = nullptr);

// Reads a tetrahedral mesh: .msh, or either file of a TetGen .node/.ele pair.
// Higher-order tets (tet10, ...) keep their corner nodes.
TetMesh ReadTetMesh(const std::string& path, const ReadOptions& options = {},
                    ReadDetails* details = nullptr);

// What a mesh file holds, for callers that accept both kinds (the mesh check).
struct AnyMesh {
  bool is_tet = false;
  TriMesh surface;  // when !is_tet
  TetMesh volume;   // when is_tet
};

// Reads tets from .node/.ele and from a .msh that has any, triangles otherwise.
AnyMesh ReadAnyMesh(const std::string& path, const ReadOptions& options = {},
                    ReadDetails* details = nullptr);

// True for extensions ReadTetMesh understands as tetrahedral-only (.node, .ele).
bool IsTetGenPath(const std::string& path);

enum class Encoding { kAscii, kBinary };
enum class MshVersion { k41, k22 };

struct WriteOptions {
  LengthUnit unit = LengthUnit::kMetre;  // unit of the written coordinates
  Encoding encoding = Encoding::kAscii;  // .ply and .stl only (binary PLY is little-endian)
  MshVersion msh_version = MshVersion::k41;
};

// Writes a triangle mesh (.obj .off .ply .stl .msh). Throws InputError when the path
// cannot be written; the file appears complete or not at all.
void WriteTriMesh(const std::string& path, const TriMesh& mesh, const WriteOptions& options = {});

// Writes a tetrahedral mesh: .msh, or a TetGen pair (path ends in .node or .ele; both files
// are written).
void WriteTetMesh(const std::string& path, const TetMesh& mesh, const WriteOptions& options = {});

}  // namespace ergo
