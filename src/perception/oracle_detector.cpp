#include "ussnav/perception/oracle_detector.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>

#include "ussnav/core/config.hpp"
#include "ussnav/core/error.hpp"
#include "ussnav/core/random.hpp"

namespace ussnav {

namespace {

uint64_t splitmix(uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

std::string normaliseLabel(std::string s) {
  for (char& c : s) {
    c = char(std::tolower(static_cast<unsigned char>(c)));
    if (c == '_' || c == '-') c = ' ';
  }
  return s;
}

}  // namespace

OracleRealism OracleRealism::fromConfig(const PerceptionConfig& cfg) {
  OracleRealism r;
  r.miss_prob = cfg.miss_prob;
  r.confusion_prob = cfg.confusion_prob;
  r.erosion_px = cfg.erosion_px;
  r.min_pixels = cfg.min_pixels;
  r.max_range = cfg.max_range;
  r.score = cfg.score;
  return r;
}

void erodeInstances(std::vector<uint16_t>& ids, int width, int height, int passes) {
  if (passes <= 0 || width <= 0 || height <= 0) return;
  std::vector<uint16_t> next(ids.size());
  for (int p = 0; p < passes; ++p) {
    next = ids;
    for (int v = 0; v < height; ++v)
      for (int u = 0; u < width; ++u) {
        const size_t i = size_t(v) * width + u;
        const uint16_t id = ids[i];
        if (id == 0) continue;
        const bool keep = (u == 0 || ids[i - 1] == id) && (u + 1 == width || ids[i + 1] == id) &&
                          (v == 0 || ids[i - width] == id) && (v + 1 == height || ids[i + width] == id);
        if (!keep) next[i] = 0;
      }
    ids.swap(next);
  }
}

OracleDetector::OracleDetector(std::unordered_map<uint32_t, std::string> instance_labels,
                               OracleRealism realism, uint64_t seed, ConfusionTable confusion)
    : labels_(std::move(instance_labels)), realism_(realism), seed_(seed) {
  for (auto& [k, v] : confusion) {
    auto& dst = confusion_[normaliseLabel(k)];
    for (const auto& s : v) dst.push_back(normaliseLabel(s));
  }
}

std::vector<Detection> OracleDetector::detect(const DepthFrame& frame) {
  const uint64_t frame_no = frame_count_++;
  std::vector<Detection> out;
  if (frame.instance.empty()) return out;
  const int w = frame.K.width, h = frame.K.height;
  const size_t n = size_t(std::max(w, 0)) * size_t(std::max(h, 0));
  if (frame.instance.size() != n)
    throw InputError("depth frame", "instance", "expected width x height = " + std::to_string(n) +
                                                    " instance ids, got " + std::to_string(frame.instance.size()));
  if (!frame.depth.empty() && frame.depth.size() != n)
    throw InputError("depth frame", "depth", "expected width x height = " + std::to_string(n) +
                                                 " depths, got " + std::to_string(frame.depth.size()));

  std::vector<uint16_t> ids = frame.instance;
  erodeInstances(ids, w, h, realism_.erosion_px);
  std::map<uint32_t, std::vector<uint32_t>> masks;  // ordered: detections come out by id
  for (size_t i = 0; i < n; ++i)
    if (ids[i] != 0) masks[ids[i]].push_back(uint32_t(i));

  std::vector<float> depths;
  for (auto& [id, mask] : masks) {
    // Draw every random number up front so that filters never shift the sequence.
    Rng rng(splitmix(seed_ ^ splitmix(frame_no * 0x100000001B3ULL + id)));
    const bool missed = rng.bernoulli(realism_.miss_prob);
    const bool confused = rng.bernoulli(realism_.confusion_prob);
    const uint64_t pick = rng.next();

    const auto lab = labels_.find(id);
    if (lab == labels_.end()) continue;
    if (int(mask.size()) < realism_.min_pixels) continue;
    if (!frame.depth.empty()) {
      depths.clear();
      for (uint32_t i : mask) {
        const float d = frame.depth[i];
        if (std::isfinite(d) && d > 0) depths.push_back(d);
      }
      if (depths.empty()) continue;
      auto mid = depths.begin() + depths.size() / 2;
      std::nth_element(depths.begin(), mid, depths.end());
      if (*mid > realism_.max_range) continue;
    }
    if (missed) continue;

    Detection d;
    d.label = lab->second;
    if (confused) {
      const auto alt = confusion_.find(normaliseLabel(d.label));
      if (alt != confusion_.end() && !alt->second.empty()) d.label = alt->second[pick % alt->second.size()];
    }
    d.mask = std::move(mask);
    d.score = realism_.score;
    d.gt_instance = id;
    out.push_back(std::move(d));
  }
  return out;
}

}  // namespace ussnav
