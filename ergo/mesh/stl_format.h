// STL triangle meshes, ASCII and binary. Binary is recognised by its size (84 + 50·n bytes
// for n triangles), so binary files whose 80-byte header starts with "solid" are read
// correctly. STL stores each triangle's corners separately; corners with identical
// coordinates are welded into one vertex. Writes ASCII (shortest exact decimals) or binary
// (float32, as the format prescribes).
#pragma once

#include <string>

#include "ergo/mesh/mesh_io.h"

namespace ergo {

TriMesh ReadStl(const std::string& path, const ReadOptions& options, ReadDetails* details);

void WriteStl(const std::string& path, const TriMesh& mesh, const WriteOptions& options);

}  // namespace ergo
