// Objects seen beyond a region go to the region of the frontier facing them through space seen
// free (episode/beyond_objects.hpp).

#include <gtest/gtest.h>

#include "support/dense_grid.hpp"
#include "ussnav/episode/beyond_objects.hpp"

using namespace ussnav;

namespace {

// Plan of the scene (x right, y up; z 0..2.4): a kitchen [0,4]x[0,4] (region 0) where the UAV
// is, a hallway [4,8]x[0,4] (region 1), a bedroom beyond x = 8 not entered. The bed at (10, 2)
// was seen from the kitchen through both doors (y 1.5..2.5), which left a free strip to it.
// Everything else beyond x = 8 is unknown but for a wall at y = 2.9..3.0 above the bed.
struct Scene {
  test::DenseGrid map{Aabb::of(Vec3(0, 0, 0), Vec3(12, 6, 2.4)), 0.1};
  ObjectBrief bed{7, "bed", Vec3(10.0, 2.0, 0.4), Vec3(1.0, 1.0, 0.8), 12};
  std::vector<ExplorationTarget> targets;
  Scene() {
    map.carve(Aabb::of(Vec3(0, 0, 0), Vec3(8, 4, 2.4)));
    map.wall(Aabb::of(Vec3(3.95, 0, 0), Vec3(4.05, 1.5, 2.4)));
    map.wall(Aabb::of(Vec3(3.95, 2.5, 0), Vec3(4.05, 4, 2.4)));
    map.wall(Aabb::of(Vec3(7.95, 0, 0), Vec3(8.05, 1.5, 2.4)));
    map.wall(Aabb::of(Vec3(7.95, 2.5, 0), Vec3(8.05, 4, 2.4)));
    map.carve(Aabb::of(Vec3(8, 1.5, 0.2), Vec3(9.5, 2.5, 2.0)));  // the strip the camera saw
    map.wall(Aabb::of(Vec3(8.5, 2.9, 0), Vec3(12, 3.0, 2.4)));
    map.wall(Aabb::of(Vec3(9.5, 1.6, 0), Vec3(10.5, 2.4, 0.8)));  // the bed itself
  }
  void add(const Vec3& c, int region, TargetKind kind = TargetKind::Frontier) {
    ExplorationTarget t;
    t.kind = kind;
    t.centroid = c;
    t.region = region;
    t.viewpoints.push_back(Viewpoint{});
    targets.push_back(t);
  }
  std::vector<RegionSummary> regions() const {
    std::vector<RegionSummary> r(4);
    for (int i = 0; i < 4; ++i) r[size_t(i)].id = i;
    r[0].beyond.push_back(bed);
    return r;
  }
};

}  // namespace

TEST(BeyondObjects, AnObjectSeenThroughDoorsGoesToTheRegionOfTheFrontierFacingIt) {
  Scene s;
  s.add(Vec3(1.0, 3.9, 1.0), 0);   // the kitchen's own frontier, 8.9 m away, behind walls
  s.add(Vec3(8.6, 2.0, 1.0), 1);   // the hallway's door frontier: 1.4 m, through the seen strip
  s.add(Vec3(10.0, 3.3, 1.0), 2);  // nearer (1.3 m), but behind the wall above the bed
  s.add(Vec3(11.3, 2.0, 1.0), 3);  // nearer (1.3 m), but the line to the bed is all unknown
  s.add(Vec3(9.0, 2.0, 1.0), 3, TargetKind::Unseen);  // an unseen patch leads nowhere new
  EXPECT_EQ(frontierFacing(s.bed, s.targets, s.map), 1);

  auto regions = s.regions();
  EXPECT_EQ(facingFrontierRegions(regions, s.targets, s.map), 1);
  EXPECT_TRUE(regions[0].beyond.empty());
  ASSERT_EQ(regions[1].beyond.size(), 1u);
  EXPECT_EQ(regions[1].beyond[0].id, 7);
  EXPECT_TRUE(regions[2].beyond.empty() && regions[3].beyond.empty());
  EXPECT_TRUE(regions[1].objects.empty());  // still beyond: evidence about the room behind
}

TEST(BeyondObjects, WithoutAFrontierFacingItAnObjectStaysWithTheRegionThatSawIt) {
  Scene s;
  s.add(Vec3(10.0, 3.3, 1.0), 2);
  s.add(Vec3(11.3, 2.0, 1.0), 3);
  EXPECT_EQ(frontierFacing(s.bed, s.targets, s.map), -1);
  auto regions = s.regions();
  EXPECT_EQ(facingFrontierRegions(regions, s.targets, s.map), 0);
  ASSERT_EQ(regions[0].beyond.size(), 1u);

  // A frontier of the observing region itself facing it: nothing moves either.
  s.add(Vec3(8.6, 2.0, 1.0), 0);
  EXPECT_EQ(frontierFacing(s.bed, s.targets, s.map), 2);
  EXPECT_EQ(facingFrontierRegions(regions, s.targets, s.map), 0);
  EXPECT_EQ(regions[0].beyond.size(), 1u);

  // A target with no region (its node not in a region yet) counts for none.
  Scene t;
  t.add(Vec3(8.6, 2.0, 1.0), -1);
  EXPECT_EQ(frontierFacing(t.bed, t.targets, t.map), -1);
}
