#include "ussnav/exploration/frontier.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <climits>
#include <cmath>

#include "ussnav/core/error.hpp"

namespace ussnav {

namespace {

constexpr int kUnclustered = -1;  // a frontier cell in a group under min_cluster_cells
constexpr int kPending = -2;      // to be re-clustered this update
constexpr int kQueued = -3;       // in the flood fill now

const Vec3i kSix[6] = {Vec3i(1, 0, 0), Vec3i(-1, 0, 0), Vec3i(0, 1, 0),
                       Vec3i(0, -1, 0), Vec3i(0, 0, 1), Vec3i(0, 0, -1)};

bool keyLess(const Vec3i& a, const Vec3i& b) {
  if (a.z() != b.z()) return a.z() < b.z();
  if (a.y() != b.y()) return a.y() < b.y();
  return a.x() < b.x();
}

// Band of voxel z-keys whose centre lies in [z_min, z_max].
void bandKeys(const ExplorationConfig& cfg, double res, int& zlo, int& zhi) {
  zlo = int(std::ceil(cfg.band_z_min / res - 0.5 - 1e-9));
  zhi = int(std::floor(cfg.band_z_max / res - 0.5 + 1e-9));
}

}  // namespace

FrontierFinder::FrontierFinder(const ExplorationConfig& cfg) : cfg_(cfg) {
  if (!(cfg.band_z_min <= cfg.band_z_max))
    throw InputError("exploration", "band_z_max", "at least band_z_min");
  if (!(cfg.viewpoint_r_min <= cfg.viewpoint_r_max))
    throw InputError("exploration", "viewpoint_r_max", "at least viewpoint_r_min");
}

bool FrontierFinder::isFrontierVoxel(const RollingGrid& grid, const CoverageMask& gcm, const Vec3i& key,
                                     const ExplorationConfig& cfg, const BandMemory* seen) {
  if (!grid.inWindow(key) || grid.stateFast(key) != VoxelState::Free) return false;
  int zlo = 0, zhi = 0;
  bandKeys(cfg, grid.resolution(), zlo, zhi);
  if (key.z() < zlo || key.z() > zhi) return false;
  bool unknown_next = false;
  for (const Vec3i& d : kSix) {
    const Vec3i n = key + d;
    if (grid.state(n) != VoxelState::Unknown) continue;
    // Beyond the window: unexplored only if that voxel was never known.
    if (seen && !grid.inWindow(n) && seen->known(n)) continue;
    unknown_next = true;
    break;
  }
  if (!unknown_next) return false;
  if (!gcm.isVisited(gcm.cellOfKey(key))) return true;
  if (!seen || !cfg.open_in_visited) return false;
  const double zc = grid.centerOf(key).z();
  if (zc < cfg.viewpoint_height - 1e-9 || zc > cfg.viewpoint_height + cfg.open_in_visited_above + 1e-9) return false;
  // A visited cell still has a frontier where its free space meets, sideways, space never known
  // (a room seen through a door: the cell is mostly known, the room beyond it is not).
  for (int i = 0; i < 4; ++i) {
    const Vec3i n = key + kSix[size_t(i)];
    if (grid.state(n) == VoxelState::Unknown && !seen->known(n)) return true;
  }
  return false;
}

const Frontier* FrontierFinder::find(int id) const {
  const auto it = index_.find(id);
  return it == index_.end() ? nullptr : &frontiers_[it->second];
}

std::vector<Vec3i> FrontierFinder::frontierCells() const {
  std::vector<Vec3i> out;
  out.reserve(cells_.size());
  for (const auto& [p, owner] : cells_) out.push_back(unpack(p));
  std::sort(out.begin(), out.end(), keyLess);
  return out;
}

void FrontierFinder::markAffected(int owner) {
  if (owner >= 0 && std::find(affected_.begin(), affected_.end(), owner) == affected_.end())
    affected_.push_back(owner);
}

FrontierUpdate FrontierFinder::update(const RollingGrid& grid, const CoverageMask& gcm, int anchor_node,
                                      double time) {
  FrontierUpdate up;
  touched_.clear();
  affected_.clear();
  const Vec3i wlo = grid.minKey(), whi = grid.minKey() + grid.dims() - Vec3i::Ones();
  if (!initialised_) {
    int zlo = 0, zhi = 0;
    bandKeys(cfg_, grid.resolution(), zlo, zhi);
    seen_ = BandMemory(zlo, zhi - zlo + 1);
  }
  const bool missed = !initialised_ || consumed_ < grid.changeSeqBegin() || consumed_ > grid.changeSeqEnd();
  if (missed) {
    up.full_rescan = true;
    scanBox(grid, gcm, wlo, whi, up);
  } else {
    Vec3i lo = Vec3i::Constant(INT_MAX), hi = Vec3i::Constant(INT_MIN);
    const auto& ch = grid.changes();
    for (size_t i = size_t(consumed_ - grid.changeSeqBegin()); i < ch.size(); ++i) {
      // Voxels that left the window are not re-judged: their frontier cells persist.
      if (!grid.inWindow(ch[i].key)) continue;
      lo = lo.cwiseMin(ch[i].key);
      hi = hi.cwiseMax(ch[i].key);
    }
    if (lo.x() <= hi.x()) scanBox(grid, gcm, lo - Vec3i::Ones(), hi + Vec3i::Ones(), up);
    if (grid.minKey() != last_min_key_) {
      // Voxels entering the window are Unknown and unlogged: re-judge them (persisted cells)
      // and the layer they border. The new outer layer on the trailing side is left alone: a
      // window that merely moved is no evidence of unexplored space (see the header).
      const Vec3i old_lo = last_min_key_, old_hi = last_min_key_ + grid.dims() - Vec3i::Ones();
      for (int a = 0; a < 3; ++a) {
        if (wlo[a] == old_lo[a]) continue;
        Vec3i l = wlo, h = whi;
        if (wlo[a] > old_lo[a]) l[a] = std::max(wlo[a], old_hi[a]);
        else h[a] = std::min(whi[a], old_lo[a]);
        scanBox(grid, gcm, l, h, up);
      }
    }
  }
  consumed_ = grid.changeSeqEnd();
  last_min_key_ = grid.minKey();
  initialised_ = true;
  if (up.full_rescan || gcm.visitedCount() != last_visited_count_) dropVisited(grid, gcm, up);
  last_visited_count_ = gcm.visitedCount();
  recluster(grid, anchor_node, time, up);
  return up;
}

void FrontierFinder::scanBox(const RollingGrid& grid, const CoverageMask& gcm, Vec3i lo, Vec3i hi,
                             FrontierUpdate& up) {
  int zlo = 0, zhi = 0;
  bandKeys(cfg_, grid.resolution(), zlo, zhi);
  lo = lo.cwiseMax(grid.minKey());
  hi = hi.cwiseMin(grid.minKey() + grid.dims() - Vec3i::Ones());
  lo.z() = std::max(lo.z(), zlo);
  hi.z() = std::min(hi.z(), zhi);
  for (int z = lo.z(); z <= hi.z(); ++z)
    for (int y = lo.y(); y <= hi.y(); ++y)
      for (int x = lo.x(); x <= hi.x(); ++x) {
        const Vec3i k(x, y, z);
        ++up.voxels_scanned;
        const VoxelState s = grid.stateFast(k);
        if (s != VoxelState::Unknown && cfg_.remember_known_band) seen_.mark(k);
        const uint64_t p = pack(k);
        if (s == VoxelState::Occupied) {  // fast path: never a frontier
          const auto it = cells_.find(p);
          if (it != cells_.end()) {
            markAffected(it->second);
            cells_.erase(it);
            ++up.cells_removed;
          }
          continue;
        }
        const auto it = cells_.find(p);
        const bool present = it != cells_.end();
        // An Unknown voxel holding a frontier cell re-entered the window unseen: it persists
        // until a frame makes it known.
        const bool now =
            s == VoxelState::Unknown ? present : isFrontierVoxel(grid, gcm, k, cfg_, cfg_.remember_known_band ? &seen_ : nullptr);
        if (now && !present) {
          cells_.emplace(p, kUnclustered);
          touched_.push_back(p);
          ++up.cells_added;
        } else if (!now && present) {
          markAffected(it->second);
          cells_.erase(it);
          ++up.cells_removed;
        }
      }
}

void FrontierFinder::dropVisited(const RollingGrid& grid, const CoverageMask& gcm, FrontierUpdate& up) {
  std::unordered_map<uint64_t, bool> memo;
  for (auto it = cells_.begin(); it != cells_.end();) {
    const uint64_t c = pack(gcm.cellOfKey(unpack(it->first)));
    auto m = memo.find(c);
    if (m == memo.end()) m = memo.emplace(c, gcm.isVisited(unpack(c))).first;
    // open_in_visited keeps some cells of visited cells: those are judged again, in the window; one
    // beyond it persists as it was judged (as every cell that left the window) until it re-enters
    // and a frame makes its voxel known again. A cell back in the window but still Unknown there
    // (forgotten, and behind a wall from where the UAV is now) has not been judged again: it
    // persists, as in scanBox; dropping it would lose the way into a room nobody looked into.
    const Vec3i key = unpack(it->first);
    bool drop = m->second;
    if (drop && cfg_.open_in_visited)
      drop = grid.inWindow(key) && grid.stateFast(key) != VoxelState::Unknown &&
             !isFrontierVoxel(grid, gcm, key, cfg_, cfg_.remember_known_band ? &seen_ : nullptr);
    if (drop) {
      markAffected(it->second);
      it = cells_.erase(it);
      ++up.cells_removed;
    } else {
      ++it;
    }
  }
}

void FrontierFinder::splitCluster(std::vector<Vec3i>& cells, double res,
                                  std::vector<std::vector<Vec3i>>& out) const {
  if (cells.size() < 2) {
    out.push_back(std::move(cells));
    return;
  }
  Vec3 mean = Vec3::Zero();
  for (const Vec3i& c : cells) mean += c.cast<double>();
  mean /= double(cells.size());
  Mat3 cov = Mat3::Zero();
  for (const Vec3i& c : cells) {
    const Vec3 d = c.cast<double>() - mean;
    cov += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Mat3> es(cov);
  const Vec3 axis = es.eigenvectors().col(2);  // largest eigenvalue last
  double lo = 1e300, hi = -1e300;
  for (const Vec3i& c : cells) {
    const double t = (c.cast<double>() - mean).dot(axis);
    lo = std::min(lo, t);
    hi = std::max(hi, t);
  }
  if ((hi - lo) * res <= cfg_.max_cluster_extent) {
    out.push_back(std::move(cells));
    return;
  }
  std::vector<Vec3i> a, b;
  for (const Vec3i& c : cells) ((c.cast<double>() - mean).dot(axis) < 0 ? a : b).push_back(c);
  if (a.empty() || b.empty()) {
    out.push_back(std::move(cells));
    return;
  }
  splitCluster(a, res, out);
  splitCluster(b, res, out);
}

void FrontierFinder::recluster(const RollingGrid& grid, int anchor_node, double time, FrontierUpdate& up) {
  // New cells join the clusters they touch.
  for (const uint64_t p : touched_) {
    const Vec3i k = unpack(p);
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const auto it = cells_.find(pack(k + Vec3i(dx, dy, dz)));
          if (it != cells_.end()) markAffected(it->second);
        }
  }
  if (touched_.empty() && affected_.empty()) return;

  // Take the affected frontiers out; remember them to keep ids of clusters that did not change.
  std::vector<uint64_t> seeds = touched_;
  std::unordered_map<int, Frontier> old;
  std::unordered_map<uint64_t, int> old_owner;
  for (const int id : affected_) {
    const auto ix = index_.find(id);
    if (ix == index_.end()) continue;
    Frontier& f = frontiers_[ix->second];
    for (const Vec3i& c : f.cells) {
      const auto it = cells_.find(pack(c));
      if (it == cells_.end()) continue;
      it->second = kPending;
      old_owner.emplace(it->first, id);
      seeds.push_back(it->first);
    }
    old.emplace(id, std::move(f));
  }
  std::vector<Frontier> kept;
  kept.reserve(frontiers_.size());
  for (Frontier& f : frontiers_)
    if (!old.count(f.id)) kept.push_back(std::move(f));
  frontiers_ = std::move(kept);
  for (const uint64_t p : seeds) {
    const auto it = cells_.find(p);
    if (it != cells_.end() && it->second == kUnclustered) it->second = kPending;
  }

  // Flood fill (26-neighbours) through pending and unclustered cells.
  std::vector<std::vector<Vec3i>> clusters;
  std::vector<uint64_t> queue;
  std::sort(seeds.begin(), seeds.end());
  for (const uint64_t s : seeds) {
    const auto si = cells_.find(s);
    if (si == cells_.end() || si->second != kPending) continue;
    si->second = kQueued;
    queue.assign(1, s);
    for (size_t q = 0; q < queue.size(); ++q) {
      const Vec3i k = unpack(queue[q]);
      for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const auto it = cells_.find(pack(k + Vec3i(dx, dy, dz)));
            if (it == cells_.end() || (it->second != kPending && it->second != kUnclustered)) continue;
            it->second = kQueued;
            queue.push_back(it->first);
          }
    }
    if (int(queue.size()) < cfg_.min_cluster_cells) {
      for (const uint64_t p : queue) cells_[p] = kUnclustered;
      continue;
    }
    std::vector<Vec3i> comp;
    comp.reserve(queue.size());
    for (const uint64_t p : queue) comp.push_back(unpack(p));
    splitCluster(comp, grid.resolution(), clusters);
  }
  for (auto& c : clusters) std::sort(c.begin(), c.end(), keyLess);
  std::sort(clusters.begin(), clusters.end(),
            [](const std::vector<Vec3i>& a, const std::vector<Vec3i>& b) { return keyLess(a[0], b[0]); });

