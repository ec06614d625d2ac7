#include <gtest/gtest.h>

#include <cctype>
#include <fstream>
#include <set>
#include <sstream>

#include "ussnav/sim/layout_geometry.hpp"
#include "ussnav/sim/object_table.hpp"

using namespace ussnav;

TEST(ObjectTable, AtLeastThirtyCategoriesWithRealisticSizes) {
  const auto& cats = objectCategories();
  EXPECT_GE(cats.size(), 30u);
  std::set<std::string> names;
  for (const auto& c : cats) {
    EXPECT_TRUE(names.insert(c.name).second) << "duplicate " << c.name;
    for (char ch : c.name) EXPECT_TRUE(std::islower(static_cast<unsigned char>(ch)) || ch == ' ') << c.name;
    EXPECT_GT(c.size.minCoeff(), 0.0) << c.name;
    EXPECT_LE(c.size.maxCoeff(), 3.0) << c.name;
    EXPECT_LE(c.mount_z + c.size.z(), 2.5) << c.name;
    for (const auto& p : c.parents) EXPECT_NE(findCategory(p), nullptr) << c.name << " parent " << p;
  }
  EXPECT_NEAR(findCategory("bed")->size.y(), 2.05, 1e-9);
  EXPECT_EQ(findCategory("unicorn"), nullptr);
}

TEST(ObjectTable, RulesReferToKnownCategoriesAndParentsComeFirst) {
  for (const auto& r : placementRules()) {
    const ObjectCategory* c = findCategory(r.category);
    ASSERT_NE(c, nullptr) << r.category;
    EXPECT_GT(r.probability, 0.0);
    EXPECT_LE(r.probability, 1.0);
    EXPECT_LE(r.min_count, r.max_count);
    EXPECT_TRUE(r.style.empty() || r.style == "office" || r.style == "apartment");
    if (r.per_parent || c->placement == Placement::OnTop || c->placement == Placement::Front) {
      // Some parent category is placed earlier in the same room type.
      bool earlier = false;
      for (const auto& q : rulesFor(r.style.empty() ? "apartment" : r.style, r.room_type)) {
        if (q.category == r.category) break;
        for (const auto& p : c->parents) earlier = earlier || q.category == p;
      }
      if (!earlier && r.style.empty())
        for (const auto& q : rulesFor("office", r.room_type)) {
          if (q.category == r.category) break;
          for (const auto& p : c->parents) earlier = earlier || q.category == p;
        }
      EXPECT_TRUE(earlier) << r.room_type << ": " << r.category << " before any parent";
    }
  }
}

TEST(ObjectTable, SomeCategoriesBelongToSeveralRoomTypes) {
  for (const char* name : {"chair", "table", "plant", "tv", "sink", "cabinet", "lamp", "laptop"}) {
    std::set<std::string> rooms;
    for (const auto& r : placementRules())
      if (r.category == name) rooms.insert(r.room_type);
    EXPECT_GE(rooms.size(), 2u) << name;
  }
  EXPECT_FALSE(rulesFor("office", "bedroom").empty());
  for (const auto& r : rulesFor("office", "bathroom")) EXPECT_NE(r.category, "bathtub");
}

TEST(ObjectTable, DocsListTheTableVerbatim) {
  std::ifstream in(std::string(USSNAV_SOURCE_DIR) + "/docs/object-table.md");
  ASSERT_TRUE(in) << "docs/object-table.md missing";
  std::stringstream ss;
  ss << in.rdbuf();
  EXPECT_NE(ss.str().find(objectTableMarkdown()), std::string::npos)
      << "docs/object-table.md is stale: regenerate the table with `ussnav world categories`";
}

// ---- layout geometry -------------------------------------------------------------------

namespace {
OrientedBox box(double x, double y, double hx, double hy, double yaw = 0, double z = 0.5, double hz = 0.5) {
  OrientedBox b;
  b.center = Vec3(x, y, z);
  b.half_extents = Vec3(hx, hy, hz);
  b.yaw = yaw;
  return b;
}
}  // namespace

TEST(LayoutGeometry, FootprintOverlapBySeparatingAxes) {
  EXPECT_TRUE(footprintsOverlap(box(0, 0, 1, 1), box(1.5, 0, 1, 1)));
  EXPECT_FALSE(footprintsOverlap(box(0, 0, 1, 1), box(2.0, 0, 1, 1)));  // touching
  EXPECT_TRUE(footprintsOverlap(box(0, 0, 1, 1), box(2.04, 0, 1, 1), 0.05));
  // Rotated 45 degrees: the AABBs overlap but the diamonds do not.
  EXPECT_FALSE(footprintsOverlap(box(0, 0, 1, 1, kPi / 4), box(2.9, 0, 1, 1, kPi / 4)));
  EXPECT_TRUE(footprintsOverlap(box(0, 0, 1, 1, kPi / 4), box(2.7, 0, 1, 1, kPi / 4)));
}

TEST(LayoutGeometry, StackedBoxesDoNotOverlap) {
  const OrientedBox desk = box(0, 0, 0.7, 0.35, 0, 0.375, 0.375);
  const OrientedBox laptop = box(0.1, 0, 0.17, 0.12, 0, 0.75 + 0.015, 0.015);
  EXPECT_FALSE(boxesOverlap(desk, laptop));
  OrientedBox sunk = laptop;
  sunk.center.z() -= 0.01;
  EXPECT_TRUE(boxesOverlap(desk, sunk));
}

TEST(LayoutGeometry, BoxInsideLShapedRoom) {
  // L: 4 x 4 square minus its top-right 2 x 2 quarter; reflex vertex at (2, 2).
  const std::vector<Vec2> l{{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}};
  EXPECT_TRUE(footprintInsidePolygon(box(1, 1, 0.5, 0.5), l, 0.1));
  EXPECT_FALSE(footprintInsidePolygon(box(1, 1, 0.95, 0.5), l, 0.1));  // too near the wall
  // All four corners inside, but the reflex vertex pokes into the middle of the box.
  const OrientedBox across = box(1.7, 1.7, 1.0607, 1.0607, kPi / 4);
  for (const auto& c : footprintCorners(across)) EXPECT_TRUE(pointInPolygon(c, l));
  EXPECT_FALSE(footprintInsidePolygon(across, l));
  EXPECT_NEAR(distanceToBoundary(Vec2(1, 1), l), 1.0, 1e-12);
  EXPECT_NEAR(distanceToFootprint(Vec2(3, 0), box(0, 0, 1, 1)), 2.0, 1e-12);
  EXPECT_EQ(distanceToFootprint(Vec2(0.5, 0.5), box(0, 0, 1, 1)), 0.0);
}
