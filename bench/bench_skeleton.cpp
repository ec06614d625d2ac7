// Skeleton benchmarks (paper Sec. IV-A): the pieces of one expansion (Qhull on 50 points,
// ExpandNewPolyhedron = 50 rays + hull, Boundary Surfaces), one full expansion step of the graph
// (pop, FindNewExpandSeed, expand, UpdateTopology), a whole 3 x 2-room floor built in a single
// update (the worst frame: everything observed at once), and the frames of a tour through that
// floor with a sensor emulation and an 8 x 8 x 4 m rolling window (typical frames; the counters
// give the median and p95 frame time). Scenes are the hand-made DenseGrids of tests/support.
// Run: build/bench_skeleton --benchmark_min_time=0.2

#include <benchmark/benchmark.h>

#include <memory>
#include <vector>

#include "support/skeleton_scenes.hpp"
#include "ussnav/core/timing.hpp"
#include "ussnav/skeleton/boundary_surface.hpp"
#include "ussnav/skeleton/connectivity_graph.hpp"
#include "ussnav/skeleton/expansion.hpp"
#include "ussnav/skeleton/polyhedron.hpp"
#include "ussnav/skeleton/sphere_sampler.hpp"

using namespace ussnav;

namespace {

const Vec3 kStart(2.0, 2.0, 1.2);

const test::FloorScene& floorScene() {
  static const test::FloorScene s = test::floorGrid(3, 2);
  return s;
}

// The tour's frames: the map as the UAV saw it so far, inside the window around it.
struct TourFrame {
  Vec3 uav;
  std::shared_ptr<test::DenseGrid> map;
};
const std::vector<TourFrame>& tourFrames() {
  static std::vector<TourFrame> frames;
  if (!frames.empty()) return frames;
  const test::DenseGrid& truth = floorScene().grid;
  test::DenseGrid known(truth.bounds(), truth.resolution(), VoxelState::Unknown);
  const double p = 4.2;  // room pitch
  const std::vector<Vec3> tour = test::samplePolyline(
      {kStart, Vec3(3.5, 1.65, 1.2), Vec3(4.7, 1.65, 1.2), Vec3(6.2, 2.0, 1.2), Vec3(7.7, 1.65, 1.2),
       Vec3(8.9, 1.65, 1.2), Vec3(10.4, 2.0, 1.2), Vec3(2 * p + 2.85, 3.5, 1.2), Vec3(2 * p + 2.85, 4.7, 1.2),
       Vec3(10.4, p + 2.0, 1.2), Vec3(p + 2.0, p + 2.0, 1.2), Vec3(2.0, p + 2.0, 1.2)},
      0.2);  // 2 m/s at 10 Hz
  for (const Vec3& uav : tour) {
    test::observe(truth, known, uav, 5.0, 20000);  // a Mid-360-sized scan
    Aabb w;
    w.min = uav - Vec3(4, 4, 2);
    w.max = uav + Vec3(4, 4, 2);
    known.setWindow(w);
    frames.push_back({uav, std::make_shared<test::DenseGrid>(known)});
  }
  return frames;
}

void BM_ConvexHull50(benchmark::State& state) {
  std::vector<Vec3> pts = fibonacciSphere(50);
  for (size_t i = 0; i < pts.size(); ++i) pts[i] *= 1.0 + 0.3 * std::sin(double(i));
  for (auto _ : state) benchmark::DoNotOptimize(convexHull(pts));
}
BENCHMARK(BM_ConvexHull50);

void BM_ExpandNewPolyhedron(benchmark::State& state) {
  const SkeletonConfig cfg;
  const std::vector<Vec3> dirs = fibonacciSphere(cfg.sphere_samples);
  // Near a door: a mix of free, floor, ceiling and wall rays.
  const Vec3 seed(3.3, 1.6, 1.1);
  for (auto _ : state) benchmark::DoNotOptimize(expandNewPolyhedron(floorScene().grid, seed, dirs, cfg));
}
BENCHMARK(BM_ExpandNewPolyhedron);

void BM_FindBoundarySurfaces(benchmark::State& state) {
  const SkeletonConfig cfg;
  const Polyhedron p = expandNewPolyhedron(floorScene().grid, Vec3(3.3, 1.6, 1.1),
                                           fibonacciSphere(cfg.sphere_samples), cfg);
  for (auto _ : state)
    benchmark::DoNotOptimize(findBoundarySurfaces(p, cfg.max_cluster_faces, cfg.max_normal_divergence_deg));
}
BENCHMARK(BM_FindBoundarySurfaces);

// One iteration of Algorithm 1 per update (max_expansions_per_frame = 1), on a graph that grows
// over the floor; rebuilt (untimed) when the floor is covered.
void BM_ExpansionStep(benchmark::State& state) {
  SkeletonConfig cfg;
  cfg.max_expansions_per_frame = 1;
  auto g = std::make_unique<ConnectivityGraph>(cfg);
  int64_t expansions = 0;
  double t = 0;
  for (auto _ : state) {
    const GraphUpdateStats st = g->update(floorScene().grid, kStart, t += 0.1);
    expansions += st.expansions;
    if (st.expansions == 0) {
      state.PauseTiming();
      g = std::make_unique<ConnectivityGraph>(cfg);
      state.ResumeTiming();
    }
  }
  state.counters["expansions_per_step"] = double(expansions) / double(state.iterations());
}
BENCHMARK(BM_ExpansionStep)->Unit(benchmark::kMicrosecond);

// The whole floor (about 60 polyhedra) in one update: every voxel observed at once.
void BM_FullFloorInOneUpdate(benchmark::State& state) {
  size_t nodes = 0, edges = 0;
  for (auto _ : state) {
    ConnectivityGraph g;
    g.update(floorScene().grid, kStart, 0.0);
    nodes = g.size();
    edges = g.edges().size();
  }
  state.counters["nodes"] = double(nodes);
  state.counters["edges"] = double(edges);
  state.counters["us_per_node"] = benchmark::Counter(double(nodes) * double(state.iterations()),
                                                     benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_FullFloorInOneUpdate)->Unit(benchmark::kMillisecond);

// Typical frames: the tour, one update per frame, on a fresh graph each iteration.
void BM_TourFrames(benchmark::State& state) {
  const std::vector<TourFrame>& frames = tourFrames();
  StageTimes times;
  size_t nodes = 0;
  for (auto _ : state) {
    ConnectivityGraph g;
    double t = 0;
    for (const TourFrame& f : frames) times.add("frame", g.update(*f.map, f.uav, t += 0.1).ms);
    nodes = g.size();
  }
  state.counters["frames"] = double(frames.size());
  state.counters["nodes"] = double(nodes);
  state.counters["frame_ms_median"] = times.median("frame");
  state.counters["frame_ms_p95"] = times.percentile("frame", 0.95);
  state.counters["frame_ms_max"] = times.percentile("frame", 1.0);
}
BENCHMARK(BM_TourFrames)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
