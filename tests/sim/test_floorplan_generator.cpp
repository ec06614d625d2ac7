#include <gtest/gtest.h>

#include <cctype>
#include <map>
#include <set>

#include "ussnav/core/error.hpp"
#include "ussnav/sim/floorplan_generator.hpp"
#include "ussnav/sim/layout_geometry.hpp"
#include "ussnav/sim/object_table.hpp"
#include "ussnav/sim/world_io.hpp"
#include "world_checks.hpp"

using namespace ussnav;

namespace {

World generate(const std::string& style, uint64_t seed, int rooms = 0, double area = 0) {
  GeneratorParams p;
  p.style = style;
  p.seed = seed;
  p.target_rooms = rooms;
  p.target_area_m2 = area;
  return generateWorld(p);
}

// Worlds for seeds 1..10 of both styles, generated once for the whole binary.
const std::vector<World>& sampleWorlds() {
  static const std::vector<World> worlds = [] {
    std::vector<World> v;
    for (const char* style : {"office", "apartment"})
      for (uint64_t seed = 1; seed <= 10; ++seed) v.push_back(generate(style, seed));
    return v;
  }();
  return worlds;
}

std::string styleOf(const World& w) { return w.name.substr(0, w.name.find('-')); }

double floorArea(const World& w) {
  double a = 0;
  for (const auto& r : w.rooms) a += std::abs(polygonArea(r.polygon));
  return a;
}

std::string roomTypeOf(const World& w, int id) { return w.room(id) ? w.room(id)->type : "?"; }

}  // namespace

TEST(FloorplanGenerator, SameSeedGivesIdenticalJsonBytes) {
  for (const char* style : {"office", "apartment"}) {
    const std::string a = worldToJson(generate(style, 7)).dump(1);
    const std::string b = worldToJson(generate(style, 7)).dump(1);
    EXPECT_EQ(a, b) << style;
    EXPECT_NE(a, worldToJson(generate(style, 8)).dump(1)) << style;
  }
}

TEST(FloorplanGenerator, RoomCountAndAreaWithinBounds) {
  for (const auto& w : sampleWorlds()) {
    EXPECT_GE(w.rooms.size(), 6u) << w.name;
    EXPECT_LE(w.rooms.size(), 30u) << w.name;
    EXPECT_GE(floorArea(w), 300.0) << w.name;
    for (const auto& r : w.rooms) {
      EXPECT_GT(polygonArea(r.polygon), 2.0) << w.name << " room " << r.id << " not CCW or tiny";
      EXPECT_NEAR(r.ceiling_z - r.floor_z, 2.8, 1e-9);
    }
  }
}

TEST(FloorplanGenerator, RequiredRoomTypesPerStyle) {
  const std::map<std::string, std::vector<std::string>> required{
      {"office", {"corridor", "office", "meeting room", "kitchen", "bathroom", "storage"}},
      {"apartment", {"living room", "kitchen", "bedroom", "bathroom", "hallway"}}};
  for (const auto& w : sampleWorlds()) {
    std::set<std::string> types;
    for (const auto& r : w.rooms) types.insert(r.type);
    for (const auto& t : required.at(styleOf(w))) EXPECT_TRUE(types.count(t)) << w.name << " lacks " << t;
  }
}

TEST(FloorplanGenerator, RoomsTileTheFloorWithoutOverlap) {
  int unions = 0;
  for (const auto& w : sampleWorlds()) {
    EXPECT_EQ(test::roomOverlapSamples(w), 0) << w.name;
    EXPECT_NO_THROW(validateWorld(w, w.name));
    // Both styles build a rectangular floor: no overlap and no gap means the room areas add
    // up to the footprint's bounding rectangle.
    Vec2 lo = w.rooms[0].polygon[0], hi = lo;
    for (const auto& r : w.rooms) {
      for (const auto& p : r.polygon) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
      unions += r.polygon.size() > 4;  // T- and L-shaped rooms (unions of rectangles)
    }
    EXPECT_NEAR(floorArea(w), (hi - lo).prod(), 1e-6) << w.name;
  }
  EXPECT_GT(unions, 3);
}

