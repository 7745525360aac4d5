// The ROS conventions users rely on (issue 10): a paused node keeps
// publishing /clock and ~bricks, so a client that joins while it is paused
// sees the clock standing still and every brick; tf names the bricks and
// the table under the frame prefix (sim1/ in conventions.test).
#include <mutex>
#include <optional>
#include <vector>

#include <gtest/gtest.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>

#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include "brick_stack_sim/BrickArray.h"
#include "ros/node_fixture.h"

namespace brick_stack_sim {
namespace {

class ConventionsNode : public test::NodeFixture {};

TEST_F(ConventionsNode, ClockAndBricksKeepArrivingWhilePaused) {
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

TEST_F(ConventionsNode, TfNamesBricksAndTableUnderTheFramePrefix) {
  ASSERT_TRUE(place("framed", -0.2, 0.1, 0.0039).success);
  ASSERT_TRUE(setPaused(false));
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);
  std::string error;
  ASSERT_TRUE(
      buffer.canTransform("world", "sim1/framed", ros::Time(0), ros::Duration(10.0), &error))
      << error;
  const geometry_msgs::TransformStamped brick =
      buffer.lookupTransform("world", "sim1/framed", ros::Time(0));
  EXPECT_NEAR(brick.transform.translation.x, -0.2, 1e-6);
  EXPECT_NEAR(brick.transform.translation.y, 0.1, 1e-6);
  // The table frame is latched on /tf_static, at the table top's centre.
  ASSERT_TRUE(buffer.canTransform("world", "sim1/table", ros::Time(0), ros::Duration(10.0), &error))
      << error;
  const geometry_msgs::TransformStamped table =
      buffer.lookupTransform("world", "sim1/table", ros::Time(0));
  EXPECT_EQ(table.transform.translation.z, 0.0);
  EXPECT_EQ(table.transform.rotation.w, 1.0);
  // No bare brick id on tf: a robot's frame called "framed" would clash.
  EXPECT_FALSE(buffer._frameExists("framed"));
}

}  // namespace
}  // namespace brick_stack_sim

int main(int argc, char** argv) {
  return brick_stack_sim::test::runNodeTests(argc, argv, "test_conventions_node");
}
