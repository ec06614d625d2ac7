#include "ussnav/sim/ground_truth.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "ussnav/core/error.hpp"

namespace ussnav {

GroundTruthGrid::GroundTruthGrid(const World& world, double resolution, double margin)
    : res_(resolution) {
  if (!(resolution > 0.0)) throw InputError("ground truth", "resolution", "must be positive");
  Aabb b = world.bounds();
  if (b.empty()) throw InputError(world.name, "world", "is empty: no rooms, walls or obstacles");
  double zmin = b.min.z(), zmax = b.max.z();
  const double slab = 0.1;
  if (world.has_floor) {
    zmin -= slab;
    zmax += slab;
  }
  b.min = Vec3(b.min.x() - margin, b.min.y() - margin, zmin - 2 * res_);
  b.max = Vec3(b.max.x() + margin, b.max.y() + margin, zmax + 2 * res_);
  min_key_ = keyOf(b.min);
  const Vec3i max_key = keyOf(b.max);
  dims_ = max_key - min_key_ + Vec3i::Ones();
  const double cells = double(dims_.x()) * dims_.y() * dims_.z();
  if (cells > 1.5e9)
    throw InputError(world.name, "world", "too large for a ground-truth grid at this resolution");
  bounds_.min = min_key_.cast<double>() * res_;
  bounds_.max = (min_key_ + dims_).cast<double>() * res_;
  labels_.assign(size_t(cells), kFree);

  instance_of_label_.assign(world.objects.size() + 1, 0);
  for (size_t i = 0; i < world.objects.size(); ++i) instance_of_label_[i + 1] = world.objects[i].id;

  if (world.has_floor && !world.rooms.empty()) {
    // Floor and ceiling slabs under and over every room (and under its walls).
    for (const auto& room : world.rooms) {
      Aabb rb;
      for (const auto& p : room.polygon) rb.extend(Vec3(p.x(), p.y(), 0));
      const Vec3i k0 = keyOf(Vec3(rb.min.x() - 0.2, rb.min.y() - 0.2, 0));
      const Vec3i k1 = keyOf(Vec3(rb.max.x() + 0.2, rb.max.y() + 0.2, 0));
      const int f0 = keyOf(Vec3(0, 0, room.floor_z - slab)).z(), f1 = keyOf(Vec3(0, 0, room.floor_z - 1e-6)).z();
      const int c0 = keyOf(Vec3(0, 0, room.ceiling_z + 1e-6)).z(), c1 = keyOf(Vec3(0, 0, room.ceiling_z + slab)).z();
      for (int y = k0.y(); y <= k1.y(); ++y)
        for (int x = k0.x(); x <= k1.x(); ++x) {
          const Vec2 c = ((Vec2(x, y).array() + 0.5) * res_).matrix();
          // Extend slabs 0.2 m past the polygon so walls on the boundary sit on the floor.
          bool near = pointInPolygon(c, room.polygon);
          for (int dy = -1; dy <= 1 && !near; ++dy)
            for (int dx = -1; dx <= 1 && !near; ++dx)
              near = pointInPolygon(c + Vec2(dx, dy) * 0.2, room.polygon);
          if (!near) continue;
          for (int z = f0; z <= f1; ++z)
            if (inWindow(Vec3i(x, y, z))) labels_[index(Vec3i(x, y, z))] = kStructure;
          for (int z = c0; z <= c1; ++z)
            if (inWindow(Vec3i(x, y, z))) labels_[index(Vec3i(x, y, z))] = kStructure;
        }
    }
  }
  for (const auto& w : world.walls) rasterizeWall(w);
  // A wall's end caps reach half its thickness past its ends (corners close); where a wall ends
  // at another wall's door, the cap would narrow the door: openings are cut through every wall.
  for (const auto& w : world.walls) carveOpenings(w);
  for (size_t i = 0; i < world.objects.size(); ++i) rasterizeBox(world.objects[i].box, uint16_t(i + 1));
  const auto& ob = world.obstacles;
  for (const auto& c : ob.cells) {
    const Vec3 lo = ob.origin + c.cast<double>() * ob.resolution;
    fillKeyBox(lo, lo + Vec3::Constant(ob.resolution), kStructure);
  }
  buildBlocks();
}

void GroundTruthGrid::buildBlocks() {
  bdims_ = (dims_ + Vec3i::Constant(kBlock - 1)) / kBlock;
  block_occupied_.assign(size_t(bdims_.x()) * bdims_.y() * bdims_.z(), 0);
  for (int z = 0; z < dims_.z(); ++z)
    for (int y = 0; y < dims_.y(); ++y)
      for (int x = 0; x < dims_.x(); ++x)
        if (labels_[(size_t(z) * dims_.y() + y) * dims_.x() + x] != kFree)
          block_occupied_[(size_t(z / kBlock) * bdims_.y() + y / kBlock) * bdims_.x() + x / kBlock] = 1;
}

VoxelState GroundTruthGrid::state(const Vec3i& key) const {
  if (!inWindow(key)) return VoxelState::Unknown;
  return labels_[index(key)] == kFree ? VoxelState::Free : VoxelState::Occupied;
}

bool GroundTruthGrid::inWindow(const Vec3i& key) const {
  const Vec3i l = key - min_key_;
  return l.x() >= 0 && l.y() >= 0 && l.z() >= 0 && l.x() < dims_.x() && l.y() < dims_.y() &&
         l.z() < dims_.z();
}

uint16_t GroundTruthGrid::label(const Vec3i& key) const {
  return inWindow(key) ? labels_[index(key)] : kStructure;
}

int GroundTruthGrid::instanceOfLabel(uint16_t l) const {
  if (l == kFree || l == kStructure || l >= instance_of_label_.size()) return 0;
  return instance_of_label_[l];
}

size_t GroundTruthGrid::occupiedCount() const {
  return size_t(std::count_if(labels_.begin(), labels_.end(), [](uint16_t l) { return l != kFree; }));
}

void GroundTruthGrid::fillKeyBox(const Vec3& lo, const Vec3& hi, uint16_t lab) {
  // Voxels whose centre lies in [lo, hi).
  const Vec3i k0 = keyOf(lo + Vec3::Constant(0.5 * res_ - 1e-9));
  const Vec3i k1 = keyOf(hi - Vec3::Constant(0.5 * res_ + 1e-9));
  for (int z = std::max(k0.z(), min_key_.z()); z <= std::min(k1.z(), min_key_.z() + dims_.z() - 1); ++z)
    for (int y = std::max(k0.y(), min_key_.y()); y <= std::min(k1.y(), min_key_.y() + dims_.y() - 1); ++y)
      for (int x = std::max(k0.x(), min_key_.x()); x <= std::min(k1.x(), min_key_.x() + dims_.x() - 1); ++x)
        labels_[index(Vec3i(x, y, z))] = lab;
}

void GroundTruthGrid::rasterizeWall(const Wall& w) {
  const Vec2 d = w.b - w.a;
  const double len = d.norm();
  if (len < 1e-9) return;
  const Vec2 u = d / len;
  const Vec2 n(-u.y(), u.x());
  // At least one voxel thick so thin walls never leak rays.
  const double half_t = std::max(0.5 * w.thickness, 0.5 * res_ + 1e-6);
  Aabb box;
  for (double s : {-half_t, len + half_t})
    for (double t : {-half_t, half_t}) {
      const Vec2 p = w.a + u * s + n * t;
      box.extend(Vec3(p.x(), p.y(), w.z0));
      box.extend(Vec3(p.x(), p.y(), w.z1));
    }
  const Vec3i k0 = keyOf(box.min), k1 = keyOf(box.max);
  for (int y = k0.y(); y <= k1.y(); ++y)
    for (int x = k0.x(); x <= k1.x(); ++x) {
      const Vec2 c((x + 0.5) * res_, (y + 0.5) * res_);
      const double s = (c - w.a).dot(u), t = (c - w.a).dot(n);
      if (std::abs(t) > half_t || s < -half_t || s > len + half_t) continue;
      for (int z = k0.z(); z <= k1.z(); ++z) {
        const double zc = (z + 0.5) * res_;
        if (zc < w.z0 || zc > w.z1) continue;
        bool open = false;
        for (const auto& o : w.openings)
          if (s >= o.start && s <= o.end && zc - w.z0 >= o.bottom && zc - w.z0 <= o.top) open = true;
        const Vec3i k(x, y, z);
        if (!open && inWindow(k)) labels_[index(k)] = kStructure;
      }
    }
}

void GroundTruthGrid::carveOpenings(const Wall& w) {
  const Vec2 d = w.b - w.a;
  const double len = d.norm();
  if (len < 1e-9 || w.openings.empty()) return;
  const Vec2 u = d / len;
  const Vec2 n(-u.y(), u.x());
  const double half_t = std::max(0.5 * w.thickness, 0.5 * res_ + 1e-6);
  for (const Opening& o : w.openings) {
    Aabb box;
    for (double s : {o.start, o.end})
      for (double t : {-half_t, half_t}) {
        const Vec2 p = w.a + u * s + n * t;
        box.extend(Vec3(p.x(), p.y(), w.z0 + o.bottom));
        box.extend(Vec3(p.x(), p.y(), w.z0 + o.top));
      }
    const Vec3i k0 = keyOf(box.min), k1 = keyOf(box.max);
    for (int y = k0.y(); y <= k1.y(); ++y)
      for (int x = k0.x(); x <= k1.x(); ++x) {
        const Vec2 c((x + 0.5) * res_, (y + 0.5) * res_);
        const double s = (c - w.a).dot(u), t = (c - w.a).dot(n);
        if (std::abs(t) > half_t || s < o.start || s > o.end) continue;
        for (int z = k0.z(); z <= k1.z(); ++z) {
          const double zc = (z + 0.5) * res_;
          const Vec3i k(x, y, z);
          if (zc < w.z0 || zc > w.z1 || zc - w.z0 < o.bottom || zc - w.z0 > o.top || !inWindow(k)) continue;
          if (labels_[index(k)] == kStructure) labels_[index(k)] = kFree;
        }
      }
  }
}

void GroundTruthGrid::rasterizeBox(const OrientedBox& b, uint16_t lab) {
  const Aabb a = b.bounds();
  const Vec3i k0 = keyOf(a.min), k1 = keyOf(a.max);
  for (int z = k0.z(); z <= k1.z(); ++z)
    for (int y = k0.y(); y <= k1.y(); ++y)
      for (int x = k0.x(); x <= k1.x(); ++x) {
        const Vec3i k(x, y, z);
        // Centre inside, or the box is thinner than a voxel and crosses it.
        if (inWindow(k) && b.contains(centerOf(k), 0.5 * res_ * 0.999)) {
          if (b.contains(centerOf(k)) || b.half_extents.minCoeff() < res_) labels_[index(k)] = lab;
        }
      }
}

bool GroundTruthGrid::walkBlock(const Vec3& o, const Vec3& dir, double t0, double max_range,
                                const Vec3i& bkey, Hit& h) const {
  // Local voxel coordinates of the entry point, clamped into the block (rounding at faces).
  int l[3], lo[3], hi[3], step[3];
  double t_max[3], t_delta[3];
  const long stride[3] = {1, dims_.x(), long(dims_.x()) * dims_.y()};
  for (int i = 0; i < 3; ++i) {
    lo[i] = bkey[i] * kBlock;
    hi[i] = std::min(lo[i] + kBlock, dims_[i]) - 1;
    const double p = o[i] + dir[i] * t0;
    l[i] = std::clamp(int(std::floor(p / res_)) - min_key_[i], lo[i], hi[i]);
    const int key = l[i] + min_key_[i];
    if (dir[i] > 0) {
      step[i] = 1;
      t_max[i] = ((key + 1) * res_ - o[i]) / dir[i];
      t_delta[i] = res_ / dir[i];
    } else if (dir[i] < 0) {
      step[i] = -1;
      t_max[i] = (key * res_ - o[i]) / dir[i];
      t_delta[i] = -res_ / dir[i];
    } else {
      step[i] = 0;
      t_max[i] = std::numeric_limits<double>::infinity();
      t_delta[i] = t_max[i];
    }
  }
  const uint16_t* lab = labels_.data();
  long idx = (long(l[2]) * dims_.y() + l[1]) * dims_.x() + l[0];
  if (t0 > 0.0 && lab[idx] != kFree) {
    h = Hit{true, t0, lab[idx]};
    return true;
  }
  while (true) {
    const int axis = t_max[0] < t_max[1] ? (t_max[0] < t_max[2] ? 0 : 2) : (t_max[1] < t_max[2] ? 1 : 2);
    const double t = t_max[axis];
    if (t > max_range) return false;
    l[axis] += step[axis];
    if (l[axis] < lo[axis] || l[axis] > hi[axis]) return false;  // left the block
    idx += step[axis] * stride[axis];
    t_max[axis] += t_delta[axis];
    if (lab[idx] != kFree) {
      h = Hit{true, t, lab[idx]};
      return true;
    }
  }
}

GroundTruthGrid::Hit GroundTruthGrid::raycast(const Vec3& o, const Vec3& dir, double max_range) const {
  // Two-level Amanatides-Woo DDA: blocks of kBlock^3 voxels are crossed in one step when they
  // hold nothing; occupied blocks are walked voxel by voxel.
  Hit h;
  const double bres = res_ * kBlock;
  Vec3i b;
  int step[3];
  double t_max[3], t_delta[3];
  for (int i = 0; i < 3; ++i) {
    const int l = int(std::floor(o[i] / res_)) - min_key_[i];
    if (l < 0 || l >= dims_[i]) return h;
    b[i] = l / kBlock;
    const double b0 = (min_key_[i] + b[i] * kBlock) * res_;  // world coordinate of the block's low face
    if (dir[i] > 0) {
      step[i] = 1;
      t_max[i] = (b0 + bres - o[i]) / dir[i];
      t_delta[i] = bres / dir[i];
    } else if (dir[i] < 0) {
      step[i] = -1;
      t_max[i] = (b0 - o[i]) / dir[i];
      t_delta[i] = -bres / dir[i];
    } else {
      step[i] = 0;
      t_max[i] = std::numeric_limits<double>::infinity();
      t_delta[i] = t_max[i];
    }
  }
  double t_entry = 0.0;
  while (true) {
    if (block_occupied_[(size_t(b.z()) * bdims_.y() + b.y()) * bdims_.x() + b.x()] &&
        walkBlock(o, dir, t_entry, max_range, b, h))
      return h;
    const int axis = t_max[0] < t_max[1] ? (t_max[0] < t_max[2] ? 0 : 2) : (t_max[1] < t_max[2] ? 1 : 2);
    t_entry = t_max[axis];
    if (t_entry > max_range) return h;
    b[axis] += step[axis];
    if (b[axis] < 0 || b[axis] >= bdims_[axis]) return h;
    t_max[axis] += t_delta[axis];
  }
}

bool GroundTruthGrid::sphereCollides(const Vec3& p, double radius) const {
  const Vec3i c = keyOf(p);
  const int n = int(std::ceil(radius / res_));
  for (int dz = -n; dz <= n; ++dz)
    for (int dy = -n; dy <= n; ++dy)
      for (int dx = -n; dx <= n; ++dx) {
        const Vec3i k = c + Vec3i(dx, dy, dz);
        const Vec3 lo = k.cast<double>() * res_, hi = lo + Vec3::Constant(res_);
        if ((p.cwiseMax(lo).cwiseMin(hi) - p).norm() > radius) continue;
        if (label(k) != kFree) return true;
      }
  return false;
}

}  // namespace ussnav
