// The AWS RoboMaker Gazebo importer on the real hospital and small-house data: walls from the
// COLLADA collision meshes land where the data's own boxes say, the objects are the buildings'
// own, the UAV can reach them from the start, and bad datasets name the file and line.

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <random>
#include <set>
#include <sstream>

#include "support/input_error.hpp"
#include "support/paths.hpp"
#include "ussnav/core/config.hpp"
#include "ussnav/core/error.hpp"
#include "ussnav/sim/ground_truth.hpp"
#include "ussnav/sim/gt_paths.hpp"
#include "ussnav/sim/importers/import.hpp"
#include "ussnav/sim/world_io.hpp"

using namespace ussnav;
namespace fs = std::filesystem;

namespace {

fs::path hospital() { return test::sharedData() / "aws_hospital"; }
fs::path smallHouse() { return test::sharedData() / "aws_small_house"; }

using test::errorOf;

std::map<std::string, int> categories(const World& w) {
  std::map<std::string, int> n;
  for (const auto& o : w.objects) ++n[o.category];
  return n;
}

// Shortest flight from the world's start to the free cell nearest each object of `category`.
std::vector<double> flightsTo(const World& w, const std::string& category) {
  const Config cfg = defaultConfig();
  const GroundTruthGrid gt(w, cfg.sim.gt_resolution, 0.5);
  const GtPlanner planner(gt, w, cfg.sim.uav.flight_height, cfg.sim.uav.radius);
  std::vector<double> out;
  for (const auto& o : w.objects) {
    if (o.category != category) continue;
    const auto goal = planner.nearestFree(o.box.center.head<2>(), 2.5);  // an L-shaped sofa's box is 2.5 m
    const auto path = goal ? planner.shortestPath(w.start.position.head<2>(), *goal) : std::nullopt;
    out.push_back(path ? GtPlanner::length(*path) : -1.0);
  }
  return out;
}

}  // namespace

TEST(Gazebo, VoxeliseTrianglesCoversAFlatSquareExactly) {
  // Two triangles spanning [0.05, 0.95]^2 at z = 0.55: the 10 x 10 cells of layer 5, no more.
  const std::vector<std::array<Vec3, 3>> square{
      {Vec3(0.05, 0.05, 0.55), Vec3(0.95, 0.05, 0.55), Vec3(0.95, 0.95, 0.55)},
      {Vec3(0.05, 0.05, 0.55), Vec3(0.95, 0.95, 0.55), Vec3(0.05, 0.95, 0.55)}};
  const auto cells = voxeliseTriangles(square, 0.1);
  ASSERT_EQ(cells.size(), 100u);
  for (const auto& c : cells) {
    EXPECT_EQ(c.z(), 5);
    EXPECT_TRUE(c.x() >= 0 && c.x() <= 9 && c.y() >= 0 && c.y() <= 9) << c.transpose();
  }
}

TEST(Gazebo, VoxeliseTrianglesHasEveryPointOfATiltedTriangleAndNothingFar) {
  const std::array<Vec3, 3> t{Vec3(-1.23, 0.4, 0.1), Vec3(2.07, -0.9, 1.3), Vec3(0.5, 1.8, 2.9)};
  const double res = 0.1;
  const auto cells = voxeliseTriangles({t}, res);
  std::set<std::tuple<int, int, int>> set;
  for (const auto& c : cells) set.insert({c.x(), c.y(), c.z()});
  // Every point of the triangle lies in a listed cell.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 20000; ++i) {
    double a = u(rng), b = u(rng);
    if (a + b > 1.0) a = 1.0 - a, b = 1.0 - b;
    const Vec3 p = t[0] + (t[1] - t[0]) * a + (t[2] - t[0]) * b;
    const Vec3 q = p / res;
    ASSERT_TRUE(set.count({int(std::floor(q.x())), int(std::floor(q.y())), int(std::floor(q.z()))})) << p.transpose();
  }
  // No cell lies farther from the triangle's plane than its half diagonal.
  const Vec3 n = (t[1] - t[0]).cross(t[2] - t[0]).normalized();
  for (const auto& c : cells) {
    const Vec3 centre = (c.cast<double>() + Vec3::Constant(0.5)) * res;
    EXPECT_LE(std::abs(n.dot(centre - t[0])), 0.5 * std::sqrt(3.0) * res + 1e-9);
  }
}

