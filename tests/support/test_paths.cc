#include "tests/support/test_paths.h"

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <random>
#include <utility>
#include <vector>

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

namespace {

// The scratch directories of this test process, removed when it exits (each ctest run left
// about a hundred behind) unless ERGO_KEEP_SCRATCH is set, to look at a failure's files.
class ScratchDirectories {
 public:
  ~ScratchDirectories() {
    if (std::getenv("ERGO_KEEP_SCRATCH") != nullptr) return;
    for (const auto& [dir, owner] : dirs_) {
      // A death test's forked child exits too: only the process that made a directory
      // removes it.
      if (owner != ::getpid()) continue;
      std::error_code ignored;
      fs::remove_all(dir, ignored);
    }
  }
  void Add(const fs::path& dir) {
    std::lock_guard<std::mutex> lock(mutex_);
    dirs_.emplace_back(dir, ::getpid());
  }

 private:
  std::mutex mutex_;
  std::vector<std::pair<fs::path, pid_t>> dirs_;
};

ScratchDirectories& Scratch() {
  static ScratchDirectories directories;
  return directories;
}

}  // namespace

std::string MakeScratchDir(const std::string& prefix) {
  static std::atomic<int> counter{0};
  const fs::path dir =
      fs::temp_directory_path() /
      ("ergo_" + prefix + "_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
  fs::remove_all(dir);
  fs::create_directories(dir);
  Scratch().Add(dir);
  return dir.string();
}

}  // namespace ergo::testing
