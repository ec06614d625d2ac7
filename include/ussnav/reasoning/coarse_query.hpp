#pragma once
// The coarse decision (paper Sec. V-B): "which region should the UAV search next?". A
// CoarseQuery holds what the reasoner may know, all from the scene graph and the planner: the
// instruction, the current region, the visit history, every region's label, description,
// adjacency and objects, the frontiers (count and gain) and travel cost per region, and the
// room-adjacency prior. toJson() is the documented schema (docs/reasoning.md) sent to the LLM.
// A reply is {"region": ID, "reason": "..."}; parseCoarseReply() validates it: malformed JSON,
// an unknown region id, or a region without frontiers are faults, and the caller falls back to
// the global-utility choice and counts the fault.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "ussnav/reasoning/instruction.hpp"

namespace ussnav {

struct RegionState {
  int id = -1;
  std::string label, description;   // "" until labelled
  std::vector<int> adjacent;
  std::vector<std::string> objects; // labels
  std::vector<std::string> beyond;  // labels of objects seen from it in space it does not reach
                                    // (RegionSummary::beyond: the room next door)
  int frontiers = 0;                // exploration targets in it
  double gain = 0.0;                // their summed gain
  double frontier_gain = 0.0;       // of that, frontiers' (they look beyond the region; the rest
                                    // is known-but-unseen space inside it)
  double cost_s = -1.0;             // to its cheapest target, s; -1 = no target
  double distance_m = -1.0;         // path length to it, m; -1 = no target
  double best_utility = 0.0;        // max over its targets of gain / cost_s (builtin only; not sent to an LLM)
  int visits = 0;                   // times the UAV entered it
  bool corridor_shaped = false;     // corridorShaped(summary) (builtin only; not sent to an LLM)
};

struct CoarseQuery {
  Instruction instruction;
  int current_region = -1;
  int last_choice = -1;             // the region chosen at the previous decision, -1 none
  std::vector<int> history;         // regions entered, oldest first (last 20)
  std::vector<RegionState> regions; // ascending id; the candidates have frontiers > 0
  struct Adjacent {
    std::string a, b;
    double weight = 0.0;
  };
  std::vector<Adjacent> room_adjacency;  // the prior (room_adjacency.tsv)
  const RegionState* find(int id) const;
};

struct CoarseDecision {
  int region = -1;
  std::string reason;
  std::string fault;                // "" = valid; else malformed | unknown_region | no_frontiers | llm_<status>
  double latency_ms = 0.0;
  bool global_utility = false;      // chance-based reasoners: the semantics did not tell the
                                    // regions apart, so `region` is the global-utility choice
  // Chance-based reasoners: every region weighed, for debugging (USSNAV_DEBUG_EPISODE prints them).
  struct Score {
    int region = -1;
    double chance = 0.0;
    double value = 0.0;  // what the choice maximised
  };
  std::vector<Score> scores;
};

nlohmann::json toJson(const CoarseQuery& q);
// Validates a reasoner's reply text (a JSON object, possibly inside ``` fences or after prose).
CoarseDecision parseCoarseReply(const std::string& text, const CoarseQuery& q);
// The first {...} JSON object in `text` (code fences and surrounding prose ignored); throws
// nlohmann::json::exception when there is none.
nlohmann::json extractJsonObject(const std::string& text);

}  // namespace ussnav
