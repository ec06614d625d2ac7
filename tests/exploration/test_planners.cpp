// The three planners on a connectivity graph grown in two hand-made rooms joined by a door:
// costs follow the graph (through the door, not through the wall), `frontier` maximises gain
// over cost, `tsp` returns the optimal open tour, `full` picks a region and stays in it.

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "support/skeleton_scenes.hpp"
#include "ussnav/core/error.hpp"
#include "ussnav/exploration/graph_costs.hpp"
#include "ussnav/exploration/planner.hpp"
#include "ussnav/exploration/tsp.hpp"

using namespace ussnav;

namespace {

struct Scene {
  test::TwoRoomsScene rooms = test::twoRoomsGrid();
  ConnectivityGraph graph{SkeletonConfig{}};
  UavConfig uav;
  EpisodeConfig ep;
  Scene() {
    for (int i = 0; i < 20; ++i) graph.update(rooms.grid, Vec3(2.0, 2.0, 1.2), i * 0.1);
  }
  ExplorationTarget target(const Vec3& at, double gain, int region = -1) const {
    ExplorationTarget t;
    t.centroid = at;
    t.viewpoints = {Viewpoint{at, 0.0, int(gain)}};
    t.gain = gain;
    t.region = region;
    return t;
  }
  PlanInput input(const std::vector<ExplorationTarget>& targets, const Vec3& uav_at) const {
    PlanInput in;
    in.graph = &graph;
    in.map = &rooms.grid;
    in.uav.position = uav_at;
    in.uav.yaw = 0.0;
    in.targets = &targets;
    in.uav_cfg = &uav;
    in.episode_cfg = &ep;
    return in;
  }
};

}  // namespace

TEST(GraphCosts, GoThroughTheDoorNotThroughTheWall) {
  Scene s;
  ASSERT_GT(s.graph.size(), 4u);
  const Vec3 a(2.0, 2.0, 1.2), b(6.2, 2.0, 1.2);
  const GraphDistances gd(s.graph, s.rooms.grid, a);
  const double d = gd.toPoint(b);
  const Vec3 door = s.rooms.door.center();
  // At least the detour via the door's centre line, at most a generous 1.6 times it.
  const double via_door = (Vec2(door.x(), door.y()) - a.head<2>()).norm() + (b.head<2>() - Vec2(door.x(), door.y())).norm();
  EXPECT_GE(d, (b - a).norm() - 1e-9);
  EXPECT_GE(d, 0.9 * via_door);
  EXPECT_LE(d, 1.6 * via_door);
}

TEST(Planners, FrontierMaximisesGainOverCost) {
  Scene s;
  std::vector<ExplorationTarget> t = {s.target(Vec3(3.0, 2.0, 1.2), 10), s.target(Vec3(7.0, 2.0, 1.2), 200)};
  auto p = makePlanner("frontier");
  EXPECT_EQ(p->choose(s.input(t, Vec3(2.0, 2.0, 1.2))).target, 1);  // 200 / ~6 s beats 10 / 1 s
  t[1].gain = 30;
  EXPECT_EQ(p->choose(s.input(t, Vec3(2.0, 2.0, 1.2))).target, 0);
  const std::vector<ExplorationTarget> none;
  EXPECT_EQ(p->choose(s.input(none, Vec3(2.0, 2.0, 1.2))).target, -1);
}

TEST(Planners, TspTourIsOptimalForTheGraphCosts) {
  Scene s;
  std::vector<ExplorationTarget> t = {s.target(Vec3(7.5, 3.0, 1.2), 10), s.target(Vec3(1.0, 1.0, 1.2), 10),
                                      s.target(Vec3(5.5, 1.0, 1.2), 10), s.target(Vec3(3.5, 3.2, 1.2), 10)};
  const PlanInput in = s.input(t, Vec3(2.0, 2.0, 1.2));
  const PlanChoice c = makePlanner("tsp")->choose(in);
  ASSERT_EQ(c.tour.size(), t.size());
  EXPECT_EQ(c.target, c.tour.front());
  // Brute force over the same cost model.
  const auto costs = targetCosts(in);
  CostMatrix m(t.size() + 1, std::vector<double>(t.size() + 1, 0.0));
  for (size_t i = 0; i < t.size(); ++i) {
    m[0][i + 1] = costs[i].cost_s;
    const GraphDistances gd(s.graph, s.rooms.grid, t[i].viewpoints[0].position);
    for (size_t j = 0; j < t.size(); ++j)
      if (i != j) m[i + 1][j + 1] = gd.toPoint(t[j].viewpoints[0].position) / s.uav.max_speed;
  }
  std::vector<int> order;
  for (int k : c.tour) order.push_back(k + 1);
  EXPECT_NEAR(openTourCost(m, order), bruteForceOpenTsp(m).cost, 1e-6);
}

