#include "ussnav/mapping/rolling_grid.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <string>

#include "ussnav/core/error.hpp"
#include "ussnav/mapping/voxel_walk.hpp"

namespace ussnav {

namespace {

constexpr const char* kCfg = "mapping.grid";
constexpr double kMaxCoordinate = 1e6;  // m; keys of 0.02 m voxels still fit an int

int16_t quantize(double log_odds) { return int16_t(std::lround(log_odds * 1000.0)); }

int floorMod(int a, int n) {
  const int r = a % n;
  return r < 0 ? r + n : r;
}

// Old range [lo, hi) minus new range [nlo, nhi): up to two intervals.
struct Interval {
  int lo, hi;
};
void subtract(int lo, int hi, int nlo, int nhi, Interval out[2], int& count) {
  count = 0;
  if (nhi <= lo || nlo >= hi) {
    out[count++] = {lo, hi};
    return;
  }
  if (lo < nlo) out[count++] = {lo, nlo};
  if (nhi < hi) out[count++] = {nhi, hi};
}

}  // namespace

RollingGrid::RollingGrid(const GridConfig& cfg, const Vec3& center) : cfg_(cfg), res_(cfg.resolution) {
  if (!std::isfinite(res_) || res_ < 1e-3)  // keys of +-1e6 m must fit an int
    throw InputError(kCfg, "resolution", "must be at least 0.001 m, got " + std::to_string(res_));
  const double sizes[3] = {cfg.size_x, cfg.size_y, cfg.size_z};
  const char* names[3] = {"size_x", "size_y", "size_z"};
  double total = 1;
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(sizes[i]) || sizes[i] <= 0)
      throw InputError(kCfg, names[i], "window size must be positive, got " + std::to_string(sizes[i]));
    const double n = std::round(sizes[i] / res_);
    if (n < 2)
      throw InputError(kCfg, names[i], "window must span at least 2 voxels of " + std::to_string(res_) + " m");
    total *= n;
    dims_[i] = int(std::min(n, 1e9));
  }
  if (total > double(1 << 28))
    throw InputError(kCfg, "size_*", "window of " + std::to_string(total) + " voxels exceeds 2^28");
  const double lim = 30.0;  // thousandths must fit int16
  if (!(cfg.log_odds_hit > 0 && cfg.log_odds_hit <= lim))
    throw InputError(kCfg, "log_odds_hit", "must be in (0, 30]");
  if (!(cfg.log_odds_miss < 0 && cfg.log_odds_miss >= -lim))
    throw InputError(kCfg, "log_odds_miss", "must be in [-30, 0)");
  if (!(cfg.log_odds_min >= -lim && cfg.log_odds_max <= lim && cfg.log_odds_min < cfg.occupied_threshold &&
        cfg.occupied_threshold < cfg.log_odds_max))
    throw InputError(kCfg, "occupied_threshold",
                     "need -30 <= log_odds_min < occupied_threshold < log_odds_max <= 30");
  hit_q_ = quantize(cfg.log_odds_hit);
  miss_q_ = quantize(cfg.log_odds_miss);
  min_q_ = quantize(cfg.log_odds_min);
  max_q_ = quantize(cfg.log_odds_max);
  thr_q_ = quantize(cfg.occupied_threshold);
  stride_y_ = size_t(dims_.x());
  stride_z_ = size_t(dims_.x()) * size_t(dims_.y());
  const size_t n = stride_z_ * size_t(dims_.z());
  log_odds_.assign(n, 0);
  state_.assign(n, uint8_t(VoxelState::Unknown));
  stamp_.assign(n, 0);
  if (!center.allFinite() || center.cwiseAbs().maxCoeff() > kMaxCoordinate)
    throw InputError("RollingGrid", "center", "must be finite and within +-1e6 m");
  setMinKey(keyOf(center) - dims_ / 2);
}

