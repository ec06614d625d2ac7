#include <gtest/gtest.h>

#include <stdexcept>

#include "support/mapping_scenes.hpp"
#include "ussnav/core/error.hpp"
#include "ussnav/core/random.hpp"
#include "ussnav/mapping/coverage_mask.hpp"

using namespace ussnav;
using test::BoxScene;

namespace {

Intrinsics d455(int w, int h) { return Intrinsics::fromFov(w, h, deg2rad(87), deg2rad(58)); }

bool overlapsWindow(const CoverageMask& m, const RollingGrid& g, const Vec3i& cell) {
  const Aabb a = m.cellBounds(cell), w = g.window();
  return (a.min.array() < w.max.array() - 1e-9).all() && (a.max.array() > w.min.array() + 1e-9).all();
}

// Every count the mask keeps equals a brute-force recount of the grid's window; cells away
// from the window hold nothing; a cell that meets the visited rule now is visited.
void expectMatchesBruteForce(const CoverageMask& m, const RollingGrid& g, const CoverageConfig& cfg) {
  const std::vector<CoverageCount> truth = m.bruteForceCounts(g);
  ASSERT_FALSE(truth.empty());
  for (const CoverageCount& t : truth) {
    ASSERT_EQ(m.inWindowCount(t.cell), t.in_window) << t.cell.transpose();
    ASSERT_EQ(m.unknownCount(t.cell), t.unknown) << t.cell.transpose();
    const bool rule = t.in_window >= cfg.min_window_fraction * m.voxelsPerCell() &&
                      t.unknown < cfg.visited_unknown_fraction * t.in_window;
    if (rule) {
      ASSERT_TRUE(m.isVisited(t.cell)) << t.cell.transpose();
    }
  }
  for (const CoverageCellInfo& c : m.allocatedCells())
    if (!overlapsWindow(m, g, c.cell)) {
      ASSERT_EQ(c.known, 0) << c.cell.transpose();
      ASSERT_EQ(m.inWindowCount(c.cell), 0);
    }
}

void randomFlight(const CoverageConfig& cfg, uint64_t seed) {
  const BoxScene scene = test::boxRoom(Vec3(-9, -6, 0), Vec3(9, 6, 2.9));
  Rng rng(seed);
  RollingGrid g(GridConfig{}, Vec3(0, 0, 1.2));
  CoverageMask m(cfg, g.resolution());
  for (int step = 0; step < 24; ++step) {
    const Vec3 p(rng.uniform(-7.5, 7.5), rng.uniform(-4.5, 4.5), rng.uniform(0.7, 2.0));
    // Rolls without insertion, several per update, and updates with nothing new.
    for (int r = rng.uniformInt(1, 3); r > 0; --r)
      g.moveTo(p + Vec3(rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5), rng.uniform(-0.6, 0.6)));
    g.moveTo(p);
    if (rng.bernoulli(0.5)) g.insertScan(test::renderScan(scene, p, 3000, -7, 52, 40.0, rng.uniform(0, 6)));
    else g.insertDepth(test::renderDepth(scene, d455(80, 60), test::cameraPose(p, rng.uniform(-3, 3)), 5.0));
    m.update(g);
    if (rng.bernoulli(0.3)) m.update(g);  // idempotent
    if (rng.bernoulli(0.7)) g.clearChanges();
    expectMatchesBruteForce(m, g, cfg);
  }
  EXPECT_GT(m.visitedCount(), 0u);
}

}  // namespace

TEST(CoverageMask, ConfigValidation) {
  CoverageConfig c;
  EXPECT_NO_THROW(CoverageMask(c, 0.1));
  c.cell_size = 0.25;  // not a whole number of 0.1 m voxels
  try {
    CoverageMask m(c, 0.1);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "cell_size");
  }
  c = CoverageConfig{};
  c.cell_size = 0;
  EXPECT_THROW(CoverageMask(c, 0.1), InputError);
  c = CoverageConfig{};
  c.cell_height = -1;
  EXPECT_THROW(CoverageMask(c, 0.1), InputError);
  c = CoverageConfig{};
  c.min_window_fraction = 0;
  EXPECT_THROW(CoverageMask(c, 0.1), InputError);
  EXPECT_THROW(CoverageMask(CoverageConfig{}, 0.0), InputError);
}

