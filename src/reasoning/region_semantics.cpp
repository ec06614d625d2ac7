// Region summaries from a scene-graph snapshot (see region_semantics.hpp).

#include "ussnav/reasoning/region_semantics.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include <Eigen/Eigenvalues>

namespace ussnav {
namespace {

uint64_t mix(uint64_t h, uint64_t v) {
  h ^= v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
  return h;
}

uint64_t hashString(const std::string& s) {
  uint64_t h = 1469598103934665603ULL;  // FNV-1a
  for (unsigned char c : s) h = (h ^ c) * 1099511628211ULL;
  return h;
}

nlohmann::json vec(const Vec3& v) {
  auto r = [](double x) { return std::round(x * 100.0) / 100.0; };
  return nlohmann::json::array({r(v.x()), r(v.y()), r(v.z())});
}

int nearestNodeIndex(const SceneGraph& g, const Vec3& p) {
  int best = -1;
  double bd = 0.0;
  for (size_t i = 0; i < g.nodes.size(); ++i) {
    const double d = (g.nodes[i].centroid.head<2>() - p.head<2>()).squaredNorm();
    if (best < 0 || d < bd) best = int(i), bd = d;
  }
  return best;
}

}  // namespace

int regionAt(const SceneGraph& g, const Vec3& p) {
  std::map<int, int> region_of;
  for (const SgRegion& r : g.regions)
    for (int n : r.nodes) region_of[n] = r.id;
  const int i = nearestNodeIndex(g, p);
  if (i < 0) return -1;
  const auto it = region_of.find(g.nodes[size_t(i)].id);
  return it == region_of.end() ? -1 : it->second;
}

std::vector<RegionSummary> summarizeRegions(const SceneGraph& g) {
  std::vector<RegionSummary> out;
  std::map<int, size_t> index;  // region id -> out index
  std::map<int, int> region_of;  // node id -> region id
  std::map<int, std::vector<size_t>> members;  // region id -> node indices
  for (const SgRegion& r : g.regions) {
    RegionSummary s;
    s.id = r.id;
    s.centroid = r.centroid;
    s.adjacent = r.adjacent;
    std::vector<Vec3> pts;
    for (int n : r.nodes) {
      region_of[n] = r.id;
      const int k = g.nodeIndex(n);
      if (k >= 0) pts.push_back(g.nodes[size_t(k)].centroid), members[r.id].push_back(size_t(k));
    }
    s.nodes = int(pts.size());
    if (!pts.empty()) {
      s.box_min = s.box_max = pts.front();
      Eigen::Vector2d mean = Eigen::Vector2d::Zero();
      for (const Vec3& p : pts) {
        s.box_min = s.box_min.cwiseMin(p);
        s.box_max = s.box_max.cwiseMax(p);
        mean += p.head<2>();
      }
      mean /= double(pts.size());
      Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
      for (const Vec3& p : pts) cov += (p.head<2>() - mean) * (p.head<2>() - mean).transpose();
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(cov / double(pts.size()));
      const double lo = std::max(es.eigenvalues()(0), 0.0), hi = std::max(es.eigenvalues()(1), 0.0);
      s.elongation = std::sqrt((hi + 0.01) / (lo + 0.01));
    }
    index[r.id] = out.size();
    out.push_back(std::move(s));
  }
  for (const SgObject& o : g.objects) {
    int i = o.node_id >= 0 ? g.nodeIndex(o.node_id) : -1;
    if (i < 0) i = nearestNodeIndex(g, o.centroid);
    if (i < 0) continue;
    const auto rit = region_of.find(g.nodes[size_t(i)].id);
    if (rit == region_of.end()) continue;
    RegionSummary& s = out[index[rit->second]];
    const auto& nodes = members[s.id];
    const bool reached = std::any_of(nodes.begin(), nodes.end(), [&](size_t k) {
      return (g.nodes[k].centroid.head<2>() - o.centroid.head<2>()).norm() <= g.nodes[k].radius + kReachMargin;
    });
    ObjectBrief b{o.id, o.label, o.centroid, o.bbox_max - o.bbox_min, o.n_observations};
    (reached ? s.objects : s.beyond).push_back(b);
  }
  return out;
}

nlohmann::json toJson(const RegionSummary& r) {
  nlohmann::json objs = nlohmann::json::array();
  for (const ObjectBrief& o : r.objects)
    objs.push_back({{"id", o.id}, {"label", o.label}, {"position", vec(o.position)}, {"size", vec(o.size)},
                    {"observations", o.n_observations}});
  const Vec3 ext = r.box_max - r.box_min;
  return {{"region", r.id},
          {"centroid", vec(r.centroid)},
          {"extent_m", vec(ext)},
          {"nodes", r.nodes},
          {"elongation", std::round(r.elongation * 10.0) / 10.0},
          {"adjacent_regions", r.adjacent},
          {"objects", objs}};
}

nlohmann::json toJson(const RegionSemantics& s) {
  return {{"label", s.label}, {"description", s.description}, {"confidence", s.confidence}, {"source", s.source}};
}

uint64_t contentKey(const RegionSummary& r) {
  std::vector<std::string> labels;
  for (const ObjectBrief& o : r.objects) labels.push_back(o.label);
  std::sort(labels.begin(), labels.end());
  uint64_t h = 0;
  for (const auto& l : labels) h = mix(h, hashString(l));
  // Node count in ~20 % buckets: the shape changed enough to look again.
  const int bucket = r.nodes <= 0 ? 0 : int(std::floor(std::log(double(r.nodes)) / std::log(1.2)));
  return mix(h, uint64_t(bucket));
}

}  // namespace ussnav
