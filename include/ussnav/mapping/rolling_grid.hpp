#pragma once
// RollingGrid: the fixed-memory local occupancy grid of the paper (Sec. V-A: 8 x 8 x 4 m at
// 0.1 m, centred on the UAV in all three axes). Voxels live in a ring buffer (index = key mod
// dims), so moveTo() resets only the voxels that leave: O(voxels leaving), no allocation.
// Insertion casts one ray per distinct end voxel per frame (hit first, then misses; each voxel
// updated at most once per frame); rays are clipped to the window. A return counts in the voxel
// 1 % of a voxel beyond it along its ray: one on a voxel face (the simulator's walls lie on a
// 5 cm lattice) marks the voxel behind the face, not the free one in front. Memory: 4 bytes per voxel
// (int16 log-odds, state byte, frame-stamp byte) plus per-frame scratch, see memoryBytes().
// Per frame a driver calls: moveTo(uav position); insertScan(scan) or insertDepth(frame);
// CoverageMask::update(grid) and any other change-log reader; clearChanges().
// Const queries may run concurrently with each other, never with an insertion or a roll.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "ussnav/core/config.hpp"
#include "ussnav/core/frame.hpp"
#include "ussnav/mapping/occupancy.hpp"

namespace ussnav {

// A voxel whose state changed. A voxel that leaves the window on moveTo() is recorded as
// (its last key, its state, Unknown) if it was known; voxels entering are Unknown, unrecorded.
struct VoxelChange {
  Vec3i key;
  VoxelState before;
  VoxelState after;
};

// What one insertion did. Invalid inputs are skipped and counted here, never inserted.
struct InsertStats {
  int points = 0;          // pixels or points offered
  int hits = 0;            // returns whose voxel is inside the window
  int hits_outside = 0;    // returns beyond the window (ray carved up to the window edge)
  int no_return = 0;       // depth 0 / +inf / beyond max_range, scan no_return_dirs
  int invalid = 0;         // NaN, -inf, negative depth, non-finite points: skipped
  int rays = 0;            // rays cast after merging rays that end in the same voxel
  int voxel_updates = 0;   // log-odds updates (hits + misses)
  int state_changes = 0;   // entries appended to changes()
  bool rejected = false;   // sensor origin outside the window: nothing inserted
};

// Totals since construction.
struct GridCounters {
  uint64_t frames = 0;
  uint64_t rejected_frames = 0;
  uint64_t invalid_points = 0;
  uint64_t rays = 0;
  uint64_t voxel_updates = 0;
  uint64_t rolls = 0;
  uint64_t voxels_rolled_out = 0;  // known voxels reset by moveTo()
};

class RollingGrid final : public OccupancyMap {
 public:
  // Window of round(size / resolution) voxels per axis around `center`. Throws InputError
  // (file "mapping.grid") on a zero/negative/non-finite size, a resolution under 1 mm, a
  // window under 2 voxels on an axis or over 2^28 in all, or inconsistent log-odds.
  explicit RollingGrid(const GridConfig& cfg, const Vec3& center = Vec3::Zero());

  // OccupancyMap
  double resolution() const override { return res_; }
  VoxelState state(const Vec3i& key) const override {
    return inWindow(key) ? stateFast(key) : VoxelState::Unknown;
  }
  bool inWindow(const Vec3i& key) const override {
    const Vec3i l = key - min_key_;
    return unsigned(l.x()) < unsigned(dims_.x()) && unsigned(l.y()) < unsigned(dims_.y()) &&
           unsigned(l.z()) < unsigned(dims_.z());
  }
  Aabb window() const override;

  // Window = keys [minKey(), minKey() + dims()).
  const Vec3i& minKey() const { return min_key_; }
  const Vec3i& dims() const { return dims_; }
  size_t voxelCount() const { return state_.size(); }
  const GridConfig& config() const { return cfg_; }

  // Ring-buffer index of an in-window key (precondition: inWindow(key)).
  size_t index(const Vec3i& key) const {
    const Vec3i l = key - min_key_;
    int rx = l.x() + off_.x(), ry = l.y() + off_.y(), rz = l.z() + off_.z();
    if (rx >= dims_.x()) rx -= dims_.x();
    if (ry >= dims_.y()) ry -= dims_.y();
    if (rz >= dims_.z()) rz -= dims_.z();
    return size_t(rx) + size_t(dims_.x()) * (size_t(ry) + size_t(dims_.y()) * size_t(rz));
  }
  // Precondition: inWindow(key). No virtual call, no bounds test.
  VoxelState stateFast(const Vec3i& key) const { return VoxelState(state_[index(key)]); }
  // Clamped log-odds of a voxel; 0 (the prior) when Unknown or outside the window.
  float logOdds(const Vec3i& key) const;
  bool isOccupied(const Vec3& p) const { return stateAt(p) == VoxelState::Occupied; }
  bool isFree(const Vec3& p) const { return stateAt(p) == VoxelState::Free; }