TEST(FloorplanGenerator, DoorGraphConnectsEveryRoom) {
  for (const auto& w : sampleWorlds()) {
    EXPECT_EQ(test::roomsReachableByDoors(w), int(w.rooms.size())) << w.name;
    EXPECT_GE(w.doors.size() + 1, w.rooms.size()) << w.name;
  }
}

TEST(FloorplanGenerator, DoorsSitOnSharedWallsWithOpenings) {
  for (const auto& w : sampleWorlds())
    for (const auto& d : w.doors) {
      EXPECT_EQ(test::doorProblem(w, d), "") << w.name << " door " << d.id;
      EXPECT_GE(d.width, 0.9 - 1e-9);
      EXPECT_LE(d.width, 1.2 + 1e-9);
      EXPECT_DOUBLE_EQ(d.height, 2.1);
      EXPECT_NE(d.room_a, -1) << "no doors to the outside";
    }
}

TEST(FloorplanGenerator, WallsAreClosedAndFullHeight) {
  for (const auto& w : sampleWorlds()) {
    size_t openings = 0;
    for (const auto& wl : w.walls) {
      EXPECT_GE(wl.thickness, 0.1);
      EXPECT_LE(wl.thickness, 0.15);
      EXPECT_DOUBLE_EQ(wl.z0, 0.0);
      EXPECT_DOUBLE_EQ(wl.z1, 2.8);
      openings += wl.openings.size();
    }
    EXPECT_EQ(openings, w.doors.size()) << w.name << ": one opening per door, no other holes";
  }
}

TEST(FloorplanGenerator, StartPoseIsFreeInCirculationAtFlightHeight) {
  for (const auto& w : sampleWorlds()) {
    const Room* r = w.roomAt(Vec2(w.start.position.x(), w.start.position.y()));
    ASSERT_NE(r, nullptr) << w.name;
    EXPECT_TRUE(r->type == "corridor" || r->type == "hallway" || r->type == "living room") << r->type;
    EXPECT_NEAR(w.start.position.z(), r->floor_z + 1.2, 1e-9);
    EXPECT_GE(distanceToBoundary(Vec2(w.start.position.x(), w.start.position.y()), r->polygon), 0.6) << w.name;
    for (const auto& o : w.objects)
      EXPECT_GT(o.box.distance(w.start.position), 0.5) << w.name << " object " << o.id;
  }
}

TEST(FloorplanGenerator, HonoursRequestedRoomCountAndArea) {
  for (const char* style : {"office", "apartment"})
    for (int rooms : {6, 11, 18, 24, 30}) {
      const World w = generate(style, 3, rooms);
      EXPECT_EQ(int(w.rooms.size()), rooms) << style;
      EXPECT_GE(floorArea(w), 300.0) << style << " " << rooms;
      EXPECT_EQ(test::roomsReachableByDoors(w), rooms) << style << " " << rooms;
    }
  const World big = generate("office", 2, 14, 800.0);
  EXPECT_GE(floorArea(big), 800.0);
  EXPECT_LT(floorArea(big), 900.0);
}

TEST(FloorplanGenerator, BadParametersNameTheParameter) {
  auto error = [](const GeneratorParams& p) {
    try {
      generateWorld(p);
    } catch (const InputError& e) {
      return std::string(e.field());
    }
    return std::string("no error");
  };
  GeneratorParams p;
  p.style = "castle";
  EXPECT_EQ(error(p), "style");
  p = {};
  p.target_rooms = 5;
  EXPECT_EQ(error(p), "rooms");
  p.target_rooms = 31;
  EXPECT_EQ(error(p), "rooms");
  p = {};
  p.uav_radius = 0.9;
  EXPECT_EQ(error(p), "uav_radius");
}

// ---- objects ---------------------------------------------------------------------------

