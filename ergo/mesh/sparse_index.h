// Where an entry of a compressed column sparse matrix lives in its value array, for
// assemblies that precompute their scatter positions into a fixed pattern.
#pragma once

#include <algorithm>

#include <glog/logging.h>

#include "ergo/mesh/eigen_types.h"

namespace ergo {

// The value index of entry (row, col) of `m` (compressed; the entry must be in its pattern,
// CHECKed).
inline int ValueIndex(const SparseMatrix& m, int row, int col) {
  const int* begin = m.innerIndexPtr() + m.outerIndexPtr()[col];
  const int* end = m.innerIndexPtr() + m.outerIndexPtr()[col + 1];
  const int* it = std::lower_bound(begin, end, row);
  CHECK(it != end && *it == row) << "entry (" << row << "," << col << ") not in the pattern";
  return static_cast<int>(it - m.innerIndexPtr());
}

}  // namespace ergo
