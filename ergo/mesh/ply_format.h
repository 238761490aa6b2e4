// Stanford PLY triangle meshes: ascii, binary_little_endian and binary_big_endian; any
// property types (int8 ... float64) and list types; x, y, z of `vertex` and the
// `vertex_indices` (or `vertex_index`) list of `face` are read, every other property and
// element skipped. Polygons are fan-triangulated. Writes ASCII or binary little-endian with
// double coordinates, so a round trip is exact.
#pragma once

#include <string>

#include "ergo/mesh/mesh_io.h"

namespace ergo {

TriMesh ReadPly(const std::string& path, const ReadOptions& options, ReadDetails* details);

void WritePly(const std::string& path, const TriMesh& mesh, const WriteOptions& options);

}  // namespace ergo
