#include "ussnav/mapping/inflated_map.hpp"

namespace ussnav {

VoxelState InflatedMap::state(const Vec3i& key) const {
  const double z = (key.z() + 0.5) * base_.resolution();
  if (z < z_min_ || z > z_max_) return VoxelState::Occupied;
  const VoxelState s = base_.state(key);
  if (s == VoxelState::Occupied) return s;
  const uint64_t k = uint64_t(uint32_t(key.x()) & 0x1FFFFF) << 42 | uint64_t(uint32_t(key.y()) & 0x1FFFFF) << 21 |
                     uint64_t(uint32_t(key.z()) & 0x1FFFFF);
  const auto it = cache_.find(k);
  if (it != cache_.end()) return it->second;
  const VoxelState v = base_.isInflatedOccupied(centerOf(key), radius_, false) ? VoxelState::Occupied : s;
  cache_.emplace(k, v);
  return v;
}

}  // namespace ussnav
