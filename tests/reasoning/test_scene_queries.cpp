// goto / ask on a hand-made scene graph of two rooms joined by a door: the request picks the
// right region, the route follows the graph through the door, the CLI flies it without a
// collision, and questions are answered from the graph.

#include <gtest/gtest.h>

#include "support/test_priors.hpp"

#include <algorithm>
#include <fstream>
#include <functional>
#include <memory>
#include <optional>

#include "support/paths.hpp"
#include "support/test_worlds.hpp"
#include "ussnav/reasoning/builtin_reasoner.hpp"
#include "ussnav/reasoning/scene_queries.hpp"
#include "ussnav/scene_graph/io.hpp"
#include "ussnav/sim/world_io.hpp"

using namespace ussnav;

namespace {

using test::priors;

// A 0.6 m cube seen 5 times; `node`: the node that saw it (-1: none).
SgObject object(int id, const std::string& label, const Vec3& c, int node = -1) {
  SgObject o;
  o.id = id;
  o.label = label;
  o.centroid = c;
  o.bbox_min = c - Vec3(0.3, 0.3, 0.3);
  o.bbox_max = c + Vec3(0.3, 0.3, 0.3);
  o.n_observations = 5;
  o.node_id = node;
  return o;
}

// Nodes along y = 2 at flight height through the door of test::twoRooms (x = 5, y 1.5..2.5),
// region 0 = room A (x < 5), region 1 = room B; a fridge and a stove in A, a conference table
// and chairs in B; a dead-end node in A's corner tempts a straight line through the wall.
SceneGraph twoRoomGraph() {
  SceneGraph g;
  const std::vector<Vec3> pts{{1.0, 1.0, 1.2}, {2.5, 2.0, 1.2}, {4.0, 2.0, 1.2}, {5.0, 2.0, 1.2},
                              {6.0, 2.0, 1.2}, {7.5, 2.0, 1.2}, {9.0, 1.0, 1.2}, {4.3, 3.5, 1.2}};
  for (size_t i = 0; i < pts.size(); ++i) {
    SgNode n;
    n.id = int(i);
    n.centroid = pts[i];
    n.radius = 1.6;  // reach, as of the polyhedra of a mapped room (1.3-1.6 m)
    g.nodes.push_back(n);
  }
  for (auto [a, b] : std::vector<std::pair<int, int>>{{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 6}, {2, 7}})
    g.edges.push_back({a, b, "overlap", 1.0});
  g.regions.push_back({0, {0, 1, 2, 3, 7}, "", "", Vec3(3.0, 2.0, 1.2), {1}});
  g.regions.push_back({1, {4, 5, 6}, "", "", Vec3(7.5, 1.7, 1.2), {0}});
  g.objects.push_back(object(1, "fridge", Vec3(0.6, 3.3, 0.9)));
  g.objects.push_back(object(2, "stove", Vec3(3.5, 3.5, 0.45)));
  g.objects.push_back(object(3, "conference table", Vec3(8.6, 3.0, 0.4)));
  g.objects.push_back(object(4, "chair", Vec3(8.0, 3.2, 0.45)));
  return g;
}

// answerQuestion on twoRoomGraph(), its regions labelled by the builtin reasoner.
std::function<std::string(const char*, std::optional<Vec3>)> twoRoomAnswers() {
  const auto g = std::make_shared<const SceneGraph>(twoRoomGraph());
  BuiltinReasoner R(priors());
  const auto sem = std::make_shared<const std::map<int, RegionSemantics>>(graphSemantics(*g, &R));
  return [g, sem](const char* q, std::optional<Vec3> at) { return answerQuestion(*g, q, at, *sem, *priors()); };
}

}  // namespace

