#include "ergo/body/core_lock.h"

#include "ergo/mesh/input_error.h"
#include "ergo/mesh/split_list.h"

namespace ergo {
namespace {

constexpr const char* kNames[6] = {"tx", "ty", "tz", "rx", "ry", "rz"};

}  // namespace

std::vector<int> CoreLock::FreeComponents() const {
  std::vector<int> free;
  for (int k = 0; k < 6; ++k)
    if (!locked[k]) free.push_back(k);
  return free;
}

int CoreLock::FreeCount() const { return static_cast<int>(FreeComponents().size()); }

std::string CoreLock::ToString() const {
  std::string text;
  for (int k = 0; k < 6; ++k) {
    if (!locked[k]) continue;
    if (!text.empty()) text += ",";
    text += kNames[k];
  }
  return text.empty() ? "none" : text;
}

void ValidateCoreLock(const CoreLock& lock, const std::string& source) {
  if (lock.locked[0] && lock.locked[1] && lock.locked[2]) {
    throw InputError(source, "", "every translation of the core is locked (" + lock.ToString() + ")",
                     "free the translation along the load (e.g. --lock=tx,tz for a load along "
                     "-y): a body that cannot move cannot settle onto the support");
  }
  const int locked_rotations = lock.locked[3] + lock.locked[4] + lock.locked[5];
  if (locked_rotations == 1) {
    throw InputError(source, "", "exactly one rotation axis is locked (" + lock.ToString() + ")",
                     "lock two rotation axes (one free axis, e.g. pitch only) or none or all "
                     "three: two free axes generate every rotation through their commutator");
  }
}

CoreLock ParseCoreLock(const std::string& text, const std::string& source) {
  CoreLock lock;
  if (text.empty() || text == "none") return lock;
  for (const std::string& name : SplitList(text, ',')) {
    bool known = false;
    for (int k = 0; k < 6; ++k) {
      if (name == kNames[k]) {
        lock.locked[k] = true;
        known = true;
      }
    }
    if (!known) {
      throw InputError(source, "", "unknown core DOF '" + name + "'",
                       "use a comma-separated list of tx, ty, tz, rx, ry, rz (or none)");
    }
  }
  ValidateCoreLock(lock, source);
  return lock;
}

}  // namespace ergo
