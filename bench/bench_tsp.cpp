// TSP and search tour over viewpoints at 10, 30 and 100 points (issue: exploration speed).
#include <benchmark/benchmark.h>

#include "ussnav/core/random.hpp"
#include "ussnav/core/types.hpp"
#include "ussnav/exploration/tsp.hpp"

using namespace ussnav;

static CostMatrix costs(int n) {
  Rng rng(42);
  std::vector<Vec2> p(n);
  for (auto& q : p) q = Vec2(rng.uniform(0, 30), rng.uniform(0, 30));
  CostMatrix c(n, std::vector<double>(n, 0.0));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) c[i][j] = (p[i] - p[j]).norm();
  return c;
}

static void BM_OpenTsp(benchmark::State& state) {
  const CostMatrix c = costs(int(state.range(0)) + 1);
  for (auto _ : state) benchmark::DoNotOptimize(solveOpenTsp(c));
}
BENCHMARK(BM_OpenTsp)->Arg(10)->Arg(30)->Arg(100)->Unit(benchmark::kMillisecond);

// The search tour (gain-weighted arrival times) of the full planner, gains 10..400.
static void BM_SearchTour(benchmark::State& state) {
  const int n = int(state.range(0)) + 1;
  const CostMatrix c = costs(n);
  Rng rng(7);
  std::vector<double> w(size_t(n), 0.0);
  for (int i = 1; i < n; ++i) w[size_t(i)] = rng.uniform(10, 400);
  for (auto _ : state) benchmark::DoNotOptimize(solveSearchTour(c, w));
}
BENCHMARK(BM_SearchTour)->Arg(10)->Arg(30)->Arg(100)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
