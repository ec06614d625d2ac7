// Mapping benchmarks: RollingGrid insertion of depth frames (160x120, 320x240) and a 20,000
// point LiDAR scan, side by side with OctoMap's insertPointCloud on the same points at the
// same resolution and log-odds; rolling the window by one metre; the Coverage Mask update.
// Frames come from analytic scenes (tests/support/mapping_scenes), rendered once up front.
// Run: build/bench_mapping --benchmark_min_time=0.2

#include <benchmark/benchmark.h>
#include <octomap/OcTree.h>

#include <vector>

#include "support/mapping_scenes.hpp"
#include "ussnav/core/random.hpp"
#include "ussnav/mapping/coverage_mask.hpp"
#include "ussnav/mapping/rolling_grid.hpp"

using namespace ussnav;

namespace {

constexpr int kFrames = 8;  // cycled, so repeated inserts are not of one identical frame
const Vec3 kCentre(0.05, -0.1, 1.4);

// 7 x 7 x 2.8 m furnished room: inside the 8 x 8 x 4 m window, so both maps trace the same rays.
const test::BoxScene& room() {
  static const test::BoxScene s = test::boxRoom(Vec3(-3.5, -3.5, 0), Vec3(3.5, 3.5, 2.8));
  return s;
}

// Every pixel returns within 6 m in this room, so OctoMap (no notion of "no return") gets the
// very same end points.
const std::vector<DepthFrame>& depthFrames(int w) {
  static std::vector<DepthFrame> f160, f320;
  std::vector<DepthFrame>& f = w == 160 ? f160 : f320;
  if (f.empty())
    for (int i = 0; i < kFrames; ++i) {
      const Intrinsics K = Intrinsics::fromFov(w, w * 3 / 4, deg2rad(87), deg2rad(58));
      const Vec3 p = kCentre + Vec3(0.2 * std::cos(i), 0.2 * std::sin(i), 0.0);
      f.push_back(test::renderDepth(room(), K, test::cameraPose(p, i * 2 * kPi / kFrames, 0.1), 6.0));
    }
  return f;
}

const std::vector<PointCloudScan>& scans() {
  static std::vector<PointCloudScan> s;
  if (s.empty())
    for (int i = 0; i < kFrames; ++i)
      s.push_back(test::renderScan(room(), kCentre + Vec3(0.1 * i, 0, 0), 20000, -7, 52, 40.0, 0.37 * i));
  return s;
}

struct OctoInput {
  octomap::Pointcloud cloud;
  octomap::point3d origin;
};

std::vector<OctoInput> toOcto(const std::vector<DepthFrame>& frames) {
  std::vector<OctoInput> out;
  for (const DepthFrame& f : frames) {
    OctoInput in;
    const Vec3 o = f.T_world_camera.translation();
    in.origin = octomap::point3d(float(o.x()), float(o.y()), float(o.z()));
    for (int v = 0; v < f.K.height; ++v)
      for (int u = 0; u < f.K.width; ++u) {
        const float d = f.depth[size_t(v) * size_t(f.K.width) + size_t(u)];
        if (!(d > 0)) continue;
        const Vec3 p = f.T_world_camera * Vec3((u - f.K.cx) / f.K.fx * d, (v - f.K.cy) / f.K.fy * d, d);
        in.cloud.push_back(float(p.x()), float(p.y()), float(p.z()));
      }
    out.push_back(std::move(in));
  }
  return out;
}

std::vector<OctoInput> toOcto(const std::vector<PointCloudScan>& ss) {
  std::vector<OctoInput> out;
  for (const PointCloudScan& s : ss) {
    OctoInput in;
    in.origin = octomap::point3d(float(s.origin.x()), float(s.origin.y()), float(s.origin.z()));
    for (const Vec3f& p : s.points) in.cloud.push_back(p.x(), p.y(), p.z());
    out.push_back(std::move(in));
  }
  return out;
}

// OctoMap with the same resolution, hit/miss log-odds (0.85 / -0.4) and clamps (-2 / 3.5).
octomap::OcTree makeOctree() {
  octomap::OcTree t(0.1);
  t.setProbHit(0.7);
  t.setProbMiss(0.4);
  t.setClampingThresMin(0.1192);
  t.setClampingThresMax(0.9707);
  return t;
}

void BM_GridInsertDepth(benchmark::State& state) {
  const auto& frames = depthFrames(int(state.range(0)));
  RollingGrid grid(GridConfig{}, kCentre);
  size_t i = 0;
  double rays = 0, updates = 0;
  for (auto _ : state) {
    const InsertStats st = grid.insertDepth(frames[i++ % kFrames]);
    rays += st.rays;
    updates += st.voxel_updates;
    grid.clearChanges();
  }
  state.counters["rays"] = benchmark::Counter(rays / double(state.iterations()));
  state.counters["updates"] = benchmark::Counter(updates / double(state.iterations()));
  state.SetItemsProcessed(int64_t(state.iterations()) * frames[0].K.width * frames[0].K.height);
}
BENCHMARK(BM_GridInsertDepth)->Arg(160)->Arg(320)->Unit(benchmark::kMillisecond);

void BM_OctomapInsertDepth(benchmark::State& state) {
  const auto input = toOcto(depthFrames(int(state.range(0))));
  const bool discretize = state.range(1) != 0;
  octomap::OcTree tree = makeOctree();
  size_t i = 0;
  for (auto _ : state) {
    const OctoInput& in = input[i++ % kFrames];
    tree.insertPointCloud(in.cloud, in.origin, -1.0, false, discretize);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(input[0].cloud.size()));
}
BENCHMARK(BM_OctomapInsertDepth)
    ->ArgsProduct({{160, 320}, {0, 1}})
    ->ArgNames({"w", "discretize"})
    ->Unit(benchmark::kMillisecond);

void BM_GridInsertScan(benchmark::State& state) {
  const auto& ss = scans();
  RollingGrid grid(GridConfig{}, kCentre);
  size_t i = 0;
  double rays = 0;
  for (auto _ : state) {
    rays += grid.insertScan(ss[i++ % kFrames]).rays;
    grid.clearChanges();
  }
  state.counters["rays"] = benchmark::Counter(rays / double(state.iterations()));
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(ss[0].points.size()));
}
BENCHMARK(BM_GridInsertScan)->Unit(benchmark::kMillisecond);