TEST(SceneQueries, RequestPicksTheRegionThatServesIt) {
  const SceneGraph g = twoRoomGraph();
  BuiltinReasoner R(priors());
  const auto sem = graphSemantics(g, &R);
  EXPECT_EQ(sem.at(0).label, "kitchen");
  const Instruction meet = interpretInstruction("I want to attend a meeting", *priors(), graphVocabulary(g));
  const RegionPick p = pickRegionForRequest(g, meet, sem, *priors());
  EXPECT_EQ(p.region, 1) << p.reason;
  EXPECT_EQ(p.object, 3);
  EXPECT_NEAR(p.goal.x(), 8.6, 1e-9);
  const Instruction cook = interpretInstruction("the fridge", *priors(), graphVocabulary(g));
  EXPECT_EQ(pickRegionForRequest(g, cook, sem, *priors()).region, 0);
  // A room asked for by name: the region labelled so, its node nearest its centroid.
  const Instruction kitchen = interpretInstruction("go to the kitchen", *priors(), graphVocabulary(g));
  const RegionPick k = pickRegionForRequest(g, kitchen, sem, *priors());
  EXPECT_EQ(k.region, 0);
  EXPECT_EQ(k.object, -1);
}

TEST(SceneQueries, ObjectsOutsideTheSpaceARegionReachesAreSeenBeyondIt) {
  SceneGraph g = twoRoomGraph();
  // A bed seen from the door node of room A (node 3) lies 3.5 m away, past every node of A
  // (radius 1.6 + kReachMargin, 1 m): evidence about the room beyond, not about A. A sink next to
  // node 2 is A's own.
  g.objects.push_back(object(5, "bed", Vec3(8.5, 2.5, 0.3), 3));
  g.objects.push_back(object(6, "sink", Vec3(4.0, 2.9, 0.8), 2));
  // A counter against A's far wall, 0.8 m past the reach of node 7 (the UAV has not flown up to
  // it): A's own. On the suites' worlds, objects seen from their own room lay within a node's
  // reach + 1 m; those seen through a door mostly further.
  g.objects.push_back(object(7, "kitchen counter", Vec3(4.3, 5.9, 0.45), 7));
  const auto s = summarizeRegions(g);
  ASSERT_EQ(s.size(), 2u);
  auto has = [](const std::vector<ObjectBrief>& v, int id) {
    return std::any_of(v.begin(), v.end(), [&](const ObjectBrief& o) { return o.id == id; });
  };
  EXPECT_TRUE(has(s[0].beyond, 5));
  EXPECT_FALSE(has(s[0].objects, 5));
  EXPECT_TRUE(has(s[0].objects, 6));
  EXPECT_TRUE(has(s[0].objects, 7));
  EXPECT_TRUE(has(s[0].objects, 1));  // the fridge in A's corner, 2.3 m from nodes 0 and 1
  EXPECT_TRUE(has(s[0].objects, 2));  // the stove, 0.8 m from node 7
  EXPECT_FALSE(has(s[1].objects, 5));
  // ask: "where" still finds it, and says where it was seen from.
  BuiltinReasoner R(priors());
  const auto sem = graphSemantics(g, &R);
  const std::string a = answerQuestion(g, "Where is the bed?", std::nullopt, sem, *priors());
  EXPECT_NE(a.find("object 5"), std::string::npos) << a;
  EXPECT_NE(a.find("seen from"), std::string::npos) << a;
}

TEST(SceneQueries, RouteFollowsTheGraphThroughTheDoor) {
  const SceneGraph g = twoRoomGraph();
  const auto r = routeOnSceneGraph(g, Vec3(2.5, 2.0, 1.2), Vec3(9.0, 1.2, 1.2));
  ASSERT_TRUE(r.has_value());
  // from, nodes 1..6, to
  ASSERT_EQ(r->size(), 8u);
  EXPECT_TRUE(r->front().isApprox(Vec3(2.5, 2.0, 1.2)));
  EXPECT_TRUE((*r)[3].isApprox(Vec3(5.0, 2.0, 1.2)));  // the door node
  // Disconnected graph: no route.
  SceneGraph cut = g;
  cut.edges.erase(cut.edges.begin() + 3);  // 3-4: the door
  EXPECT_FALSE(routeOnSceneGraph(cut, Vec3(2.5, 2.0, 1.2), Vec3(9.0, 1.2, 1.2)).has_value());
}

