#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "ussnav/core/error.hpp"
#include "ussnav/exploration/graph_costs.hpp"
#include "ussnav/exploration/planner.hpp"
#include "ussnav/exploration/tsp.hpp"

namespace ussnav {

const char* toString(TargetKind k) { return k == TargetKind::Frontier ? "frontier" : "unseen"; }

namespace {

double yawChange(double from, double to) { return std::abs(std::remainder(to - from, 2.0 * std::numbers::pi)); }

double moveCost(const PlanInput& in, double dist, double yaw_from, double yaw_to) {
  const double v = std::max(1e-3, in.uav_cfg->max_speed);
  const double w = std::max(1e-3, in.uav_cfg->max_yaw_rate_deg * std::numbers::pi / 180.0);
  return std::max(dist / v, in.episode_cfg->yaw_weight * yawChange(yaw_from, yaw_to) / w);
}

double utilityOf(const ExplorationTarget& t, const TargetCost& c) { return t.gain / std::max(c.cost_s, 0.1); }

// Open tour from the UAV over `ids` (indices into targets), each at its best viewpoint. Pairwise
// costs use one graph Dijkstra per target. `search`: minimise the gain-weighted arrival times
// (solveSearchTour) instead of the distance. `first` (an index into ids, -1 none): the tour
// starts there and orders the rest from its viewpoint.
std::vector<int> tourOver(const PlanInput& in, const std::vector<TargetCost>& costs, const std::vector<int>& ids,
                          bool search = false, int first = -1) {
  const auto& T = *in.targets;
  const size_t n = ids.size() + 1;
  CostMatrix m(n, std::vector<double>(n, 0.0));
  for (size_t i = 0; i < ids.size(); ++i) m[0][i + 1] = costs[size_t(ids[i])].cost_s;
  for (size_t i = 0; i < ids.size(); ++i) {
    const Viewpoint& vi = T[size_t(ids[i])].viewpoints[size_t(costs[size_t(ids[i])].viewpoint)];
    const GraphDistances gd(*in.graph, *in.map, vi.position);
    for (size_t j = 0; j < ids.size(); ++j) {
      if (i == j) continue;
      const Viewpoint& vj = T[size_t(ids[j])].viewpoints[size_t(costs[size_t(ids[j])].viewpoint)];
      double d = gd.toPoint(vj.position);
      if (!std::isfinite(d)) d = 1e3 + (vj.position - vi.position).norm();
      m[i + 1][j + 1] = moveCost(in, d, vi.yaw, vj.yaw);
    }
  }
  for (auto& row : m)
    for (double& c : row)
      if (!std::isfinite(c)) c = 1e6;
  // Nodes of the problem solved: the start (the UAV, or `first`), then the others.
  std::vector<size_t> node{first >= 0 ? size_t(first) + 1 : 0};
  for (size_t i = 1; i < n; ++i)
    if (int(i) - 1 != first) node.push_back(i);
  CostMatrix sub(node.size(), std::vector<double>(node.size(), 0.0));
  std::vector<double> w(node.size(), 0.0);
  for (size_t a = 0; a < node.size(); ++a) {
    if (a > 0) w[a] = std::max(0.0, T[size_t(ids[node[a] - 1])].gain);
    for (size_t b = 0; b < node.size(); ++b) sub[a][b] = a == b ? 0.0 : m[node[a]][node[b]];
  }
  const TspResult r = search ? solveSearchTour(sub, w) : solveOpenTsp(sub);
  std::vector<int> tour;
  if (first >= 0) tour.push_back(ids[size_t(first)]);
  for (int k : r.order) tour.push_back(ids[node[size_t(k)] - 1]);
  return tour;
}

class FrontierPlanner final : public ExplorationPlanner {
 public:
  std::string name() const override { return "frontier"; }
  PlanChoice choose(const PlanInput& in) override {
    PlanChoice c;
    const auto costs = targetCosts(in);
    double best = -1.0;
    for (size_t i = 0; i < costs.size(); ++i) {
      if (!std::isfinite(costs[i].cost_s)) continue;
      const double u = utilityOf((*in.targets)[i], costs[i]);
      if (u > best) best = u, c.target = int(i);
    }
    if (c.target >= 0) {
      c.viewpoint = costs[size_t(c.target)].viewpoint;
      c.cost_s = costs[size_t(c.target)].cost_s;
      c.region = (*in.targets)[size_t(c.target)].region;
      c.tour = {c.target};
      c.note = "best gain/cost " + std::to_string(best);
    }
    return c;
  }
};

class TspPlanner final : public ExplorationPlanner {
 public:
  std::string name() const override { return "tsp"; }
  PlanChoice choose(const PlanInput& in) override {
    PlanChoice c;
    const auto costs = targetCosts(in);
    std::vector<int> ids;
    for (size_t i = 0; i < costs.size(); ++i)
      if (std::isfinite(costs[i].cost_s)) ids.push_back(int(i));
    if (ids.empty()) return c;
    c.tour = tourOver(in, costs, ids);
    c.target = c.tour.front();
    c.viewpoint = costs[size_t(c.target)].viewpoint;
    c.cost_s = costs[size_t(c.target)].cost_s;
    c.region = (*in.targets)[size_t(c.target)].region;
    c.note = "tour over " + std::to_string(ids.size()) + " targets";
    return c;
  }
};

class FullPlanner final : public ExplorationPlanner {
 public:
  explicit FullPlanner(RegionChooser coarse) : coarse_(std::move(coarse)) {}
  std::string name() const override { return "full"; }
  PlanChoice choose(const PlanInput& in) override {
    PlanChoice c;
    const auto costs = targetCosts(in);
    std::map<int, RegionCandidate> by_region;
    for (size_t i = 0; i < costs.size(); ++i) {
      if (!std::isfinite(costs[i].cost_s)) continue;
      const ExplorationTarget& t = (*in.targets)[i];
      RegionCandidate& rc = by_region[t.region];
      if (rc.targets == 0) rc.region = t.region, rc.cost_s = costs[i].cost_s;
      ++rc.targets;
      rc.gain += t.gain;
      if (t.kind == TargetKind::Frontier) rc.frontier_gain += t.gain;
      rc.cost_s = std::min(rc.cost_s, costs[i].cost_s);
      rc.best_utility = std::max(rc.best_utility, utilityOf(t, costs[i]));
    }
    if (by_region.empty()) return c;
    std::vector<RegionCandidate> cands;
    for (const auto& [id, rc] : by_region) cands.push_back(rc);
    int region = -1;
    std::string why;
    if (coarse_) {
      region = coarse_(in, cands);
      why = "coarse chooser";
    }
    if (!by_region.count(region)) {
      // Default coarse level: stay in the committed region while it has targets, else the region
      // holding the best target (gain / cost).
      if (by_region.count(committed_)) {
        region = committed_;
        why = "committed region";
      } else {
        double best = -1.0;
        for (const RegionCandidate& rc : cands)
          if (rc.best_utility > best) best = rc.best_utility, region = rc.region;
        why = "best target utility";
      }
    }
    committed_ = region;
    // Fine level: the first stop is the region's best gain / cost target (the frontier
    // planner's criterion, inside the region); the tour orders the rest from there.
    std::vector<int> ids;
    int first = -1;
    double best_u = -1.0;
    for (size_t i = 0; i < costs.size(); ++i)
      if (std::isfinite(costs[i].cost_s) && (*in.targets)[i].region == region) {
        const double u = utilityOf((*in.targets)[i], costs[i]);
        if (u > best_u) best_u = u, first = int(ids.size());
        ids.push_back(int(i));
      }
    c.tour = tourOver(in, costs, ids, in.episode_cfg->tour == "search", first);
    c.target = c.tour.front();
    c.viewpoint = costs[size_t(c.target)].viewpoint;
    c.cost_s = costs[size_t(c.target)].cost_s;
    c.region = region;
    c.note = why + ": region " + std::to_string(region) + ", " + std::to_string(ids.size()) + " targets";
    return c;
  }

