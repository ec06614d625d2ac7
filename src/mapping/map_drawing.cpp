#include "ussnav/mapping/map_drawing.hpp"

#include <cmath>
#include <cstdio>
#include <set>
#include <utility>

namespace ussnav {

void drawGridSlice(Image& img, const TopDownView& view, const RollingGrid& grid, double z_min, double z_max) {
  const double r = grid.resolution();
  const Vec3i lo = grid.minKey(), d = grid.dims();
  const int kz0 = std::max(lo.z(), int(std::floor(z_min / r))), kz1 = std::min(lo.z() + d.z() - 1, int(std::floor(z_max / r)));
  for (int y = lo.y(); y < lo.y() + d.y(); ++y)
    for (int x = lo.x(); x < lo.x() + d.x(); ++x) {
      VoxelState best = VoxelState::Unknown;
      for (int z = kz0; z <= kz1; ++z) {
        const VoxelState s = grid.stateFast(Vec3i(x, y, z));
        if (s == VoxelState::Occupied) { best = s; break; }
        if (s == VoxelState::Free) best = s;
      }
      const Vec2 a = view.toPx(Vec2(x * r, y * r)), b = view.toPx(Vec2((x + 1) * r, (y + 1) * r));
      const Rgb c = best == VoxelState::Occupied ? Rgb{20, 20, 20}
                    : best == VoxelState::Free   ? Rgb{255, 255, 255}
                                                 : Rgb{150, 150, 150};
      img.fillRect(int(std::lround(a.x())), int(std::lround(b.y())), int(std::lround(b.x())) - 1,
                   int(std::lround(a.y())) - 1, c, best == VoxelState::Unknown ? 0.35 : 0.85);
    }
}

void drawCoverageMask(Image& img, const TopDownView& view, const CoverageMask& mask) {
  for (const auto& c : mask.allocatedCells()) {
    if (c.known == 0 && !c.visited) continue;
    const Aabb b = mask.cellBounds(c.cell);
    const Vec2 p0 = view.toPx(Vec2(b.min.x(), b.min.y())), p1 = view.toPx(Vec2(b.max.x(), b.max.y()));
    img.fillRect(int(p0.x()), int(p1.y()), int(p1.x()) - 1, int(p0.y()) - 1,
                 c.visited ? Rgb{120, 200, 120} : Rgb{200, 200, 200}, c.visited ? 0.30 : 0.15);
  }
}

std::string asciiSlice(const RollingGrid& grid, const CoverageMask& mask, const std::vector<Vec3i>& marked, double z) {
  const int kz = int(std::floor(z / grid.resolution()));
  std::set<std::pair<int, int>> columns;
  for (const Vec3i& k : marked) columns.insert({k.x(), k.y()});
  const Vec3i lo = grid.minKey(), hi = grid.minKey() + grid.dims() - Vec3i::Ones();
  char head[160];
  std::snprintf(head, sizeof head, "z-key %d, x-keys %d..%d (left to right), y-keys %d..%d (top to bottom), %.2f m voxels\n",
                kz, lo.x(), hi.x(), hi.y(), lo.y(), grid.resolution());
  std::string out = head;
  for (int y = hi.y(); y >= lo.y(); --y) {
    char row[16];
    std::snprintf(row, sizeof row, "%5d|", y);
    out += row;
    for (int x = lo.x(); x <= hi.x(); ++x) {
      const Vec3i k(x, y, kz);
      const VoxelState s = grid.state(k);
      const bool visited = mask.isVisited(mask.cellOfKey(k));
      char c = s == VoxelState::Occupied ? '#' : s == VoxelState::Free ? (visited ? ',' : '.') : (visited ? 'u' : ' ');
      if (columns.count({x, y})) c = 'F';
      out += c;
    }
    out += "|\n";
  }
  return out;
}

}  // namespace ussnav