TEST(SceneQueries, RoutePassesThroughTheOverlapOfPolyhedraThatMeetThroughADoor) {
  // test::twoRooms' door: the wall x = 5, door y 1.5..2.5. Two nodes whose centres lie beside
  // the door (y = 1.0): the straight stretch between them crosses the wall. Their polyhedra
  // (prisms z 0.3..2.5) reach through the door into each other's room, cutting its corner as
  // the hull of ray ends does; they meet around the doorway.
  auto prism = [](std::vector<Vec2> xy) {
    std::vector<Vec3> v;
    for (const double z : {0.3, 2.5})
      for (const Vec2& p : xy) v.emplace_back(p.x(), p.y(), z);
    return v;
  };
  SceneGraph g;
  SgNode a, b;
  a.id = 0, a.centroid = Vec3(4.4, 1.0, 1.2);
  a.hull = prism({{3.0, 0.2}, {4.9, 0.2}, {5.6, 1.6}, {5.6, 2.4}, {3.0, 2.4}});
  b.id = 1, b.centroid = Vec3(5.6, 1.0, 1.2);
  b.hull = prism({{7.0, 0.2}, {5.1, 0.2}, {4.4, 1.6}, {4.4, 2.4}, {7.0, 2.4}});
  g.nodes = {a, b};
  g.edges.push_back({0, 1, "overlap", 1.0});
  const auto portal = portalBetween(a, b, 1.2);
  ASSERT_TRUE(portal.has_value());
  EXPECT_NEAR(portal->x(), 5.0, 0.05);  // the prisms mirror each other about x = 5
  EXPECT_GT(portal->y(), 1.5);          // in the doorway
  EXPECT_LT(portal->y(), 2.5);
  const auto r = routeOnSceneGraph(g, Vec3(4.0, 1.0, 1.2), Vec3(6.0, 1.0, 1.2));
  ASSERT_TRUE(r.has_value());
  ASSERT_EQ(r->size(), 5u);  // from, node 0, the portal, node 1, to
  EXPECT_TRUE((*r)[2].isApprox(*portal));
  // Polyhedra that only touch (boxes 0.1 m apart across the doorway): where they come within
  // 0.2 m of each other.
  SgNode c = a, d = b;
  c.hull = prism({{3.0, 1.5}, {4.95, 1.5}, {4.95, 2.5}, {3.0, 2.5}});
  d.hull = prism({{5.05, 1.5}, {7.0, 1.5}, {7.0, 2.5}, {5.05, 2.5}});
  const auto touch = portalBetween(c, d, 1.2);
  ASSERT_TRUE(touch.has_value());
  EXPECT_NEAR(touch->x(), 5.0, 0.1);
  EXPECT_NEAR(touch->y(), 2.0, 0.1);
  // Polyhedra that do not meet at that height, and nodes without hulls: no portal.
  EXPECT_FALSE(portalBetween(a, b, 3.0).has_value());
  g.nodes[1].hull.clear();
  EXPECT_FALSE(portalBetween(g.nodes[0], g.nodes[1], 1.2).has_value());
  EXPECT_EQ(routeOnSceneGraph(g, Vec3(4.0, 1.0, 1.2), Vec3(6.0, 1.0, 1.2))->size(), 4u);
}

TEST(SceneQueries, AnswersQuestionsFromTheGraph) {
  const auto ask = twoRoomAnswers();
  const std::string here = ask("Describe the current area", Vec3(2.0, 2.0, 1.2));
  EXPECT_NE(here.find("region 0 (kitchen)"), std::string::npos) << here;
  EXPECT_NE(here.find("fridge"), std::string::npos) << here;
  EXPECT_EQ(here.find("conference table"), std::string::npos) << here;
  const std::string where = ask("Where is the fridge?", std::nullopt);
  EXPECT_NE(where.find("fridge (object 1) is at (0.6, 3.3) in region 0"), std::string::npos) << where;
  const std::string none = ask("Is there a bed?", std::nullopt);
  EXPECT_NE(none.find("No bed"), std::string::npos) << none;
  // A request that is no question: the objects seen that serve it (session 47; was the layout).
  const std::string sit = ask("I want to sit down", std::nullopt);
  EXPECT_NE(sit.find("A chair (object 4) is at (8.0, 3.2) in region 1"), std::string::npos) << sit;
  EXPECT_EQ(sit.find("fridge"), std::string::npos) << sit;
  const std::string cook = ask("I need to cook dinner", std::nullopt);  // a stove serves; no target names it
  EXPECT_NE(cook.find("A stove (object 2)"), std::string::npos) << cook;
  const std::string tired = ask("I'm tired", std::nullopt);
  EXPECT_NE(tired.find("No bed has been seen yet"), std::string::npos) << tired;
  const std::string layout = ask("Describe the layout", std::nullopt);
  EXPECT_NE(layout.find("2 regions and 4 objects"), std::string::npos) << layout;
  EXPECT_NE(layout.find("next to region 1 ("), std::string::npos) << layout;  // was "next to 1"
}

