#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "ussnav/core/config.hpp"
#include "ussnav/core/error.hpp"
#include "ussnav/perception/oracle_detector.hpp"

using namespace ussnav;

namespace {

// A W x H frame at constant depth with rectangles of instance ids painted in.
struct FrameBuilder {
  DepthFrame f;
  FrameBuilder(int w, int h, float depth = 2.0f) {
    f.K = Intrinsics::fromFov(w, h, deg2rad(87), deg2rad(58));
    f.depth.assign(size_t(w) * h, depth);
    f.instance.assign(size_t(w) * h, 0);
  }
  // Fills [u0, u1) x [v0, v1) with id (and depth when > 0).
  FrameBuilder& rect(int u0, int v0, int u1, int v1, uint16_t id, float depth = -1) {
    for (int v = v0; v < v1; ++v)
      for (int u = u0; u < u1; ++u) {
        f.instance[size_t(v) * f.K.width + u] = id;
        if (depth > 0) f.depth[size_t(v) * f.K.width + u] = depth;
      }
    return *this;
  }
};

OracleRealism perfect() { return OracleRealism{}; }

const Detection* byId(const std::vector<Detection>& d, uint32_t id) {
  for (const auto& x : d)
    if (x.gt_instance == id) return &x;
  return nullptr;
}

}  // namespace

TEST(OracleDetector, PerfectRealismReportsEveryLabelledInstance) {
  FrameBuilder b(40, 30);
  b.rect(2, 2, 12, 12, 7).rect(20, 5, 30, 25, 3).rect(32, 0, 36, 4, 99);  // 99 has no label
  OracleDetector det({{7, "chair"}, {3, "bed"}}, perfect());
  const auto d = det.detect(b.f);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0].gt_instance, 3u);  // ascending ids
  EXPECT_EQ(d[0].label, "bed");
  EXPECT_EQ(d[0].mask.size(), 10u * 20u);
  EXPECT_EQ(d[1].label, "chair");
  EXPECT_EQ(d[1].mask.size(), 100u);
  EXPECT_TRUE(std::is_sorted(d[1].mask.begin(), d[1].mask.end()));
  EXPECT_EQ(d[1].mask.front(), 2u * 40u + 2u);  // pixel (u=2, v=2)
  EXPECT_DOUBLE_EQ(d[1].score, 1.0);
  EXPECT_EQ(byId(d, 99), nullptr);
  EXPECT_EQ(det.frames(), 1u);
}

TEST(OracleDetector, MinPixelsDropsSmallMasks) {
  FrameBuilder b(20, 20);
  b.rect(0, 0, 3, 3, 1).rect(10, 10, 14, 14, 2);  // 9 and 16 pixels
  OracleRealism r;
  r.min_pixels = 10;
  OracleDetector det({{1, "cup"}, {2, "lamp"}}, r);
  const auto d = det.detect(b.f);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].gt_instance, 2u);
  r.min_pixels = 9;
  EXPECT_EQ(OracleDetector({{1, "cup"}, {2, "lamp"}}, r).detect(b.f).size(), 2u);
}

TEST(OracleDetector, MaxRangeUsesMedianDepth) {
  FrameBuilder b(20, 20);
  b.rect(0, 0, 5, 5, 1, 6.0f).rect(10, 10, 15, 15, 2, 4.0f);
  // Instance 3: mostly near with a few far pixels -> the median keeps it.
  b.rect(0, 10, 5, 15, 3, 3.0f).rect(0, 10, 5, 11, 3, 9.0f);
  OracleRealism r;
  r.max_range = 5.0;
  OracleDetector det({{1, "bed"}, {2, "sofa"}, {3, "desk"}}, r);
  const auto d = det.detect(b.f);
  EXPECT_EQ(byId(d, 1), nullptr);
  EXPECT_NE(byId(d, 2), nullptr);
  EXPECT_NE(byId(d, 3), nullptr);
  // No valid depth at all: nothing to place, not reported.
  FrameBuilder nod(10, 10, 0.0f);
  nod.rect(0, 0, 5, 5, 1);
  EXPECT_TRUE(OracleDetector({{1, "bed"}}, r).detect(nod.f).empty());
}

