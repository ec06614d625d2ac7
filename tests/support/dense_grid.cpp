#include "support/dense_grid.hpp"

#include <algorithm>
#include <climits>
#include <cmath>

#include "ussnav/skeleton/sphere_sampler.hpp"

namespace ussnav::test {

DenseGrid::DenseGrid(const Aabb& bounds, double resolution, VoxelState fill) : res_(resolution) {
  for (int i = 0; i < 3; ++i) {
    lo_[i] = int(std::floor(bounds.min[i] / res_ + 1e-9));
    const int hi = int(std::ceil(bounds.max[i] / res_ - 1e-9));
    dims_[i] = std::max(1, hi - lo_[i]);
  }
  bounds_.min = lo_.cast<double>() * res_;
  bounds_.max = (lo_ + dims_).cast<double>() * res_;
  cells_.assign(size_t(dims_.x()) * dims_.y() * dims_.z(), uint8_t(fill));
  resetWindow();
}

bool DenseGrid::inGrid(const Vec3i& k) const {
  return (k.array() >= lo_.array()).all() && (k.array() < (lo_ + dims_).array()).all();
}

size_t DenseGrid::index(const Vec3i& k) const {
  const Vec3i r = k - lo_;
  return (size_t(r.z()) * dims_.y() + r.y()) * dims_.x() + r.x();
}

VoxelState DenseGrid::state(const Vec3i& key) const {
  if (!inWindow(key)) return VoxelState::Unknown;
  return VoxelState(cells_[index(key)]);
}

bool DenseGrid::inWindow(const Vec3i& key) const {
  return (key.array() >= win_lo_.array()).all() && (key.array() <= win_hi_.array()).all();
}

Aabb DenseGrid::window() const {
  Aabb w;
  w.min = win_lo_.cast<double>() * res_;
  w.max = (win_hi_ + Vec3i::Ones()).cast<double>() * res_;
  return w;
}

void DenseGrid::fill(const Aabb& box, VoxelState s) {
  Vec3i a, b;
  for (int i = 0; i < 3; ++i) {
    // Voxel k's centre (k + 0.5) * res lies in [min, max].
    a[i] = std::max(lo_[i], int(std::ceil(box.min[i] / res_ - 0.5 - 1e-9)));
    b[i] = std::min(lo_[i] + dims_[i] - 1, int(std::floor(box.max[i] / res_ - 0.5 + 1e-9)));
  }
  for (int z = a.z(); z <= b.z(); ++z)
    for (int y = a.y(); y <= b.y(); ++y)
      for (int x = a.x(); x <= b.x(); ++x) cells_[index(Vec3i(x, y, z))] = uint8_t(s);
}

VoxelState DenseGrid::stored(const Vec3i& key) const {
  return inGrid(key) ? VoxelState(cells_[index(key)]) : VoxelState::Unknown;
}

void DenseGrid::set(const Vec3i& key, VoxelState s) {
  if (inGrid(key)) cells_[index(key)] = uint8_t(s);
}

void DenseGrid::setWindow(const Aabb& w) {
  for (int i = 0; i < 3; ++i) {
    win_lo_[i] = std::max(lo_[i], int(std::floor(w.min[i] / res_ + 1e-9)));
    win_hi_[i] = std::min(lo_[i] + dims_[i] - 1, int(std::ceil(w.max[i] / res_ - 1e-9)) - 1);
  }
}

void DenseGrid::resetWindow() {
  win_lo_ = lo_;
  win_hi_ = lo_ + dims_ - Vec3i::Ones();
}

size_t DenseGrid::count(VoxelState s) const {
  size_t n = 0;
  for (int z = win_lo_.z(); z <= win_hi_.z(); ++z)
    for (int y = win_lo_.y(); y <= win_hi_.y(); ++y)
      for (int x = win_lo_.x(); x <= win_hi_.x(); ++x)
        if (cells_[index(Vec3i(x, y, z))] == uint8_t(s)) ++n;
  return n;
}

namespace {
Aabb box(double x0, double y0, double z0, double x1, double y1, double z1) {
  Aabb b;
  b.min = Vec3(x0, y0, z0);
  b.max = Vec3(x1, y1, z1);
  return b;
}
}  // namespace

BoxRoomScene boxRoom(const Vec3& size, double resolution) {
  const double t = 0.2;  // wall thickness
  BoxRoomScene s{DenseGrid(box(-t, -t, -t, size.x() + t, size.y() + t, size.z() + t), resolution,
                           VoxelState::Occupied),
                 box(0, 0, 0, size.x(), size.y(), size.z())};
  s.grid.carve(s.room);
  return s;
}

TwoRoomsScene twoRooms(double resolution) {
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

CorridorScene corridor(double length, double width, double height, double resolution) {
  const double t = 0.2;
  CorridorScene s{DenseGrid(box(-t, -t, -t, length + t, width + t, height + t), resolution,
                            VoxelState::Occupied),
                  box(0, 0, 0, length, width, height)};
  s.grid.carve(s.corridor);
  return s;
}

FloorScene roomFloor(int nx, int ny, double room_size, double height, double resolution) {
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
