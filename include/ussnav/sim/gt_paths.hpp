#pragma once
// Shortest collision-free paths on the ground truth, for the evaluation (SPL's L*, room
// reachability) and for scripted trajectories. A 2D grid at the ground-truth resolution marks
// where a UAV of `radius` can hover at `height` (no occupied voxel within the radius in the
// band height +- radius); for worlds with rooms, cells outside every room are excluded.
// Dijkstra with 16-connected moves, then line-of-sight string pulling: lengths come within
// about 1 % of the true Euclidean shortest path.

#include <optional>
#include <vector>

#include "ussnav/sim/ground_truth.hpp"
#include "ussnav/sim/world.hpp"

namespace ussnav {

class GtPlanner {
 public:
  // `height` is the flight height above each room's floor (rooms assumed at floor_z = 0 when
  // there are none: then `height` is absolute above the world's lowest occupied level).
  GtPlanner(const GroundTruthGrid& gt, const World& world, double height, double radius);

  bool freeAt(const Vec2& p) const;
  // Shortest path from `from` to the nearest of `goals` (x, y; z set to the flight height).
  // nullopt when none is reachable.
  std::optional<std::vector<Vec3>> shortestPath(const Vec2& from, const std::vector<Vec2>& goals) const;
  std::optional<std::vector<Vec3>> shortestPath(const Vec2& from, const Vec2& to) const {
    return shortestPath(from, std::vector<Vec2>{to});
  }
  // Nearest free cell centre to p within `search` metres, if any.
  std::optional<Vec2> nearestFree(const Vec2& p, double search = 1.0) const;
  double flightZ() const { return z_; }
  // Free cells (x, y) as points, every `stride` cells (for sampling poses).
  std::vector<Vec2> freeSamples(int stride) const;
  // Every pair of rooms joined by a free path (one free sample per room, BFS labels).
  bool allRoomsConnected(const World& world) const;

  static double length(const std::vector<Vec3>& path);

 private:
  int idx(int x, int y) const { return y * nx_ + x; }
  bool cellFree(int x, int y) const { return x >= 0 && y >= 0 && x < nx_ && y < ny_ && free_[idx(x, y)]; }
  Vec2 cellCenter(int x, int y) const { return Vec2(x0_ + (x + 0.5) * res_, y0_ + (y + 0.5) * res_); }
  bool cellOf(const Vec2& p, int& x, int& y) const;
  bool segmentFree(const Vec2& a, const Vec2& b) const;

  double res_, x0_, y0_, z_;
  int nx_ = 0, ny_ = 0;
  std::vector<uint8_t> free_;
};

}  // namespace ussnav
