#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "support/input_error.hpp"
#include "support/paths.hpp"
#include "ussnav/core/error.hpp"
#include "ussnav/core/io.hpp"
#include "ussnav/sim/ground_truth.hpp"
#include "ussnav/sim/importers/import.hpp"
#include "ussnav/sim/sensors.hpp"
#include "ussnav/sim/world_io.hpp"

using namespace ussnav;
namespace fs = std::filesystem;

namespace {

fs::path house(int i) { return test::sharedData() / "procthor_houses" / "houses" / ("house_" + std::to_string(i) + ".json"); }

int countSourceObjects(const nlohmann::json& objs) {
  int n = 0;
  for (const auto& o : objs) n += 1 + (o.contains("children") ? countSourceObjects(o["children"]) : 0);
  return n;
}

bool roomsConnectedByDoors(const World& w) {
  std::map<int, std::set<int>> adj;
  for (const auto& d : w.doors)
    if (d.room_a >= 0 && d.room_b >= 0) {
      adj[d.room_a].insert(d.room_b);
      adj[d.room_b].insert(d.room_a);
    }
  std::set<int> seen{w.rooms.front().id};
  std::vector<int> pending{w.rooms.front().id};
  while (!pending.empty()) {
    const int r = pending.back();
    pending.pop_back();
    for (int n : adj[r])
      if (seen.insert(n).second) pending.push_back(n);
  }
  return seen.size() == w.rooms.size();
}

using test::errorOf;

class ProcthorHouse : public ::testing::TestWithParam<int> {
 protected:
  void SetUp() override {
    if (!test::haveSharedData()) GTEST_SKIP() << "shared data absent";
  }
};

}  // namespace

TEST_P(ProcthorHouse, FourTypedRoomsConnectedByDoorsAndAllObjectsKept) {
  ImportReport rep;
  const World w = importProcthorHouse(house(GetParam()), {}, &rep);
  std::multiset<std::string> types;
  for (const auto& r : w.rooms) {
    types.insert(r.type);
    EXPECT_GT(polygonArea(r.polygon), 1.0) << r.name << " must be counter-clockwise with real area";
  }
  EXPECT_EQ(types, (std::multiset<std::string>{"bathroom", "bedroom", "kitchen", "living room"}));
  EXPECT_TRUE(roomsConnectedByDoors(w));
  for (const auto& d : w.doors) EXPECT_NE(d.room_a, d.room_b);

  const nlohmann::json src = readJsonFile(house(GetParam()));
  const int in_json = countSourceObjects(src["objects"]);
  EXPECT_EQ(rep.source_objects, in_json);
  EXPECT_LE(rep.dropped_objects, 2);
  EXPECT_EQ(int(w.objects.size()), in_json - rep.dropped_objects - rep.skipped_entries);
}

TEST_P(ProcthorHouse, ObjectsSitInTheRoomTheirTypeBelongsTo) {
  const World w = importProcthorHouse(house(GetParam()));
  std::map<std::string, std::string> expected{{"bed", "bedroom"}, {"toilet", "bathroom"}, {"fridge", "kitchen"}};
  int checked = 0;
  for (const auto& o : w.objects) {
    auto it = expected.find(o.category);
    if (it == expected.end()) continue;
    const Room* r = w.room(o.room_id);
    ASSERT_NE(r, nullptr);
    EXPECT_EQ(r->type, it->second) << o.category << " " << o.id;
    EXPECT_TRUE(pointInPolygon(o.box.center.head<2>(), r->polygon));
    ++checked;
  }
  EXPECT_GE(checked, 3);  // every 4-room house has a bed, a toilet and a fridge
}

TEST_P(ProcthorHouse, SavedAndReloadedWorldValidatesAndMatches) {
  const World w = importProcthorHouse(house(GetParam()));
  const auto out = test::tempDir("procthor_roundtrip") / "w.json";
  saveWorld(w, out);
  const World back = loadWorld(out);  // loadWorld runs validateWorld
  EXPECT_EQ(back.rooms.size(), w.rooms.size());
  EXPECT_EQ(back.walls.size(), w.walls.size());
  EXPECT_EQ(back.doors.size(), w.doors.size());
  EXPECT_EQ(back.objects.size(), w.objects.size());
  EXPECT_EQ(back.source, w.source);
}

