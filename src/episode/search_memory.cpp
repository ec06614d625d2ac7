#include "ussnav/episode/search_memory.hpp"

#include <algorithm>

namespace ussnav {

namespace {
constexpr double kSameTarget = 0.75;  // m: centroids this close are one target
constexpr double kForGood = 1e18, kForGoodBelow = 1e17;
}  // namespace

bool TargetMemory::skipped(const Vec3& c, double t) const {
  return std::any_of(skipped_.begin(), skipped_.end(),
                     [&](const Skipped& s) { return s.until > t && (s.centroid - c).norm() < kSameTarget; });
}

void TargetMemory::skipForGood(const Vec3& c) { skipped_.push_back({c, kForGood}); }

int TargetMemory::skipUnreachable(const Vec3& c, double t, double retry_s) {
  const auto times = std::count_if(skipped_.begin(), skipped_.end(),
                                   [&](const Skipped& s) { return (s.centroid - c).norm() < kSameTarget; });
  skipped_.push_back({c, times >= 2 ? kForGood : t + retry_s});
  return int(times);
}

bool TargetMemory::pendingRetry(double t) const {
  return std::any_of(skipped_.begin(), skipped_.end(), [&](const Skipped& s) { return s.until > t && s.until < kForGoodBelow; });
}

const Vec3* TargetMemory::lookedFrom(const Vec3& c) const {
  for (const auto& [centroid, from] : looked_)
    if ((centroid - c).norm() < kSameTarget) return &from;
  return nullptr;
}

bool ObjectTries::skipped(int id, double t, double distance) const {
  const auto it = retry_at_.find(id);
  if (it == retry_at_.end() || it->second <= t) return false;
  const auto near = near_radius_.find(id);
  return near == near_radius_.end() || distance > near->second;
}

void ObjectTries::fail(int id, double t, double retry_s, bool sighting) {
  if (sighting) return sightingFailed(id);
  retry_at_[id] = ++failures_[id] >= kMaxObjectTries ? kForGood : t + retry_s;
  near_radius_.erase(id);
}

void ObjectTries::failFromAfar(int id, double t, double retry_s, bool near, bool sighting, double near_radius) {
  if (sighting) return sightingFailed(id);
  if (near || ++far_failures_[id] > kMaxFarTries) {
    fail(id, t, retry_s);
  } else {
    retry_at_[id] = t + retry_s;
    transits_[id] = std::min(transits_[id], kMaxTransits - 1);
    if (near_radius > 0.0) near_radius_[id] = near_radius;
  }
}

bool ObjectTries::mayTransit(int id) const {
  const auto it = transits_.find(id);
  return it == transits_.end() || it->second < kMaxTransits;
}

void ObjectTries::transitBlocked(int id) {
  if (++transit_replans_[id] <= kMaxTransitReplans) transits_[id] = std::max(0, transits_[id] - 1);
}

const std::vector<Vec3>& ObjectTries::noPoseSpots(int id) const {
  static const std::vector<Vec3> none;
  const auto it = no_pose_from_.find(id);
  return it == no_pose_from_.end() ? none : it->second;
}

bool ObjectTries::lookedInVainFrom(int id, const Vec3& p) const {
  const auto it = no_view_from_.find(id);
  return it != no_view_from_.end() &&
         std::any_of(it->second.begin(), it->second.end(), [&](const Vec3& q) { return (q - p).norm() < 0.5; });
}

void ObjectTries::seenFrom(int id, const Vec3& where, const Vec3& object) {
  const double d = (where - object).norm();
  const auto it = seen_from_.find(id);
  if (it == seen_from_.end() || d < it->second.second) seen_from_[id] = {where, d};
}

const Vec3* ObjectTries::seenFromSpot(int id) const {
  const auto it = seen_from_.find(id);
  return it == seen_from_.end() ? nullptr : &it->second.first;
}

bool ObjectTries::pendingRetry(double t) const {
  return std::any_of(retry_at_.begin(), retry_at_.end(), [&](const auto& r) { return r.second > t && r.second < kForGoodBelow; });
}

int BlockingObstacles::add(const OccupancyMap& map, const Vec3& hit, double radius) {
  const Vec3i lo = map.keyOf(hit - Vec3::Constant(radius)), hi = map.keyOf(hit + Vec3::Constant(radius));
  int added = 0;
  for (int x = lo.x(); x <= hi.x(); ++x)
    for (int y = lo.y(); y <= hi.y(); ++y)
      for (int z = lo.z(); z <= hi.z(); ++z) {
        const Vec3i k(x, y, z);
        const Vec3 box_min = k.cast<double>() * map.resolution(), box_max = box_min + Vec3::Constant(map.resolution());
        const double to_box = (hit.cwiseMax(box_min).cwiseMin(box_max) - hit).norm();  // 0 inside the voxel
        if (to_box > radius || map.state(k) != VoxelState::Occupied) continue;
        if (!known_.insert({x, y, z}).second) continue;
        if (voxels_.size() >= kMax) {
          known_.erase({voxels_.front().x(), voxels_.front().y(), voxels_.front().z()});
          voxels_.pop_front();
        }
        voxels_.push_back(k);
        ++added;
      }
  return added;
}

std::vector<Vec3> BlockingObstacles::forgotten(const OccupancyMap& map) const {
  std::vector<Vec3> out;
  for (const Vec3i& k : voxels_)
    if (map.state(k) == VoxelState::Unknown) out.push_back(map.centerOf(k));
  return out;
}

}  // namespace ussnav
