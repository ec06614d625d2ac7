// Region and object quality against ground truth on hand-made inputs with hand-computed values.

#include <gtest/gtest.h>

#include "support/test_worlds.hpp"
#include "ussnav/eval/scene_quality.hpp"

namespace ussnav {
namespace {

// "couch" and "sofa" share a direction; every other label gets its own axis.
class TinyEncoder : public TextEncoder {
 public:
  Embedding encode(const std::string& label) const override {
    Embedding v = Embedding::Zero(8);
    const std::vector<std::string> axes = {"sofa", "chair", "table", "bed", "lamp"};
    const std::string l = label == "couch" ? "sofa" : label;
    for (size_t i = 0; i < axes.size(); ++i)
      if (axes[i] == l) v[long(i)] = 1.0f;
    if (v.squaredNorm() == 0) v[7] = 1.0f;
    return v;
  }
  int dim() const override { return 8; }
  std::string name() const override { return "tiny"; }
};

TEST(SceneQuality, RegionPurityAndAriAgainstRooms) {
  const World w = test::twoRooms();  // room 1 = [0,5]x[0,4], room 2 = [5,10]x[0,4]
  SceneGraph g;
  for (int i = 0; i < 7; ++i) {
    const double x = i < 4 ? 1.0 + i : (i < 6 ? 2.0 + i : 12.0);  // 1,2,3,4 | 6,7 | 12 (outside)
    g.nodes.push_back({i, Vec3(x, 2.0, 1.0), 1.0, {}, 0.0});
  }
  g.regions.push_back({0, {0, 1, 2}, "", "", Vec3::Zero(), {1}});
  g.regions.push_back({1, {3, 4, 5, 6}, "", "", Vec3::Zero(), {0}});
  const RegionQuality q = regionQuality(g, w);
  // pred 0 0 0 1 1 1 vs rooms 1 1 1 1 2 2 (node 6 skipped): purity (3 + 2) / 6.
  // ARI: sum C(n_ij,2) = 3 + 0 + 1 = 4; rows 3+3 = 6; cols 6+1 = 7; C(6,2) = 15;
  // (4 - 6*7/15) / ((6+7)/2 - 6*7/15) = 1.2 / 3.7.
  EXPECT_EQ(q.count, 2);
  EXPECT_EQ(q.nodes_scored, 6);
  EXPECT_EQ(q.rooms_touched, 2);
  EXPECT_NEAR(q.purity, 5.0 / 6.0, 1e-12);
  EXPECT_NEAR(q.ari, 1.2 / 3.7, 1e-12);
  // The largest region holds 4 of the 7 nodes in regions (node 6, outside the rooms, counts here).
  EXPECT_NEAR(q.largest_share, 4.0 / 7.0, 1e-12);
}

TEST(SceneQuality, RegionLabelsAgainstTheRoomHoldingMostNodes) {
  World w = test::twoRooms();  // room 1 "office" = [0,5]x[0,4], room 2 "kitchen" = [5,10]x[0,4]
  Room storage;
  storage.id = 3;
  storage.type = "storage";
  storage.polygon = {Vec2(10, 0), Vec2(14, 0), Vec2(14, 4), Vec2(10, 4)};
  w.rooms.push_back(storage);
  SceneGraph g;
  const std::vector<double> xs = {1, 2, 3, 6, 7, 8, 4, 11, 12, 20};
  for (size_t i = 0; i < xs.size(); ++i) g.nodes.push_back({int(i), Vec3(xs[i], 2.0, 1.0), 1.0, {}, 0.0});
  g.regions.push_back({0, {0, 1, 2}, "study", "", Vec3::Zero(), {}});        // office: right (an alias)
  g.regions.push_back({1, {3, 4, 5, 6}, "bathroom", "", Vec3::Zero(), {}});  // 3 of 4 in the kitchen: wrong
  g.regions.push_back({2, {7, 8}, "kitchen", "", Vec3::Zero(), {}});         // storage: not nameable
  g.regions.push_back({3, {9}, "kitchen", "", Vec3::Zero(), {}});            // outside every room
  g.regions.push_back({4, {}, "", "", Vec3::Zero(), {}});                    // no node
  SceneGraph unlabelled = g;
  unlabelled.regions[0].label.clear();
  const auto index = [](const std::string& n) {
    if (n == "office" || n == "study") return 0;
    if (n == "kitchen") return 1;
    if (n == "bathroom") return 2;
    return -1;
  };
  const RegionLabelQuality q = regionLabelQuality(g, w, index);
  EXPECT_EQ(q.regions, 3);
  EXPECT_EQ(q.labelled, 3);
  EXPECT_EQ(q.scored, 2);
  EXPECT_EQ(q.correct, 1);
  EXPECT_NEAR(q.accuracy, 0.5, 1e-12);
  ASSERT_EQ(q.confusions.size(), 1u);
  EXPECT_EQ(q.confusions.at("bathroom <- kitchen"), 1);
  const RegionLabelQuality u = regionLabelQuality(unlabelled, w, index);
  EXPECT_EQ(u.labelled, 2);
  EXPECT_EQ(u.scored, 1);
  EXPECT_EQ(u.correct, 0);
  EXPECT_NEAR(u.accuracy, 0.0, 1e-12);
}

TEST(SceneQuality, ObjectPrecisionRecallDuplicates) {
  World w = test::twoRooms();
  const int chair = test::addObject(w, "chair", Vec3(1, 1, 0.45), Vec3(0.3, 0.3, 0.45));
  const int table = test::addObject(w, "table", Vec3(3, 2, 0.4), Vec3(0.6, 0.4, 0.4));
  const int sofa = test::addObject(w, "sofa", Vec3(7, 2, 0.4), Vec3(1.0, 0.5, 0.4));
  const int lamp = test::addObject(w, "lamp", Vec3(9, 3, 0.5), Vec3(0.2, 0.2, 0.5));
  const int unseen = test::addObject(w, "bed", Vec3(8, 1, 0.3), Vec3(0.9, 0.7, 0.3));
  auto obj = [](int id, const std::string& label, const Vec3& c) {
    SgObject o;
    o.id = id;
    o.label = label;
    o.centroid = c;
    return o;
  };
  const std::vector<SgObject> mapped = {
      obj(1, "chair", Vec3(1.1, 1.0, 0.5)),   // inside the chair
      obj(2, "chair", Vec3(1.0, 1.45, 0.45)), // inside the chair grown by 0.3: a duplicate
      obj(3, "couch", Vec3(7.0, 2.0, 0.4)),   // sofa, by embedding
      obj(4, "table", Vec3(3.0, 2.0, 1.2)),   // 0.4 above the table: nearest box within 0.5
      obj(5, "bed", Vec3(3.0, 2.0, 0.4)),     // inside the table, wrong label
      obj(6, "table", Vec3(5.5, 3.5, 0.4)),   // nothing near
  };
  const std::set<int> seen = {chair, table, sofa, lamp};
  const TinyEncoder enc;
  const ObjectQuality q = objectQuality(mapped, w, seen, &enc);
  EXPECT_EQ(q.count, 6);
  EXPECT_EQ(q.seen_instances, 4);
  EXPECT_EQ(q.matched_objects, 4);
  EXPECT_EQ(q.matched_instances, 3);
  EXPECT_EQ(q.duplicates, 1);
  EXPECT_NEAR(q.precision, 4.0 / 6.0, 1e-12);
  EXPECT_NEAR(q.recall, 3.0 / 4.0, 1e-12);
  EXPECT_NEAR(q.duplicate_rate, 1.0 / 4.0, 1e-12);
  EXPECT_EQ(q.match, (std::vector<int>{chair, chair, sofa, table, 0, 0}));
  (void)unseen;

  // Without an encoder "couch" no longer matches "sofa".
  const ObjectQuality plain = objectQuality(mapped, w, seen, nullptr);
  EXPECT_EQ(plain.matched_objects, 3);
  EXPECT_EQ(plain.matched_instances, 2);
}

TEST(SceneQuality, SeenInstancesNeedMinPixels) {
  SeenInstances s(3);
  DepthFrame f;
  f.instance = {0, 3, 3, 3, 4, 4, 0, 7, 7, 7, 7};
  s.add(f);
  EXPECT_EQ(s.ids(), (std::set<int>{3, 7}));
  f.instance = {4, 4, 4};
  s.add(f);
  EXPECT_EQ(s.ids(), (std::set<int>{3, 4, 7}));
}

}  // namespace
}  // namespace ussnav
