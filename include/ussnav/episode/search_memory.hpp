#pragma once
// What the flight loop remembers about what it gave up on, so that it does not fly there again
// at once, and when it may try again:
//  - TargetMemory: exploration targets (frontiers, unseen patches) by centroid. One found
//    unreachable is skipped for blacklist_s, the third time for good; one reached and still open
//    is skipped for good, or (close_look) first tried once more from the graph node nearest to it.
//  - ObjectTries: goal objects by id. A failed approach skips the object for blacklist_s, the
//    kMaxObjectTries-th for good; transits (flights to a graph node near an object no approach
//    pose is found for yet) are counted per object, and a transit cut short by a blocked path is
//    refunded (up to kMaxTransitReplans); failures from afar count for good only after
//    kMaxFarTries. A sighting (an object seen too few times to be declared yet) is approached
//    once: when that fails, it waits until it has been seen often enough, no failure counted.
//  - BlockingObstacles: the occupied voxels that blocked a path being flown, kept for the paths
//    planned after the rolling window has forgotten them.
// Time is the episode's clock (s). Plain state, no I/O.

#include <cmath>
#include <deque>
#include <limits>
#include <map>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include "ussnav/core/types.hpp"
#include "ussnav/mapping/occupancy.hpp"

namespace ussnav {

class TargetMemory {
 public:
  // Whether a target at centroid c is skipped at time t (within 0.75 m of a skipped one).
  bool skipped(const Vec3& c, double t) const;
  // Skipped for good (reached and still open, or no place to look at it from).
  void skipForGood(const Vec3& c);
  // Found unreachable at time t: skipped until t + retry_s, the third time for good. Returns how
  // many times it was found unreachable before.
  int skipUnreachable(const Vec3& c, double t, double retry_s);
  // Whether a target skipped for a while becomes eligible again after t.
  bool pendingRetry(double t) const;
  size_t size() const { return skipped_.size(); }

  // close_look: a target reached once but still open, and where the UAV looked at it from.
  void addLooked(const Vec3& c, const Vec3& from) { looked_.emplace_back(c, from); }
  // Where the UAV looked at the target at c from (nullptr: never looked at it).
  const Vec3* lookedFrom(const Vec3& c) const;

 private:
  struct Skipped {
    Vec3 centroid;
    double until;
  };
  std::vector<Skipped> skipped_;
  std::vector<std::pair<Vec3, Vec3>> looked_;
};

class ObjectTries {
 public:
  static constexpr int kMaxObjectTries = 3, kMaxTransits = 2, kMaxFarTries = 10, kMaxTransitReplans = 5;

  // Whether object `id` is skipped at time t, the UAV `distance` from it in the plane: a wait
  // that began from afar (failFromAfar) ends early once the UAV is within its `near_radius`, as
  // the map around the object, which was what was missing, is then there.
  bool skipped(int id, double t, double distance = std::numeric_limits<double>::infinity()) const;
  // An approach failed (reached and not in view, or dropped on the way): skipped for retry_s,
  // the kMaxObjectTries-th time for good; for a `sighting`, only sightingFailed(id).
  void fail(int id, double t, double retry_s, bool sighting = false);
  // No approach pose and no transit: from within the transit radius (`near`) a failure as above;
  // from afar (the map around the object is what is missing) skipped for retry_s with one more
  // transit allowed, and only the kMaxFarTries-th such failure counts as a failure. For a
  // `sighting`, only sightingFailed(id). A wait from afar ends early within `near_radius` (0: never).
  void failFromAfar(int id, double t, double retry_s, bool near, bool sighting = false, double near_radius = 0.0);
  bool mayTransit(int id) const;
  void countTransit(int id) { ++transits_[id]; }
  // A transit cut short by a blocked path: no try of the object (up to kMaxTransitReplans times).
  void transitBlocked(int id);
  // Whether an object skipped for a while becomes eligible again after t.
  bool pendingRetry(double t) const;
  // The approach to a sighting failed: it is not approached again as a sighting.
  void sightingFailed(int id) { sightings_failed_.insert(id); }
  bool sightingChecked(int id) const { return sightings_failed_.count(id) > 0; }
  // Where the UAV stood, near object `id`, when no approach pose was found for it: the next
  // transit goes elsewhere (transitNode's `avoid`).
  void noPoseFrom(int id, const Vec3& where) { no_pose_from_[id].push_back(where); }
  const std::vector<Vec3>& noPoseSpots(int id) const;
  // An approach pose from which the detector did not see object `id`: poses within 0.5 m of it
  // are not flown to again for that object (the map said it was in view; the camera disagreed).
  void noViewFrom(int id, const Vec3& where) { no_view_from_[id].push_back(where); }
  bool lookedInVainFrom(int id, const Vec3& p) const;
  // Where the UAV stood when its camera saw object `id`, the nearest such spot kept: a transit
  // with no node in sight of the object goes to the side it was seen from (transitNode's
  // `seen_from`). nullptr when it was never recorded.
  void seenFrom(int id, const Vec3& where, const Vec3& object);
  const Vec3* seenFromSpot(int id) const;

 private:
  std::map<int, double> retry_at_;  // id -> time it may be tried again (1e18: never)
  std::map<int, double> near_radius_;  // id -> the distance within which a wait from afar ends
  std::map<int, int> failures_, transits_, transit_replans_, far_failures_;
  std::set<int> sightings_failed_;
  std::map<int, std::vector<Vec3>> no_pose_from_, no_view_from_;
  std::map<int, std::pair<Vec3, double>> seen_from_;  // id -> spot, its distance to the object
};

// The obstacles that blocked paths being flown: the occupied voxels around the point where a
// path's segment met the inflated map. Once the window has moved on, the map holds nothing
// there, and a graph edge that passes too close to the obstacle for the UAV's margin looks clear
// again: the same path came back every time (held-out house_6 "toilet", unknown_volume_weight
// 10: two targets, each path blocked just past the other side of one door, the UAV shuttling
// through it every 12 s). forgotten() are the voxel centres the map no longer knows (Unknown), for
// FlightPathOptions::avoid; where the map knows them again, it decides. At most kMax voxels (the
// oldest go first).
class BlockingObstacles {
 public:
  static constexpr size_t kMax = 4096;

  // The occupied voxels of `map` that come within `radius` of `hit` (the inflation that blocked
  // the path, plus half a voxel diagonal: the hit lies on the inflated voxel's face). Returns how
  // many were new.
  int add(const OccupancyMap& map, const Vec3& hit, double radius);
  // A path found blocked at `hit` by the map inflated by `margin`: add() with margin plus half a
  // voxel diagonal.
  int addBlockedAt(const OccupancyMap& map, const Vec3& hit, double margin) {
    return add(map, hit, margin + 0.5 * std::sqrt(3.0) * map.resolution());
  }
  std::vector<Vec3> forgotten(const OccupancyMap& map) const;
  size_t size() const { return voxels_.size(); }

 private:
  std::deque<Vec3i> voxels_;  // in the order remembered
  std::set<std::tuple<int, int, int>> known_;
};

}  // namespace ussnav
