// CoreLock: which of the rigid core's six degrees of freedom (translations tx, ty, tz and
// rotations rx, ry, rz about world axes) are held fixed (paper §5: the chair's core moves
// only vertically and rotates freely; the shoe translates vertically and pitches; the
// mouse only translates vertically).
#pragma once

#include <array>
#include <string>
#include <vector>

namespace ergo {

struct CoreLock {
  // locked[k] for k = tx, ty, tz, rx, ry, rz.
  std::array<bool, 6> locked{};

  // Indices (0..5) of the unlocked DOFs, in increasing order.
  std::vector<int> FreeComponents() const;
  int FreeCount() const;
  // "tx,tz,rx" style list of the locked DOFs ("none" when nothing is locked).
  std::string ToString() const;
};

// Parses a comma-separated list of DOF names to lock ("tx,tz", "tx,tz,rx,ry", "" or
// "none" for nothing). Throws InputError naming `source` (e.g. the flag) for an unknown
// name, and for exactly one locked rotation: with multiplicative rotation updates two free
// axes generate every rotation (their commutator), so lock 0, 2 or 3 rotation axes.
CoreLock ParseCoreLock(const std::string& text, const std::string& source = "--lock");

// Throws InputError when the lock is not supported: exactly one rotation axis locked, or all
// three translations (nothing could carry the body onto the support).
void ValidateCoreLock(const CoreLock& lock, const std::string& source);

}  // namespace ergo