TEST_P(ProcthorHouse, EachPhysicalWallAppearsOnce) {
  const World w = importProcthorHouse(house(GetParam()));
  std::set<std::pair<std::pair<long, long>, std::pair<long, long>>> seen;
  for (const auto& wl : w.walls) {
    auto a = std::make_pair(std::lround(wl.a.x() * 100), std::lround(wl.a.y() * 100));
    auto b = std::make_pair(std::lround(wl.b.x() * 100), std::lround(wl.b.y() * 100));
    if (b < a) std::swap(a, b);
    EXPECT_TRUE(seen.insert({a, b}).second) << "duplicate wall";
    EXPECT_DOUBLE_EQ(wl.thickness, 0.1);
  }
}

INSTANTIATE_TEST_SUITE_P(Houses, ProcthorHouse, ::testing::Values(0, 1, 4));

TEST(Procthor, UnityFrameBecomesRightHandedEnuWithoutMirroring) {
  if (!test::haveSharedData()) GTEST_SKIP() << "shared data absent";
  const World w = importProcthorHouse(house(0));
  // Dresser|4|0: Unity position (5.842, 0.485, 0.832), rotation.y 270 -> centre (x, z, y), yaw +90 deg.
  const Object* dresser = nullptr;
  for (const auto& o : w.objects)
    if (o.category == "dresser") dresser = &o;
  ASSERT_NE(dresser, nullptr);
  EXPECT_NEAR(dresser->box.center.x(), 5.842, 1e-3);
  EXPECT_NEAR(dresser->box.center.y(), 0.832, 1e-3);
  EXPECT_NEAR(dresser->box.center.z(), 0.485, 1e-3);
  EXPECT_NEAR(std::abs(std::sin(dresser->box.yaw)), 1.0, 1e-9);
  EXPECT_GT(std::sin(dresser->box.yaw), 0.0);  // -270 deg wraps to +90 deg
  EXPECT_EQ(w.room(dresser->room_id)->type, "bedroom");
  // room|4 (Bedroom) spans Unity x 2.06..6.16, z 0..6.16: (4, 3) is inside, (4, -3) is not.
  EXPECT_EQ(w.roomAt(Vec2(4, 3))->type, "bedroom");
  EXPECT_EQ(w.roomAt(Vec2(4, -3)), nullptr);
  // Start from metadata.agent (9.75, 0.95, 7.25) at flight height.
  EXPECT_NEAR(w.start.position.x(), 9.75, 1e-9);
  EXPECT_NEAR(w.start.position.y(), 7.25, 1e-9);
  EXPECT_NEAR(w.start.position.z(), 1.2, 1e-9);
}

TEST(Procthor, DoorHolesAreMeasuredAlongWallZeroAndCutIntoTheWall) {
  if (!test::haveSharedData()) GTEST_SKIP() << "shared data absent";
  const World w = importProcthorHouse(house(0));
  // door|4|5: on wall x = 2.055 from (2.055, 0); hole 3.389..5.354 along it.
  const Door* d = nullptr;
  for (const auto& x : w.doors)
    if (std::set<int>{x.room_a, x.room_b} == std::set<int>{4, 5}) d = &x;
  ASSERT_NE(d, nullptr);
  EXPECT_NEAR(d->center.x(), 2.055, 1e-6);
  EXPECT_NEAR(d->center.y(), 0.5 * (3.3886 + 5.3538), 1e-3);
  EXPECT_NEAR(d->width, 5.3538 - 3.3886, 1e-3);
  EXPECT_NEAR(d->height, 2.099, 1e-3);
  int cut = 0;
  for (const auto& wl : w.walls)
    for (const auto& o : wl.openings) {
      const Vec2 u = (wl.b - wl.a).normalized();
      const Vec2 c = wl.a + u * (0.5 * (o.start + o.end));
      if ((c - d->center).norm() < 1e-6) ++cut;
    }
  EXPECT_EQ(cut, 1);
  // The kitchen (6) and living room (7) are joined by open wall segments, not by a wall.
  int open = 0;
  for (const auto& x : w.doors)
    if (std::set<int>{x.room_a, x.room_b} == std::set<int>{6, 7}) ++open;
  EXPECT_GE(open, 1);
}

