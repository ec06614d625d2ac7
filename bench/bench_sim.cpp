// Simulator speed: building the ground-truth grid of a ~340 m^2 floor, rendering one depth
// frame (160x120, 320x240) and one 20k-point LiDAR scan from it.
#include <benchmark/benchmark.h>

#include "ussnav/sim/ground_truth.hpp"
#include "ussnav/sim/sensors.hpp"

using namespace ussnav;

// A 5 x 3 grid of 5 x 4.5 m rooms with doors between neighbours (~340 m^2).
static World gridWorld() {
  World w;
  w.name = "bench_grid";
  const int nx = 5, ny = 3;
  const double sx = 5.0, sy = 4.5, h = 2.8;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      Room r;
      r.id = j * nx + i + 1;
      r.type = "office";
      r.polygon = {{i * sx, j * sy}, {(i + 1) * sx, j * sy}, {(i + 1) * sx, (j + 1) * sy}, {i * sx, (j + 1) * sy}};
      r.ceiling_z = h;
      w.rooms.push_back(r);
    }
  for (int i = 0; i <= nx; ++i) {
    Wall wl;
    wl.a = Vec2(i * sx, 0);
    wl.b = Vec2(i * sx, ny * sy);
    wl.z1 = h;
    if (i > 0 && i < nx)
      for (int j = 0; j < ny; ++j) wl.openings.push_back({j * sy + 1.5, j * sy + 2.5, 0, 2.1});
    w.walls.push_back(wl);
  }
  for (int j = 0; j <= ny; ++j) {
    Wall wl;
    wl.a = Vec2(0, j * sy);
    wl.b = Vec2(nx * sx, j * sy);
    wl.z1 = h;
    if (j > 0 && j < ny)
      for (int i = 0; i < nx; ++i) wl.openings.push_back({i * sx + 2.0, i * sx + 3.0, 0, 2.1});
    w.walls.push_back(wl);
  }
  return w;
}

static void BM_BuildGroundTruth(benchmark::State& state) {
  const World w = gridWorld();
  for (auto _ : state) benchmark::DoNotOptimize(GroundTruthGrid(w, 0.05));
}
BENCHMARK(BM_BuildGroundTruth)->Unit(benchmark::kMillisecond);

static void BM_RenderDepth(benchmark::State& state) {
  const World w = gridWorld();
  const GroundTruthGrid gt(w, 0.05);
  CameraConfig cc;
  cc.width = int(state.range(0));
  cc.height = int(state.range(1));
  DepthCamera cam(cc);
  double yaw = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(cam.render(gt, Pose{Vec3(7.5, 6.7, 1.2), yaw}));
    yaw += 0.1;
  }
}
BENCHMARK(BM_RenderDepth)->Args({160, 120})->Args({320, 240})->Unit(benchmark::kMillisecond);

static void BM_LidarScan(benchmark::State& state) {
  const World w = gridWorld();
  const GroundTruthGrid gt(w, 0.05);
  LidarConfig lc;
  lc.points_per_scan = int(state.range(0));
  Lidar lidar(lc);
  for (auto _ : state) benchmark::DoNotOptimize(lidar.scan(gt, Pose{Vec3(7.5, 6.7, 1.2), 0}));
}
BENCHMARK(BM_LidarScan)->Arg(20000)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
