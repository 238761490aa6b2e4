// Where tests find the project's files, the shared peer-mesh corpus, and scratch space.
#pragma once

#include <string>

namespace ergo::testing {

// Absolute path of a file in the source tree, e.g. SourcePath("tests/mesh/corpus").
std::string SourcePath(const std::string& relative);

// ../shared/peer-meshes next to the checkout, or "" when absent (a user's clone).
std::string PeerMeshDir();

// ../shared/real-scans (a real foot scan and its licence) next to the checkout, or "".
std::string RealScanDir();

// A fresh empty directory under the system temp dir, unique per call; removed when the test
// process exits (set ERGO_KEEP_SCRATCH=1 to keep it).
std::string MakeScratchDir(const std::string& prefix);

// True in the AddressSanitizer + UBSan build (tools/setup.sh test --sanitize), which runs
// 10-20x slower: there the sanitizers look for memory and undefined-behaviour errors, so the
// longest numerical sweeps (component-wise finite differences, long optimisation runs) check
// a subset of what the Release run checks in full.
constexpr bool SanitizedBuild() {
#ifdef ERGO_SANITIZED_BUILD
  return true;
#else
  return false;
#endif
}

// True where the command-line programs are built (ERGO_BUILD_TOOLS, on by default). The
// sanitizer run builds the libraries and their stage tests only: the tests that run a
// program are end-to-end runs, minutes each under the sanitizers, and run in the Release pass.
constexpr bool ToolsBuilt() {
#ifdef ERGO_TOOLS_BUILT
  return true;
#else
  return false;
#endif
}

}  // namespace ergo::testing

// In a test that runs one of the programs (bin/ergo_*): skip where they are not built.
#define ERGO_SKIP_WITHOUT_TOOLS()                                                               \
  if (!::ergo::testing::ToolsBuilt())                                                           \
  GTEST_SKIP() << "the programs are not built here (ERGO_BUILD_TOOLS=OFF: the sanitizer run); " \
                  "the Release run runs this test"
