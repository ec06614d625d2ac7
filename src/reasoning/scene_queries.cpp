// goto / ask on a saved scene graph (see scene_queries.hpp).

#include "ussnav/reasoning/scene_queries.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <queue>
#include <set>
#include <sstream>

#include "english.hpp"
#include "ussnav/reasoning/builtin_reasoner.hpp"
#include "ussnav/skeleton/polyhedron.hpp"

namespace ussnav {
namespace {

std::string fmt(const Vec3& p) {
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(1);
  s << "(" << p.x() << ", " << p.y() << ")";
  return s.str();
}

std::string regionName(int id, const std::map<int, RegionSemantics>& sem) {
  const auto it = sem.find(id);
  const std::string l = it == sem.end() || it->second.label.empty() ? "unidentified area" : it->second.label;
  return "region " + std::to_string(id) + " (" + l + ")";
}

int nearestNode(const SceneGraph& g, const Vec3& p, const std::set<int>* among = nullptr) {
  int best = -1;
  double bd = 0.0;
  for (size_t i = 0; i < g.nodes.size(); ++i) {
    if (among && !among->count(g.nodes[i].id)) continue;
    const double d = (g.nodes[i].centroid - p).squaredNorm();
    if (best < 0 || d < bd) best = int(i), bd = d;
  }
  return best;
}

}  // namespace

std::map<int, RegionSemantics> graphSemantics(const SceneGraph& g, Reasoner* reasoner) {
  std::map<int, RegionSemantics> out;
  const auto summaries = summarizeRegions(g);
  for (const RegionSummary& s : summaries) {
    const SgRegion& r = g.regions[size_t(g.regionIndex(s.id))];
    if (!r.label.empty() || !r.description.empty()) {
      RegionSemantics sem;
      sem.label = r.label;
      sem.description = r.description;
      sem.confidence = r.label.empty() ? 0.0 : 0.8;
      sem.source = "graph";
      out[s.id] = sem;
    } else if (reasoner) {
      out[s.id] = reasoner->labelRegion(s);
    }
  }
  return out;
}

std::vector<std::string> graphVocabulary(const SceneGraph& g) {
  std::set<std::string> v;
  for (const SgObject& o : g.objects) v.insert(o.label);
  return {v.begin(), v.end()};
}

RegionPick pickRegionForRequest(const SceneGraph& g, const Instruction& ins, const std::map<int, RegionSemantics>& sem,
                                const CommonsensePriors& priors, double goal_similarity) {
  RegionPick best;
  const auto summaries = summarizeRegions(g);
  BuiltinReasoner builtin(std::shared_ptr<const CommonsensePriors>(&priors, [](const CommonsensePriors*) {}));
  CoarseQuery q;
  q.instruction = ins;
  const int want_room = priors.roomIndex(ins.room.empty() ? ins.room_hint : ins.room);
  for (const RegionSummary& s : summaries) {
    RegionPick p;
    p.region = s.id;
    const auto it = sem.find(s.id);
    const bool room_ok = want_room >= 0 && it != sem.end() && priors.roomIndex(it->second.label) == want_room;
    // A matching object in the region.
    double obj_best = 0.0;
    std::string obj_label;
    for (const auto* list : {&s.objects, &s.beyond})  // beyond: seen from it, reached through it
      for (const ObjectBrief& o : *list)
        for (const auto& t : ins.targets) {
          const double c = priors.encoder().similarity(o.label, t);
          if (c >= goal_similarity && c > obj_best) obj_best = c, p.object = o.id, p.goal = o.position, obj_label = o.label;
        }
    if (p.object >= 0 && (ins.room.empty() || room_ok)) {
      p.score = 1.0 + (room_ok ? 0.5 : 0.0);
      p.reason = "holds object " + std::to_string(p.object) + " (" + obj_label + ") matching \"" + ins.text + "\"";
    } else {
      RegionState st;
      st.id = s.id;
      for (const ObjectBrief& o : s.objects) st.objects.push_back(o.label);
      for (const ObjectBrief& o : s.beyond) st.beyond.push_back(o.label);
      st.corridor_shaped = corridorShaped(s);
      p.score = ins.targets.empty() ? 0.0 : 0.5 * builtin.targetChance(q, st);
      if (room_ok) p.score += 0.6;
      p.object = -1;
      p.reason = room_ok ? "its label names the room asked for" : "commonsense chance of holding it";
    }
    if (p.object < 0) {
      const int n = nearestNode(g, s.centroid, nullptr);
      std::set<int> mine(g.regions[size_t(g.regionIndex(s.id))].nodes.begin(), g.regions[size_t(g.regionIndex(s.id))].nodes.end());
      const int k = nearestNode(g, s.centroid, &mine);
      p.goal = g.nodes[size_t(k >= 0 ? k : n)].centroid;
    }
    if (p.score > best.score || best.region < 0) best = p;
  }
  if (best.region >= 0) best.reason = regionName(best.region, sem) + ": " + best.reason;
  return best;
}

std::optional<Vec3> portalBetween(const SgNode& a, const SgNode& b, double z) {
  const Polyhedron pa = buildPolyhedron(a.hull, std::vector<VertexKind>(a.hull.size(), VertexKind::Free));
  const Polyhedron pb = buildPolyhedron(b.hull, std::vector<VertexKind>(b.hull.size(), VertexKind::Free));
  if (!pa.valid() || !pb.valid()) return std::nullopt;
  // Where they overlap; else, within 0.2 m of both: polyhedra linked as overlapping may only
  // touch (faces a voxel apart).
  for (const double slack : {1e-9, 0.2}) {
    const Vec3 lo = pa.bounds.min.cwiseMax(pb.bounds.min) - Vec3::Constant(slack);
    const Vec3 hi = pa.bounds.max.cwiseMin(pb.bounds.max) + Vec3::Constant(slack);
    if (lo.x() > hi.x() || lo.y() > hi.y() || z < lo.z() || z > hi.z()) continue;
    if ((hi.x() - lo.x()) * (hi.y() - lo.y()) > 400.0) return std::nullopt;  // bounded work: 40,000 samples
    constexpr double kStep = 0.1;
    Vec3 sum = Vec3::Zero();
    int n = 0;
    for (double x = lo.x(); x <= hi.x(); x += kStep)
      for (double y = lo.y(); y <= hi.y(); y += kStep)
        if (const Vec3 p(x, y, z); pa.contains(p, slack) && pb.contains(p, slack)) sum += p, ++n;
    if (n > 0) return Vec3(sum / n);
  }
  return std::nullopt;
}

std::optional<std::vector<Vec3>> routeOnSceneGraph(const SceneGraph& g, const Vec3& from, const Vec3& to) {
  const int a = nearestNode(g, from), b = nearestNode(g, to);
  if (a < 0 || b < 0) return std::nullopt;
  std::vector<std::vector<std::pair<int, double>>> adj(g.nodes.size());
  for (const SgEdge& e : g.edges) {
    const int i = g.nodeIndex(e.a), j = g.nodeIndex(e.b);
    if (i < 0 || j < 0 || e.blocked) continue;
    const double d = (g.nodes[size_t(i)].centroid - g.nodes[size_t(j)].centroid).norm();
    adj[size_t(i)].push_back({j, d});
    adj[size_t(j)].push_back({i, d});
  }
  std::vector<double> dist(g.nodes.size(), 1e300);
  std::vector<int> prev(g.nodes.size(), -1);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> pq;
  dist[size_t(a)] = 0.0;
  pq.push({0.0, a});
  while (!pq.empty()) {
    const auto [d, u] = pq.top();
    pq.pop();
    if (d > dist[size_t(u)]) continue;
    if (u == b) break;
    for (const auto& [v, w] : adj[size_t(u)])
      if (d + w < dist[size_t(v)]) dist[size_t(v)] = d + w, prev[size_t(v)] = u, pq.push({d + w, v});
  }
  if (dist[size_t(b)] >= 1e300) return std::nullopt;
  std::vector<Vec3> path{to};
  for (int u = b; u >= 0; u = prev[size_t(u)]) {
    const SgNode& n = g.nodes[size_t(u)];
    if (const int v = prev[size_t(u)]; v >= 0) {
      // Between two overlapping polyhedra, through their overlap when the straight stretch
      // between the centres passes more than 0.2 m from it (it cuts a door's corner).
      const SgNode& m = g.nodes[size_t(v)];
      const Vec3 c = n.centroid, d = m.centroid - c;
      if (const auto p = portalBetween(n, m, 0.5 * (c.z() + m.centroid.z()))) {
        const double t = d.squaredNorm() > 0.0 ? std::clamp((*p - c).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
        path.push_back(n.centroid);
        if ((c + t * d - *p).norm() > 0.2) path.push_back(*p);
        continue;
      }
    }
    path.push_back(n.centroid);
  }
  path.push_back(from);
  std::reverse(path.begin(), path.end());
  return path;
}

std::string answerQuestion(const SceneGraph& g, const std::string& question, const std::optional<Vec3>& at,
                           const std::map<int, RegionSemantics>& sem, const CommonsensePriors& priors) {
  const auto summaries = summarizeRegions(g);
  std::vector<std::string> words = instructionWords(question);
  auto has = [&](std::initializer_list<const char*> ws) {
    for (const char* w : ws)
      if (std::find(words.begin(), words.end(), w) != words.end()) return true;
    return false;
  };
  std::ostringstream out;
  auto describe = [&](const RegionSummary& s, const std::string& lead) {
    const auto it = sem.find(s.id);
    out << lead << (lead.empty() ? english::capitalised(regionName(s.id, sem)) : regionName(s.id, sem)) << ". ";
    if (it != sem.end() && !it->second.description.empty()) out << it->second.description << " ";
    if (!s.objects.empty()) {
      out << "Objects here: ";
      for (size_t i = 0; i < s.objects.size(); ++i) out << (i ? ", " : "") << s.objects[i].label << " at " << fmt(s.objects[i].position);
      out << ". ";
    }
    if (!s.beyond.empty()) {
      out << "Seen from here, beyond it: ";
      for (size_t i = 0; i < s.beyond.size(); ++i) out << (i ? ", " : "") << s.beyond[i].label << " at " << fmt(s.beyond[i].position);
      out << ". ";
    }
    if (!s.adjacent.empty()) {
      out << "It connects to ";
      for (size_t i = 0; i < s.adjacent.size(); ++i) out << (i ? ", " : "") << regionName(s.adjacent[i], sem);
      out << ".";
    }
  };
  // The question read as an instruction: what it looks for, and a room it names ("in the kitchen").
  std::optional<Instruction> ins;
  try {
    ins = interpretInstruction(question, priors, graphVocabulary(g));
  } catch (const std::exception&) {  // nothing to look for ("describe the current area")
  }
  const std::string room_named = ins ? ins->room : "";
  const bool about_layout = has({"layout", "rooms", "regions", "building", "map", "overview"});
  // "List all objects", "what objects are there?": every label with its count, most first.
  if (has({"objects", "things", "list", "inventory", "everything"}) && !has({"here", "current", "layout", "map"}) &&
      room_named.empty()) {
    std::map<std::string, int> count;
    for (const SgObject& o : g.objects) ++count[o.label];
    std::vector<std::pair<int, std::string>> by;
    for (const auto& [l, c] : count) by.push_back({c, l});
    std::stable_sort(by.begin(), by.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    out << "The map holds " << g.objects.size() << (g.objects.size() == 1 ? " object" : " objects") << " in "
        << summaries.size() << (summaries.size() == 1 ? " region" : " regions") << (by.empty() ? "." : ": ");
    for (size_t i = 0; i < by.size(); ++i) {
      const std::string& l = by[i].second;
      out << (i ? ", " : "") << english::counted(by[i].first, l);
    }
    if (!by.empty()) out << ".";
    return out.str();
  }
  // "Where is / is there / find X": objects matching X. A request that is no question ("I'm
  // tired", "I want to sit down") is answered the same way, with the objects seen that serve it.
  const bool request = ins && ins->how == "functional" && !has({"what", "which", "describe"});
  if ((has({"where", "there", "find", "any", "how"}) || request) && !has({"layout", "rooms", "regions", "am"}) && ins &&
      !ins->targets.empty() && ins->how != "literal") {
    int n = 0;
    const auto matches = [&](const std::string& label) {
      for (const auto& t : ins->targets)
        if (priors.encoder().similarity(label, t) >= 0.85) return true;
      return ins->how == "functional" && servesRequest(*ins, label);
    };
    for (const RegionSummary& s : summaries)
      for (const auto* list : {&s.objects, &s.beyond})
        for (const ObjectBrief& o : *list)
          if (matches(o.label))
            out << (n++ ? " " : "") << english::capitalised(english::withArticle(o.label)) << " (object " << o.id << ") is at " << fmt(o.position)
                << (list == &s.objects ? " in " : ", seen from ") << regionName(s.id, sem) << ".";
    if (n == 0) out << "No " << ins->targets.front() << " has been seen yet.";
    return out.str();
  }
  // "What is in the kitchen?", "Describe the bedroom": the regions labelled with the room named.
  if (!about_layout) {
    if (const int want = priors.roomIndex(room_named); want >= 0) {
      int n = 0;
      for (const RegionSummary& s : summaries)
        if (const auto it = sem.find(s.id); it != sem.end() && priors.roomIndex(it->second.label) == want) {
          if (n++) out << " ";
          describe(s, "");
        }
      if (n == 0) out << "No region is labelled " << room_named << " yet; the map has " << summaries.size() << " regions.";
      return out.str();
    }
  }
  if (about_layout || !at) {
    out << "The map has " << summaries.size() << " regions and " << g.objects.size() << " objects.";
    for (const RegionSummary& s : summaries) {
      out << " " << english::capitalised(regionName(s.id, sem)) << ": " << s.objects.size() << (s.objects.size() == 1 ? " object" : " objects");
      if (!s.adjacent.empty()) {
        out << ", next to ";
        for (size_t i = 0; i < s.adjacent.size(); ++i) out << (i ? ", " : "") << regionName(s.adjacent[i], sem);
      }
      out << ".";
    }
    return out.str();
  }
  const int r = regionAt(g, *at);
  for (const RegionSummary& s : summaries)
    if (s.id == r) describe(s, "You are in ");
  if (out.str().empty()) out << "The point " << fmt(*at) << " is in no mapped region.";
  return out.str();
}

}  // namespace ussnav
