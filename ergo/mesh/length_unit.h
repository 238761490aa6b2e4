// Length units accepted by every reader. Inside ergo everything is SI (metres); a file
// in millimetres is scaled once, on reading, and never silently.
#pragma once

#include <string>

namespace ergo {

enum class LengthUnit { kMetre, kMillimetre };

// Metres per file unit: 1 for m, 1e-3 for mm.
inline double MetresPerUnit(LengthUnit unit) {
  return unit == LengthUnit::kMillimetre ? 1e-3 : 1.0;
}

// Parses "m" or "mm"; returns false for anything else.
inline bool ParseLengthUnit(const std::string& text, LengthUnit* unit) {
  if (text == "m") {
    *unit = LengthUnit::kMetre;
    return true;
  }
  if (text == "mm") {
    *unit = LengthUnit::kMillimetre;
    return true;
  }
  return false;
}

}  // namespace ergo
