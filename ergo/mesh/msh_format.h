// gmsh .msh files: reads MSH 2.x (ASCII and binary) and MSH 4.0 / 4.1 (ASCII), keeping
// tetrahedra (type 4; tet10 and higher order by their corners) or triangles (type 2, tri6
// and higher order by their corners, quads split). MSH 1, MSH 3 and binary MSH 4 are
// refused with the gmsh command that converts them. Writes MSH 4.1 or 2.2 ASCII.
#pragma once

#include <string>

#include "ergo/mesh/mesh_io.h"

namespace ergo {

enum class MshContent { kTets, kTriangles, kTetsElseTriangles };

// Reads what `content` asks for; throws InputError when the file has none of it.
AnyMesh ReadMsh(const std::string& path, const ReadOptions& options, MshContent content,
                ReadDetails* details);

void WriteMsh(const std::string& path, const TriMesh& mesh, const WriteOptions& options);
void WriteMsh(const std::string& path, const TetMesh& mesh, const WriteOptions& options);

}  // namespace ergo
