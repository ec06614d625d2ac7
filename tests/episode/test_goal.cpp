#include <gtest/gtest.h>

#include "support/test_worlds.hpp"
#include "ussnav/core/config.hpp"
#include "ussnav/core/error.hpp"
#include "ussnav/episode/goal.hpp"
#include "ussnav/perception/text_encoder.hpp"

using namespace ussnav;

TEST(Goal, SynonymsMatchAndOtherCategoriesDoNot) {
  const std::shared_ptr<const TextEncoder> enc(makeTextEncoder(defaultConfig().perception));
  const GoalMatcher sofa("Sofa", enc, 0.85);
  EXPECT_TRUE(sofa.matches("sofa"));
  EXPECT_TRUE(sofa.matches("couch"));
  EXPECT_FALSE(sofa.matches("bed"));
  EXPECT_FALSE(sofa.matches("chair"));
  const GoalMatcher bed("bed", enc, 0.85);
  EXPECT_FALSE(bed.matches("bedside table"));
  EXPECT_THROW(GoalMatcher("", enc, 0.85), InputError);
}

TEST(Goal, InstancesInTheWorld) {
  World w = test::twoRooms(true);
  test::addObject(w, "couch", Vec3(1, 1, 0.4), Vec3(0.8, 0.4, 0.4));
  test::addObject(w, "chair", Vec3(7, 1, 0.4), Vec3(0.3, 0.3, 0.4));
  const std::shared_ptr<const TextEncoder> enc(makeTextEncoder(defaultConfig().perception));
  const auto inst = goalInstances(w, GoalMatcher("sofa", enc, 0.85));
  ASSERT_EQ(inst.size(), 1u);
  EXPECT_EQ(inst[0]->category, "couch");
}
