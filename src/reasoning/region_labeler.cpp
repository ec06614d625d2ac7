// Rate-limited, cached, optionally asynchronous region labelling (see region_labeler.hpp).

#include "ussnav/reasoning/region_labeler.hpp"

#include "ussnav/core/timing.hpp"

namespace ussnav {

RegionLabeler::RegionLabeler(std::shared_ptr<Reasoner> reasoner, double min_interval_s, int max_queue, bool asynchronous)
    : reasoner_(std::move(reasoner)), min_interval_s_(min_interval_s), max_queue_(size_t(std::max(1, max_queue))),
      async_(asynchronous) {
  if (async_) worker_ = std::thread([this] { work(); });
}

RegionLabeler::~RegionLabeler() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  cv_.notify_all();
  if (worker_.joinable()) worker_.join();
}

void RegionLabeler::offer(const std::vector<RegionSummary>& regions, double t) {
  std::vector<Request> now;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const RegionSummary& r : regions) {
      const uint64_t key = contentKey(r);
      if (auto it = requested_key_.find(r.id); it != requested_key_.end() && it->second == key) continue;
      if (auto it = requested_t_.find(r.id); it != requested_t_.end() && t - it->second < min_interval_s_) continue;
      requested_key_[r.id] = key;
      requested_t_[r.id] = t;
      if (auto c = cache_.find(key); c != cache_.end()) {
        semantics_[r.id] = c->second;
        ++stats_.cache_hits;
        continue;
      }
      if (!async_) {
        now.push_back({r, key});
        continue;
      }
      if (queue_.size() >= max_queue_) {
        requested_key_.erase(queue_.front().region.id);  // may be offered again
        queue_.pop_front();
        ++stats_.dropped;
      }
      queue_.push_back({r, key});
    }
  }
  if (async_) cv_.notify_one();
  for (const Request& r : now) label(r);
}

void RegionLabeler::label(const Request& r) {
  const Stopwatch sw;
  RegionSemantics s = reasoner_->labelRegion(r.region);
  const double ms = sw.ms();
  s.key = r.key;
  std::lock_guard<std::mutex> lock(mutex_);
  ++stats_.requests;
  ++stats_.labelled;
  stats_.fallbacks += s.source == "fallback";
  stats_.latency_ms.push_back(ms);
  if (s.source != "fallback") cache_[r.key] = s;  // a failed LLM call may succeed next time
  semantics_[r.region.id] = std::move(s);
}

void RegionLabeler::work() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (true) {
    cv_.wait(lock, [&] { return stop_ || !queue_.empty(); });
    if (stop_) return;
    Request r = std::move(queue_.front());
    queue_.pop_front();
    busy_ = true;
    lock.unlock();
    label(r);
    lock.lock();
    busy_ = false;
    if (queue_.empty()) idle_cv_.notify_all();
  }
}

void RegionLabeler::drain() {
  std::unique_lock<std::mutex> lock(mutex_);
  idle_cv_.wait(lock, [&] { return stop_ || (queue_.empty() && !busy_); });
}

std::map<int, RegionSemantics> RegionLabeler::semantics() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return semantics_;
}

RegionLabeler::Stats RegionLabeler::stats() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return stats_;
}

}  // namespace ussnav