Aabb RollingGrid::window() const {
  Aabb b;
  b.min = min_key_.cast<double>() * res_;
  b.max = (min_key_ + dims_).cast<double>() * res_;
  return b;
}

float RollingGrid::logOdds(const Vec3i& key) const {
  if (!inWindow(key)) return 0.f;
  const size_t i = index(key);
  return state_[i] == uint8_t(VoxelState::Unknown) ? 0.f : float(log_odds_[i]) * 1e-3f;
}

void RollingGrid::setMinKey(const Vec3i& k) {
  min_key_ = k;
  off_ = Vec3i(floorMod(k.x(), dims_.x()), floorMod(k.y(), dims_.y()), floorMod(k.z(), dims_.z()));
  std::vector<uint32_t>* tables[3] = {&ring_x_, &ring_y_, &ring_z_};
  const size_t stride[3] = {1, stride_y_, stride_z_};
  for (int i = 0; i < 3; ++i) {
    tables[i]->resize(size_t(dims_[i]));
    for (int l = 0; l < dims_[i]; ++l) (*tables[i])[size_t(l)] = uint32_t(size_t((l + off_[i]) % dims_[i]) * stride[i]);
  }
}

void RollingGrid::resetBox(const Vec3i& lo, const Vec3i& hi) {
  for (int z = lo.z(); z < hi.z(); ++z)
    for (int y = lo.y(); y < hi.y(); ++y)
      for (int x = lo.x(); x < hi.x(); ++x) {
        const Vec3i k(x, y, z);
        const size_t i = index(k);
        if (state_[i] == uint8_t(VoxelState::Unknown)) continue;
        changes_.push_back({k, VoxelState(state_[i]), VoxelState::Unknown});
        state_[i] = uint8_t(VoxelState::Unknown);
        log_odds_[i] = 0;
        --known_count_;
        ++counters_.voxels_rolled_out;
      }
}

void RollingGrid::moveTo(const Vec3& center) {
  if (!center.allFinite())
    throw InputError("RollingGrid::moveTo", "center", "must be finite (got NaN or inf)");
  if (center.cwiseAbs().maxCoeff() > kMaxCoordinate)
    throw InputError("RollingGrid::moveTo", "center", "lies beyond +-1e6 m of the world origin");
  const Vec3i nk = keyOf(center) - dims_ / 2;
  if (nk == min_key_) return;
  ++counters_.rolls;
  const Vec3i lo = min_key_, hi = min_key_ + dims_, nhi = nk + dims_;
  // Old keys not in the new window, as disjoint boxes: x outside the new x-range; then x in
  // the overlap and y outside; then x, y in the overlap and z outside.
  Interval parts[2];
  int count = 0;
  Vec3i ov_lo = lo.cwiseMax(nk), ov_hi = hi.cwiseMin(nhi);
  subtract(lo.x(), hi.x(), nk.x(), nhi.x(), parts, count);
  for (int p = 0; p < count; ++p)
    resetBox(Vec3i(parts[p].lo, lo.y(), lo.z()), Vec3i(parts[p].hi, hi.y(), hi.z()));
  if (ov_lo.x() < ov_hi.x()) {
    subtract(lo.y(), hi.y(), nk.y(), nhi.y(), parts, count);
    for (int p = 0; p < count; ++p)
      resetBox(Vec3i(ov_lo.x(), parts[p].lo, lo.z()), Vec3i(ov_hi.x(), parts[p].hi, hi.z()));
    if (ov_lo.y() < ov_hi.y()) {
      subtract(lo.z(), hi.z(), nk.z(), nhi.z(), parts, count);
      for (int p = 0; p < count; ++p)
        resetBox(Vec3i(ov_lo.x(), ov_lo.y(), parts[p].lo), Vec3i(ov_hi.x(), ov_hi.y(), parts[p].hi));
    }
  }
  setMinKey(nk);
}

void RollingGrid::clear() { resetBox(min_key_, min_key_ + dims_); }

void RollingGrid::clearChanges() {
  change_seq_begin_ += changes_.size();
  changes_.clear();
}

