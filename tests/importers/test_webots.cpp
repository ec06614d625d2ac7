#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <set>

#include "support/paths.hpp"
#include "ussnav/core/error.hpp"
#include "ussnav/sim/importers/import.hpp"
#include "ussnav/sim/world_io.hpp"

using namespace ussnav;
namespace fs = std::filesystem;

namespace {

fs::path apartment() { return test::sharedData() / "webots_complete_apartment"; }

class WebotsApartment : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!test::haveSharedData()) GTEST_SKIP() << "shared data absent";
    world_ = importWebotsApartment(apartment(), {}, &rep_);
  }
  const Room* named(const std::string& name) const {
    for (const auto& r : world_.rooms)
      if (r.name == name) return &r;
    return nullptr;
  }
  World world_;
  ImportReport rep_;
};

}  // namespace

TEST_F(WebotsApartment, LabelledPatchesBecomeRoomsWithoutTheGarden) {
  std::map<std::string, std::string> expect{{"LIVING_ROOM_1", "living room"}, {"LIVING_ROOM_2", "living room"},
                                            {"KITCHEN", "kitchen"},          {"CORRIDOR", "corridor"},
                                            {"BATHROOM_1", "bathroom"},      {"ROOM_1", "bedroom"},
                                            {"ROOM_2", "bedroom"}};
  for (const auto& [name, type] : expect) {
    const Room* r = named(name);
    ASSERT_NE(r, nullptr) << name;
    EXPECT_EQ(r->type, type) << name;
  }
  EXPECT_EQ(named("GARDEN"), nullptr);
  // The corridor patch also covers a walled-off WC (toilet + basin) and the kitchen patch the
  // stairwell behind wall 7(8): both are split off and relabelled by content.
  ASSERT_NE(named("CORRIDOR_W"), nullptr);
  EXPECT_EQ(named("CORRIDOR_W")->type, "bathroom");
  ASSERT_NE(named("KITCHEN_S"), nullptr);
  EXPECT_EQ(named("KITCHEN_S")->type, "stairwell");
  EXPECT_EQ(world_.rooms.size(), 9u);
}

TEST_F(WebotsApartment, FurnitureLandsInTheRightRooms) {
  std::map<std::string, int> count;
  for (const auto& o : world_.objects) {
    const std::string& type = world_.room(o.room_id)->type;
    const std::map<std::string, std::string> home{
        {"bed", "bedroom"}, {"toilet", "bathroom"}, {"fridge", "kitchen"}, {"bathtub", "bathroom"}};
    if (auto it = home.find(o.category); it != home.end()) {
      EXPECT_EQ(type, it->second) << o.category;
    }
    ++count[o.category];
  }
  EXPECT_EQ(count["bed"], 2);
  EXPECT_EQ(count["toilet"], 2);
  EXPECT_EQ(count["fridge"], 1);
  EXPECT_EQ(count["sofa"], 2);  // the third sofa stands in the garden
  EXPECT_GE(world_.objects.size(), 120u);
  // Only garden furniture (barbecue, table, sofa, 9 cypresses) falls outside every room.
  EXPECT_EQ(rep_.dropped_objects, 12);
}

TEST_F(WebotsApartment, DoorsJoinNeighboursAndConnectEveryRoom) {
  std::map<int, std::set<int>> adj;
  int with_opening = 0;
  for (const auto& d : world_.doors) {
    ASSERT_GE(d.room_a, 1);
    ASSERT_GE(d.room_b, 1);
    adj[d.room_a].insert(d.room_b);
    adj[d.room_b].insert(d.room_a);
  }
  for (const auto& wl : world_.walls) with_opening += int(wl.openings.size());
  EXPECT_EQ(with_opening, 6);  // 7 Door nodes, the one to the outside stays shut
  std::set<int> seen{1};
  std::vector<int> pending{1};
  while (!pending.empty()) {
    const int r = pending.back();
    pending.pop_back();
    for (int n : adj[r])
      if (seen.insert(n).second) pending.push_back(n);
  }
  EXPECT_EQ(seen.size(), world_.rooms.size());
  // The living room opens onto the corridor without a door node (no wall between x -6.8..-4.5).
  const int lr = named("LIVING_ROOM_1")->id, cor = named("CORRIDOR")->id;
  EXPECT_TRUE(adj[lr].count(cor));
}

TEST_F(WebotsApartment, StartsAtTheRobotAndReloads) {
  EXPECT_NEAR(world_.start.position.x(), -5.32, 1e-9);
  EXPECT_NEAR(world_.start.position.y(), -5.42, 1e-9);
  EXPECT_NEAR(world_.start.position.z(), 1.2, 1e-9);
  const auto out = test::tempDir("webots_roundtrip") / "w.json";
  saveWorld(world_, out);
  EXPECT_EQ(loadWorld(out).objects.size(), world_.objects.size());
}

TEST_F(WebotsApartment, FolderWbtAndTsvPathsGiveTheSameWorld) {
  for (const auto& p : {apartment() / "complete_apartment.wbt", apartment() / "rooms_enu.tsv"}) {
    const World w = importWorld(p);
    EXPECT_EQ(w.rooms.size(), world_.rooms.size()) << p;
    EXPECT_EQ(w.objects.size(), world_.objects.size()) << p;
    EXPECT_EQ(w.doors.size(), world_.doors.size()) << p;
  }
}

TEST(Webots, MissingTablesAreInputErrors) {
  const auto dir = test::tempDir("webots_bad");
  const auto wbt = dir / "lonely.wbt";
  { std::ofstream(wbt) << "#VRML_SIM R2021a utf8\n"; }
  try {
    importWorld(wbt);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("lonely.wbt"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("rooms_enu.tsv"), std::string::npos) << e.what();
  }
}