  std::vector<int> reused;
  for (auto& cells : clusters) {
    Frontier f;
    const auto oo = old_owner.find(pack(cells[0]));
    if (oo != old_owner.end() && old.at(oo->second).cells == cells) {
      const Frontier& o = old.at(oo->second);
      f.id = o.id;
      f.anchor_node = o.anchor_node;
      f.created_time = o.created_time;
      reused.push_back(o.id);
    } else {
      f.id = next_id_++;
      f.anchor_node = anchor_node;
      f.created_time = time;
      up.added.push_back(f.id);
    }
    f.cells = std::move(cells);
    const double res = grid.resolution();
    for (const Vec3i& c : f.cells) {
      cells_[pack(c)] = f.id;
      f.centroid += grid.centerOf(c);
      f.box.extend(c.cast<double>() * res);
      f.box.extend((c + Vec3i::Ones()).cast<double>() * res);
    }
    f.centroid /= double(f.cells.size());
    f.viewpoints = computeViewpoints(grid, f.cells, f.centroid, cfg_);
    frontiers_.push_back(std::move(f));
  }
  for (const auto& [id, f] : old)
    if (std::find(reused.begin(), reused.end(), id) == reused.end()) up.removed.push_back(id);
  std::sort(up.removed.begin(), up.removed.end());
  std::sort(frontiers_.begin(), frontiers_.end(), [](const Frontier& a, const Frontier& b) { return a.id < b.id; });
  index_.clear();
  for (size_t i = 0; i < frontiers_.size(); ++i) index_.emplace(frontiers_[i].id, i);
}

}  // namespace ussnav
