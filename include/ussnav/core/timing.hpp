#pragma once
// Per-stage wall-time bookkeeping: every stage of the frame pipeline reports its milliseconds,
// and results carry median and p95 per stage (the `stage_ms` section of stats/result JSON).

#include <chrono>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace ussnav {

class StageTimes {
 public:
  void add(const std::string& stage, double ms) { samples_[stage].push_back(ms); }
  // {stage: {"median": x, "p95": y, "count": n}}
  nlohmann::json summary() const;
  double median(const std::string& stage) const;
  double percentile(const std::string& stage, double q) const;
  const std::map<std::string, std::vector<double>>& samples() const { return samples_; }

 private:
  std::map<std::string, std::vector<double>> samples_;
};

// Milliseconds since construction.
class Stopwatch {
 public:
  Stopwatch() : t0_(std::chrono::steady_clock::now()) {}
  double ms() const {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0_).count();
  }

 private:
  std::chrono::steady_clock::time_point t0_;
};

// Percentile by linear interpolation between order statistics; q in [0, 1]. Empty -> 0.
double percentile(std::vector<double> v, double q);

}  // namespace ussnav