void BM_OctomapInsertScan(benchmark::State& state) {
  const auto input = toOcto(scans());
  const bool discretize = state.range(0) != 0;
  octomap::OcTree tree = makeOctree();
  size_t i = 0;
  for (auto _ : state) {
    const OctoInput& in = input[i++ % kFrames];
    tree.insertPointCloud(in.cloud, in.origin, -1.0, false, discretize);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(input[0].cloud.size()));
}
BENCHMARK(BM_OctomapInsertScan)->Arg(0)->Arg(1)->ArgName("discretize")->Unit(benchmark::kMillisecond);

// A large hall, so the window is full of known voxels wherever it rolls.
const test::BoxScene& hall() {
  static const test::BoxScene s = test::boxRoom(Vec3(-20, -20, 0), Vec3(20, 20, 3.0));
  return s;
}

// Rolls the window by 1 m (alternately +x and -x) right after a fresh 20k-point scan, so the
// slab that leaves is mostly known and logged; the scan itself is not timed.
void BM_GridRoll1m(benchmark::State& state) {
  const Vec3 a(0.05, 0.05, 1.4), b = a + Vec3(1.0, 0, 0);
  const PointCloudScan sa = test::renderScan(hall(), a, 20000, -7, 52, 40.0);
  const PointCloudScan sb = test::renderScan(hall(), b, 20000, -7, 52, 40.0);
  RollingGrid grid(GridConfig{}, a);
  bool at_a = true;
  double rolled = 0;
  for (auto _ : state) {
    state.PauseTiming();
    grid.insertScan(at_a ? sa : sb);
    grid.clearChanges();
    state.ResumeTiming();
    grid.moveTo(at_a ? b : a);
    at_a = !at_a;
    rolled += double(grid.changes().size());
  }
  state.counters["known_voxels_reset"] = benchmark::Counter(rolled / double(state.iterations()));
}
BENCHMARK(BM_GridRoll1m)->Unit(benchmark::kMicrosecond);

// The Coverage Mask update after one step of a flight (0.5 m roll + a 20k-point scan, not
// timed) through the hall; the mask consumes every change of that step.
void BM_CoverageUpdate(benchmark::State& state) {
  std::vector<Vec3> path;
  std::vector<PointCloudScan> path_scans;
  for (int i = 0; i < 40; ++i) {
    const double t = i * 0.5;
    path.push_back(Vec3(-10 + t, 4.0 * std::sin(0.3 * t), 1.4));
    path_scans.push_back(test::renderScan(hall(), path.back(), 20000, -7, 52, 40.0, 0.1 * i));
  }
  RollingGrid grid(GridConfig{}, path[0]);
  CoverageMask mask(CoverageConfig{}, grid.resolution());
  size_t i = 0;
  double changes = 0;
  for (auto _ : state) {
    state.PauseTiming();
    grid.clearChanges();
    const size_t k = i++ % path.size();
    grid.moveTo(path[k]);
    grid.insertScan(path_scans[k]);
    changes += double(grid.changes().size());
    state.ResumeTiming();
    mask.update(grid);
  }
  state.counters["changes"] = benchmark::Counter(changes / double(state.iterations()));
  state.counters["bytes_per_m2"] = benchmark::Counter(mask.bytesPerExploredSquareMetre());
}
BENCHMARK(BM_CoverageUpdate)->Unit(benchmark::kMicrosecond);

// Line of sight over 1.4 m (the skeleton's ray length) in a mapped room.
void BM_GridLineOfSight(benchmark::State& state) {
  RollingGrid grid(GridConfig{}, kCentre);
  for (const auto& s : scans()) grid.insertScan(s);
  Rng rng(3);
  std::vector<Vec3> ends;
  for (int i = 0; i < 1024; ++i) {
    const Vec3 d(rng.normal(), rng.normal(), rng.normal());
    ends.push_back(kCentre + d.normalized() * 1.4);
  }
  size_t i = 0;
  int clear = 0;
  for (auto _ : state) clear += grid.lineOfSight(kCentre, ends[i++ & 1023], true);
  benchmark::DoNotOptimize(clear);
}
BENCHMARK(BM_GridLineOfSight);

}  // namespace

BENCHMARK_MAIN();