TEST(SceneQueries, AnswersAboutANamedRoomAndListsObjects) {
  const auto ask = twoRoomAnswers();
  const std::string all = ask("List all objects", Vec3(2.0, 2.0, 1.2));
  EXPECT_EQ(all.rfind("The map holds 4 objects in 2 regions: ", 0), 0u) << all;
  for (const SgObject& o : twoRoomGraph().objects) EXPECT_NE(all.find("1 " + o.label), std::string::npos) << all;
  // A room named in the question: the regions labelled so, wherever the asker is.
  for (const char* q : {"What is in the kitchen?", "What objects are in the kitchen?"}) {
    const std::string kitchen = ask(q, Vec3(9.0, 1.2, 1.2));
    EXPECT_EQ(kitchen.rfind("Region 0 (kitchen).", 0), 0u) << q << ": " << kitchen;
    EXPECT_NE(kitchen.find("fridge"), std::string::npos) << kitchen;
    EXPECT_EQ(kitchen.find("conference table"), std::string::npos) << kitchen;
  }
  const std::string next = ask("Which room is next to the kitchen?", std::nullopt);
  EXPECT_NE(next.find("It connects to region 1"), std::string::npos) << next;
  const std::string no_room = ask("Describe the bedroom", std::nullopt);
  EXPECT_NE(no_room.find("No region is labelled bedroom yet"), std::string::npos) << no_room;
}

TEST(SceneQueriesCli, GotoFliesToTheMeetingRoomAndAskAnswers) {
  const auto dir = test::tempDir("goto_cli");
  SceneGraph g = twoRoomGraph();
  saveSceneGraph(dir / "sg.json", g);
  saveWorld(test::twoRooms(true), dir / "w.json");
  std::string out;
  const std::string base = test::cliPath() + " --quiet ";
  const int rc = test::runCommand(base + "goto --graph " + (dir / "sg.json").string() + " --world " + (dir / "w.json").string() +
                                      " --request \"I want to attend a meeting\" --out " + (dir / "goto.json").string(),
                                  &out);
  ASSERT_EQ(rc, 0) << out;
  const auto j = nlohmann::json::parse(std::ifstream(dir / "goto.json"));
  EXPECT_EQ(j["region"], 1);
  EXPECT_EQ(j["object"], 3);
  EXPECT_EQ(j["collisions"], 0);
  EXPECT_TRUE(j["arrived"].get<bool>());
  EXPECT_EQ(j["final_region"], 1);
  EXPECT_GT(j["path_length_m"].get<double>(), 5.0);
  ASSERT_EQ(test::runCommand(base + "ask --graph " + (dir / "sg.json").string() + " --question \"where is the conference table\"", &out), 0);
  EXPECT_NE(out.find("conference table (object 3)"), std::string::npos) << out;
  // Bad input: a graph without regions, a malformed point.
  g.regions.clear();
  saveSceneGraph(dir / "empty.json", g);
  EXPECT_NE(test::runCommand(base + "ask --graph " + (dir / "empty.json").string() + " --question x", &out), 0);
  EXPECT_NE(out.find("no regions"), std::string::npos) << out;
  EXPECT_NE(test::runCommand(base + "ask --graph " + (dir / "sg.json").string() + " --question x --at 1,b", &out), 0);
  EXPECT_NE(out.find("--at"), std::string::npos) << out;
  out.clear();
  EXPECT_NE(test::runCommand(base + "ask --graph " + (dir / "sg.json").string() + " --question x --at nan,1,1", &out), 0);
  EXPECT_NE(out.find("--at"), std::string::npos) << out;
}
