#pragma once
// Detector interface (paper Sec. IV-C step 1: YOLO-E instance masks and class labels). A
// detector turns one frame into instance masks with a free-text label and a score; the object
// layer back-projects the masks with the frame's depth. Backends by name (perception.detector):
// "oracle" (simulator instance ids with configurable realism, oracle_detector.hpp); an ONNX
// backend comes later behind the same interface and will read the frame's colour image.

#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "ussnav/core/frame.hpp"

namespace ussnav {

struct PerceptionConfig;

struct Detection {
  std::vector<uint32_t> mask;  // pixel indices v * width + u into the frame, ascending
  std::string label;           // free text, e.g. "chair", "dining table"
  double score = 1.0;          // confidence in [0, 1]
  uint32_t gt_instance = 0;    // ground-truth instance id, for evaluation only (0 = unknown)
};

class Detector {
 public:
  virtual ~Detector() = default;
  // Detections in a deterministic order. Not const: backends may keep state (random draws,
  // a frame counter, a model session).
  virtual std::vector<Detection> detect(const DepthFrame& frame) = 0;
  virtual std::string name() const = 0;
};

// Similar categories a detector may mix up: label -> labels it can be mistaken for.
using ConfusionTable = std::unordered_map<std::string, std::vector<std::string>>;
// The built-in table (chair <-> armchair/stool, table <-> desk/dining table, tv <-> monitor,
// cabinet <-> dresser/wardrobe, sofa <-> couch, ...). Keys and values are lower case with
// spaces; lookups normalise '_' and '-' to spaces.
ConfusionTable defaultConfusionTable();

// What a backend may need besides the config. The oracle needs the instance id -> category map
// (the simulator gives it from the world; nothing else in the pipeline reads ground truth).
struct DetectorContext {
  std::unordered_map<uint32_t, std::string> instance_labels;
  ConfusionTable confusion = defaultConfusionTable();
  uint64_t seed = 0;
};

// `name` is "oracle"; anything else throws InputError naming perception.detector.
std::unique_ptr<Detector> makeDetector(const std::string& name, const PerceptionConfig& cfg,
                                       const DetectorContext& ctx);
// Uses cfg.detector as the name.
std::unique_ptr<Detector> makeDetector(const PerceptionConfig& cfg, const DetectorContext& ctx);

}  // namespace ussnav
