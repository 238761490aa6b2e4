// Wavefront OBJ triangle meshes. Reads `v` and `f` records (f with v, v/vt, v//vn or
// v/vt/vn corners, negative indices relative to the last vertex, polygons fan-triangulated,
// lines ending in '\' continued); every other record is ignored. Writes v and f only.
#pragma once

#include <string>

#include "ergo/mesh/mesh_io.h"

namespace ergo {

TriMesh ReadObj(const std::string& path, const ReadOptions& options, ReadDetails* details);

void WriteObj(const std::string& path, const TriMesh& mesh, const WriteOptions& options);

}  // namespace ergo
