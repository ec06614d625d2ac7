#include "support/skeleton_scenes.hpp"

#include <climits>
#include <cmath>

#include "ussnav/skeleton/sphere_sampler.hpp"

namespace ussnav::test {

namespace {
Aabb box(double x0, double y0, double z0, double x1, double y1, double z1) {
  Aabb b;
  b.min = Vec3(x0, y0, z0);
  b.max = Vec3(x1, y1, z1);
  return b;
}
}  // namespace

BoxRoomScene boxRoomGrid(const Vec3& size, double resolution) {
  const double t = 0.2;  // wall thickness
  BoxRoomScene s{DenseGrid(box(-t, -t, -t, size.x() + t, size.y() + t, size.z() + t), resolution,
                           VoxelState::Occupied),
                 box(0, 0, 0, size.x(), size.y(), size.z())};
  s.grid.carve(s.room);
  return s;
}

TwoRoomsScene twoRoomsGrid(double resolution) {
  // Room A: x in [0, 4], room B: x in [4.2, 8.2], y in [0, 4], z in [0, 2.6]; a 0.9 x 2.0 m door
  // at y in [1.6, 2.5].
  const double t = 0.2;
  TwoRoomsScene s{DenseGrid(box(-t, -t, -t, 8.2 + t, 4.0 + t, 2.6 + t), resolution, VoxelState::Occupied),
                  box(0, 0, 0, 4.0, 4.0, 2.6), box(4.2, 0, 0, 8.2, 4.0, 2.6),
                  box(4.0, 1.6, 0, 4.2, 2.5, 2.0), 4.0, 4.2};
  s.grid.carve(s.room_a);
  s.grid.carve(s.room_b);
  s.grid.carve(s.door);
  return s;
}

CorridorScene corridorGrid(double length, double width, double height, double resolution) {
  const double t = 0.2;
  CorridorScene s{DenseGrid(box(-t, -t, -t, length + t, width + t, height + t), resolution,
                            VoxelState::Occupied),
                  box(0, 0, 0, length, width, height)};
  s.grid.carve(s.corridor);
  return s;
}

FloorScene floorGrid(int nx, int ny, double room_size, double height, double resolution) {
  const double t = 0.2;
  const double pitch = room_size + t;
  FloorScene s{DenseGrid(box(-t, -t, -t, nx * pitch, ny * pitch, height + t), resolution,
                         VoxelState::Occupied),
               {},
               {}};
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double x0 = i * pitch, y0 = j * pitch;
      s.rooms.push_back(box(x0, y0, 0, x0 + room_size, y0 + room_size, height));
      s.grid.carve(s.rooms.back());
      // Doors towards +x and +y, off-centre so that the door pattern is not symmetric.
      if (i + 1 < nx) s.doors.push_back(box(x0 + room_size, y0 + 0.3 * room_size, 0,
                                            x0 + pitch, y0 + 0.3 * room_size + 0.9, 2.0));
      if (j + 1 < ny) s.doors.push_back(box(x0 + 0.6 * room_size, y0 + room_size, 0,
                                            x0 + 0.6 * room_size + 0.9, y0 + pitch, 2.0));
    }
  for (const Aabb& d : s.doors) s.grid.carve(d);
  return s;
}

void observe(const DenseGrid& truth, DenseGrid& known, const Vec3& origin, double range, int rays) {
  const double step = truth.resolution() / 3.0;
  for (const Vec3& dir : fibonacciSphere(rays)) {
    Vec3i last(INT32_MIN, INT32_MIN, INT32_MIN);
    for (double t = 0.0; t <= range; t += step) {
      const Vec3i k = truth.keyOf(origin + dir * t);
      if (k == last) continue;
      last = k;
      const VoxelState s = truth.stored(k);
      if (s == VoxelState::Unknown) break;  // outside the world
      known.set(k, s);
      if (s == VoxelState::Occupied) break;
    }
  }
}

std::vector<Vec3> samplePolyline(const std::vector<Vec3>& waypoints, double step) {
  std::vector<Vec3> out;
  if (waypoints.empty()) return out;
  out.push_back(waypoints.front());
  for (size_t i = 1; i < waypoints.size(); ++i) {
    const Vec3 a = waypoints[i - 1], b = waypoints[i];
    const int n = std::max(1, int(std::ceil((b - a).norm() / step)));
    for (int j = 1; j <= n; ++j) out.push_back(a + (b - a) * (double(j) / n));
  }
  return out;
}

}  // namespace ussnav::test
