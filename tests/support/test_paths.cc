#include "tests/support/test_paths.h"

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <random>

#include <unistd.h>

namespace ergo::testing {

namespace fs = std::filesystem;

std::string SourcePath(const std::string& relative) {
  const char* env = std::getenv("ERGO_SOURCE_DIR");
  const std::string root = env ? env : ERGO_SOURCE_DIR;
  return (fs::path(root) / relative).string();
}

std::string PeerMeshDir() {
  const fs::path dir = fs::path(SourcePath("")) / ".." / "shared" / "peer-meshes";
  std::error_code ec;
  if (fs::is_directory(dir, ec)) return fs::canonical(dir, ec).string();
  return "";
}

std::string RealScanDir() {
  const fs::path dir = fs::path(SourcePath("")) / ".." / "shared" / "real-scans";
  std::error_code ec;
  if (fs::is_directory(dir, ec)) return fs::canonical(dir, ec).string();
  return "";
}

std::string MakeScratchDir(const std::string& prefix) {
  static std::atomic<int> counter{0};
  const fs::path dir =
      fs::temp_directory_path() /
      ("ergo_" + prefix + "_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

}  // namespace ergo::testing
