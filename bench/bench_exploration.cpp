// Exploration benchmarks: FrontierFinder::update per frame (incremental frontier cells,
// re-clustering, viewpoints of new clusters) on a furnished 12 x 6 m room mapped by a
// 160x120 depth camera or a 20,000-point LiDAR along a 6 m flight; the same with a forced
// whole-window rescan; viewpoints of one frontier. Insertion and the Coverage Mask update are
// outside the timed region. Arg of the depth benchmark: min_cluster_cells.
// Run: build/bench_exploration --benchmark_min_time=0.2

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <vector>

#include "support/mapping_scenes.hpp"
#include "ussnav/exploration/frontier.hpp"

using namespace ussnav;

namespace {

constexpr int kFrames = 40;

const test::BoxScene& room() {
  static const test::BoxScene s = test::boxRoom(Vec3(-3.03, -2.87, 0.0), Vec3(9.03, 2.91, 2.73));
  return s;
}

Vec3 flight(int i) { return Vec3(0.15 * i, 0.5 * std::sin(0.3 * i), 1.2); }
double heading(int i) { return 0.45 * i; }

const std::vector<DepthFrame>& depthFrames() {
  static std::vector<DepthFrame> f;
  if (f.empty())
    for (int i = 0; i < kFrames; ++i)
      f.push_back(test::renderDepth(room(), Intrinsics::fromFov(160, 120, deg2rad(87), deg2rad(58)),
                                    test::cameraPose(flight(i), heading(i)), 5.0));
  return f;
}

const std::vector<PointCloudScan>& scans() {
  static std::vector<PointCloudScan> s;
  if (s.empty())
    for (int i = 0; i < kFrames; ++i) s.push_back(test::renderScan(room(), flight(i), 20000, -7, 52, 40.0, 0.37 * i));
  return s;
}

struct Rig {
  RollingGrid grid{GridConfig{}, flight(0)};
  CoverageMask gcm{CoverageConfig{}, 0.1};
  FrontierFinder finder;
  explicit Rig(const ExplorationConfig& cfg) : finder(cfg) {}
};

// One iteration = one frame of the flight; the rig restarts (untimed) after the last frame.
template <bool kLidar>
void runFlight(benchmark::State& state, const ExplorationConfig& cfg, bool force_full) {
  if (kLidar) scans();
  else depthFrames();
  std::unique_ptr<Rig> rig;
  int i = kFrames;
  double frontiers = 0, cells = 0, scanned = 0, viewpoints = 0, added = 0;
  int64_t n = 0;
  for (auto _ : state) {
    state.PauseTiming();
    if (i == kFrames) {
      rig = std::make_unique<Rig>(cfg);
      i = 0;
    }
    rig->grid.moveTo(flight(i));
    if (kLidar) rig->grid.insertScan(scans()[size_t(i)]);
    else rig->grid.insertDepth(depthFrames()[size_t(i)]);
    rig->gcm.update(rig->grid);
    if (force_full) rig->finder = FrontierFinder(cfg);
    state.ResumeTiming();
    const FrontierUpdate up = rig->finder.update(rig->grid, rig->gcm, 0, i);
    state.PauseTiming();
    rig->grid.clearChanges();
    ++i;
    ++n;
    frontiers += double(rig->finder.frontiers().size());
    cells += double(rig->finder.cellCount());
    scanned += up.voxels_scanned;
    added += double(up.added.size());
    for (const Frontier& f : rig->finder.frontiers()) viewpoints += double(f.viewpoints.size());
    state.ResumeTiming();
  }
  const double k = 1.0 / double(std::max<int64_t>(n, 1));
  state.counters["frontiers"] = frontiers * k;
  state.counters["cells"] = cells * k;
  state.counters["scanned"] = scanned * k;
  state.counters["new_per_frame"] = added * k;
  state.counters["viewpoints"] = viewpoints * k;
}

void BM_FrontierUpdateDepth(benchmark::State& state) {
  ExplorationConfig cfg;
  cfg.min_cluster_cells = int(state.range(0));
  runFlight<false>(state, cfg, false);
}
BENCHMARK(BM_FrontierUpdateDepth)->Arg(1)->Arg(10)->Arg(20)->Arg(50)->Arg(100)->Unit(benchmark::kMillisecond);

void BM_FrontierUpdateLidar(benchmark::State& state) { runFlight<true>(state, ExplorationConfig{}, false); }
BENCHMARK(BM_FrontierUpdateLidar)->Unit(benchmark::kMillisecond);

void BM_FrontierFullRescanDepth(benchmark::State& state) { runFlight<false>(state, ExplorationConfig{}, true); }
BENCHMARK(BM_FrontierFullRescanDepth)->Unit(benchmark::kMillisecond);

// Viewpoints (72 positions, gain by ray casting) for each frontier after 10 depth frames.
void BM_Viewpoints(benchmark::State& state) {
  const ExplorationConfig cfg;
  Rig rig(cfg);
  for (int i = 0; i < 10; ++i) {
    rig.grid.moveTo(flight(i));
    rig.grid.insertDepth(depthFrames()[size_t(i)]);
    rig.gcm.update(rig.grid);
    rig.finder.update(rig.grid, rig.gcm, 0, i);
    rig.grid.clearChanges();
  }
  double cells = 0;
  for (const Frontier& f : rig.finder.frontiers()) cells += double(f.cells.size());
  for (auto _ : state)
    for (const Frontier& f : rig.finder.frontiers())
      benchmark::DoNotOptimize(computeViewpoints(rig.grid, f.cells, f.centroid, cfg));
  state.counters["frontiers"] = double(rig.finder.frontiers().size());
  state.counters["cells"] = cells;
}
BENCHMARK(BM_Viewpoints)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
