#include <gtest/gtest.h>

#include <fstream>
#include <functional>

#include <nlohmann/json.hpp>

#include "support/paths.hpp"
#include "ussnav/core/error.hpp"
#include "ussnav/core/io.hpp"
#include "ussnav/sim/floorplan_generator.hpp"
#include "ussnav/sim/world_io.hpp"

using namespace ussnav;
using nlohmann::json;

namespace {

const World& sample() {
  static const World w = [] {
    GeneratorParams p;
    p.style = "apartment";
    p.seed = 4;
    return generateWorld(p);
  }();
  return w;
}

std::filesystem::path dir() {
  static const auto d = test::tempDir("world_io");
  return d;
}

std::filesystem::path writeText(const std::string& name, const std::string& text) {
  const auto p = dir() / name;
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

// The InputError message from loading `text` as file `name` ("" when it loads).
std::string loadError(const std::string& name, const std::string& text) {
  const auto p = writeText(name, text);
  try {
    loadWorld(p);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string mutated(const std::function<void(json&)>& f) {
  json j = worldToJson(sample());
  f(j);
  return j.dump(1);
}

}  // namespace

TEST(WorldIo, RoundTripIsByteExact) {
  const auto p1 = dir() / "a.json", p2 = dir() / "b.json";
  saveWorld(sample(), p1);
  const World back = loadWorld(p1);
  saveWorld(back, p2);
  EXPECT_EQ(readFile(p1), readFile(p2));
  // And the loaded world equals the original field by field where it matters.
  ASSERT_EQ(back.rooms.size(), sample().rooms.size());
  ASSERT_EQ(back.objects.size(), sample().objects.size());
  ASSERT_EQ(back.doors.size(), sample().doors.size());
  ASSERT_EQ(back.walls.size(), sample().walls.size());
  for (size_t i = 0; i < back.rooms.size(); ++i) {
    EXPECT_EQ(back.rooms[i].type, sample().rooms[i].type);
    EXPECT_EQ(back.rooms[i].polygon, sample().rooms[i].polygon);
  }
  for (size_t i = 0; i < back.objects.size(); ++i) {
    EXPECT_EQ(back.objects[i].category, sample().objects[i].category);
    EXPECT_EQ(back.objects[i].box.center, sample().objects[i].box.center);
    EXPECT_EQ(back.objects[i].box.half_extents, sample().objects[i].box.half_extents);
    EXPECT_EQ(back.objects[i].box.yaw, sample().objects[i].box.yaw);
  }
  EXPECT_EQ(back.walls[3].openings.size(), sample().walls[3].openings.size());
  EXPECT_EQ(back.start.position, sample().start.position);
  EXPECT_EQ(back.source, sample().source);
  EXPECT_EQ(worldToJson(back), worldToJson(sample()));
}

TEST(WorldIo, ObstacleOnlyWorldRoundTrips) {
  World w;
  w.name = "scan";
  w.has_floor = false;
  w.obstacles.resolution = 0.1;
  w.obstacles.origin = Vec3(-1, -2, 0);
  w.obstacles.cells = {{0, 0, 0}, {5, -3, 2}, {-7, 4, 10}};
  const auto p = dir() / "scan.json";
  saveWorld(w, p);
  const World back = loadWorld(p);
  EXPECT_EQ(back.obstacles.cells, w.obstacles.cells);
  EXPECT_EQ(back.obstacles.origin, w.obstacles.origin);
  EXPECT_FALSE(back.has_floor);
  EXPECT_TRUE(back.rooms.empty());
}

TEST(WorldIo, MalformedAndTruncatedFilesNameTheFile) {
  std::string e = loadError("broken.json", "{ \"format\": \"ussnav-world\", ");
  EXPECT_NE(e.find("broken.json"), std::string::npos) << e;
  EXPECT_NE(e.find("malformed JSON"), std::string::npos) << e;
  const std::string full = worldToJson(sample()).dump(1);
  e = loadError("half.json", full.substr(0, full.size() / 2));
  EXPECT_NE(e.find("half.json"), std::string::npos) << e;
  e = loadError("empty.json", "");
  EXPECT_NE(e.find("empty.json"), std::string::npos) << e;
  e = loadError("list.json", "[1, 2]");
  EXPECT_NE(e.find("expected a JSON object"), std::string::npos) << e;
}

TEST(WorldIo, MissingFieldNamesThePath) {
  const std::string e = loadError("missing.json", mutated([](json& j) { j["rooms"][2].erase("polygon"); }));
  EXPECT_NE(e.find("missing.json: rooms[2].polygon: missing required field"), std::string::npos) << e;
  const std::string e2 = loadError("nover.json", mutated([](json& j) { j.erase("version"); }));
  EXPECT_NE(e2.find("version"), std::string::npos) << e2;
}

TEST(WorldIo, WrongTypesNameThePath) {
  std::string e = loadError("type.json", mutated([](json& j) { j["rooms"][1]["id"] = "one"; }));
  EXPECT_NE(e.find("type.json: rooms[1].id: expected an integer"), std::string::npos) << e;
  e = loadError("type2.json", mutated([](json& j) { j["objects"][0]["center"] = {1, 2}; }));
  EXPECT_NE(e.find("objects[0].center: expected [x, y, z]"), std::string::npos) << e;
  // Used to escape as a nlohmann type_error instead of an InputError.
  e = loadError("format.json", mutated([](json& j) { j["format"] = 5; }));
  EXPECT_NE(e.find("format.json: format:"), std::string::npos) << e;
  // Used to wrap silently to a different id.
  e = loadError("big.json", mutated([](json& j) { j["doors"][0]["id"] = 99999999999LL; }));
  EXPECT_NE(e.find("doors[0].id: expected an integer within 32-bit range"), std::string::npos) << e;
  e = loadError("version.json", mutated([](json& j) { j["version"] = 2; }));
  EXPECT_NE(e.find("unsupported version 2"), std::string::npos) << e;
  e = loadError("opening.json", mutated([](json& j) {
    for (auto& w : j["walls"])
      if (!w["openings"].empty()) {
        w["openings"][0]["top"] = -1.0;
        break;
      }
  }));
  EXPECT_NE(e.find(".top: expected top > bottom"), std::string::npos) << e;
}

TEST(WorldIo, OverlappingRoomsAreRejected) {
  // Room 3 moved 1 m onto its neighbours.
  std::string e = loadError("overlap.json", mutated([](json& j) {
    for (auto& p : j["rooms"][2]["polygon"]) p[0] = p[0].get<double>() + 1.0;
  }));
  EXPECT_NE(e.find("overlap.json: rooms["), std::string::npos) << e;
  EXPECT_NE(e.find("rooms must not overlap"), std::string::npos) << e;
  // A partial overlap the old probe test (centroid + shrunk corners) let through: B pokes
  // 0.5 m into A over 6 m, away from all of B's probe points.
  World w;
  Room a, b;
  a.id = 1, a.type = "office", a.polygon = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  b.id = 2, b.type = "office", b.polygon = {{9.5, 2}, {19.5, 2}, {19.5, 8}, {9.5, 8}};
  w.rooms = {a, b};
  try {
    validateWorld(w, "w.json");
    ADD_FAILURE() << "overlap not detected";
  } catch (const InputError& err) {
    EXPECT_EQ(err.field(), "rooms[1].polygon");
  }
  // Sharing a wall is fine, and so is a 5 cm sliver along it (imprecise imported plans).
  w.rooms[1].polygon = {{10, 2}, {20, 2}, {20, 8}, {10, 8}};
  EXPECT_NO_THROW(validateWorld(w, "w.json"));
  w.rooms[1].polygon = {{9.95, 2}, {20, 2}, {20, 8}, {9.95, 8}};
  EXPECT_NO_THROW(validateWorld(w, "w.json"));
  // An L-shaped room with a rectangle in its notch: bounding boxes overlap, floors do not.
  w.rooms[0].polygon = {{0, 0}, {10, 0}, {10, 4}, {4, 4}, {4, 10}, {0, 10}};
  w.rooms[1].polygon = {{4, 4}, {10, 4}, {10, 10}, {4, 10}};
  EXPECT_NO_THROW(validateWorld(w, "w.json"));
  w.rooms[1].polygon = {{3.5, 3.5}, {10, 3.5}, {10, 10}, {3.5, 10}};
  EXPECT_THROW(validateWorld(w, "w.json"), InputError);
}

TEST(WorldIo, ObjectOutsideEveryRoomIsRejected) {
  const std::string e = loadError("outside.json", mutated([](json& j) { j["objects"][4]["center"] = {500.0, 500.0, 0.5}; }));
  EXPECT_NE(e.find("outside.json: objects[4]"), std::string::npos) << e;
  EXPECT_NE(e.find("outside every room"), std::string::npos) << e;
}

TEST(WorldIo, DuplicateIdsAndBadDoorsAreRejected) {
  std::string e = loadError("dup.json", mutated([](json& j) { j["objects"][1]["id"] = j["objects"][0]["id"]; }));
  EXPECT_NE(e.find("objects[1].id: duplicate object id"), std::string::npos) << e;
  e = loadError("door.json", mutated([](json& j) { j["doors"][0]["room_b"] = 999; }));
  EXPECT_NE(e.find("doors[0]: refers to unknown room id 999"), std::string::npos) << e;
}

TEST(WorldIo, MissingFileIsAnInputError) {
  EXPECT_THROW(loadWorld(dir() / "nope.json"), InputError);
}

TEST(WorldIo, DocumentedExampleLoads) {
  // The example in docs/world-format.md must stay a valid world.
  const std::string doc = readFile(std::string(USSNAV_SOURCE_DIR) + "/docs/world-format.md");
  const size_t a = doc.find("```json\n");
  ASSERT_NE(a, std::string::npos);
  const size_t b = doc.find("```", a + 8);
  const World w = worldFromJson(json::parse(doc.substr(a + 8, b - a - 8)), "docs example");
  EXPECT_EQ(w.rooms.size(), 2u);
  EXPECT_EQ(w.rooms[1].ceiling_z, 2.8);
  EXPECT_EQ(w.walls[0].openings.size(), 1u);
  EXPECT_EQ(w.objects[0].category, "desk");
}
