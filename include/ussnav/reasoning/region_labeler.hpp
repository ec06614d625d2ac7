#pragma once
// Region semantics kept current without stalling mapping (paper Sec. V-B). offer() hands over
// the current region summaries; a region is (re)labelled only when its content key changed
// (objects or shape, region_semantics.hpp), at most once per min_interval_s of simulated time,
// and answers are cached by content key (two regions with the same objects share a label).
// Asynchronous mode: a worker thread calls the reasoner; offer() only queues (bounded: the
// oldest request is dropped when full) and semantics() returns what has been answered so far.
// Synchronous mode labels inside offer() — used with the builtin reasoner, which takes
// microseconds, so episodes stay bit-for-bit deterministic for a seed.

#include <condition_variable>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "ussnav/reasoning/reasoner.hpp"

namespace ussnav {

class RegionLabeler {
 public:
  RegionLabeler(std::shared_ptr<Reasoner> reasoner, double min_interval_s, int max_queue, bool asynchronous);
  ~RegionLabeler();
  RegionLabeler(const RegionLabeler&) = delete;
  RegionLabeler& operator=(const RegionLabeler&) = delete;

  void offer(const std::vector<RegionSummary>& regions, double t);
  // Latest semantics per region id.
  std::map<int, RegionSemantics> semantics() const;
  // Blocks until every queued request is answered (end of an episode, tests).
  void drain();

  struct Stats {
    int requests = 0;     // handed to the reasoner
    int labelled = 0;     // answers stored
    int cache_hits = 0;   // served from the cache
    int dropped = 0;      // queue full
    int fallbacks = 0;    // answers whose source is "fallback"
    std::vector<double> latency_ms;
  };
  Stats stats() const;

 private:
  struct Request {
    RegionSummary region;
    uint64_t key = 0;
  };
  void label(const Request& r);
  void work();

  std::shared_ptr<Reasoner> reasoner_;
  double min_interval_s_;
  size_t max_queue_;
  bool async_;
  mutable std::mutex mutex_;
  std::condition_variable cv_, idle_cv_;
  std::deque<Request> queue_;
  bool busy_ = false, stop_ = false;
  std::map<int, RegionSemantics> semantics_;
  std::map<int, uint64_t> requested_key_;
  std::map<int, double> requested_t_;
  std::map<uint64_t, RegionSemantics> cache_;
  Stats stats_;
  std::thread worker_;
};

}  // namespace ussnav