TEST(Gazebo, HospitalWallsLandWhereTheDataBoxesSay) {
  if (!test::haveSharedData()) GTEST_SKIP() << "shared data absent";
  ImportReport rep;
  const World w = importWorld(hospital(), {}, &rep);
  EXPECT_EQ(rep.format, "gazebo");
  EXPECT_EQ(w.name, "hospital");
  EXPECT_TRUE(w.rooms.empty());
  EXPECT_FALSE(w.has_floor);
  EXPECT_DOUBLE_EQ(w.obstacles.resolution, 0.1);
  // objects.tsv: the wall mesh's world box is [-12.572, 12.544] x [-35.071, 21.044]; the
  // voxels of the walls (between floor and ceiling slabs) cover the same to a voxel.
  Vec3i lo = Vec3i::Constant(1 << 20), hi = -lo;
  int top = -100, bottom = 100;
  for (const auto& c : w.obstacles.cells) {
    top = std::max(top, c.z());
    bottom = std::min(bottom, c.z());
    if (c.z() < 0 || c.z() >= 30) continue;
    lo = lo.cwiseMin(c);
    hi = hi.cwiseMax(c);
  }
  EXPECT_EQ(bottom, -1);  // the floor slab, top at z = 0
  EXPECT_EQ(top, 30);     // the ceiling slab on the 3 m walls
  EXPECT_NEAR(lo.x() * 0.1, -12.572, 0.1);
  EXPECT_NEAR((hi.x() + 1) * 0.1, 12.544, 0.1);
  EXPECT_NEAR(lo.y() * 0.1, -35.071, 0.1);
  EXPECT_NEAR((hi.y() + 1) * 0.1, 21.044, 0.1);
  // The floor slab covers the footprint: 252 x 562 cells.
  const auto floor = std::count_if(w.obstacles.cells.begin(), w.obstacles.cells.end(), [](const Vec3i& c) { return c.z() == -1; });
  EXPECT_EQ(floor, (hi.x() - lo.x() + 1) * (hi.y() - lo.y() + 1));
}

TEST(Gazebo, HospitalObjectsAreTheDatasetsAndReachable) {
  if (!test::haveSharedData()) GTEST_SKIP() << "shared data absent";
  ImportReport rep;
  const World w = importWorld(hospital() / "hospital.world", {}, &rep);
  EXPECT_EQ(rep.source_objects, 181);
  const auto n = categories(w);
  // README: Toilet x6, one refrigerator, one TV, Sofa + SofaB x2, 9 CGMClassic ward beds and a
  // MalePatientBed; 16 curtains skipped as cloth.
  EXPECT_EQ(n.at("toilet"), 6);
  EXPECT_EQ(n.at("fridge"), 1);
  EXPECT_EQ(n.at("tv"), 1);
  EXPECT_EQ(n.at("sofa"), 3);
  EXPECT_EQ(n.at("bed"), 10);
  EXPECT_EQ(n.count("curtain"), 0u);
  // Three Fuel models have a pose z of -757769000 in the source: a warning each, on the floor.
  int far_z = 0;
  for (const auto& m : rep.warnings) far_z += m.find("is not on this floor") != std::string::npos;
  EXPECT_EQ(far_z, 3);
  for (const auto& o : w.objects) EXPECT_GE(o.box.bounds().min.z(), -0.03) << o.category;
  // The start lies in free space and every toilet and the fridge can be flown to from it.
  const Config cfg = defaultConfig();
  const GroundTruthGrid gt(w, cfg.sim.gt_resolution, 0.5);
  EXPECT_FALSE(gt.sphereCollides(w.start.position, cfg.sim.uav.radius));
  for (const std::string cat : {"toilet", "fridge", "tv", "sofa"})
    for (double d : flightsTo(w, cat)) EXPECT_GT(d, 0.0) << cat << " unreachable";
  // The fridge is in the far south-west lounge: a long flight (L* of the episodes: 32.5 m).
  EXPECT_GT(flightsTo(w, "fridge").front(), 25.0);
}

