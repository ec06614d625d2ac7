// BandMemory: one bit per voxel of a height band, across chunk borders and negative keys.

#include <gtest/gtest.h>

#include <random>
#include <set>
#include <tuple>

#include "ussnav/mapping/band_memory.hpp"

using namespace ussnav;

TEST(BandMemory, RemembersExactlyTheVoxelsMarkedInTheBand) {
  BandMemory m(3, 18);  // z-keys 3..20
  EXPECT_FALSE(m.known(Vec3i(0, 0, 5)));
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> u(-100, 100), uz(0, 24);
  std::set<std::tuple<int, int, int>> marked;
  for (int i = 0; i < 20000; ++i) {
    const Vec3i k(u(rng), u(rng), uz(rng));
    m.mark(k);
    if (k.z() >= 3 && k.z() <= 20) marked.insert({k.x(), k.y(), k.z()});
  }
  // Chunk borders and the sign change: -1 / 0 and 31 / 32 lie in different chunks.
  for (const Vec3i& k : {Vec3i(-1, -1, 3), Vec3i(31, 32, 20), Vec3i(-32, 0, 7), Vec3i(-33, 31, 7)}) {
    m.mark(k);
    marked.insert({k.x(), k.y(), k.z()});
  }
  int wrong = 0;
  for (int x = -102; x <= 102; ++x)
    for (int y = -102; y <= 102; ++y)
      for (int z = 0; z <= 24; ++z) wrong += m.known(Vec3i(x, y, z)) != (marked.count({x, y, z}) == 1);
  EXPECT_EQ(wrong, 0);
  EXPECT_FALSE(m.known(Vec3i(-1, -1, 2)));  // below the band: never remembered
  EXPECT_LE(m.chunks(), 64u);               // keys in [-128, 127]^2: 8 x 8 chunks of 32 x 32 at most
  m.clear();
  EXPECT_FALSE(m.known(Vec3i(-1, -1, 3)));
}
