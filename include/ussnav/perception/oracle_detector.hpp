#pragma once
// A detector that reads the simulator's per-pixel instance ids instead of running a network,
// made imperfect on purpose so that the object layer meets the failures a real detector has:
// missed detections, labels swapped for similar categories, masks eroded at their border,
// small masks dropped, far objects dropped. Every random draw is keyed by (seed, frame number,
// instance id), so a run is repeatable and one object's luck does not depend on what else is
// in view. Cost: one pass over the image per erosion pixel plus one to group pixels.

#include "ussnav/perception/detector.hpp"

namespace ussnav {

struct OracleRealism {
  double miss_prob = 0.0;       // chance an instance in view is not reported in a frame
  double confusion_prob = 0.0;  // chance its label is replaced by a similar category
  int erosion_px = 0;           // 4-neighbour erosion passes (the image border does not erode)
  int min_pixels = 1;           // masks smaller than this after erosion are dropped
  double max_range = 1e9;       // masks whose median depth is farther are dropped, m
  double score = 1.0;           // reported confidence
  static OracleRealism fromConfig(const PerceptionConfig& cfg);
};

class OracleDetector : public Detector {
 public:
  // instance_labels: instance id -> category; ids missing from it are never reported.
  OracleDetector(std::unordered_map<uint32_t, std::string> instance_labels, OracleRealism realism,
                 uint64_t seed = 0, ConfusionTable confusion = defaultConfusionTable());
  // Throws InputError when the frame's instance image is present but not width x height.
  // A frame without an instance image gives no detections.
  std::vector<Detection> detect(const DepthFrame& frame) override;
  std::string name() const override { return "oracle"; }
  const OracleRealism& realism() const { return realism_; }
  // Frames processed so far (the frame number in the random key).
  uint64_t frames() const { return frame_count_; }

 private:
  std::unordered_map<uint32_t, std::string> labels_;
  OracleRealism realism_;
  uint64_t seed_;
  ConfusionTable confusion_;
  uint64_t frame_count_ = 0;
};

// Erodes an instance-id image in place by `passes` 4-neighbour passes: a pixel keeps its id only
// when every in-image 4-neighbour has the same id (0 = background). Exposed for tests.
void erodeInstances(std::vector<uint16_t>& ids, int width, int height, int passes);

}  // namespace ussnav
