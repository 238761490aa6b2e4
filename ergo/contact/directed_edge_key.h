// A hash key for the directed edge from → to of a triangle mesh (both vertex indices ≥ 0).
#pragma once

#include <cstdint>

namespace ergo {

inline std::uint64_t DirectedEdgeKey(int from, int to) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(from)) << 32) |
         static_cast<std::uint32_t>(to);
}

}  // namespace ergo
