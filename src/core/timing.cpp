#include "ussnav/core/timing.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

namespace ussnav {

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const double pos = q * double(v.size() - 1);
  const size_t lo = size_t(pos);
  const size_t hi = std::min(lo + 1, v.size() - 1);
  return v[lo] + (pos - double(lo)) * (v[hi] - v[lo]);
}

double StageTimes::percentile(const std::string& stage, double q) const {
  auto it = samples_.find(stage);
  return it == samples_.end() ? 0.0 : ussnav::percentile(it->second, q);
}

double StageTimes::median(const std::string& stage) const { return percentile(stage, 0.5); }

nlohmann::json StageTimes::summary() const {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [k, v] : samples_)
    j[k] = {{"median", ussnav::percentile(v, 0.5)}, {"p95", ussnav::percentile(v, 0.95)},
            {"count", v.size()}};
  return j;
}

}  // namespace ussnav
