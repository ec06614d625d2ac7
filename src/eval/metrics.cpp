#include "ussnav/eval/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ussnav {

double splOf(bool success, double L, double Ls) {
  if (!std::isfinite(L) || !std::isfinite(Ls) || L < 0 || Ls < 0)
    throw std::invalid_argument("SPL: path lengths must be finite and >= 0");
  if (!success) return 0.0;
  const double denom = std::max(L, Ls);
  if (denom <= 0.0) return 1.0;  // started at a success pose: perfect by definition
  return Ls / denom;
}

SplitSummary summarize(const std::vector<EpisodeOutcome>& eps) {
  SplitSummary s;
  s.episodes = int(eps.size());
  if (eps.empty()) return s;
  for (const auto& e : eps) {
    s.sr += e.success ? 1.0 : 0.0;
    s.spl += splOf(e.success, e.path_length_m, e.shortest_path_m);
    s.path_length_m += e.path_length_m;
    s.time_s += e.time_s;
    s.collisions += e.collisions;
  }
  const double n = double(eps.size());
  s.sr /= n;
  s.spl /= n;
  s.path_length_m /= n;
  s.time_s /= n;
  s.collisions /= n;
  return s;
}

}  // namespace ussnav
