// Region partitioning: incremental update (local Leiden + consolidation + id matching) against
// Leiden on the whole graph every frame, on room-grid graphs of about 200, 1000 and 3000 nodes.
// Before the timings it prints, for each size, a replay of an exploration (the graph revealed
// in BFS order, 20 nodes per update): time per update, how often an old node's region id
// changes, and purity / ARI against the rooms at the end; and a resolution sweep.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <unordered_map>

#include "ussnav/core/timing.hpp"
#include "ussnav/regions/consolidation.hpp"
#include "ussnav/regions/leiden.hpp"
#include "ussnav/regions/partition_metrics.hpp"
#include "ussnav/regions/region_partitioner.hpp"
#include "ussnav/regions/room_graph.hpp"

using namespace ussnav;

namespace {

constexpr int kBatch = 20;

RoomGraph buildingOf(int target_nodes) {
  RoomGridSpec s;
  s.rooms_x = s.rooms_y = target_nodes <= 200 ? 3 : target_nodes <= 1000 ? 7 : 12;
  s.seed = static_cast<uint64_t>(target_nodes);
  return makeRoomGrid(s);
}

std::vector<int> truthOf(const RoomGraph& rg, const std::vector<int>& ids) {
  std::unordered_map<int, int> room;
  for (size_t i = 0; i < rg.graph.node_ids.size(); ++i) room[rg.graph.node_ids[i]] = rg.room[i];
  std::vector<int> out;
  for (int id : ids) out.push_back(room.at(id));
  return out;
}

struct Replay {
  std::vector<double> ms;
  long old_nodes = 0, id_changes = 0;
  double purity = 0, ari = 0, quality = 0;
  int regions = 0;
};

// Grows the graph batch by batch; `partition(view, new_ids)` returns node id -> label.
template <class F>
Replay replay(const RoomGraph& rg, double resolution, F partition) {
  Replay out;
  const std::vector<int> order = explorationOrder(rg.graph, rg.graph.node_ids.front());
  std::unordered_map<int, int> prev;
  std::vector<int> shown;
  for (size_t done = 0; done < order.size();) {
    const size_t next = std::min(order.size(), done + kBatch);
    std::vector<int> fresh(order.begin() + static_cast<long>(done),
                           order.begin() + static_cast<long>(next));
    shown.insert(shown.end(), fresh.begin(), fresh.end());
    const WeightedGraphView view = inducedView(rg.graph, shown);
    Stopwatch w;
    const std::unordered_map<int, int> now = partition(view, fresh);
    out.ms.push_back(w.ms());
    for (const auto& [id, label] : prev) {
      ++out.old_nodes;
      out.id_changes += now.at(id) != label;
    }
    prev = now;
    done = next;
  }
  std::vector<int> ids, labels;
  for (const auto& [id, l] : prev) ids.push_back(id);
  std::sort(ids.begin(), ids.end());
  for (int id : ids) labels.push_back(prev.at(id));
  const std::vector<int> truth = truthOf(rg, ids);
  out.purity = purity(labels, truth);
  out.ari = adjustedRandIndex(labels, truth);
  const IndexedGraph g = indexGraph(rg.graph);
  out.quality = cpmQuality(g, labels, resolution);
  out.regions = compactLabels(labels);
  return out;
}

Replay replayPartitioner(const RoomGraph& rg, RegionsConfig cfg) {
  RegionPartitioner p(cfg);
  return replay(rg, cfg.resolution, [&](const WeightedGraphView& v, const std::vector<int>& f) {
    p.update(v, f);
    std::unordered_map<int, int> m;
    for (int id : v.node_ids) m[id] = p.regionOf(id);
    return m;
  });
}

// Leiden's own labels, no consolidation, no matching: what "re-cluster every frame" gives.
Replay replayRawLeiden(const RoomGraph& rg, const RegionsConfig& cfg) {
  return replay(rg, cfg.resolution, [&](const WeightedGraphView& v, const std::vector<int>&) {
    const IndexedGraph g = indexGraph(v);
    const auto r = leiden(g.size(), g.edges, {cfg.resolution, cfg.beta, cfg.iterations,
                                              static_cast<uint64_t>(cfg.seed)});
    std::unordered_map<int, int> m;
    for (int i = 0; i < g.size(); ++i) m[g.ids[i]] = r.membership[i];
    return m;
  });
}

void printReplays() {
  std::printf("Exploration replay, %d new nodes per update (room grids, rooms of 3..6 x 3..6)\n",
              kBatch);
  std::printf("%-6s %-22s %8s %8s %8s %10s %8s %6s %8s %8s\n", "nodes", "mode", "updates",
              "med_ms", "p95_ms", "id_change", "regions", "rooms", "purity", "ARI");
  for (int size : {200, 1000, 3000}) {
    const RoomGraph rg = buildingOf(size);
    RegionsConfig inc, cold, full, two;
    cold.warm_start = false;
    two.iterations = 2;
    full.incremental = false;
    const std::pair<const char*, Replay> rows[] = {
        {"incremental", replayPartitioner(rg, inc)},
        {"incremental cold local", replayPartitioner(rg, cold)},
        {"incremental 2 iter", replayPartitioner(rg, two)},
        {"full+consolidate+match", replayPartitioner(rg, full)},
        {"full raw leiden", replayRawLeiden(rg, inc)}};
    for (const auto& [name, r] : rows)
      std::printf("%-6zu %-22s %8zu %8.3f %8.3f %9.2f%% %8d %6d %8.3f %8.3f\n",
                  rg.graph.node_ids.size(), name, r.ms.size(), percentile(r.ms, 0.5),
                  percentile(r.ms, 0.95), 100.0 * double(r.id_changes) / double(r.old_nodes),
                  r.regions, rg.rooms, r.purity, r.ari);
  }
}

void printResolutionSweep(const RoomGridSpec& spec) {
  const RoomGraph rg = makeRoomGrid(spec);
  const IndexedGraph g = indexGraph(rg.graph);
  const std::vector<int> truth = truthOf(rg, g.ids);
  std::printf("\nResolution sweep, whole graph: %d nodes, %d rooms of %d..%d nodes, doors of "
              "1..%d edges\n", g.size(), rg.rooms, spec.min_side * spec.min_side,
              spec.max_side * spec.max_side, spec.door_edges_max);
  std::printf("%-10s %8s %8s %8s %8s %8s | %8s %8s %8s\n", "resolution", "leiden_k", "min_sz",
              "med_sz", "max_sz", "ARI", "consol_k", "purity", "ARI");
  for (double res : {0.005, 0.01, 0.02, 0.05, 0.1, 0.2}) {
    std::vector<int> labels = leiden(g.size(), g.edges, {res, 0.01, -1, 1}).membership;
    const int k = compactLabels(labels);
    std::vector<double> sizes(k, 0.0);
    for (int l : labels) sizes[l] += 1;
    const double ari_raw = adjustedRandIndex(labels, truth);
    consolidate(g, labels, {});
    const int kc = compactLabels(labels);
    std::printf("%-10.3f %8d %8.0f %8.0f %8.0f %8.3f | %8d %8.3f %8.3f\n", res, k,
                percentile(sizes, 0.0), percentile(sizes, 0.5), percentile(sizes, 1.0), ari_raw,
                kc, purity(labels, truth), adjustedRandIndex(labels, truth));
  }
  std::printf("\n");
}

// One update in steady state: the last batch of an exploration is removed (untimed) and added
// back (timed), so the partitioner's memory is warm as in a running system.
void runLastBatch(benchmark::State& state, bool incremental) {
  const RoomGraph rg = buildingOf(static_cast<int>(state.range(0)));
  const std::vector<int> order = explorationOrder(rg.graph, 0);
  const std::vector<int> before(order.begin(), order.end() - kBatch);
  const std::vector<int> fresh(order.end() - kBatch, order.end());
  RegionsConfig cfg;
  cfg.incremental = incremental;
  RegionPartitioner p(cfg);
  const WeightedGraphView without = inducedView(rg.graph, before);
  const WeightedGraphView with = inducedView(rg.graph, order);
  p.update(without, before);
  int subgraph = 0;
  for (auto _ : state) {
    subgraph = p.update(with, fresh).subgraph_nodes;
    state.PauseTiming();
    p.update(without, {});
    state.ResumeTiming();
  }
  state.counters["nodes"] = static_cast<double>(order.size());
  state.counters["leiden_nodes"] = subgraph;
}

void BM_IncrementalUpdate(benchmark::State& s) { runLastBatch(s, true); }
void BM_FullLeidenUpdate(benchmark::State& s) { runLastBatch(s, false); }

// Bookkeeping floor: validating and indexing the view, which every update pays.
void BM_IndexGraph(benchmark::State& state) {
  const RoomGraph rg = buildingOf(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(indexGraph(rg.graph).size());
}

}  // namespace

BENCHMARK(BM_IncrementalUpdate)->Arg(200)->Arg(1000)->Arg(3000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FullLeidenUpdate)->Arg(200)->Arg(1000)->Arg(3000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_IndexGraph)->Arg(200)->Arg(1000)->Arg(3000)->Unit(benchmark::kMillisecond);

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  printReplays();
  RoomGridSpec spec;  // the 1000-node building of the replay
  spec.rooms_x = spec.rooms_y = 7;
  spec.seed = 1000;
  printResolutionSweep(spec);
  spec.min_side = 2;  // harder: rooms of 4..64 nodes, doors up to 3 edges wide
  spec.max_side = 8;
  spec.door_edges_max = 3;
  printResolutionSweep(spec);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
