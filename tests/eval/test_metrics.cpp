#include <gtest/gtest.h>

#include <limits>

#include "ussnav/eval/metrics.hpp"

using namespace ussnav;

TEST(Metrics, SplMatchesHandComputation) {
  // Flew 12 m where 8 m was the shortest: SPL = 8 / 12.
  EXPECT_DOUBLE_EQ(splOf(true, 12.0, 8.0), 8.0 / 12.0);
  // A path shorter than L* (can happen with a coarser L* grid): capped at 1 by max(L, L*).
  EXPECT_DOUBLE_EQ(splOf(true, 7.5, 8.0), 1.0);
  EXPECT_DOUBLE_EQ(splOf(false, 8.0, 8.0), 0.0);
  EXPECT_DOUBLE_EQ(splOf(true, 0.0, 0.0), 1.0);
  EXPECT_THROW(splOf(true, -1.0, 2.0), std::invalid_argument);
  EXPECT_THROW(splOf(true, std::numeric_limits<double>::quiet_NaN(), 2.0), std::invalid_argument);
}

TEST(Metrics, SummaryAveragesOverEpisodes) {
  // Three episodes: success 10/20 (SPL 0.5), failure, success 6/6 (SPL 1).
  std::vector<EpisodeOutcome> eps{{true, 20.0, 10.0, 40.0, 0}, {false, 30.0, 12.0, 90.0, 1},
                                  {true, 6.0, 6.0, 10.0, 0}};
  const SplitSummary s = summarize(eps);
  EXPECT_EQ(s.episodes, 3);
  EXPECT_DOUBLE_EQ(s.sr, 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(s.spl, (0.5 + 0.0 + 1.0) / 3.0);
  EXPECT_DOUBLE_EQ(s.path_length_m, 56.0 / 3.0);
  EXPECT_DOUBLE_EQ(s.time_s, 140.0 / 3.0);
  EXPECT_DOUBLE_EQ(s.collisions, 1.0 / 3.0);
  EXPECT_EQ(summarize({}).episodes, 0);
}
