// Objects seen beyond a region, given to the region of the frontier facing them (see
// beyond_objects.hpp).

#include "ussnav/episode/beyond_objects.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace ussnav {
namespace {

// Whether the segment from `from` to the box of `o` (grown by two voxels) crosses no occupied
// voxel and runs through Free voxels for at least `min_free` of the samples before the box.
bool faces(const Vec3& from, const ObjectBrief& o, const OccupancyMap& map, double min_free) {
  const double res = map.resolution();
  const Vec3 half = o.size / 2.0 + Vec3::Constant(2.0 * res);
  const auto inBox = [&](const Vec3& p) { return ((p - o.position).cwiseAbs() - half).maxCoeff() <= 0.0; };
  const Vec3 d = o.position - from;
  const double len = d.norm();
  const int steps = std::max(1, int(std::ceil(len / (0.5 * res))));
  int free = 0, samples = 0;
  for (int i = 1; i <= steps; ++i) {
    const Vec3 p = from + d * (double(i) / steps);
    if (inBox(p)) break;
    const VoxelState s = map.stateAt(p);
    if (s == VoxelState::Occupied) return false;
    ++samples;
    free += s == VoxelState::Free;
  }
  return samples == 0 || double(free) >= min_free * double(samples);
}

}  // namespace

int frontierFacing(const ObjectBrief& o, const std::vector<ExplorationTarget>& targets, const OccupancyMap& map,
                   double min_free) {
  // Nearest first (ties: the lower index), so only the frontiers up to the first facing one
  // cost a walk along their line.
  std::vector<std::pair<double, int>> order;
  for (size_t i = 0; i < targets.size(); ++i) {
    const ExplorationTarget& t = targets[i];
    if (t.kind == TargetKind::Frontier && t.region >= 0)
      order.emplace_back((t.centroid.head<2>() - o.position.head<2>()).norm(), int(i));
  }
  std::sort(order.begin(), order.end());
  for (const auto& [d, i] : order)
    if (faces(targets[size_t(i)].centroid, o, map, min_free)) return i;
  return -1;
}

int facingFrontierRegions(std::vector<RegionSummary>& regions, const std::vector<ExplorationTarget>& targets,
                          const OccupancyMap& map, double min_free) {
  const auto find = [&](int id) {
    return std::find_if(regions.begin(), regions.end(), [&](const RegionSummary& r) { return r.id == id; });
  };
  struct Move {
    size_t to;
    ObjectBrief o;
  };
  std::vector<Move> moves;
  for (RegionSummary& r : regions) {
    std::vector<ObjectBrief> stay;
    for (ObjectBrief& o : r.beyond) {
      const int f = frontierFacing(o, targets, map, min_free);
      const auto to = f >= 0 ? find(targets[size_t(f)].region) : regions.end();
      if (to == regions.end() || to->id == r.id)
        stay.push_back(std::move(o));
      else
        moves.push_back({size_t(to - regions.begin()), std::move(o)});
    }
    r.beyond = std::move(stay);
  }
  for (Move& m : moves) regions[m.to].beyond.push_back(std::move(m.o));
  for (RegionSummary& r : regions)
    std::sort(r.beyond.begin(), r.beyond.end(), [](const ObjectBrief& a, const ObjectBrief& b) { return a.id < b.id; });
  return int(moves.size());
}

}  // namespace ussnav