size_t RollingGrid::voxelBytes(const GridConfig& cfg) {
  const auto n = [&](double s) { return size_t(std::max(0.0, std::round(s / cfg.resolution))); };
  return n(cfg.size_x) * n(cfg.size_y) * n(cfg.size_z) * (sizeof(int16_t) + sizeof(uint8_t) + sizeof(uint8_t));
}

size_t RollingGrid::memoryBytes() const {
  return sizeof(*this) + log_odds_.capacity() * sizeof(int16_t) + state_.capacity() +
         stamp_.capacity() + (ring_x_.capacity() + ring_y_.capacity() + ring_z_.capacity()) * sizeof(uint32_t) +
         (hit_rays_.capacity() + open_rays_.capacity()) * sizeof(Ray) +
         (col_scale_.capacity() + row_scale_.capacity()) * sizeof(float) +
         changes_.capacity() * sizeof(VoxelChange);
}

// ---- insertion -------------------------------------------------------------------------

uint8_t RollingGrid::beginFrame() {
  // Three stamps per frame (claimed < hit < missed, all above earlier frames' stamps); when
  // they run out, every 84 frames, all stamps are forgotten at once.
  if (cur_stamp_ >= 252) {
    std::fill(stamp_.begin(), stamp_.end(), uint8_t(0));
    cur_stamp_ = 0;
  }
  cur_stamp_ = uint8_t(cur_stamp_ + 3);
  hit_rays_.clear();
  open_rays_.clear();
  return cur_stamp_;
}

bool RollingGrid::originInWindow(const Vec3f& s, InsertStats& st) {
  if (s.x() >= 0 && s.y() >= 0 && s.z() >= 0 && s.x() < dims_.x() && s.y() < dims_.y() && s.z() < dims_.z())
    return true;
  st.rejected = true;
  ++counters_.rejected_frames;
  ++counters_.frames;
  // Counted warning: the 1st, 2nd, 4th, 8th ... rejection, so a runaway driver cannot flood.
  if (std::has_single_bit(counters_.rejected_frames))
    spdlog::warn("RollingGrid: sensor origin outside the window, frame rejected ({} so far); call moveTo() first",
                 counters_.rejected_frames);
  return false;
}

void RollingGrid::applyHit(size_t idx, const Vec3i& local, InsertStats& st) {
  ++st.voxel_updates;
  const uint8_t s0 = state_[idx];
  const int lo = std::min(int(s0 ? log_odds_[idx] : 0) + hit_q_, int(max_q_));
  log_odds_[idx] = int16_t(lo);
  const uint8_t s1 = lo > thr_q_ ? uint8_t(VoxelState::Occupied) : uint8_t(VoxelState::Free);
  if (s1 != s0) {
    known_count_ += s0 == 0;
    state_[idx] = s1;
    record(local, VoxelState(s0), VoxelState(s1), st);
  }
}

inline void RollingGrid::applyMiss(size_t idx, int x, int y, int z, InsertStats& st) {
  if (stamp_[idx] > claimedStamp()) return;  // hit or missed in this frame already
  stamp_[idx] = missStamp();
  ++st.voxel_updates;
  const uint8_t s0 = state_[idx];
  const int lo = std::max(int(s0 ? log_odds_[idx] : 0) + miss_q_, int(min_q_));
  log_odds_[idx] = int16_t(lo);
  const uint8_t s1 = lo > thr_q_ ? uint8_t(VoxelState::Occupied) : uint8_t(VoxelState::Free);
  if (s1 != s0) {
    known_count_ += s0 == 0;
    state_[idx] = s1;
    record(Vec3i(x, y, z), VoxelState(s0), VoxelState(s1), st);
  }
}

