// Coarse query schema and reply validation (see coarse_query.hpp).

#include "ussnav/reasoning/coarse_query.hpp"

#include <cmath>

namespace ussnav {

const RegionState* CoarseQuery::find(int id) const {
  for (const RegionState& r : regions)
    if (r.id == id) return &r;
  return nullptr;
}

nlohmann::json toJson(const CoarseQuery& q) {
  auto r2 = [](double x) { return std::round(x * 100.0) / 100.0; };
  nlohmann::json regions = nlohmann::json::array();
  for (const RegionState& r : q.regions)
    regions.push_back({{"id", r.id},
                       {"label", r.label},
                       {"description", r.description},
                       {"adjacent", r.adjacent},
                       {"objects", r.objects},
                       {"seen_beyond", r.beyond},
                       {"frontiers", r.frontiers},
                       {"frontier_gain", r2(r.frontier_gain)},
                       {"unseen_gain", r2(r.gain - r.frontier_gain)},
                       {"distance_m", r2(r.distance_m)},
                       {"visits", r.visits}});
  nlohmann::json prior = nlohmann::json::array();
  for (const auto& a : q.room_adjacency) prior.push_back({a.a, a.b, a.weight});
  return {{"instruction", q.instruction.text},
          {"targets", q.instruction.targets},
          {"room_constraint", q.instruction.room},
          {"current_region", q.current_region},
          {"last_choice", q.last_choice},
          {"visit_history", q.history},
          {"regions", regions},
          {"room_adjacency_prior", prior}};
}

nlohmann::json extractJsonObject(const std::string& text) {
  // Try every '{' from the left until a balanced object parses.
  for (size_t start = text.find('{'); start != std::string::npos; start = text.find('{', start + 1)) {
    int depth = 0;
    bool in_str = false, esc = false;
    for (size_t i = start; i < text.size(); ++i) {
      const char c = text[i];
      if (in_str) {
        if (esc) esc = false;
        else if (c == '\\') esc = true;
        else if (c == '"') in_str = false;
        continue;
      }
      if (c == '"') in_str = true;
      else if (c == '{') ++depth;
      else if (c == '}' && --depth == 0) {
        auto j = nlohmann::json::parse(text.substr(start, i - start + 1), nullptr, false);
        if (!j.is_discarded() && j.is_object()) return j;
        break;
      }
    }
  }
  return nlohmann::json::parse("no JSON object");  // throws parse_error
}

CoarseDecision parseCoarseReply(const std::string& text, const CoarseQuery& q) {
  CoarseDecision d;
  nlohmann::json j;
  try {
    j = extractJsonObject(text);
  } catch (const nlohmann::json::exception&) {
    d.fault = "malformed";
    d.reason = "reply is not a JSON object";
    return d;
  }
  const auto it = j.find("region");
  if (it == j.end() || !(it->is_number_integer() || (it->is_string() && !it->get<std::string>().empty()))) {
    d.fault = "malformed";
    d.reason = "reply has no integer \"region\"";
    return d;
  }
  int id = -1;
  if (it->is_number_integer()) {
    id = it->get<int>();
  } else {
    try {
      size_t used = 0;
      const std::string s = it->get<std::string>();
      id = std::stoi(s, &used);
      if (used != s.size()) throw std::invalid_argument(s);
    } catch (const std::exception&) {
      d.fault = "malformed";
      d.reason = "\"region\" is not an integer";
      return d;
    }
  }
  if (auto r = j.find("reason"); r != j.end() && r->is_string()) d.reason = r->get<std::string>().substr(0, 300);
  const RegionState* r = q.find(id);
  d.region = id;
  if (!r) {
    d.fault = "unknown_region";
    d.reason = "region " + std::to_string(id) + " does not exist";
  } else if (r->frontiers <= 0) {
    d.fault = "no_frontiers";
    d.reason = "region " + std::to_string(id) + " has nothing left to explore";
  }
  return d;
}

}  // namespace ussnav
