#pragma once
// BandMemory: which voxels of a height band have ever been known (Free or Occupied), kept
// after the rolling window has moved on and forgotten them. Per x-y column one 64-bit word,
// bit i for the voxel at z-key z_lo + i (layers past 64 are never remembered), in chunks of
// 32 x 32 columns allocated where something was marked: a 30 x 30 m floor at 0.1 m voxels
// takes ~0.8 MiB. The frontier finder marks the known voxels it scans and asks about space
// just outside the window: free space the window cuts off counts as unexplored only where the
// voxel beyond was never seen (so the window's edge does not make frontiers of rooms flown
// before).

#include <array>
#include <cstdint>
#include <unordered_map>

#include "ussnav/core/types.hpp"

namespace ussnav {

class BandMemory {
 public:
  // Remembers voxels with z-key in [z_lo, z_lo + layers), layers <= 64.
  explicit BandMemory(int z_lo = 0, int layers = 64) : z_lo_(z_lo), layers_(layers < 64 ? layers : 64) {}

  void mark(const Vec3i& k) {
    const int b = k.z() - z_lo_;
    if (b < 0 || b >= layers_) return;
    chunks_[chunkKey(k.x(), k.y())][size_t(index(k.x(), k.y()))] |= uint64_t(1) << b;
  }
  bool known(const Vec3i& k) const {
    const int b = k.z() - z_lo_;
    if (b < 0 || b >= layers_) return false;
    const auto it = chunks_.find(chunkKey(k.x(), k.y()));
    return it != chunks_.end() && ((it->second[size_t(index(k.x(), k.y()))] >> b) & 1) != 0;
  }
  size_t chunks() const { return chunks_.size(); }
  size_t memoryBytes() const { return chunks_.size() * (sizeof(Chunk) + 32) + sizeof(*this); }
  void clear() { chunks_.clear(); }

 private:
  static constexpr int kBits = 5;  // 32 x 32 columns per chunk
  using Chunk = std::array<uint64_t, 1 << (2 * kBits)>;
  static uint64_t chunkKey(int x, int y) {
    return uint64_t(uint32_t(x >> kBits)) << 32 | uint64_t(uint32_t(y >> kBits));
  }
  static int index(int x, int y) {
    constexpr int m = (1 << kBits) - 1;
    return (y & m) << kBits | (x & m);
  }
  int z_lo_;
  int layers_;
  std::unordered_map<uint64_t, Chunk> chunks_;  // value-initialised (zero) on first mark
};

}  // namespace ussnav