// p: end point in local voxel units (origin = window min corner). Returns inside the window
// get their hit now (once per voxel per frame: a second return in the same voxel adds no
// ray); everything else becomes an open ray clipped to the window, carved to its end.
// A return on a voxel face (a surface at a multiple of the resolution, as the simulator's
// ground truth puts walls) is counted in the voxel behind the face, kReturnInside voxels along
// the ray: otherwise rounding puts it in the free voxel in front, which rays grazing the wall on
// their way to its other points clear again, and a wall seen only from that side stays unknown
// (house_18: the bathroom side of the wall behind the fridge).
void RollingGrid::addEndpoint(const Vec3f& s, const Vec3f& p_in, bool is_return, InsertStats& st) {
  constexpr float kReturnInside = 0.01f;
  Vec3f p = p_in;
  if (is_return) {
    const float n = (p - s).norm();
    if (n > 1e-6f) p += (p - s) * (kReturnInside / n);
    if (p.x() >= 0 && p.y() >= 0 && p.z() >= 0 && p.x() < dims_.x() && p.y() < dims_.y() && p.z() < dims_.z()) {
      ++st.hits;
      const Vec3i k(int(p.x()), int(p.y()), int(p.z()));
      const size_t idx = ring_x_[size_t(k.x())] + ring_y_[size_t(k.y())] + ring_z_[size_t(k.z())];
      if (stamp_[idx] == hitStamp()) return;
      stamp_[idx] = hitStamp();
      applyHit(idx, k, st);
      hit_rays_.push_back({p.x(), p.y(), p.z(), k.x(), k.y(), k.z()});
      return;
    }
    ++st.hits_outside;
  }
  float t = 1.f;
  for (int i = 0; i < 3; ++i) {
    const float d = p[i] - s[i];
    if (d > 0) t = std::min(t, (float(dims_[i]) - s[i]) / d);
    else if (d < 0) t = std::min(t, s[i] / -d);
  }
  const Vec3f e = s + (p - s) * t;
  Ray r{e.x(), e.y(), e.z(), 0, 0, 0};
  int* ek = &r.ex;
  for (int i = 0; i < 3; ++i) ek[i] = std::clamp(int(std::floor(e[i])), 0, dims_[i] - 1);
  // One open ray per end voxel: rays from one origin that end in the same voxel run within a
  // voxel of each other all the way (no-return pixels and returns beyond the window come in
  // bundles of tens per boundary voxel).
  uint8_t& stamp = stamp_[ring_x_[size_t(r.ex)] + ring_y_[size_t(r.ey)] + ring_z_[size_t(r.ez)]];
  if (stamp == claimedStamp()) return;
  if (stamp < claimedStamp()) stamp = claimedStamp();
  open_rays_.push_back(r);
}

template <bool kIncludeEnd>
void RollingGrid::walkMisses(const Vec3f& s, const Ray& r, InsertStats& st) {
  constexpr float inf = std::numeric_limits<float>::infinity();
  const float e[3] = {r.x, r.y, r.z};
  const int b[3] = {r.ex, r.ey, r.ez};
  int c[3], step[3], rem[3];
  float t_max[3], t_delta[3];
  for (int i = 0; i < 3; ++i) {
    c[i] = std::min(int(s[i]), dims_[i] - 1);
    rem[i] = std::abs(b[i] - c[i]);
    step[i] = b[i] > c[i] ? 1 : -1;
    if (rem[i] == 0) {
      t_max[i] = t_delta[i] = inf;
      continue;
    }
    t_delta[i] = 1.f / std::max(std::abs(e[i] - s[i]), 1e-6f);
    t_max[i] = (step[i] > 0 ? float(c[i] + 1) - s[i] : s[i] - float(c[i])) * t_delta[i];
  }
  // Scalars, not arrays, so the loop state stays in registers; per-axis ring tables turn a
  // local coordinate into its share of the ring index without a modulo or a wrap branch.
  int cx = c[0], cy = c[1], cz = c[2], rx = rem[0], ry = rem[1], rz = rem[2];
  float tx = t_max[0], ty = t_max[1], tz = t_max[2];
  const float dx = t_delta[0], dy = t_delta[1], dz = t_delta[2];
  const int sx = step[0], sy = step[1], sz = step[2];
  const uint32_t *RX = ring_x_.data(), *RY = ring_y_.data(), *RZ = ring_z_.data();
  for (int k = rx + ry + rz; k > 0; --k) {
    applyMiss(RX[cx] + RY[cy] + RZ[cz], cx, cy, cz, st);
    if (tx <= ty && tx <= tz) {
      cx += sx;
      tx = --rx ? tx + dx : inf;
    } else if (ty <= tz) {
      cy += sy;
      ty = --ry ? ty + dy : inf;
    } else {
      cz += sz;
      tz = --rz ? tz + dz : inf;
    }
  }
  if constexpr (kIncludeEnd) applyMiss(RX[cx] + RY[cy] + RZ[cz], cx, cy, cz, st);
}

