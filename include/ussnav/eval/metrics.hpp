#pragma once
// Episode metrics of the evaluation protocol (DESIGN.md): success rate and
// SPL = S * L* / max(L, L*), with L the flown path length and L* the shortest collision-free
// path from the start to the nearest success pose, both in metres.

#include <string>
#include <vector>

namespace ussnav {

// SPL of one episode. Returns 0 when not successful; throws std::invalid_argument when a
// length is negative or not finite, or L* is 0 for a successful episode that flew nowhere.
double splOf(bool success, double path_length, double shortest_path);

struct EpisodeOutcome {
  bool success = false;
  double path_length_m = 0.0;
  double shortest_path_m = 0.0;
  double time_s = 0.0;
  int collisions = 0;
};

struct SplitSummary {
  int episodes = 0;
  double sr = 0.0;              // fraction of successful episodes
  double spl = 0.0;             // mean SPL
  double path_length_m = 0.0;   // mean
  double time_s = 0.0;          // mean
  double collisions = 0.0;      // mean per episode
};

SplitSummary summarize(const std::vector<EpisodeOutcome>& episodes);

}  // namespace ussnav