TEST(CoverageMask, CellIndexing) {
  CoverageMask m(CoverageConfig{}, 0.1);
  EXPECT_EQ(m.cellVoxels(), Vec3i(10, 10, 40));
  EXPECT_EQ(m.cellOf(Vec3(0.05, 0.95, 3.9)), Vec3i(0, 0, 0));
  EXPECT_EQ(m.cellOf(Vec3(-0.05, 1.05, 4.1)), Vec3i(-1, 1, 1));
  EXPECT_EQ(m.cellOfKey(Vec3i(-10, -11, -1)), Vec3i(-1, -2, -1));
  const Aabb b = m.cellBounds(Vec3i(-1, 2, 0));
  EXPECT_NEAR(b.min.x(), -1.0, 1e-12);
  EXPECT_NEAR(b.max.y(), 3.0, 1e-12);
  EXPECT_NEAR(b.max.z(), 4.0, 1e-12);
}

TEST(CoverageMask, CountsEqualBruteForceAfterRandomInsertionsAndRolls) {
  randomFlight(CoverageConfig{}, 7);
}

TEST(CoverageMask, CountsEqualBruteForceWithSmall3DCells) {
  CoverageConfig c;
  c.cell_size = 0.5;
  c.cell_height = 0.7;
  c.visited_unknown_fraction = 0.3;
  randomFlight(c, 11);
}

TEST(CoverageMask, VisitedCellsStayVisitedAfterTheWindowLeaves) {
  const BoxScene scene = test::boxRoom(Vec3(-3.03, -2.87, 0.0), Vec3(3.03, 2.91, 2.73), 0.2, false);
  const Vec3 c(0.05, 0.05, 1.3);
  RollingGrid g(GridConfig{}, c);
  CoverageMask m(CoverageConfig{}, g.resolution());
  for (int i = 0; i < 6; ++i) {
    g.insertScan(test::renderScan(scene, c + Vec3(0.3 * std::cos(i), 0.3 * std::sin(i), 0), 20000, -90, 90, 40, i));
    m.update(g);
    g.clearChanges();
  }
  // Inside the empty room every cell column 0 <= z < 4 m is seen down to the unknown band above
  // the ceiling (2.73 .. 3.3 m) and the ring of wall voxels: well under 20% unknown.
  const Vec3i inside = m.cellOf(Vec3(1.5, -1.5, 1.0));
  EXPECT_TRUE(m.isVisited(inside)) << m.unknownCount(inside) << " of " << m.inWindowCount(inside);
  // Beyond the walls nothing is known: not visited.
  EXPECT_FALSE(m.isVisitedAt(Vec3(3.5, 0.5, 1.0)));
  EXPECT_FALSE(m.isVisitedAt(Vec3(0.5, 0.5, -1.0)));  // under the floor
  const size_t visited = m.visitedCount();
  EXPECT_GE(visited, 16u);
  // Fly away: the grid forgets, the mask remembers.
  g.moveTo(Vec3(60, 0, 1.3));
  m.update(g);
  g.clearChanges();
  EXPECT_EQ(g.knownVoxels(), 0u);
  EXPECT_TRUE(m.isVisited(inside));
  EXPECT_EQ(m.visitedCount(), visited);
  EXPECT_EQ(m.knownCount(inside), 0);
  EXPECT_EQ(m.unknownCount(inside), 0);  // Eq. 3 counts only voxels inside the window
  expectMatchesBruteForce(m, g, CoverageConfig{});
}