TEST(Gazebo, SmallHouseKeepsItsOuterDoorShutAndOpensTheInnerOnes) {
  if (!test::haveSharedData()) GTEST_SKIP() << "shared data absent";
  ImportReport rep;
  const World w = importWorld(smallHouse(), {}, &rep);
  EXPECT_EQ(w.name, "small_house");
  const auto n = categories(w);
  EXPECT_EQ(n.at("door"), 1);  // Door_01 at (6.0, -5.55), on the south wall
  EXPECT_EQ(n.at("bed"), 1);
  EXPECT_EQ(n.at("fridge"), 1);
  EXPECT_EQ(n.at("tv"), 2);
  EXPECT_EQ(n.at("sofa"), 1);
  for (const auto& o : w.objects) {
    if (o.category == "door") {
      EXPECT_NEAR(o.box.center.y(), -5.55, 0.1);
    }
  }
  // Behind the four inner (folding) doors: the bedroom, the kitchen and the gym.
  for (const std::string cat : {"bed", "fridge", "exercise machine"})
    for (double d : flightsTo(w, cat)) EXPECT_GT(d, 0.0) << cat << " unreachable";
  // Reloads the same from its file.
  const fs::path tmp = fs::temp_directory_path() / "ussnav_gazebo_house.json";
  saveWorld(w, tmp);
  const World back = loadWorld(tmp);
  EXPECT_EQ(back.obstacles.cells.size(), w.obstacles.cells.size());
  EXPECT_EQ(back.objects.size(), w.objects.size());
  fs::remove(tmp);
}

TEST(Gazebo, BadDatasetsNameTheFileAndLine) {
  if (!test::haveSharedData()) GTEST_SKIP() << "shared data absent";
  const fs::path dir = fs::temp_directory_path() / "ussnav_gazebo_bad";
  fs::remove_all(dir);
  fs::create_directories(dir);
  fs::create_directory_symlink(smallHouse() / "models", dir / "models");
  std::ifstream in(smallHouse() / "objects.tsv");
  std::stringstream all;
  all << in.rdbuf();
  const std::string table = all.str();
  auto write = [&](const std::string& name, const std::string& text) { std::ofstream(dir / name) << text; };

  // No .world beside objects.tsv: not a dataset this importer reads.
  write("objects.tsv", table);
  EXPECT_NE(errorOf([&] { importWorld(dir); }).find("accepted"), std::string::npos);
  write("small_house.world", "<sdf/>");
  EXPECT_NO_THROW(importWorld(dir));

  // Truncated in the middle of a row: the row's missing cells are named with file and line.
  write("objects.tsv", table.substr(0, table.find('\n', table.size() / 2) + 12));
  std::string e = errorOf([&] { importWorld(dir / "small_house.world"); });
  EXPECT_NE(e.find("objects.tsv"), std::string::npos) << e;
  EXPECT_NE(e.find("line"), std::string::npos) << e;

  // A wall model whose meshes are missing.
  std::string renamed = table;
  const std::string wall = "aws_robomaker_residential_HouseWallB_01\t";
  renamed.replace(renamed.find(wall), wall.size(), "aws_robomaker_residential_HouseWallZ_01\t");
  write("objects.tsv", renamed);
  e = errorOf([&] { importWorld(dir / "objects.tsv"); });
  EXPECT_NE(e.find("HouseWallZ_01"), std::string::npos) << e;
  EXPECT_NE(e.find("collision"), std::string::npos) << e;

  // geometry_in_repo neither yes nor no.
  std::string bad_flag = table;
  const size_t row2 = bad_flag.find('\n', bad_flag.find('\n') + 1) + 1;
  const size_t flag = bad_flag.find("\tyes\t", row2);
  bad_flag.replace(flag, 5, "\tmaybe\t");
  write("objects.tsv", bad_flag);
  e = errorOf([&] { importWorld(dir); });
  EXPECT_NE(e.find("geometry_in_repo"), std::string::npos) << e;
  EXPECT_NE(e.find("line 3"), std::string::npos) << e;
  fs::remove_all(dir);
}