TEST(OracleDetector, ErosionShrinksMasks) {
  FrameBuilder b(30, 30);
  b.rect(5, 5, 15, 15, 1);    // 10 x 10 inside the image
  b.rect(20, 0, 30, 10, 2);   // 10 x 10 in the corner: the image border does not erode
  b.rect(15, 5, 18, 15, 3);   // touches instance 1: both lose the shared edge
  OracleRealism r;
  r.erosion_px = 1;
  auto d = OracleDetector({{1, "a"}, {2, "b"}, {3, "c"}}, r).detect(b.f);
  EXPECT_EQ(byId(d, 1)->mask.size(), 8u * 8u);
  EXPECT_EQ(byId(d, 2)->mask.size(), 9u * 9u);
  EXPECT_EQ(byId(d, 3)->mask.size(), 1u * 8u);
  r.erosion_px = 2;
  d = OracleDetector({{1, "a"}, {2, "b"}, {3, "c"}}, r).detect(b.f);
  EXPECT_EQ(byId(d, 1)->mask.size(), 6u * 6u);
  EXPECT_EQ(byId(d, 2)->mask.size(), 8u * 8u);
  EXPECT_EQ(byId(d, 3), nullptr);  // 3 px wide: gone
  // Every eroded pixel was in the original mask and away from other ids.
  for (uint32_t i : byId(d, 1)->mask) EXPECT_EQ(b.f.instance[i], 1);
}

TEST(OracleDetector, MissesAreDeterministicPerSeed) {
  FrameBuilder b(40, 10);
  for (int k = 0; k < 8; ++k) b.rect(k * 5, 0, k * 5 + 4, 10, uint16_t(k + 1));
  std::unordered_map<uint32_t, std::string> labels;
  for (int k = 1; k <= 8; ++k) labels[k] = "box";
  OracleRealism r;
  r.miss_prob = 0.5;
  auto run = [&](uint64_t seed) {
    OracleDetector det(labels, r, seed);
    std::vector<uint32_t> seen;
    for (int frame = 0; frame < 50; ++frame) {
      for (const auto& d : det.detect(b.f)) seen.push_back(d.gt_instance);
      seen.push_back(0);  // frame separator
    }
    return seen;
  };
  const auto a = run(42), again = run(42), other = run(43);
  EXPECT_EQ(a, again);
  EXPECT_NE(a, other);
  const double reported = double(a.size() - 50) / (50.0 * 8.0);
  EXPECT_GT(reported, 0.4);
  EXPECT_LT(reported, 0.6);
  r.miss_prob = 0.0;
  EXPECT_EQ(OracleDetector(labels, r, 1).detect(b.f).size(), 8u);
  r.miss_prob = 1.0;
  EXPECT_TRUE(OracleDetector(labels, r, 1).detect(b.f).empty());
}

TEST(OracleDetector, ConfusionSwapsForSimilarCategories) {
  FrameBuilder b(20, 10);
  b.rect(0, 0, 5, 5, 1).rect(10, 0, 15, 5, 2);
  OracleRealism r;
  r.confusion_prob = 1.0;
  r.score = 0.8;
  const ConfusionTable table = defaultConfusionTable();
  OracleDetector det({{1, "Chair"}, {2, "zorblax"}}, r, 5);
  std::set<std::string> labels;
  for (int i = 0; i < 40; ++i)
    for (const auto& d : det.detect(b.f)) {
      if (d.gt_instance == 2) EXPECT_EQ(d.label, "zorblax");  // nothing similar known
      else labels.insert(d.label);
      EXPECT_DOUBLE_EQ(d.score, 0.8);
    }
  const auto& alts = table.at("chair");
  EXPECT_EQ(labels.size(), alts.size());  // every alternative shows up, nothing else
  for (const auto& l : labels) EXPECT_NE(std::find(alts.begin(), alts.end(), l), alts.end()) << l;
}

TEST(OracleDetector, BadFrameIsInputError) {
  FrameBuilder b(10, 10);
  b.f.instance.resize(50);
  OracleDetector det({{1, "a"}}, perfect());
  EXPECT_THROW(det.detect(b.f), InputError);
  b.f.instance.clear();  // no instance image: a real detector would need colour; the oracle sees nothing
  EXPECT_TRUE(det.detect(b.f).empty());
}

TEST(DetectorFactory, ByNameFromConfig) {
  PerceptionConfig cfg;
  DetectorContext ctx;
  ctx.instance_labels = {{1, "bed"}};
  auto det = makeDetector(cfg, ctx);
  EXPECT_EQ(det->name(), "oracle");
  auto* oracle = dynamic_cast<OracleDetector*>(det.get());
  ASSERT_NE(oracle, nullptr);
  EXPECT_DOUBLE_EQ(oracle->realism().miss_prob, cfg.miss_prob);
  EXPECT_EQ(oracle->realism().min_pixels, cfg.min_pixels);
  try {
    makeDetector("yoloe", cfg, ctx);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("perception.detector"), std::string::npos);
  }
}