TEST(CoverageMask, PartlyInsideCellsAreNotJudged) {
  // Only 4 of the 10 voxel slabs of cell x = 4 lie in the window, and we make them all known:
  // with min_window_fraction 0.5 that 40 % says nothing about the rest, so not visited.
  RollingGrid g(GridConfig{}, Vec3(0.45, 0.05, 2.05));  // window x in [-3.6, 4.4)
  CoverageMask m(CoverageConfig{}, g.resolution());
  PointCloudScan s;
  s.origin = Vec3(0.45, 0.05, 2.05);
  s.max_range = 10.0;
  const Vec3i cell(4, 0, 0);
  const Aabb w = g.window();
  for (int x = 40; x < 44; ++x)
    for (int y = 0; y < 10; ++y)
      for (int z = 0; z < 40; ++z) {
        const Vec3 target = (Vec3(x, y, z) + Vec3::Constant(0.5)) * 0.1;
        if (w.contains(target)) s.no_return_dirs.push_back((target - s.origin).cast<float>());
      }
  g.insertScan(s);
  m.update(g);
  const int in_window = m.inWindowCount(cell);
  EXPECT_EQ(in_window, 4 * 10 * (g.minKey().z() + g.dims().z() - std::max(0, g.minKey().z())));
  EXPECT_LT(in_window, m.voxelsPerCell() / 2);
  EXPECT_LT(m.unknownCount(cell), 0.1 * in_window);  // nearly all known...
  EXPECT_FALSE(m.isVisited(cell));                    // ...but too little of the cell to judge
  expectMatchesBruteForce(m, g, CoverageConfig{});
  // The same grid judged by a mask that accepts 35 % of a cell: visited.
  CoverageConfig lax;
  lax.min_window_fraction = 0.35;
  CoverageMask m2(lax, g.resolution());
  m2.update(g);
  EXPECT_TRUE(m2.isVisited(cell));
}

TEST(CoverageMask, MissedChangesAreALogicError) {
  RollingGrid g(GridConfig{}, Vec3(0, 0, 1.2));
  CoverageMask m(CoverageConfig{}, g.resolution());
  PointCloudScan s;
  s.origin = Vec3(0, 0, 1.2);
  s.points = {Vec3f(2, 0, 1.2f)};
  g.insertScan(s);
  g.clearChanges();  // before the mask saw them
  EXPECT_THROW(m.update(g), std::logic_error);
}

TEST(CoverageMask, MemoryGrowsWithExploredAreaOnly) {
  const BoxScene scene = test::corridor(200, 3.0, 2.8);
  RollingGrid g(GridConfig{}, Vec3(1, 0, 1.2));
  CoverageMask m(CoverageConfig{}, g.resolution());
  size_t bytes_at_100 = 0;
  double area_at_100 = 0;
  for (double x = 1.0; x < 199.0; x += 1.0) {
    const Vec3 p(x, 0, 1.2);
    g.moveTo(p);
    g.insertScan(test::renderScan(scene, p, 3000, -7, 52, 40.0, x));
    m.update(g);
    g.clearChanges();
    if (x == 100.0) {
      bytes_at_100 = m.memoryBytes();
      area_at_100 = m.exploredArea();
    }
  }
  // A 3 m corridor with 0.2 m walls: 4-5 one-metre cells across, about 200 m long.
  EXPECT_GT(m.exploredArea(), 200 * 3.0);
  EXPECT_LT(m.exploredArea(), 210 * 6.0);
  const double per_m2 = m.bytesPerExploredSquareMetre();
  std::printf("[ GCM ] %zu bytes for %.0f m^2 explored: %.1f bytes/m^2, %zu cells visited\n", m.memoryBytes(),
              m.exploredArea(), per_m2, m.visitedCount());
  EXPECT_LT(per_m2, 200.0);
  // Twice the area, about twice the bytes: linear in the area, nothing per frame.
  EXPECT_GT(m.exploredArea(), 1.8 * area_at_100);
  EXPECT_LT(double(m.memoryBytes()), 2.6 * double(bytes_at_100));
  // The default threshold (configs/default.yaml) marks the cells the UAV flew through, not
  // those cut by or behind the walls (y = +-1.5 .. +-1.7).
  EXPECT_GT(m.visitedCount(), 300u);
  for (int x : {150, 190}) {
    EXPECT_TRUE(m.isVisited(Vec3i(x, -1, 0)));
    EXPECT_TRUE(m.isVisited(Vec3i(x, 0, 0)));
    EXPECT_FALSE(m.isVisited(Vec3i(x, 1, 0)));
    EXPECT_FALSE(m.isVisited(Vec3i(x, -2, 0)));
    EXPECT_FALSE(m.isVisited(Vec3i(x, 2, 0)));
    EXPECT_FALSE(m.isVisited(Vec3i(x, 0, -1)));
  }
}
