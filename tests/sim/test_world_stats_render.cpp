#include <gtest/gtest.h>

#include "ussnav/sim/floorplan_generator.hpp"
#include "ussnav/sim/layout_geometry.hpp"
#include "ussnav/sim/world_render.hpp"
#include "ussnav/sim/world_stats.hpp"

using namespace ussnav;

namespace {

// Two rooms side by side (office 6 x 4, kitchen 4 x 4, ceiling 3), a door between them, one
// 1 x 1 x 1 box in the office.
World twoRooms() {
  World w;
  w.name = "two";
  Room a, b;
  a.id = 1, a.type = "office", a.polygon = {{0, 0}, {6, 0}, {6, 4}, {0, 4}}, a.ceiling_z = 3.0;
  b.id = 2, b.type = "kitchen", b.polygon = {{6, 0}, {10, 0}, {10, 4}, {6, 4}}, b.ceiling_z = 3.0;
  w.rooms = {a, b};
  Wall wl;
  wl.a = Vec2(6, 0), wl.b = Vec2(6, 4), wl.thickness = 0.12;
  wl.openings.push_back({1.5, 2.5, 0.0, 2.1});
  w.walls.push_back(wl);
  for (auto [p, q] : {std::pair{Vec2(0, 0), Vec2(10, 0)}, {Vec2(10, 0), Vec2(10, 4)}, {Vec2(10, 4), Vec2(0, 4)},
                      {Vec2(0, 4), Vec2(0, 0)}}) {
    Wall e;
    e.a = p, e.b = q, e.thickness = 0.12;
    w.walls.push_back(e);
  }
  Door d;
  d.id = 1, d.room_a = 1, d.room_b = 2, d.center = Vec2(6, 2), d.width = 1.0;
  w.doors.push_back(d);
  Object o;
  o.id = 1, o.category = "cabinet", o.room_id = 1;
  o.box.center = Vec3(2, 2, 0.5), o.box.half_extents = Vec3(0.5, 0.5, 0.5);
  w.objects.push_back(o);
  w.start.position = Vec3(4, 2, 1.2);
  return w;
}

}  // namespace

TEST(WorldStats, AreaAndFreeVolumeFollowTheirDefinitions) {
  const WorldStats s = computeWorldStats(twoRooms());
  EXPECT_EQ(s.rooms, 2);
  EXPECT_EQ(s.objects, 1);
  EXPECT_EQ(s.rooms_by_type.at("office"), 1);
  EXPECT_EQ(s.objects_by_category.at("cabinet"), 1);
  EXPECT_DOUBLE_EQ(s.floor_area_m2, 40.0);
  EXPECT_DOUBLE_EQ(s.room_volume_m3, 120.0);
  EXPECT_DOUBLE_EQ(s.object_volume_m3, 1.0);
  EXPECT_DOUBLE_EQ(s.free_volume_m3, 119.0);
  const auto j = worldStatsToJson(s);
  for (const char* k : {"rooms", "rooms_by_type", "objects", "objects_by_category", "floor_area_m2", "free_volume_m3"})
    EXPECT_TRUE(j.contains(k)) << k;
  EXPECT_NE(worldStatsToText(s).find("floor area: 40.0 m^2"), std::string::npos);
}

TEST(WorldStats, GeneratedWorldVolumesAddUp) {
  GeneratorParams p;
  p.seed = 5;
  const World w = generateWorld(p);
  const WorldStats s = computeWorldStats(w);
  int rooms = 0;
  for (const auto& [t, n] : s.rooms_by_type) rooms += n;
  EXPECT_EQ(rooms, s.rooms);
  EXPECT_GT(s.object_volume_m3, 5.0);
  EXPECT_LT(s.object_volume_m3, 0.2 * s.room_volume_m3);
  EXPECT_NEAR(s.free_volume_m3, s.room_volume_m3 - s.object_volume_m3, 1e-9);
  EXPECT_NEAR(s.room_volume_m3, 2.8 * s.floor_area_m2, 1e-6);
}

TEST(WorldRender, DrawsRoomsWallsDoorsAndObjectsWhereTheyAre) {
  const World w = twoRooms();
  RenderOptions o;
  o.px_per_m = 30;
  o.object_labels = false;
  const Image img = renderWorld(w, o);
  const TopDownView v = TopDownView::fit(w.bounds(), 30, 30, o.max_px);
  auto at = [&](double x, double y) {
    const Vec2 p = v.toPx(Vec2(x, y));
    return img.at(int(std::lround(p.x())), int(std::lround(p.y())));
  };
  EXPECT_EQ(at(5, 0.5), roomTypeColor("office"));
  EXPECT_EQ(at(9, 0.5), roomTypeColor("kitchen"));
  EXPECT_EQ(at(6, 0.5), (Rgb{0, 0, 0})) << "wall";
  EXPECT_EQ(at(6, 1.8), (Rgb{220, 0, 200})) << "door across the opening";
  EXPECT_NE(at(2.0, 1.7), roomTypeColor("office")) << "object fill";
  EXPECT_NE(at(2.0, 1.7), (Rgb{255, 255, 255}));
  EXPECT_GT(img.height(), v.height) << "footer with the scale bar";
}

TEST(WorldRender, ObstacleVoxelWorldIsDrawnAsMaxProjection) {
  World w;
  w.obstacles.resolution = 0.5;
  w.obstacles.cells = {{0, 0, 0}, {0, 0, 4}, {4, 4, 0}};
  w.start.position = Vec3(2.0, 0.5, 1.0);
  RenderOptions o;
  const Image img = renderWorld(w, o);
  const TopDownView v = TopDownView::fit(w.bounds(), o.px_per_m, 30, o.max_px);
  const Vec2 tall = v.toPx(Vec2(0.25, 0.25)), low = v.toPx(Vec2(2.25, 2.25)), empty = v.toPx(Vec2(1.25, 1.25));
  const Rgb t = img.at(int(tall.x()), int(tall.y())), l = img.at(int(low.x()), int(low.y()));
  EXPECT_LT(t[0], l[0]) << "the taller column is darker";
  EXPECT_LT(l[0], 255);
  EXPECT_EQ(img.at(int(empty.x()), int(empty.y())), (Rgb{255, 255, 255}));
}

// A wall's solid runs, as the top-down picture and the web page draw them: overlapping
// openings merge, an opening past the wall's end is clamped, windows stay solid for doors only.
TEST(WallRuns, OpeningsAreCutOutMergedAndClamped) {
  Wall w;
  w.a = Vec2(0, 0);
  w.b = Vec2(10, 0);
  w.openings = {{2.0, 3.0, 0.0, 2.1}, {2.5, 4.0, 0.0, 2.1}, {6.0, 7.0, 1.0, 2.0}, {9.0, 12.0, 0.0, 2.1}};
  using Runs = std::vector<std::pair<double, double>>;
  EXPECT_EQ(solidRuns(w, anyOpening), (Runs{{0, 2}, {4, 6}, {7, 9}}));
  EXPECT_EQ(solidRuns(w, doorOpening), (Runs{{0, 2}, {4, 9}}));
  w.openings.clear();
  EXPECT_EQ(solidRuns(w, doorOpening), (Runs{{0, 10}}));
  w.b = w.a;
  EXPECT_TRUE(solidRuns(w, anyOpening).empty());
}
