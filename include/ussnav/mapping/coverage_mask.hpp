#pragma once
// CoverageMask: the Global Coverage Mask of the paper (Sec. V-A, Eq. 3). Sparse coarse cells
// (cell_size x cell_size x cell_height, z-cells from z = 0) count the voxels of the cell that
// the rolling grid holds (in_window) and how many of those are known; Eq. 3's unknown count is
// in_window - known. A cell becomes *visited* when at least min_window_fraction of it is in
// the window and unknown < visited_unknown_fraction * in_window, and stays visited once the
// window has moved on: that is what the mask remembers. update() reads the grid's change log:
// O(changes + cells overlapping the window), never a rescan. Memory: 8 bytes per cell in
// chunks of 8 x 8 cells, allocated where the window has made a voxel known.

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "ussnav/core/config.hpp"
#include "ussnav/mapping/rolling_grid.hpp"

namespace ussnav {

struct CoverageCount {
  Vec3i cell;
  int in_window = 0;  // voxels of the cell inside the grid window
  int unknown = 0;    // of those, Unknown (Eq. 3)
  bool operator==(const CoverageCount&) const = default;
};

struct CoverageCellInfo {
  Vec3i cell;
  int known = 0;       // known voxels of the cell inside the window
  bool visited = false;
};

class CoverageMask {
 public:
  // Throws InputError (file "mapping.coverage") unless cell_size and cell_height are positive
  // whole multiples of voxel_resolution and the fractions lie in range.
  CoverageMask(const CoverageConfig& cfg, double voxel_resolution);

  // Consumes grid.changes() appended since the previous update, then re-judges the cells that
  // overlap the grid's window. Call it after every insertion/roll and before the driver's
  // grid.clearChanges(); throws std::logic_error if entries were cleared before it saw them.
  void update(const RollingGrid& grid);

  Vec3i cellOf(const Vec3& p) const;
  Vec3i cellOfKey(const Vec3i& voxel_key) const;
  Aabb cellBounds(const Vec3i& cell) const;
  const Vec3i& cellVoxels() const { return cell_vox_; }  // voxels per cell along x, y, z
  int voxelsPerCell() const { return cell_vox_.x() * cell_vox_.y() * cell_vox_.z(); }

  bool isVisited(const Vec3i& cell) const;
  bool isVisitedAt(const Vec3& p) const { return isVisited(cellOf(p)); }
  // Counts as of the last update. Eq. 3: unknownCount = inWindowCount - knownCount.
  int knownCount(const Vec3i& cell) const;
  int inWindowCount(const Vec3i& cell) const;
  int unknownCount(const Vec3i& cell) const { return inWindowCount(cell) - knownCount(cell); }

  size_t visitedCount() const { return visited_count_; }
  std::vector<CoverageCellInfo> allocatedCells() const;  // every cell with storage, any order
  size_t cellsAllocated() const { return chunks_.size() * kChunkCells; }

  // Bytes held (chunks, hash table, object), the x-y area (m^2) of cell columns in which a
  // voxel was ever known, and their ratio.
  size_t memoryBytes() const;
  double exploredArea() const;
  double bytesPerExploredSquareMetre() const;

  // Brute force for tests: scans every voxel of the grid's window and counts per cell, sorted
  // by cell (z, y, x). O(window voxels).
  std::vector<CoverageCount> bruteForceCounts(const RollingGrid& grid) const;

 private:
  static constexpr int kChunkBits = 3;  // 8 x 8 cells per chunk (x, y), one z-layer
  static constexpr int kChunkCells = 1 << (2 * kChunkBits);
  struct Cell {
    int32_t known = 0;
    uint8_t visited = 0;
    uint8_t seen = 0;  // a voxel of it has been known at some time
  };
  struct Chunk {
    Cell cells[kChunkCells];
  };
  static uint64_t chunkKey(const Vec3i& cell);
  static int cellSlot(const Vec3i& cell);
  Cell& cellRef(const Vec3i& cell);
  const Cell* findCell(const Vec3i& cell) const;

  CoverageConfig cfg_;
  double res_;
  Vec3i cell_vox_;
  std::unordered_map<uint64_t, Chunk> chunks_;
  uint64_t last_chunk_key_ = ~uint64_t(0);
  Chunk* last_chunk_ = nullptr;
  uint64_t consumed_ = 0;  // grid change sequence number consumed so far
  Vec3i win_min_ = Vec3i::Zero(), win_dims_ = Vec3i::Zero();
  size_t visited_count_ = 0;
};

}  // namespace ussnav
