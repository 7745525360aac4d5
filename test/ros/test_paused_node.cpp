// A paused node keeps publishing /clock and ~bricks (issue 10): a client
// that joins while it is paused sees the clock standing still and every
// brick.
#include <mutex>
#include <optional>
#include <vector>

#include <gtest/gtest.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>

#include "brick_stack_sim/BrickArray.h"
#include "ros/node_fixture.h"

namespace brick_stack_sim {
namespace {

class PausedNode : public test::NodeFixture {};

TEST_F(PausedNode, ClockAndBricksKeepArrivingWhilePaused) {
  ASSERT_TRUE(place("resting", 0.2, 0.1, 0.0039).success);
  ASSERT_TRUE(setPaused(true));
  // Subscribed only now: a client joining a paused simulation.
  std::mutex mutex;
  std::vector<double> clocks;
  std::optional<BrickArray> last_bricks;
  int bricks_received = 0;
  ros::Subscriber clock_sub = nh_.subscribe<rosgraph_msgs::Clock>(
      "/clock", 100, [&](const rosgraph_msgs::Clock::ConstPtr& msg) {
        std::lock_guard<std::mutex> lock(mutex);
        clocks.push_back(msg->clock.toSec());
      });
  ros::Subscriber bricks_sub =
      nh_.subscribe<BrickArray>("/brick_sim/bricks", 100, [&](const BrickArray::ConstPtr& msg) {
        std::lock_guard<std::mutex> lock(mutex);
        last_bricks = *msg;
        ++bricks_received;
      });
  const bool arrived = waitFor(
      [&] {
        std::lock_guard<std::mutex> lock(mutex);
        return clocks.size() >= 5 && bricks_received >= 5;
      },
      10.0);
  std::lock_guard<std::mutex> lock(mutex);
  ASSERT_TRUE(arrived) << clocks.size() << " clocks and " << bricks_received
                       << " brick arrays in 10 s while paused";
  // The clock stands still while paused.
  for (double clock : clocks) EXPECT_EQ(clock, clocks.front());
  ASSERT_TRUE(last_bricks);
  ASSERT_EQ(last_bricks->bricks.size(), 1u);
  EXPECT_EQ(last_bricks->bricks.front().id, "resting");
  // Stamped in sim time, as /clock says (publish_clock is on).
  EXPECT_EQ(last_bricks->header.stamp.toSec(), clocks.front());
}

}  // namespace
}  // namespace brick_stack_sim

int main(int argc, char** argv) {
  return brick_stack_sim::test::runNodeTests(argc, argv, "test_paused_node");
}
