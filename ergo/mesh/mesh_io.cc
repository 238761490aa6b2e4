#include "ergo/mesh/mesh_io.h"

#include <filesystem>

#include <glog/logging.h>

#include "ergo/mesh/input_error.h"
#include "ergo/mesh/msh_format.h"
#include "ergo/mesh/obj_format.h"
#include "ergo/mesh/off_format.h"
#include "ergo/mesh/ply_format.h"
#include "ergo/mesh/stl_format.h"
#include "ergo/mesh/tetgen_format.h"
#include "ergo/mesh/text_reader.h"

namespace ergo {

namespace {

const char kSurfaceFormats[] = ".obj, .off, .ply, .stl or .msh";
const char kVolumeFormats[] = ".msh or a TetGen .node/.ele pair";

std::string Extension(const std::string& path) {
  return ToLower(std::filesystem::path(path).extension().string());
}

[[noreturn]] void UnknownExtension(const std::string& path, const char* formats) {
  const std::string extension = Extension(path);
  throw InputError(path, "",
                   extension.empty() ? "the file name has no extension, so its format is unknown"
                                     : "unknown mesh file extension '" + extension + "'",
                   std::string("use one of ") + formats);
}

// Writers are handed meshes built by the program: a bad index or a NaN is a bug upstream.
template <typename Elements>
void CheckWritable(const Vertices& vertices, const Elements& elements, const std::string& path) {
  CHECK(vertices.allFinite()) << path << ": refusing to write non-finite coordinates";
  if (elements.size() > 0) {
    CHECK_GE(elements.minCoeff(), 0) << path << ": negative vertex index";
    CHECK_LT(elements.maxCoeff(), vertices.rows()) << path << ": vertex index out of range";
  }
}

}  // namespace

bool IsTetGenPath(const std::string& path) {
  const std::string extension = Extension(path);
  return extension == ".node" || extension == ".ele";
}

TriMesh ReadTriMesh(const std::string& path, const ReadOptions& options, ReadDetails* details) {
  const std::string extension = Extension(path);
  if (extension == ".obj") return ReadObj(path, options, details);
  if (extension == ".off") return ReadOff(path, options, details);
  if (extension == ".ply") return ReadPly(path, options, details);
  if (extension == ".stl") return ReadStl(path, options, details);
  if (extension == ".msh") {
    return ReadMsh(path, options, MshContent::kTriangles, details).surface;
  }
  if (IsTetGenPath(path)) {
    throw InputError(path, "", "a TetGen .node/.ele pair is a tetrahedral mesh, not a surface",
                     "read it as a tetrahedral mesh, or pass a surface file");
  }
  UnknownExtension(path, kSurfaceFormats);
}

TetMesh ReadTetMesh(const std::string& path, const ReadOptions& options, ReadDetails* details) {
  if (IsTetGenPath(path)) return ReadTetGen(path, options, details);
  if (Extension(path) == ".msh") {
    return ReadMsh(path, options, MshContent::kTets, details).volume;
  }
  const std::string extension = Extension(path);
  if (extension == ".obj" || extension == ".off" || extension == ".ply" || extension == ".stl") {
    throw InputError(path, "", "a " + extension + " file holds a surface, not tetrahedra",
                     std::string("pass a tetrahedral mesh: ") + kVolumeFormats);
  }
  UnknownExtension(path, kVolumeFormats);
}

AnyMesh ReadAnyMesh(const std::string& path, const ReadOptions& options, ReadDetails* details) {
  if (IsTetGenPath(path)) {
    AnyMesh mesh;
    mesh.is_tet = true;
    mesh.volume = ReadTetGen(path, options, details);
    return mesh;
  }
  if (Extension(path) == ".msh") {
    return ReadMsh(path, options, MshContent::kTetsElseTriangles, details);
  }
  const std::string extension = Extension(path);
  if (extension != ".obj" && extension != ".off" && extension != ".ply" && extension != ".stl") {
    UnknownExtension(path, ".obj, .off, .ply, .stl, .msh, .node or .ele");
  }
  AnyMesh mesh;
  mesh.surface = ReadTriMesh(path, options, details);
  return mesh;
}

void WriteTriMesh(const std::string& path, const TriMesh& mesh, const WriteOptions& options) {
  CheckWritable(mesh.vertices, mesh.triangles, path);
  const std::string extension = Extension(path);
  if (extension == ".obj") return WriteObj(path, mesh, options);
  if (extension == ".off") return WriteOff(path, mesh, options);
  if (extension == ".ply") return WritePly(path, mesh, options);
  if (extension == ".stl") return WriteStl(path, mesh, options);
  if (extension == ".msh") return WriteMsh(path, mesh, options);
  UnknownExtension(path, kSurfaceFormats);
}

void WriteTetMesh(const std::string& path, const TetMesh& mesh, const WriteOptions& options) {
  CheckWritable(mesh.vertices, mesh.tets, path);
  if (IsTetGenPath(path)) return WriteTetGen(path, mesh, options);
  if (Extension(path) == ".msh") return WriteMsh(path, mesh, options);
  UnknownExtension(path, kVolumeFormats);
}

}  // namespace ergo
