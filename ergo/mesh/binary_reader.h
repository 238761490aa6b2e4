// Bounds-checked reading of binary mesh data (PLY, STL, gmsh) in either byte order, and
// little-endian output for the binary writers. Values are assembled byte by byte, so the
// code does not depend on the host's byte order or on alignment.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <ostream>
#include <string>
#include <string_view>

namespace ergo {

enum class ByteOrder { kLittleEndian, kBigEndian };

class ByteReader {
 public:
  ByteReader(std::string_view bytes, size_t offset, ByteOrder order)
      : bytes_(bytes), offset_(offset), order_(order) {}

  size_t offset() const { return offset_; }
  size_t remaining() const { return offset_ < bytes_.size() ? bytes_.size() - offset_ : 0; }
  bool Has(size_t count) const { return count <= remaining(); }

  // Each returns false (and reads nothing) when fewer bytes remain than the value needs.
  bool ReadUnsigned(int size, uint64_t* value) {
    if (!Has(static_cast<size_t>(size))) return false;
    uint64_t result = 0;
    for (int i = 0; i < size; ++i) {
      const uint64_t byte = static_cast<unsigned char>(bytes_[offset_ + i]);
      const int shift = order_ == ByteOrder::kLittleEndian ? 8 * i : 8 * (size - 1 - i);
      result |= byte << shift;
    }
    offset_ += static_cast<size_t>(size);
    *value = result;
    return true;
  }
  bool ReadInt32(int32_t* value) {
    uint64_t bits = 0;
    if (!ReadUnsigned(4, &bits)) return false;
    const uint32_t narrow = static_cast<uint32_t>(bits);
    std::memcpy(value, &narrow, 4);
    return true;
  }
  bool ReadFloat32(float* value) {
    uint64_t bits = 0;
    if (!ReadUnsigned(4, &bits)) return false;
    const uint32_t narrow = static_cast<uint32_t>(bits);
    std::memcpy(value, &narrow, 4);
    return true;
  }
  bool ReadFloat64(double* value) {
    uint64_t bits = 0;
    if (!ReadUnsigned(8, &bits)) return false;
    std::memcpy(value, &bits, 8);
    return true;
  }
  bool Skip(size_t count) {
    if (!Has(count)) return false;
    offset_ += count;
    return true;
  }

 private:
  std::string_view bytes_;
  size_t offset_;
  ByteOrder order_;
};

// Little-endian output of fixed-size values.
inline void WriteLittleEndian(std::ostream& out, uint64_t bits, int size) {
  char bytes[8];
  for (int i = 0; i < size; ++i) bytes[i] = static_cast<char>((bits >> (8 * i)) & 0xFF);
  out.write(bytes, size);
}
inline void WriteInt32LE(std::ostream& out, int32_t value) {
  uint32_t bits;
  std::memcpy(&bits, &value, 4);
  WriteLittleEndian(out, bits, 4);
}
inline void WriteFloat32LE(std::ostream& out, float value) {
  uint32_t bits;
  std::memcpy(&bits, &value, 4);
  WriteLittleEndian(out, bits, 4);
}
inline void WriteFloat64LE(std::ostream& out, double value) {
  uint64_t bits;
  std::memcpy(&bits, &value, 8);
  WriteLittleEndian(out, bits, 8);
}

}  // namespace ergo