  // Centres the window on `center` (voxel key of center minus dims/2), in z as well: a driver
  // that wants a vertically anchored window passes a fixed z. Voxels that leave are reset to
  // Unknown and logged in changes(). Throws InputError on a non-finite centre or one beyond
  // +-1e6 m (keys would overflow). Cost: O(voxels that leave); a no-op within the same voxel.
  void moveTo(const Vec3& center);

  // Inserts a depth image (z-depth along the optical axis, camera optical frame; see
  // frame.hpp). Per pixel, following ROS REP 117: 0 or +inf = no return, carved free up to
  // frame.max_range (z-depth); depth > max_range is treated as no return; NaN, -inf and
  // negative depth are invalid: skipped and counted, never carved. Throws InputError on a
  // malformed frame (size mismatch, bad intrinsics, non-finite pose or max_range). A frame
  // whose camera centre is outside the window is rejected (stats.rejected, a counted
  // warning): the driver must moveTo() first.
  InsertStats insertDepth(const DepthFrame& frame);
  // Inserts a LiDAR scan (world-frame points, rays from scan.origin). Non-finite points and
  // zero/non-finite no-return directions are skipped and counted; rejection as insertDepth.
  InsertStats insertScan(const PointCloudScan& scan);

  // Queries. Outside the window every voxel is Unknown.
  RayHit castRay(const Vec3& from, const Vec3& to, bool unknown_blocks) const;
  bool lineOfSight(const Vec3& a, const Vec3& b, bool unknown_blocks) const {
    return !castRay(a, b, unknown_blocks).blocked;
  }
  // Distance from p to the box of the nearest Occupied voxel (0 inside one), or max_dist when
  // none is within max_dist. O((max_dist / res)^3) worst case, early exit by shells.
  double distanceToObstacle(const Vec3& p, double max_dist) const;
  // True when an Occupied (or, if unknown_unsafe, Unknown) voxel comes within radius of p.
  bool isInflatedOccupied(const Vec3& p, double radius, bool unknown_unsafe = false) const;

  // All voxels back to Unknown (logged as changes).
  void clear();

  // Voxel storage plus scratch buffers and the change log's capacity, in bytes. The voxel
  // part is fixed by the configuration; scratch grows with the largest frame seen.
  size_t memoryBytes() const;
  static size_t voxelBytes(const GridConfig& cfg);  // the fixed part, from the config alone
  size_t knownVoxels() const { return known_count_; }

  // Change log: every state change since clearChanges(), in order. Consumers (CoverageMask,
  // frontiers) read it after each insertion/roll; the driver clears it once all have read it.
  // Sequence numbers let a consumer detect that it missed entries.
  const std::vector<VoxelChange>& changes() const { return changes_; }
  uint64_t changeSeqBegin() const { return change_seq_begin_; }
  uint64_t changeSeqEnd() const { return change_seq_begin_ + changes_.size(); }
  void clearChanges();

  const GridCounters& counters() const { return counters_; }

 private:
  struct Ray {  // end point in local voxel units and its (in-window) end voxel
    float x, y, z;
    int ex, ey, ez;
  };
  void resetBox(const Vec3i& lo, const Vec3i& hi);  // old-window keys [lo, hi)
  void setMinKey(const Vec3i& k);
  uint8_t beginFrame();
  bool originInWindow(const Vec3f& local, InsertStats& st);
  void addEndpoint(const Vec3f& s, const Vec3f& p, bool is_return, InsertStats& st);
  void castRays(const Vec3f& s, InsertStats& st);
  template <bool kIncludeEnd>
  void walkMisses(const Vec3f& s, const Ray& r, InsertStats& st);
  void applyHit(size_t idx, const Vec3i& local, InsertStats& st);
  void applyMiss(size_t idx, int x, int y, int z, InsertStats& st);
  void record(const Vec3i& local, VoxelState before, VoxelState after, InsertStats& st) {
    changes_.push_back({min_key_ + local, before, after});
    ++st.state_changes;
  }
  void finishFrame(const InsertStats& st);

  GridConfig cfg_;
  double res_;
  Vec3i dims_, min_key_, off_;  // off_ = min_key_ mod dims_ (ring offset)
  size_t stride_y_, stride_z_;
  int16_t hit_q_, miss_q_, min_q_, max_q_, thr_q_;  // log-odds in thousandths
  std::vector<int16_t> log_odds_;
  std::vector<uint8_t> state_;
  std::vector<uint8_t> stamp_;  // per-frame marks, see beginFrame()
  uint8_t cur_stamp_ = 0;
  uint8_t claimedStamp() const { return cur_stamp_; }  // end voxel of an open ray of this frame
  uint8_t hitStamp() const { return uint8_t(cur_stamp_ + 1); }
  uint8_t missStamp() const { return uint8_t(cur_stamp_ + 2); }
  std::vector<uint32_t> ring_x_, ring_y_, ring_z_;  // local coordinate -> ring index share
  size_t known_count_ = 0;
  std::vector<Ray> hit_rays_, open_rays_;
  std::vector<float> col_scale_, row_scale_;  // per-pixel (u-cx)/fx, (v-cy)/fy
  std::vector<VoxelChange> changes_;
  uint64_t change_seq_begin_ = 0;
  GridCounters counters_;
};

}  // namespace ussnav