TEST(Procthor, CategoriesAreLowerCaseWords) {
  if (!test::haveSharedData()) GTEST_SKIP() << "shared data absent";
  std::set<std::string> cats;
  for (int i = 0; i < 20; ++i)
    for (const auto& o : importProcthorHouse(house(i)).objects) cats.insert(o.category);
  for (const char* c : {"dining table", "tv", "armchair", "fridge", "tv stand", "house plant", "garbage can"})
    EXPECT_TRUE(cats.count(c)) << c;
  for (const auto& c : cats) {
    EXPECT_FALSE(c.empty());
    for (char ch : c) EXPECT_TRUE(std::islower(static_cast<unsigned char>(ch)) || ch == ' ') << c;
  }
}

TEST(Procthor, TruncatedOrIncompleteHousesAreInputErrors) {
  if (!test::haveSharedData()) GTEST_SKIP() << "shared data absent";
  const auto dir = test::tempDir("procthor_bad");
  const std::string text = readFile(house(0));
  const auto truncated = dir / "truncated_house.json";
  std::ofstream(truncated) << text.substr(0, text.size() / 2);
  const ImportOptions opt{.asset_database = test::sharedData() / "procthor_houses" / "asset_bboxes.tsv"};
  std::string e = errorOf([&] { importWorld(truncated, opt); });
  EXPECT_NE(e.find("truncated_house.json"), std::string::npos) << e;

  nlohmann::json j = nlohmann::json::parse(text);
  j["rooms"][1].erase("floorPolygon");
  const auto missing = dir / "missing_field.json";
  std::ofstream(missing) << j.dump();
  e = errorOf([&] { importProcthorHouse(missing, opt); });
  EXPECT_NE(e.find("missing_field.json"), std::string::npos) << e;
  EXPECT_NE(e.find("rooms[1].floorPolygon"), std::string::npos) << e;

  // Without an asset database beside it (and none given) the sizes are unknown.
  const auto alone = dir / "alone.json";
  std::ofstream(alone) << text;
  e = errorOf([&] { importProcthorHouse(alone); });
  EXPECT_NE(e.find("asset"), std::string::npos) << e;
}

// ProcTHOR's boxes are an asset's bounds: a bed's holds its headboard, a sofa's its backrest. A
// book lying on the mattress (Book|4|2 on Bed|4|2 of house 5: top at 0.675 m, the bed's box at
// 0.712 m) is inside the bed's box, and a world of solid boxes would never show it. The importer
// rests such a child on its receptacle's top, where the depth camera sees it; what lies in a
// closed receptacle (a fridge) stays inside.
TEST(Procthor, AChildInsideItsReceptaclesBoxRestsOnItsTopAndIsSeen) {
  if (!test::haveSharedData()) GTEST_SKIP() << "shared data absent";
  ImportReport rep;
  const World w = importProcthorHouse(house(5), {}, &rep);
  const Object *book = nullptr, *bed = nullptr, *fridge = nullptr;
  for (const auto& o : w.objects) {
    if (o.category == "book" && (o.box.center.head<2>() - Vec2(11.522, 1.787)).norm() < 1e-3) book = &o;
    if (o.category == "bed") bed = &o;
    if (o.category == "fridge") fridge = &o;
  }
  ASSERT_TRUE(book && bed && fridge);
  const double bed_top = bed->box.center.z() + bed->box.half_extents.z();
  EXPECT_NEAR(bed_top, 0.7116, 1e-3);
  EXPECT_NEAR(book->box.center.z() - book->box.half_extents.z(), bed_top, 1e-9);
  // In the fridge: an egg, still inside its box.
  int in_fridge = 0;
  for (const auto& o : w.objects)
    if (&o != fridge && fridge->box.contains(o.box.center)) ++in_fridge;
  EXPECT_GE(in_fridge, 1);
  bool noted = false;
  for (const auto& n : rep.notes) noted |= n.find("set on its top") != std::string::npos;
  EXPECT_TRUE(noted);

  // The depth camera at flight height 1.6 m from the bed's foot sees the book: enough pixels
  // for the detector (perception.min_pixels 20).
  const GroundTruthGrid gt(w, 0.05);
  DepthCamera cam(CameraConfig{});
  const DepthFrame f = cam.render(gt, Pose{Vec3(11.0, 3.4, 1.2), -kPi / 2});
  const long seen = std::count(f.instance.begin(), f.instance.end(), static_cast<uint16_t>(book->id));
  EXPECT_GE(seen, 30);
}
