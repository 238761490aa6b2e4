// Geomview OFF triangle meshes (ASCII). Reads the OFF, COFF, NOFF, CNOFF and STOFF headers,
// counts on the header line or the next, '#' comments, vertex colours and normals (ignored),
// and face records that wrap lines or carry colours; polygons are fan-triangulated.
// Refuses 4OFF / nOFF and binary OFF with a clear message. Writes plain OFF.
#pragma once

#include <string>

#include "ergo/mesh/mesh_io.h"

namespace ergo {

TriMesh ReadOff(const std::string& path, const ReadOptions& options, ReadDetails* details);

void WriteOff(const std::string& path, const TriMesh& mesh, const WriteOptions& options);

}  // namespace ergo
