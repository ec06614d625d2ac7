#include "ussnav/perception/detector.hpp"

#include "ussnav/core/config.hpp"
#include "ussnav/core/error.hpp"
#include "ussnav/perception/oracle_detector.hpp"

namespace ussnav {

ConfusionTable defaultConfusionTable() {
  // Pairs an open-vocabulary detector plausibly mixes up indoors: same function, similar shape.
  // Deliberately not symmetric everywhere (a stool is called a chair more often than the
  // reverse). Synonym pairs (sofa/couch) test that embeddings, not strings, drive association.
  return {
      {"chair", {"armchair", "stool", "office chair"}},
      {"armchair", {"chair", "sofa"}},
      {"office chair", {"chair"}},
      {"stool", {"chair"}},
      {"sofa", {"couch", "armchair"}},
      {"couch", {"sofa"}},
      {"table", {"desk", "dining table", "coffee table"}},
      {"desk", {"table"}},
      {"dining table", {"table"}},
      {"coffee table", {"table"}},
      {"nightstand", {"cabinet", "table"}},
      {"tv", {"monitor"}},
      {"television", {"monitor"}},
      {"tv monitor", {"tv", "monitor"}},
      {"monitor", {"tv"}},
      {"cabinet", {"dresser", "wardrobe", "chest of drawers"}},
      {"dresser", {"cabinet", "chest of drawers"}},
      {"chest of drawers", {"dresser", "cabinet"}},
      {"wardrobe", {"cabinet"}},
      {"shelf", {"bookshelf", "cabinet"}},
      {"bookshelf", {"shelf"}},
      {"counter", {"table"}},
      {"bed", {"sofa"}},
      {"cushion", {"pillow"}},
      {"pillow", {"cushion"}},
      {"picture", {"painting", "poster"}},
      {"painting", {"picture"}},
      {"plant", {"houseplant", "flower"}},
      {"sink", {"basin"}},
      {"bathtub", {"tub", "shower"}},
      {"refrigerator", {"fridge"}},
      {"lamp", {"light"}},
  };
}

std::unique_ptr<Detector> makeDetector(const std::string& name, const PerceptionConfig& cfg,
                                       const DetectorContext& ctx) {
  if (name == "oracle")
    return std::make_unique<OracleDetector>(ctx.instance_labels, OracleRealism::fromConfig(cfg), ctx.seed,
                                            ctx.confusion);
  throw InputError("config", "perception.detector", "'" + name + "' is not one of oracle");
}

std::unique_ptr<Detector> makeDetector(const PerceptionConfig& cfg, const DetectorContext& ctx) {
  return makeDetector(cfg.detector, cfg, ctx);
}

}  // namespace ussnav