TEST(Planners, FullPicksTheBestRegionAndStaysInIt) {
  Scene s;
  std::vector<ExplorationTarget> t = {s.target(Vec3(3.0, 1.0, 1.2), 5, 0), s.target(Vec3(7.0, 1.0, 1.2), 100, 1),
                                      s.target(Vec3(7.5, 3.0, 1.2), 100, 1)};
  auto p = makePlanner("full");
  const PlanChoice c1 = p->choose(s.input(t, Vec3(2.0, 2.0, 1.2)));
  EXPECT_EQ(c1.region, 1);
  EXPECT_TRUE(c1.target == 1 || c1.target == 2);
  // Region 0 now looks better, but the committed region still has targets: stay.
  t[0].gain = 1000;
  const PlanChoice c2 = p->choose(s.input(t, Vec3(6.5, 2.0, 1.2)));
  EXPECT_EQ(c2.region, 1);
  // When region 1 is exhausted the planner moves on.
  t.erase(t.begin() + 1, t.end());
  EXPECT_EQ(p->choose(s.input(t, Vec3(6.5, 2.0, 1.2))).region, 0);
  // A coarse chooser overrides the default.
  std::vector<ExplorationTarget> t2 = {s.target(Vec3(3.0, 1.0, 1.2), 5, 0), s.target(Vec3(7.0, 1.0, 1.2), 100, 1)};
  auto q = makePlanner("full", [](const PlanInput&, const std::vector<RegionCandidate>&) { return 0; });
  EXPECT_EQ(q->choose(s.input(t2, Vec3(2.0, 2.0, 1.2))).region, 0);
}

TEST(Planners, FullFliesToTheRegionsBestTargetAndToursTheRestBySearchOrder) {
  // All in region 1 (room B). From the UAV at the door: a sliver 0.5 m away (gain 5), a big
  // opening 2 m away (gain 300), and beyond it two more. Gain / cost picks the opening first.
  Scene s;
  std::vector<ExplorationTarget> t = {s.target(Vec3(6.0, 2.0, 1.2), 5, 1), s.target(Vec3(7.5, 2.0, 1.2), 300, 1),
                                      s.target(Vec3(8.5, 3.0, 1.2), 40, 1), s.target(Vec3(8.5, 1.0, 1.2), 200, 1)};
  const PlanInput in = s.input(t, Vec3(5.5, 2.0, 1.2));
  const auto costs = targetCosts(in);
  int best = 0;
  for (int i = 1; i < 4; ++i)
    if (t[size_t(i)].gain / std::max(costs[size_t(i)].cost_s, 0.1) > t[size_t(best)].gain / std::max(costs[size_t(best)].cost_s, 0.1))
      best = i;
  ASSERT_EQ(best, 1);
  const PlanChoice c = makePlanner("full")->choose(in);
  EXPECT_EQ(c.region, 1);
  EXPECT_EQ(c.target, 1);
  ASSERT_EQ(c.tour.size(), 4u);
  EXPECT_EQ(c.tour.front(), 1);
  std::vector<int> sorted = c.tour;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(sorted, (std::vector<int>{0, 1, 2, 3}));
  // The rest (0, 2, 3) is the optimal search order from the opening's viewpoint: brute force
  // over the same cost model.
  const std::vector<int> rest{0, 2, 3};
  CostMatrix m(4, std::vector<double>(4, 0.0));
  std::vector<double> w{0, 5, 40, 200};
  std::vector<Vec3> at{t[1].viewpoints[0].position};
  for (int k : rest) at.push_back(t[size_t(k)].viewpoints[0].position);
  for (size_t i = 0; i < 4; ++i) {
    const GraphDistances gd(s.graph, s.rooms.grid, at[i]);
    for (size_t j = 0; j < 4; ++j)
      if (i != j) m[i][j] = gd.toPoint(at[j]) / s.uav.max_speed;
  }
  std::vector<int> order;
  for (size_t k = 1; k < 4; ++k) order.push_back(int(std::find(rest.begin(), rest.end(), c.tour[k]) - rest.begin()) + 1);
  std::vector<int> perm{1, 2, 3};
  double opt = 1e300;
  do opt = std::min(opt, searchTourCost(m, w, perm));
  while (std::next_permutation(perm.begin(), perm.end()));
  EXPECT_NEAR(searchTourCost(m, w, order), opt, 1e-6);
}

TEST(Planners, UnknownNameIsAnInputError) { EXPECT_THROW(makePlanner("astar"), InputError); }
