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

// A fresh empty directory under the system temp dir, unique per call.
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

}  // namespace ergo::testing