TEST(ObjectPlacement, IdsUniqueCategoriesKnownRoomsSet) {
  for (const auto& w : sampleWorlds()) {
    ASSERT_FALSE(w.objects.empty()) << w.name;
    for (size_t i = 0; i < w.objects.size(); ++i) {
      const auto& o = w.objects[i];
      EXPECT_EQ(o.id, int(i) + 1);
      EXPECT_NE(findCategory(o.category), nullptr) << o.category;
      for (char c : o.category) EXPECT_FALSE(std::isupper(static_cast<unsigned char>(c)));
      EXPECT_NE(w.room(o.room_id), nullptr);
    }
  }
}

TEST(ObjectPlacement, ObjectsInsideTheirRoomClearOfWalls) {
  for (const auto& w : sampleWorlds())
    for (const auto& o : w.objects) {
      const Room* r = w.room(o.room_id);
      ASSERT_NE(r, nullptr);
      for (const auto& c : footprintCorners(o.box)) {
        EXPECT_TRUE(pointInPolygon(c, r->polygon)) << w.name << " " << o.category << " " << o.id;
        EXPECT_GE(distanceToBoundary(c, r->polygon), 0.06) << w.name << " " << o.category << " " << o.id;
      }
      EXPECT_GE(o.box.center.z() - o.box.half_extents.z(), r->floor_z - 1e-9);
      EXPECT_LE(o.box.center.z() + o.box.half_extents.z(), r->ceiling_z);
    }
}

TEST(ObjectPlacement, NoTwoObjectsOverlap) {
  for (const auto& w : sampleWorlds())
    for (size_t i = 0; i < w.objects.size(); ++i)
      for (size_t k = i + 1; k < w.objects.size(); ++k)
        EXPECT_FALSE(boxesOverlap(w.objects[i].box, w.objects[k].box))
            << w.name << ": " << w.objects[i].category << " " << w.objects[i].id << " and "
            << w.objects[k].category << " " << w.objects[k].id;
}

TEST(ObjectPlacement, DoorClearZonesStayEmpty) {
  for (const auto& w : sampleWorlds())
    for (const auto& d : w.doors)
      for (int rid : {d.room_a, d.room_b}) {
        const OrientedBox zone = doorClearZone(w, d, rid);
        // The zone is on the room's side: its far middle point lies in the room.
        const Vec2 far = Vec2(zone.center.x(), zone.center.y()) * 2 - d.center;
        EXPECT_TRUE(pointInPolygon(far - (far - d.center).normalized() * 0.05, w.room(rid)->polygon));
        for (const auto& o : w.objects)
          EXPECT_FALSE(footprintsOverlap(o.box, zone))
              << w.name << ": " << o.category << " " << o.id << " blocks door " << d.id;
      }
}

TEST(ObjectPlacement, EveryRoomAndObjectReachableByTheUav) {
  for (const auto& w : sampleWorlds()) {
    const auto r = test::checkReachability(w, 0.25, 1.0);
    EXPECT_TRUE(r.start_free) << w.name;
    EXPECT_TRUE(r.unreachable_rooms.empty()) << w.name << ": room " << r.unreachable_rooms.front();
    EXPECT_TRUE(r.unreachable_objects.empty()) << w.name << ": object " << r.unreachable_objects.front();
  }
}

TEST(ObjectPlacement, AnchorObjectsOfEachRoomType) {
  // Rules with probability 1 must have found room: the object that defines the room type.
  const std::map<std::string, std::string> anchor{{"bedroom", "bed"},          {"bathroom", "toilet"},
                                                  {"kitchen", "fridge"},       {"living room", "sofa"},
                                                  {"meeting room", "conference table"}, {"office", "desk"},
                                                  {"dining room", "dining table"}, {"study", "desk"}};
  for (const auto& w : sampleWorlds())
    for (const auto& r : w.rooms) {
      auto it = anchor.find(r.type);
      if (it == anchor.end()) continue;
      bool found = false;
      for (const auto& o : w.objects) found = found || (o.room_id == r.id && o.category == it->second);
      EXPECT_TRUE(found) << w.name << " " << r.type << " " << r.id << " has no " << it->second;
    }
}

