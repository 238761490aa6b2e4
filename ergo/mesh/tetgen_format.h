// TetGen .node/.ele tetrahedral meshes. Either file of the pair may be named; the other is
// found by swapping the extension. Node numbering may start at 0 or 1 (the first node's
// number decides); attributes and boundary markers are skipped; 10-node tets keep their
// corners. Two-dimensional files of Shewchuk's Triangle program, which use the same
// extensions, are refused clearly. Writes 1-based files, as TetGen does by default.
#pragma once

#include <string>

#include "ergo/mesh/mesh_io.h"

namespace ergo {

TetMesh ReadTetGen(const std::string& path, const ReadOptions& options, ReadDetails* details);

// `path` ends in .node or .ele; both files are written (each atomically).
void WriteTetGen(const std::string& path, const TetMesh& mesh, const WriteOptions& options);

// The .node and .ele paths of the pair that `path` (either of them) belongs to.
std::string TetGenNodePath(const std::string& path);
std::string TetGenElePath(const std::string& path);

}  // namespace ergo