void RollingGrid::castRays(const Vec3f& s, InsertStats& st) {
  const int rays = int(hit_rays_.size());
  for (const Ray& r : hit_rays_) walkMisses<false>(s, r, st);
  for (const Ray& r : open_rays_) walkMisses<true>(s, r, st);
  st.rays = rays + int(open_rays_.size());
}

void RollingGrid::finishFrame(const InsertStats& st) {
  ++counters_.frames;
  counters_.invalid_points += uint64_t(st.invalid);
  counters_.rays += uint64_t(st.rays);
  counters_.voxel_updates += uint64_t(st.voxel_updates);
}

InsertStats RollingGrid::insertDepth(const DepthFrame& f) {
  const char* kSrc = "DepthFrame";
  const Intrinsics& K = f.K;
  if (K.width <= 0 || K.height <= 0)
    throw InputError(kSrc, "K.width/height", "must be positive");
  if (f.depth.size() != size_t(K.width) * size_t(K.height))
    throw InputError(kSrc, "depth", "has " + std::to_string(f.depth.size()) + " pixels, expected width*height = " +
                                        std::to_string(size_t(K.width) * size_t(K.height)));
  if (!(std::isfinite(K.fx) && std::isfinite(K.fy) && K.fx > 0 && K.fy > 0 && std::isfinite(K.cx) &&
        std::isfinite(K.cy)))
    throw InputError(kSrc, "K", "focal lengths must be positive and the principal point finite");
  if (!(std::isfinite(f.max_range) && f.max_range > 0))
    throw InputError(kSrc, "max_range", "must be a positive finite range");
  if (!f.T_world_camera.matrix().allFinite())
    throw InputError(kSrc, "T_world_camera", "pose must be finite (got NaN or inf)");
  const Mat3 R = f.T_world_camera.linear();
  if ((R * R.transpose() - Mat3::Identity()).cwiseAbs().maxCoeff() > 1e-3)
    throw InputError(kSrc, "T_world_camera", "rotation part is not orthonormal");

  InsertStats st;
  st.points = K.width * K.height;
  const Vec3 wmin = min_key_.cast<double>() * res_;
  const Vec3f s = ((f.T_world_camera.translation() - wmin) / res_).cast<float>();
  if (!originInWindow(s, st)) return st;
  beginFrame();
  col_scale_.resize(size_t(K.width));
  row_scale_.resize(size_t(K.height));
  for (int u = 0; u < K.width; ++u) col_scale_[size_t(u)] = float((u - K.cx) / K.fx);
  for (int v = 0; v < K.height; ++v) row_scale_[size_t(v)] = float((v - K.cy) / K.fy);
  const Eigen::Matrix3f Rl = (R / res_).cast<float>();
  const Vec3f c0 = Rl.col(0), c1 = Rl.col(1), c2 = Rl.col(2);
  const float max_range = float(f.max_range);
  const float* depth = f.depth.data();
  for (int v = 0; v < K.height; ++v) {
    const Vec3f row = c1 * row_scale_[size_t(v)] + c2;
    for (int u = 0; u < K.width; ++u) {
      const float d = *depth++;
      if (std::isnan(d) || d < 0) {
        ++st.invalid;
        continue;
      }
      const bool is_return = d > 0 && d <= max_range;
      st.no_return += !is_return;
      const Vec3f p = (c0 * col_scale_[size_t(u)] + row) * (is_return ? d : max_range) + s;
      addEndpoint(s, p, is_return, st);
    }
  }
  castRays(s, st);
  finishFrame(st);
  return st;
}

