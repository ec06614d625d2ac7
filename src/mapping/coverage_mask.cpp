#include "ussnav/mapping/coverage_mask.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <unordered_set>

#include "ussnav/core/error.hpp"

namespace ussnav {

namespace {

constexpr const char* kCfg = "mapping.coverage";

int floorDiv(int a, int n) { return a >= 0 ? a / n : -((-a - 1) / n) - 1; }

int wholeVoxels(double size, double res, const char* field) {
  if (!std::isfinite(size) || size <= 0)
    throw InputError(kCfg, field, "must be positive, got " + std::to_string(size));
  const double n = std::round(size / res);
  if (n < 1 || std::abs(size / res - n) > 1e-6 * n)
    throw InputError(kCfg, field,
                     "must be a whole multiple of mapping.grid.resolution (" + std::to_string(res) + " m), got " +
                         std::to_string(size));
  if (n > 4096) throw InputError(kCfg, field, "spans more than 4096 voxels");
  return int(n);
}

// Overlap length of [a, a+n) and [b, b+m).
int overlap(int a, int n, int b, int m) { return std::max(0, std::min(a + n, b + m) - std::max(a, b)); }

}  // namespace

CoverageMask::CoverageMask(const CoverageConfig& cfg, double voxel_resolution)
    : cfg_(cfg), res_(voxel_resolution) {
  if (!std::isfinite(res_) || res_ <= 0)
    throw InputError(kCfg, "resolution", "voxel resolution must be positive");
  const int xy = wholeVoxels(cfg.cell_size, res_, "cell_size");
  cell_vox_ = Vec3i(xy, xy, wholeVoxels(cfg.cell_height, res_, "cell_height"));
  if (double(xy) * xy * cell_vox_.z() > 2e9) throw InputError(kCfg, "cell_size", "cell holds too many voxels");
  if (!(cfg.visited_unknown_fraction >= 0 && cfg.visited_unknown_fraction <= 1))
    throw InputError(kCfg, "visited_unknown_fraction", "must be in [0, 1]");
  if (!(cfg.min_window_fraction > 0 && cfg.min_window_fraction <= 1))
    throw InputError(kCfg, "min_window_fraction", "must be in (0, 1]");
}

Vec3i CoverageMask::cellOfKey(const Vec3i& k) const {
  return Vec3i(floorDiv(k.x(), cell_vox_.x()), floorDiv(k.y(), cell_vox_.y()), floorDiv(k.z(), cell_vox_.z()));
}

Vec3i CoverageMask::cellOf(const Vec3& p) const {
  return cellOfKey(Vec3i(int(std::floor(p.x() / res_)), int(std::floor(p.y() / res_)), int(std::floor(p.z() / res_))));
}

Aabb CoverageMask::cellBounds(const Vec3i& c) const {
  Aabb b;
  b.min = c.cwiseProduct(cell_vox_).cast<double>() * res_;
  b.max = (c + Vec3i::Ones()).cwiseProduct(cell_vox_).cast<double>() * res_;
  return b;
}

uint64_t CoverageMask::chunkKey(const Vec3i& c) {
  const auto part = [](int v) { return uint64_t(uint32_t(v)) & 0x1FFFFF; };
  return part(c.x() >> kChunkBits) << 42 | part(c.y() >> kChunkBits) << 21 | part(c.z());
}

int CoverageMask::cellSlot(const Vec3i& c) {
  constexpr int mask = (1 << kChunkBits) - 1;
  return (c.x() & mask) | (c.y() & mask) << kChunkBits;
}

CoverageMask::Cell& CoverageMask::cellRef(const Vec3i& c) {
  const uint64_t key = chunkKey(c);
  if (key != last_chunk_key_) {
    last_chunk_ = &chunks_[key];  // node-based map: the address stays valid
    last_chunk_key_ = key;
  }
  return last_chunk_->cells[cellSlot(c)];
}

const CoverageMask::Cell* CoverageMask::findCell(const Vec3i& c) const {
  const auto it = chunks_.find(chunkKey(c));
  return it == chunks_.end() ? nullptr : &it->second.cells[cellSlot(c)];
}

void CoverageMask::update(const RollingGrid& grid) {
  if (consumed_ < grid.changeSeqBegin() || consumed_ > grid.changeSeqEnd())
    throw std::logic_error("CoverageMask::update: the grid's change log no longer holds entries " +
                           std::to_string(consumed_) + ".." + std::to_string(grid.changeSeqBegin()) +
                           " (update the mask before RollingGrid::clearChanges, one mask per grid)");
  const auto& log = grid.changes();
  for (size_t i = size_t(consumed_ - grid.changeSeqBegin()); i < log.size(); ++i) {
    const VoxelChange& ch = log[i];
    const bool was = ch.before != VoxelState::Unknown, now = ch.after != VoxelState::Unknown;
    if (was == now) continue;
    Cell& cell = cellRef(cellOfKey(ch.key));
    cell.known += now ? 1 : -1;
    cell.seen |= uint8_t(now);
  }
  consumed_ = grid.changeSeqEnd();
  win_min_ = grid.minKey();
  win_dims_ = grid.dims();
  // Re-judge the cells the window overlaps (a few hundred): their in-window share may have
  // changed with a roll even where no voxel changed state.
  const Vec3i lo = cellOfKey(win_min_), hi = cellOfKey(win_min_ + win_dims_ - Vec3i::Ones());
  const double need = cfg_.min_window_fraction * voxelsPerCell();
  for (int z = lo.z(); z <= hi.z(); ++z)
    for (int y = lo.y(); y <= hi.y(); ++y)
      for (int x = lo.x(); x <= hi.x(); ++x) {
        const Vec3i c(x, y, z);
        const uint64_t key = chunkKey(c);
        if (key != last_chunk_key_) {
          const auto it = chunks_.find(key);
          if (it == chunks_.end()) continue;  // nothing known there: cannot be visited
          last_chunk_ = &it->second;
          last_chunk_key_ = key;
        }
        Cell& cell = last_chunk_->cells[cellSlot(c)];
        if (cell.visited) continue;
        const int in_window = inWindowCount(c);
        if (in_window >= need && in_window - cell.known < cfg_.visited_unknown_fraction * in_window) {
          cell.visited = 1;
          ++visited_count_;
        }
      }
}

bool CoverageMask::isVisited(const Vec3i& cell) const {
  const Cell* c = findCell(cell);
  return c && c->visited;
}

int CoverageMask::knownCount(const Vec3i& cell) const {
  const Cell* c = findCell(cell);
  return c ? c->known : 0;
}

int CoverageMask::inWindowCount(const Vec3i& c) const {
  int n = 1;
  for (int i = 0; i < 3; ++i) n *= overlap(c[i] * cell_vox_[i], cell_vox_[i], win_min_[i], win_dims_[i]);
  return n;
}

std::vector<CoverageCellInfo> CoverageMask::allocatedCells() const {
  std::vector<CoverageCellInfo> out;
  out.reserve(cellsAllocated());
  for (const auto& [key, chunk] : chunks_) {
    // Unpack the chunk key back into cell coordinates (sign-extend the 21-bit fields).
    const auto field = [&](int shift) { return int32_t(uint32_t((key >> shift) & 0x1FFFFF) << 11) >> 11; };
    const int cx = field(42) << kChunkBits, cy = field(21) << kChunkBits, cz = field(0);
    for (int s = 0; s < kChunkCells; ++s) {
      const Vec3i c(cx + (s & ((1 << kChunkBits) - 1)), cy + (s >> kChunkBits), cz);
      out.push_back({c, chunk.cells[s].known, chunk.cells[s].visited != 0});
    }
  }
  return out;
}

size_t CoverageMask::memoryBytes() const {
  // Node-based hash map: per chunk its value, the key and a next pointer; plus the buckets.
  const size_t node = sizeof(std::pair<const uint64_t, Chunk>) + sizeof(void*);
  return sizeof(*this) + chunks_.size() * node + chunks_.bucket_count() * sizeof(void*);
}

double CoverageMask::exploredArea() const {
  std::unordered_set<uint64_t> columns;
  for (const auto& [key, chunk] : chunks_)
    for (int s = 0; s < kChunkCells; ++s)
      if (chunk.cells[s].seen) columns.insert((key >> 21) << kChunkBits * 2 | uint64_t(s));
  return double(columns.size()) * cfg_.cell_size * cfg_.cell_size;
}

double CoverageMask::bytesPerExploredSquareMetre() const {
  const double a = exploredArea();
  return a > 0 ? double(memoryBytes()) / a : 0.0;
}

std::vector<CoverageCount> CoverageMask::bruteForceCounts(const RollingGrid& grid) const {
  std::map<std::tuple<int, int, int>, CoverageCount> counts;
  const Vec3i lo = grid.minKey(), hi = grid.minKey() + grid.dims();
  for (int z = lo.z(); z < hi.z(); ++z)
    for (int y = lo.y(); y < hi.y(); ++y)
      for (int x = lo.x(); x < hi.x(); ++x) {
        const Vec3i k(x, y, z), c = cellOfKey(k);
        CoverageCount& e = counts[{c.z(), c.y(), c.x()}];
        e.cell = c;
        ++e.in_window;
        e.unknown += grid.stateFast(k) == VoxelState::Unknown;
      }
  std::vector<CoverageCount> out;
  out.reserve(counts.size());
  for (const auto& [key, e] : counts) out.push_back(e);
  return out;
}

}  // namespace ussnav
