#include <string>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/io/end_state_scene.h"
#include "support/kapla.h"

namespace brick_stack_sim {
namespace {

const BrickOutcome& outcomeOf(const RunReport& report, const std::string& id) {
  for (const BrickOutcome& outcome : report.bricks)
    if (outcome.brick.id == id) return outcome;
  ADD_FAILURE() << "no brick " << id << " at the end";
  return report.bricks.front();
}

// A plank at rest, one still sliding, and one that has fallen past the
// table's edge to the floor: the first two are saved as they ended, the
// third left out, since no scene can place a brick below the table top.
TEST(EndStateScene, PlacesEveryBrickWhereTheRunLeftItButThoseOnTheFloor) {
  Scene scene;
  ASSERT_TRUE(
      parseScene("bricks:\n"
                 "  - {id: rest, position: [0, 0.2, 0.0039]}\n"
                 "  - {id: slide, position: [-0.5, 0, 0.0039], linear_velocity: [2.5, 0, 0]}\n"
                 "  - {id: off, position: [0.65, 0, 0.01]}\n",
                 "three", test::packageTypes(), &scene)
          .ok);
  RunOptions options;
  // The off plank lands on the floor, 0.76 m down, after 0.39 s; the slider
  // (mu g = 4.9 m/s^2) still slides at about 0.3 m/s.
  options.duration = 0.45;
  RunReport report;
  ASSERT_TRUE(runScene(scene, test::packageTypes(), options, &report).ok);
  ASSERT_EQ(report.bricks.size(), 3u);
  EXPECT_GT(outcomeOf(report, "slide").brick.linear_velocity.x(), 0.1);
  EXPECT_LT(outcomeOf(report, "off").brick.pose.translation().z(), -0.7);

  Scene end_state;
  std::vector<SetAsideBrick> left_out;
  ASSERT_TRUE(
      endStateScene(scene, report, test::packageTypes(), options.world, &end_state, &left_out).ok);
  ASSERT_EQ(left_out.size(), 1u);
  EXPECT_EQ(left_out[0].brick.placement.id, "off");
  EXPECT_NE(left_out[0].reason.find("below the table top"), std::string::npos)
      << left_out[0].reason;
  ASSERT_EQ(end_state.bricks.size(), 2u);
  EXPECT_EQ(end_state.name, "three");
  for (const ScheduledBrick& saved : end_state.bricks) {
    const BrickSnapshot& ended = outcomeOf(report, saved.placement.id).brick;
    EXPECT_EQ(saved.at, 0.0);
    EXPECT_EQ(saved.placement.type, ended.type);
    EXPECT_TRUE(saved.placement.pose.isApprox(ended.pose, 0.0));
    EXPECT_EQ(saved.placement.linear_velocity, ended.linear_velocity);
    EXPECT_EQ(saved.placement.angular_velocity, ended.angular_velocity);
  }

  // Written and read back, it runs from there: both planks placed where
  // they ended, the slider sliding on.
  Scene again;
  ASSERT_TRUE(parseScene(sceneAsYaml(end_state), "again", test::packageTypes(), &again).ok);
  RunOptions restart;
  restart.duration = 0.001;
  RunReport next;
  ASSERT_TRUE(runScene(again, test::packageTypes(), restart, &next).ok);
  EXPECT_TRUE(next.refused.empty());
  ASSERT_EQ(next.bricks.size(), 2u);
  const Eigen::Vector3d rest_end = outcomeOf(report, "rest").brick.pose.translation();
  EXPECT_LT((outcomeOf(next, "rest").brick.pose.translation() - rest_end).norm(), 1e-6);
  const BrickSnapshot& slider = outcomeOf(next, "slide").brick;
  const BrickSnapshot& slid = outcomeOf(report, "slide").brick;
  // One more step of 1 ms at the slide's speed and deceleration.
  EXPECT_NEAR(slider.pose.translation().x(),
              slid.pose.translation().x() + slid.linear_velocity.x() * 0.001, 2e-5);
  EXPECT_NEAR(slider.linear_velocity.x(), slid.linear_velocity.x() - 0.5 * 9.81 * 0.001, 1e-3);
}

}  // namespace
}  // namespace brick_stack_sim
