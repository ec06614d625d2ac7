#include "ussnav/regions/region_partitioner.hpp"

#include <algorithm>
#include <limits>
#include <numeric>
#include <queue>
#include <set>

#include "ussnav/core/error.hpp"
#include "ussnav/core/timing.hpp"
#include "ussnav/regions/assignment.hpp"
#include "ussnav/regions/consolidation.hpp"
#include "ussnav/regions/leiden.hpp"

namespace ussnav {

namespace {

// Old regions whose surroundings changed: regions that lost nodes, regions of listed nodes
// that already had one, regions holding an old neighbour of a new node, and regions with an
// edge added, removed or re-weighted since the last update.
std::set<int> touchedRegions(const IndexedGraph& g, const std::vector<int>& old_region,
                             const std::vector<char>& listed,
                             const std::unordered_map<int, int>& region_of, bool nodes_removed,
                             const std::vector<IndexedEdge>& prev_edges) {
  std::set<int> touched;
  if (nodes_removed)
    for (const auto& [node, region] : region_of)
      if (g.indexOf(node) < 0) touched.insert(region);
  for (int i = 0; i < g.size(); ++i) {
    if (old_region[i] >= 0) {
      if (listed[i]) touched.insert(old_region[i]);
      continue;
    }
    for (int a = g.offsets[i]; a < g.offsets[i + 1]; ++a)
      if (old_region[g.nbrs[a]] >= 0) touched.insert(old_region[g.nbrs[a]]);
  }
  // Both edge lists are sorted by (id, id); a linear merge finds the differences.
  auto touchEnds = [&](int id_u, int id_v) {
    for (int id : {id_u, id_v}) {
      const int i = g.indexOf(id);
      if (i >= 0 && old_region[i] >= 0) touched.insert(old_region[i]);
    }
  };
  size_t a = 0, b = 0;
  while (a < g.edges.size() || b < prev_edges.size()) {
    constexpr int kEnd = std::numeric_limits<int>::max();
    std::pair<int, int> ka{kEnd, kEnd}, kb{kEnd, kEnd};
    if (a < g.edges.size()) ka = {g.ids[g.edges[a].u], g.ids[g.edges[a].v]};
    if (b < prev_edges.size()) kb = {prev_edges[b].u, prev_edges[b].v};
    if (ka == kb) {
      if (g.edges[a].w != prev_edges[b].w) touchEnds(ka.first, ka.second);
      ++a, ++b;
    } else if (ka < kb) {
      touchEnds(ka.first, ka.second), ++a;
    } else {
      touchEnds(kb.first, kb.second), ++b;
    }
  }
  return touched;
}

std::vector<int> sortedVector(const std::set<int>& s) { return {s.begin(), s.end()}; }

// Region of each satellite: that of the partitioned node nearest along the edges (centroid
// distances; ties by dense index). A satellite no edge path joins to a partitioned node takes
// the region of the Euclidean-nearest one.
std::vector<int> satelliteRegions(const IndexedGraph& g, const std::vector<char>& satellite,
                                  std::vector<int> now) {
  const int n = g.size();
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  for (int i = 0; i < n; ++i)
    if (!satellite[i]) {
      dist[i] = 0.0;
      open.emplace(0.0, i);
    }
  while (!open.empty()) {
    const auto [d, i] = open.top();
    open.pop();
    if (d > dist[i]) continue;
    for (int a = g.offsets[i]; a < g.offsets[i + 1]; ++a) {
      const int j = g.nbrs[a];
      const double dj = d + (g.centroids[i] - g.centroids[j]).norm();
      if (dj < dist[j] || (dj == dist[j] && satellite[j] && now[i] < now[j])) {
        dist[j] = dj;
        now[j] = now[i];
        open.emplace(dj, j);
      }
    }
  }
  for (int i = 0; i < n; ++i) {
    if (!satellite[i] || now[i] >= 0) continue;
    double best = std::numeric_limits<double>::infinity();
    for (int j = 0; j < n; ++j)
      if (!satellite[j] && (g.centroids[i] - g.centroids[j]).squaredNorm() < best) {
        best = (g.centroids[i] - g.centroids[j]).squaredNorm();
        now[i] = now[j];
      }
  }
  return now;
}

}  // namespace

RegionPartitioner::RegionPartitioner(const RegionsConfig& cfg) : cfg_(cfg) {
  if (cfg_.iterations == 0)
    throw InputError("regions config", "regions.iterations",
                     "0 would never optimise; use -1 (until stable) or a positive count");
}

int RegionPartitioner::regionOf(int node) const {
  if (auto it = region_of_.find(node); it != region_of_.end()) return it->second;
  auto it = satellite_region_.find(node);
  return it == satellite_region_.end() ? -1 : it->second;
}

void RegionPartitioner::partition(const IndexedGraph& g, const std::vector<char>& listed,
                                  RegionUpdate& report) {
  const int n = g.size();
  std::vector<int> old_region(n, -1);
  size_t known = 0;
  for (int i = 0; i < n; ++i) {
    const auto it = region_of_.find(g.ids[i]);
    old_region[i] = it == region_of_.end() ? -1 : it->second;
    known += old_region[i] >= 0;
  }
  const bool any_new = known < static_cast<size_t>(n);
  const bool nodes_removed = known < region_of_.size();

  // Which nodes Leiden sees: all of them on the first update or without incrementality,
  // else the new nodes plus every node of the touched regions and of their neighbours.
  std::vector<int> keep;
  std::set<int> candidates;
  if (!cfg_.incremental || regions_.empty()) {
    keep.resize(n);
    for (int i = 0; i < n; ++i) keep[i] = i;
    for (const auto& [id, r] : regions_) candidates.insert(id);
  } else {
    const std::set<int> touched =
        touchedRegions(g, old_region, listed, region_of_, nodes_removed, prev_edges_);
    std::vector<char> is_touched(next_id_, 0), is_candidate(next_id_, 0);
    for (int r : touched) is_touched[r] = is_candidate[r] = 1;
    candidates = touched;
    for (int i = 0; i < n; ++i) {
      if (old_region[i] < 0 || !is_touched[old_region[i]]) continue;
      for (int a = g.offsets[i]; a < g.offsets[i + 1]; ++a) {
        const int r = old_region[g.nbrs[a]];
        if (r >= 0 && !is_candidate[r]) {
          is_candidate[r] = 1;
          candidates.insert(r);
        }
      }
    }
    if (any_new || !candidates.empty())
      for (int i = 0; i < n; ++i)
        if (old_region[i] < 0 || is_candidate[old_region[i]]) keep.push_back(i);
  }

  std::vector<int> now = old_region;  // region id per dense index after this update
  if (!keep.empty()) {
    const bool whole = static_cast<int>(keep.size()) == n;
    const IndexedGraph sub_storage = whole ? IndexedGraph{} : inducedSubgraph(g, keep);
    const IndexedGraph& sub = whole ? g : sub_storage;
    const int k = sub.size();

    // Warm start: old nodes start in their region, new nodes alone.
    const std::vector<int> cand = sortedVector(candidates);
    std::vector<int> initial(k);
    int next_label = static_cast<int>(cand.size());
    for (int i = 0; i < k; ++i) {
      const int r = old_region[keep[i]];
      const auto it = std::lower_bound(cand.begin(), cand.end(), r);
      initial[i] = (r >= 0 && it != cand.end() && *it == r) ? static_cast<int>(it - cand.begin())
                                                            : next_label++;
    }
    const bool warm = cfg_.warm_start && cfg_.incremental;
    const LeidenParams lp{cfg_.resolution, cfg_.beta, cfg_.iterations,
                          static_cast<uint64_t>(cfg_.seed)};
    std::vector<int> labels = leiden(k, sub.edges, lp, warm ? &initial : nullptr).membership;
    report.leiden_communities = compactLabels(labels);
    report.merges = consolidate(
        sub, labels,
        {cfg_.merge_shared_border_nodes, cfg_.border_edge_min_weight, cfg_.min_region_nodes, cfg_.merge_min_opening_m});
    const int communities = compactLabels(labels);

    // Stable ids: optimal assignment of communities to the old regions by shared old nodes.
    std::vector<std::vector<double>> overlap(communities, std::vector<double>(cand.size(), 0.0));
    for (int i = 0; i < k; ++i)
      if (old_region[keep[i]] >= 0 && initial[i] < static_cast<int>(cand.size()))
        overlap[labels[i]][initial[i]] += 1.0;
    const std::vector<int> match = maxScoreAssignment(overlap);
    std::vector<int> region_id(communities);
    for (int c = 0; c < communities; ++c)
      region_id[c] = (match[c] >= 0 && overlap[c][match[c]] > 0.0) ? cand[match[c]] : next_id_++;
    for (int i = 0; i < k; ++i) now[keep[i]] = region_id[labels[i]];
    report.subgraph_nodes = k;
    report.subgraph_regions = static_cast<int>(cand.size());
  }
  if (nodes_removed)
    for (auto it = region_of_.begin(); it != region_of_.end();)
      it = g.indexOf(it->first) < 0 ? region_of_.erase(it) : std::next(it);
  for (int i : keep) region_of_[g.ids[i]] = now[i];

  prev_edges_.clear();
  prev_edges_.reserve(g.edges.size());
  for (const auto& e : g.edges) prev_edges_.push_back({g.ids[e.u], g.ids[e.v], e.w});
}

RegionUpdate RegionPartitioner::update(const WeightedGraphView& view,
                                       const std::vector<int>& new_node_ids) {
  Stopwatch watch;
  RegionUpdate report;
  const IndexedGraph g = indexGraph(view, "region update graph");
  const int n = g.size();

  std::vector<char> listed(n, 0);
  for (size_t k = 0; k < new_node_ids.size(); ++k) {
    const int i = g.indexOf(new_node_ids[k]);
    if (i < 0)
      throw InputError("region update", "new_node_ids[" + std::to_string(k) + "]",
                       "node id " + std::to_string(new_node_ids[k]) + " is not in the graph");
    listed[i] = 1;
  }
  std::vector<char> satellite(n, 0);
  for (size_t k = 0; k < view.satellites.size(); ++k) {
    const int i = g.indexOf(view.satellites[k]);
    if (i < 0)
      throw InputError("region update", "satellites[" + std::to_string(k) + "]",
                       "node id " + std::to_string(view.satellites[k]) + " is not in the graph");
    satellite[i] = 1;
  }
  std::vector<int> core;  // dense indices of the partitioned nodes
  for (int i = 0; i < n; ++i)
    if (!satellite[i]) core.push_back(i);
  if (core.empty() && n > 0) {  // nothing to hang satellites on: partition them all
    std::fill(satellite.begin(), satellite.end(), 0);
    core.resize(n);
    std::iota(core.begin(), core.end(), 0);
  }

  std::vector<int> now(n, -1);  // region id per dense index after this update
  if (static_cast<int>(core.size()) == n) {
    partition(g, listed, report);
    satellite_region_.clear();
    for (int i = 0; i < n; ++i) now[i] = region_of_.at(g.ids[i]);
  } else {
    const IndexedGraph cg = inducedSubgraph(g, core);
    std::vector<char> core_listed(core.size());
    for (size_t c = 0; c < core.size(); ++c) core_listed[c] = listed[core[c]];
    partition(cg, core_listed, report);
    for (int i : core) now[i] = region_of_.at(g.ids[i]);
    now = satelliteRegions(g, satellite, std::move(now));
    satellite_region_.clear();
    for (int i = 0; i < n; ++i)
      if (satellite[i]) satellite_region_[g.ids[i]] = now[i];
  }

  // Rebuild the region table (O(N + E), flat arrays) and diff it against the previous one.
  std::vector<int> slot(next_id_, -1);
  std::vector<Region> table;
  for (int i = 0; i < n; ++i) {
    int& s = slot[now[i]];
    if (s < 0) {
      s = static_cast<int>(table.size());
      table.emplace_back().id = now[i];
    }
    table[s].nodes.push_back(g.ids[i]);  // ascending, as g.ids is
    table[s].centroid += g.centroids[i];
  }
  std::vector<std::pair<int, int>> links;
  for (const auto& e : g.edges) {
    const int a = slot[now[e.u]], b = slot[now[e.v]];
    if (a != b) links.emplace_back(std::min(a, b), std::max(a, b));
  }
  std::sort(links.begin(), links.end());
  links.erase(std::unique(links.begin(), links.end()), links.end());
  for (const auto& [a, b] : links) {
    table[a].adjacent.push_back(table[b].id);
    table[b].adjacent.push_back(table[a].id);
  }
  std::map<int, Region> fresh;
  for (auto& r : table) {
    r.centroid /= static_cast<double>(r.nodes.size());
    std::sort(r.adjacent.begin(), r.adjacent.end());
    auto old = regions_.find(r.id);
    if (old == regions_.end())
      report.created.push_back(r.id);
    else if (old->second.nodes != r.nodes)
      report.changed.push_back(r.id);
    const int id = r.id;
    fresh.emplace(id, std::move(r));
  }
  std::sort(report.created.begin(), report.created.end());
  std::sort(report.changed.begin(), report.changed.end());
  for (const auto& [id, r] : regions_)
    if (!fresh.count(id)) report.removed.push_back(id);
  regions_ = std::move(fresh);

  report.ms = watch.ms();
  return report;
}

}  // namespace ussnav