InsertStats RollingGrid::insertScan(const PointCloudScan& scan) {
  const char* kSrc = "PointCloudScan";
  if (!scan.origin.allFinite()) throw InputError(kSrc, "origin", "must be finite (got NaN or inf)");
  if (!(std::isfinite(scan.max_range) && scan.max_range > 0))
    throw InputError(kSrc, "max_range", "must be a positive finite range");
  InsertStats st;
  st.points = int(scan.points.size() + scan.no_return_dirs.size());
  const Vec3 wmin = min_key_.cast<double>() * res_;
  const Vec3f s = ((scan.origin - wmin) / res_).cast<float>();
  if (!originInWindow(s, st)) return st;
  beginFrame();
  const double inv_res = 1.0 / res_;
  for (const Vec3f& p : scan.points) {
    if (!p.allFinite()) {
      ++st.invalid;
      continue;
    }
    // Window-relative in double: far from the world origin a float difference loses voxels.
    addEndpoint(s, ((p.cast<double>() - wmin) * inv_res).cast<float>(), true, st);
  }
  const float reach = float(scan.max_range / res_);
  for (const Vec3f& d : scan.no_return_dirs) {
    const float n = d.norm();
    if (!std::isfinite(n) || n < 1e-6f) {
      ++st.invalid;
      continue;
    }
    ++st.no_return;
    addEndpoint(s, s + d * (reach / n), false, st);
  }
  castRays(s, st);
  finishFrame(st);
  return st;
}

// ---- queries ---------------------------------------------------------------------------

RayHit RollingGrid::castRay(const Vec3& from, const Vec3& to, bool unknown_blocks) const {
  return detail::walkSegment(res_, from, to, unknown_blocks, [this](const Vec3i& k) { return state(k); });
}

bool RollingGrid::isInflatedOccupied(const Vec3& p, double radius, bool unknown_unsafe) const {
  return !detail::sphereIsSafe(res_, p, radius, unknown_unsafe, [this](const Vec3i& k) { return state(k); });
}

double RollingGrid::distanceToObstacle(const Vec3& p, double max_dist) const {
  if (!p.allFinite() || !(max_dist > 0)) return max_dist;
  const Vec3i c = keyOf(p);
  const int n = int(std::ceil(max_dist / res_)) + 1;
  double best2 = max_dist * max_dist;
  bool found = false;
  const auto test = [&](const Vec3i& k) {
    if (!inWindow(k) || stateFast(k) != VoxelState::Occupied) return;
    const Vec3 lo = k.cast<double>() * res_, hi = lo + Vec3::Constant(res_);
    const double d2 = (p.cwiseMax(lo).cwiseMin(hi) - p).squaredNorm();
    if (d2 <= best2) {
      best2 = d2;
      found = true;
    }
  };
  // Shells of growing Chebyshev radius; every voxel of shell s is at least (s-1)*res away.
  for (int s = 0; s <= n; ++s) {
    const double bound = (s - 1) * res_;
    if (s > 0 && bound > 0 && bound * bound > best2) break;
    for (int dz = -s; dz <= s; ++dz)
      for (int dy = -s; dy <= s; ++dy) {
        const bool face = std::abs(dz) == s || std::abs(dy) == s;
        for (int dx = -s; dx <= s; dx += face ? 1 : 2 * s) {
          test(c + Vec3i(dx, dy, dz));
          if (s == 0) break;
        }
      }
  }
  return found ? std::sqrt(best2) : max_dist;
}

}  // namespace ussnav