 private:
  RegionChooser coarse_;
  int committed_ = -2;
};

}  // namespace

std::vector<TargetCost> targetCosts(const PlanInput& in) {
  std::vector<TargetCost> out(in.targets->size());
  const GraphDistances gd(*in.graph, *in.map, in.uav.position);
  const double yaw = in.uav.yaw;
  for (size_t i = 0; i < in.targets->size(); ++i) {
    const ExplorationTarget& t = (*in.targets)[i];
    TargetCost best;
    best.cost_s = GraphDistances::kInf;
    for (size_t k = 0; k < t.viewpoints.size(); ++k) {
      int node = -1;
      const double d = gd.toPoint(t.viewpoints[k].position, &node);
      const double c = std::isfinite(d) ? moveCost(in, d, yaw, t.viewpoints[k].yaw) : GraphDistances::kInf;
      if (c < best.cost_s) best = TargetCost{c, int(k), node, d};
    }
    out[i] = best;
  }
  return out;
}

std::unique_ptr<ExplorationPlanner> makePlanner(const std::string& name, RegionChooser coarse) {
  if (name == "frontier") return std::make_unique<FrontierPlanner>();
  if (name == "tsp") return std::make_unique<TspPlanner>();
  if (name == "full") return std::make_unique<FullPlanner>(std::move(coarse));
  throw InputError("planner", "name", "unknown planner '" + name + "' (expected frontier, tsp or full)");
}

const std::vector<std::string>& plannerNames() {
  static const std::vector<std::string> names{"frontier", "tsp", "full"};
  return names;
}

}  // namespace ussnav
