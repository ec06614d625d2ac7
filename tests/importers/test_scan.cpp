#include <gtest/gtest.h>

#include <fstream>

#include "support/input_error.hpp"
#include "support/paths.hpp"
#include "ussnav/core/error.hpp"
#include "ussnav/core/io.hpp"
#include "ussnav/sim/importers/import.hpp"
#include "ussnav/sim/world_io.hpp"

using namespace ussnav;
namespace fs = std::filesystem;

namespace {

fs::path freiburg(const std::string& f) { return test::sharedData() / "freiburg_octomaps" / f; }

using test::errorOf;

}  // namespace

TEST(Scan, Geb079OfficeFloorBecomesObstacleVoxels) {
  if (!test::haveSharedData()) GTEST_SKIP() << "shared data absent";
  ImportReport rep;
  const World w = importWorld(freiburg("geb079.bt"), {}, &rep);
  EXPECT_EQ(rep.format, "scan");
  EXPECT_TRUE(w.rooms.empty());
  EXPECT_FALSE(w.has_floor);
  EXPECT_DOUBLE_EQ(w.obstacles.resolution, 0.08);  // the octree's own
  // README: 185,673 occupied leaves, no pruned ones; one stray voxel lies below the floor band.
  EXPECT_GT(w.obstacles.cells.size(), 180000u);
  EXPECT_LE(w.obstacles.cells.size(), 185673u);
  // README: occupied extent [-7.96, 30.92] x [-7.48, 7.40] (leaf centres): about 39 x 15 m.
  const Aabb b = w.bounds();
  EXPECT_NEAR(b.min.x(), -8.0, 0.1);
  EXPECT_NEAR(b.max.x(), 30.96, 0.1);
  EXPECT_NEAR(b.size().y(), 15.0, 0.2);
  EXPECT_LT(b.size().z(), 3.2);
}

TEST(Scan, Geb079StartIsInTheCorridorFarFromEveryVoxel) {
  if (!test::haveSharedData()) GTEST_SKIP() << "shared data absent";
  const World w = importWorld(freiburg("geb079.bt"));
  const Vec3 s = w.start.position;
  EXPECT_NEAR(s.z(), 1.2, 0.1);  // the floor slab tops out at z = 0
  double nearest = 1e9;
  for (const auto& c : w.obstacles.cells) {
    const Vec3 centre = w.obstacles.origin + (c.cast<double>() + Vec3::Constant(0.5)) * w.obstacles.resolution;
    nearest = std::min(nearest, (centre - s).norm());
  }
  EXPECT_GT(nearest, 0.7);
  // The corridor runs along x through the middle of the floor (|y| < 1.2 m).
  EXPECT_LT(std::abs(s.y()), 1.2);
  EXPECT_GT(s.x(), 0.0);
  EXPECT_LT(s.x(), 25.0);
}

TEST(Scan, PcdAndOctreeReadersAgreeWithTheReadmeCounts) {
  if (!test::haveSharedData()) GTEST_SKIP() << "shared data absent";
  EXPECT_EQ(readPcdXyz(freiburg("geb079_occupied.pcd")).size(), 185673u);
  const OctreeVoxels ot = readOctomapOccupied(freiburg("fr_079_scene.ot"));
  EXPECT_DOUBLE_EQ(ot.resolution, 0.05);
  EXPECT_EQ(ot.centers.size(), 38325u);  // README: occupied leaves read by liboctomap
  // The PCD at 0.1 m: coarser than the octree, same building.
  const World w = importWorld(freiburg("geb079_occupied.pcd"));
  EXPECT_DOUBLE_EQ(w.obstacles.resolution, 0.1);
  EXPECT_NEAR(w.bounds().size().x(), 39.0, 0.2);
}

TEST(Scan, TruncatedAndGarbageFilesAreInputErrors) {
  const auto dir = test::tempDir("scan_bad");
  // PCD whose POINTS promises more than the file holds.
  const auto pcd = dir / "short.pcd";
  {
    std::ofstream o(pcd, std::ios::binary);
    o << "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 1000\nHEIGHT 1\nPOINTS 1000\nDATA binary\n";
    const float xyz[6] = {0, 0, 0, 1, 1, 1};
    o.write(reinterpret_cast<const char*>(xyz), sizeof xyz);
  }
  std::string e = errorOf([&] { importWorld(pcd); });
  EXPECT_NE(e.find("short.pcd"), std::string::npos) << e;
  EXPECT_NE(e.find("POINTS"), std::string::npos) << e;

  const auto no_header = dir / "noise.pcd";
  std::ofstream(no_header) << "hello\x01\x02 world";
  e = errorOf([&] { readPcdXyz(no_header); });
  EXPECT_NE(e.find("noise.pcd"), std::string::npos) << e;

  const auto garbage = dir / "garbage.bt";
  std::ofstream(garbage) << "# Octomap OcTree binary file\nid OcTree\nsize 99999\nres 0.1\ndata\n\xff\xff\xff\xff";
  e = errorOf([&] { importWorld(garbage); });
  EXPECT_NE(e.find("garbage.bt"), std::string::npos) << e;

  if (!test::haveSharedData()) return;
  const std::string bytes = readFile(freiburg("geb079.bt"));
  const auto cut = dir / "cut.bt";
  std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  e = errorOf([&] { importWorld(cut); });
  EXPECT_NE(e.find("cut.bt"), std::string::npos) << e;
  EXPECT_NE(e.find("truncated"), std::string::npos) << e;

  const std::string ot = readFile(freiburg("fr_079_scene.ot"));
  const auto cut_ot = dir / "cut.ot";
  std::ofstream(cut_ot, std::ios::binary) << ot.substr(0, ot.size() - 100);
  e = errorOf([&] { importWorld(cut_ot); });
  EXPECT_NE(e.find("cut.ot"), std::string::npos) << e;
}
