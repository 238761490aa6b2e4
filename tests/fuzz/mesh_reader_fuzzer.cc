// libFuzzer harness of one mesh reader (ERGO_FUZZ_FORMAT: obj, off, ply, stl, msh, tetgen):
// the input becomes a file with that extension and goes through the reader and then the mesh
// check, as `ergo_mesh check` does. InputError is a reader's answer to bad input and ends the
// run normally; anything else (another exception, a crash, a CHECK, a sanitizer report, a
// hang or a huge allocation) is a finding, and so is a message that does not name the input
// file, or lacks what is wrong or the fix. A TetGen input is split at its first line "#ele"
// into the .node part and the .ele part (a '#' line is a comment to TetGen).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "ergo/mesh/input_error.h"
#include "ergo/mesh/mesh_check.h"
#include "ergo/mesh/mesh_io.h"
#include "ergo/mesh/tetgen_format.h"

namespace {

namespace fs = std::filesystem;

constexpr std::string_view kFormat = ERGO_FUZZ_FORMAT;
constexpr std::string_view kEleSeparator = "\n#ele\n";

// A directory of this process for the input files, in memory when /dev/shm exists; removed
// at exit (never destroyed before that, so the exit handler can still name it).
const std::string& InputDir() {
  static const std::string* const dir = [] {
    const fs::path base =
        fs::is_directory("/dev/shm") ? fs::path("/dev/shm") : fs::temp_directory_path();
    const fs::path path =
        base / ("ergo_fuzz_" + std::string(kFormat) + "_" + std::to_string(::getpid()));
    fs::create_directories(path);
    return new std::string(path.string());
  }();
  static const bool cleanup = std::atexit([] {
                                std::error_code ignored;
                                fs::remove_all(*dir, ignored);
                              }) == 0;
  (void)cleanup;
  return *dir;
}

void WriteInput(const std::string& path, std::string_view bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// Writes the input as the reader's file(s); returns the path to read.
std::string WriteFiles(std::string_view bytes) {
  const std::string stem = InputDir() + "/input";
  if (kFormat != "tetgen") {
    WriteInput(stem + "." + std::string(kFormat), bytes);
    return stem + "." + std::string(kFormat);
  }
  const size_t split = bytes.find(kEleSeparator);
  const std::string_view node = bytes.substr(0, split);
  const std::string_view ele = split == std::string_view::npos
                                   ? std::string_view()
                                   : bytes.substr(split + kEleSeparator.size());
  WriteInput(stem + ".node", node);
  WriteInput(stem + ".ele", ele);
  return stem + ".node";
}

// A message without what is wrong, what to do or the file it is about is a finding too.
void RequireMessage(bool ok, const std::string& message) {
  if (ok) return;
  std::fprintf(stderr, "incomplete message: %s\n", message.c_str());
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = WriteFiles(std::string_view(reinterpret_cast<const char*>(data), size));
  ergo::MeshCheckOptions options;
  options.require_closed = size % 2 == 1;  // both severities of an open boundary
  // A small budget: the fuzzer is after crashes, not verdicts on huge candidate sets.
  options.self_intersection.min_pair_tests = 200000;
  options.self_intersection.max_seconds = 1;
  try {
    ergo::ReadDetails details;
    const ergo::AnyMesh mesh = ergo::ReadAnyMesh(path, {}, &details);
    const ergo::MeshCheckReport report =
        mesh.is_tet ? ergo::CheckTetMesh(mesh.volume, path, options, &details)
                    : ergo::CheckTriMesh(mesh.surface, path, options, &details);
    const std::string text = report.FullReport() + report.BriefReport();
    for (const ergo::MeshIssue& issue : report.issues) {
      RequireMessage(!issue.what.empty(), text);
      RequireMessage(issue.severity == ergo::Severity::kNote || !issue.fix.empty(), text);
    }
  } catch (const ergo::InputError& error) {
    const std::string& source = error.source();
    const bool names_input =
        source == path || (kFormat == "tetgen" && source == ergo::TetGenElePath(path));
    RequireMessage(names_input && !error.problem().empty() && !error.fix().empty(), error.what());
  }
  return 0;
}