TEST(ObjectPlacement, CategoriesFollowRoomTypes) {
  std::map<std::string, std::set<std::string>> rooms_of;  // category -> room types seen
  for (const auto& w : sampleWorlds())
    for (const auto& o : w.objects) rooms_of[o.category].insert(roomTypeOf(w, o.room_id));
  EXPECT_EQ(rooms_of["bed"], std::set<std::string>{"bedroom"});
  EXPECT_EQ(rooms_of["toilet"], std::set<std::string>{"bathroom"});
  EXPECT_EQ(rooms_of["whiteboard"].count("meeting room"), 1u);
  EXPECT_EQ(rooms_of["fridge"], std::set<std::string>{"kitchen"});
  EXPECT_EQ(rooms_of["sofa"].count("living room"), 1u);
  for (const char* shared : {"chair", "plant", "cabinet", "trash can", "laptop"})
    EXPECT_GE(rooms_of[shared].size(), 3u) << shared;
  for (const char* shared : {"sink", "tv", "table", "desk", "mirror"}) EXPECT_GE(rooms_of[shared].size(), 2u) << shared;
  EXPECT_GE(rooms_of.size(), 30u) << "most of the table shows up in 20 worlds";
}

TEST(ObjectPlacement, SmallObjectsRestOnTheirParents) {
  int on_top = 0;
  for (const auto& w : sampleWorlds())
    for (const auto& o : w.objects) {
      if (findCategory(o.category)->placement != Placement::OnTop) continue;
      ++on_top;
      const double bottom = o.box.center.z() - o.box.half_extents.z();
      EXPECT_GT(bottom, 0.2) << o.category;
      bool resting = false;
      for (const auto& p : w.objects) {
        const double top = p.box.center.z() + p.box.half_extents.z();
        const auto& parents = findCategory(o.category)->parents;
        if (std::abs(top - bottom) < 1e-9 && std::find(parents.begin(), parents.end(), p.category) != parents.end() &&
            p.box.contains(Vec3(o.box.center.x(), o.box.center.y(), top - 0.01)))
          resting = true;
      }
      EXPECT_TRUE(resting) << w.name << " " << o.category << " " << o.id;
    }
  EXPECT_GT(on_top, 20);
}

TEST(WorldChecks, CatchBrokenWorlds) {
  // The independent checks above must be able to fail: break a world three ways.
  World w = sampleWorlds()[0];
  // 1. A wardrobe-sized box across the first door, on both sides.
  const Door d = w.doors[0];
  Object block;
  block.id = int(w.objects.size()) + 1;
  block.category = "box";
  block.room_id = d.room_a;
  block.box.center = Vec3(d.center.x(), d.center.y(), 1.0);
  block.box.half_extents = Vec3(1.0, 1.0, 1.0);
  World blocked = w;
  blocked.objects.push_back(block);
  const auto r = test::checkReachability(blocked, 0.25, 1.0);
  const auto before = test::checkReachability(w, 0.25, 1.0);
  EXPECT_GT(r.unreachable_rooms.size() + r.unreachable_objects.size() + (r.start_free ? 0 : 1), 0u);
  EXPECT_TRUE(before.unreachable_rooms.empty());
  // 2. A door without its opening.
  World closed = w;
  for (auto& wl : closed.walls) wl.openings.clear();
  EXPECT_NE(test::doorProblem(closed, closed.doors[0]), "");
  EXPECT_FALSE(test::checkReachability(closed, 0.25, 1.0).unreachable_rooms.empty());
  // 3. A room slid onto its neighbour, and a door graph cut in two.
  World slid = w;
  for (auto& p : slid.rooms[3].polygon) p.x() += 1.0;
  EXPECT_GT(test::roomOverlapSamples(slid), 0);
  World cut = w;
  cut.doors.erase(std::remove_if(cut.doors.begin(), cut.doors.end(),
                                 [&](const Door& x) { return x.room_a == 1 || x.room_b == 1; }),
                  cut.doors.end());
  EXPECT_EQ(test::roomsReachableByDoors(cut), 1);
}
