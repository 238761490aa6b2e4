// Wall-clock seconds elapsed since a steady_clock time point: the timings in every stage's
// reports and summaries (assembly, contact, factorization, body build, ...), in seconds.
//
//   const auto start = std::chrono::steady_clock::now();
//   ...
//   result.seconds = SecondsSince(start);
#pragma once

#include <chrono>

namespace ergo {

inline double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace ergo
