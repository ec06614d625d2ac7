// Waypoints from a CSV file (`ussnav map --trajectory FILE.csv`, `graph view --trajectory`): plain
// x,y,z rows, or a header naming the columns, as in `explore`'s trajectory.csv (t,x,y,z,yaw).

#include <gtest/gtest.h>

#include <fstream>

#include "support/paths.hpp"
#include "ussnav/core/error.hpp"
#include "ussnav/sim/trajectory.hpp"

namespace ussnav {
namespace {

std::vector<Vec3> load(const std::string& name, const std::string& text) {
  const auto p = test::tempDir("trajectory_csv") / name;
  { std::ofstream(p) << text; }
  return loadWaypointsCsv(p);
}

TEST(TrajectoryCsv, AHeaderNamesTheColumnsPlainRowsAreXyz) {
  const auto plain = load("plain.csv", "1,2,1.2\n-3.5,.5,1.0,0.7\n");
  ASSERT_EQ(plain.size(), 2u);
  EXPECT_EQ(plain[1], Vec3(-3.5, 0.5, 1.0));
  const auto named = load("named.csv", "t,x,y,z,yaw\r\n0.00,1.000,2.000,1.200,0.0\r\n0.07,1.100,2.050,1.200,0.1\r\n");
  ASSERT_EQ(named.size(), 2u);
  EXPECT_EQ(named[1], Vec3(1.1, 2.05, 1.2));  // not t,x,y
  const auto swapped = load("swapped.csv", "# comment\nz,y,x\n1.2,2,1\n");
  EXPECT_EQ(swapped.at(0), Vec3(1, 2, 1.2));
}

TEST(TrajectoryCsv, BadFilesNameTheLine) {
  auto expectError = [](const std::string& name, const std::string& text, const std::string& field) {
    try {
      load(name, text);
      ADD_FAILURE() << name << " accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), field) << e.what();
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  };
  expectError("noz.csv", "t,x,y\n0,1,2\n", "line 1");             // header without z
  expectError("short.csv", "t,x,y,z,yaw\n0,1,2\n", "line 2");     // row shorter than the header says
  expectError("word.csv", "1,2,3\n4,five,6\n", "line 2");
  expectError("nan.csv", "1,2,nan\n", "line 1");
  expectError("empty.csv", "x,y,z\n", "");
}

}  // namespace
}  // namespace ussnav
