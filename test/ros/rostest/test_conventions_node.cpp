// The ROS conventions users rely on: a paused node keeps
// publishing /clock and ~bricks, so a client that joins while it is paused
// sees the clock standing still and every brick; with publish_clock,
// sim.launch sets /use_sim_time and every stamp (~bricks, ~markers, ~events,
// tf, /tf_static, ~get_bricks) is sim time; tf names the bricks and the table
// under the frame prefix with its '/' (sim1 in conventions.test gives
// sim1/table), and the latched /tf_static loses what a removal or a reset
// took away.
#include <cmath>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>

#include <tf2_msgs/TFMessage.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>
#include <visualization_msgs/MarkerArray.h>

#include "brick_stack_sim/ros/interface_names.h"
#include "node_fixture.h"

namespace brick_stack_sim {
namespace {

class ConventionsNode : public test::NodeFixture {
 protected:
  /// The child frames of the latched /tf_static as a subscriber that joins
  /// now reads them (tf2_ros's listener subscribes the same way); empty when
  /// nothing arrived within 5 s.
  static std::set<std::string> latchedStaticFrames(ros::NodeHandle& nh) {
    std::mutex mutex;
    std::optional<std::set<std::string>> frames;
    ros::Subscriber subscriber = nh.subscribe<tf2_msgs::TFMessage>(
        "/tf_static", 10, [&](const tf2_msgs::TFMessage::ConstPtr& msg) {
          std::lock_guard<std::mutex> lock(mutex);
          frames.emplace();
          for (const auto& transform : msg->transforms) frames->insert(transform.child_frame_id);
        });
    waitFor(
        [&] {
          std::lock_guard<std::mutex> lock(mutex);
          return frames.has_value();
        },
        5.0);
    subscriber.shutdown();
    std::lock_guard<std::mutex> lock(mutex);
    return frames.value_or(std::set<std::string>());
  }

  /// Waits at most `seconds` for a new subscriber's latched /tf_static to
  /// hold `frame` (`present`) or not; the frames it last read.
  static std::set<std::string> waitForStaticFrame(ros::NodeHandle& nh, const std::string& frame,
                                                  bool present, double seconds) {
    std::set<std::string> frames;
    waitFor(
        [&] {
          frames = latchedStaticFrames(nh);
          return frames.count(frame) == (present ? 1u : 0u);
        },
        seconds);
    return frames;
  }
};

TEST_F(ConventionsNode, ClockAndBricksKeepArrivingWhilePaused) {
  ASSERT_TRUE(place("resting", 0.2, 0.1, 0.0039).success);
  ASSERT_TRUE(setPaused(true));
  // Subscribed only now: a client joining a paused simulation.
  std::mutex mutex;
  std::vector<double> clocks;
  std::optional<BrickArray> last_bricks;
  int bricks_received = 0;
  ros::Subscriber clock_sub = sim_->subscribeClock(
      [&](const rosgraph_msgs::Clock::ConstPtr& msg) {
        std::lock_guard<std::mutex> lock(mutex);
        clocks.push_back(msg->clock.toSec());
      },
      100);
  ros::Subscriber bricks_sub = sim_->subscribeBricks(
      [&](const BrickArray::ConstPtr& msg) {
        std::lock_guard<std::mutex> lock(mutex);
        last_bricks = *msg;
        ++bricks_received;
      },
      100);
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

TEST_F(ConventionsNode, PublishClockSetsUseSimTimeAndEveryStampIsSimTime) {
  bool use_sim_time = false;
  ASSERT_TRUE(ros::param::get("/use_sim_time", use_sim_time)) << "sim.launch did not set it";
  EXPECT_TRUE(use_sim_time);
  EXPECT_TRUE(ros::Time::isSimTime());
  // The node publishes /clock and then its state at every publish period of
  // sim time, and /clock again after each step of its timer: a sim stamp lies
  // within one period of the latest /clock whichever arrives first. Wall
  // time would be ~1.8e9 s away from a sim clock that started at 0.
  double publish_rate = 0.0;
  ASSERT_TRUE(ros::param::get(sim_->resolve(ros_adapter::kPublishRateParameter), publish_rate));
  const double period = 1.0 / publish_rate + 1e-6;  // and rounding
  ASSERT_TRUE(setPaused(false));
  std::mutex mutex;
  double clock = -1.0;
  // Per topic: the largest distance between a stamp and the latest /clock at
  // receipt [s], and how many stamps were compared.
  std::map<std::string, double> worst;
  std::map<std::string, int> received;
  std::optional<ros::Time> table_stamp;
  auto note = [&](const std::string& topic, const ros::Time& stamp) {
    std::lock_guard<std::mutex> lock(mutex);
    if (clock < 0.0) return;
    worst[topic] = std::max(worst[topic], std::abs(stamp.toSec() - clock));
    ++received[topic];
  };
  ros::Subscriber clock_sub = sim_->subscribeClock(
      [&](const rosgraph_msgs::Clock::ConstPtr& msg) {
        std::lock_guard<std::mutex> lock(mutex);
        clock = msg->clock.toSec();
      },
      100);
  ros::Subscriber bricks_sub = sim_->subscribeBricks(
      [&](const BrickArray::ConstPtr& msg) { note("bricks", msg->header.stamp); }, 100);
  ros::Subscriber markers_sub = sim_->subscribeMarkers(
      [&](const visualization_msgs::MarkerArray::ConstPtr& msg) {
        for (const auto& marker : msg->markers) note("markers", marker.header.stamp);
      },
      100);
  ros::Subscriber events_sub = sim_->subscribeEvents(
      [&](const StabilityEvent::ConstPtr& msg) { note("events", msg->header.stamp); }, 100);
  ros::Subscriber tf_sub =
      nh_.subscribe<tf2_msgs::TFMessage>("/tf", 100, [&](const tf2_msgs::TFMessage::ConstPtr& msg) {
        for (const auto& transform : msg->transforms) note("tf", transform.header.stamp);
      });
  // Latched: the table frame, with the bricks at rest.
  ros::Subscriber tf_static_sub = nh_.subscribe<tf2_msgs::TFMessage>(
      "/tf_static", 10, [&](const tf2_msgs::TFMessage::ConstPtr& msg) {
        std::lock_guard<std::mutex> lock(mutex);
        for (const auto& transform : msg->transforms)
          if (transform.child_frame_id == "sim1/table") table_stamp = transform.header.stamp;
      });
  ros::WallDuration(1.0).sleep();  // connections up
  // Falls for a quarter of a second: events, and tf at every publish meanwhile
  // (tf sends only what moves).
  ASSERT_TRUE(place("stamped", 0.0, -0.2, 0.3).success);
  const bool arrived = waitFor(
      [&] {
        std::lock_guard<std::mutex> lock(mutex);
        return received["bricks"] >= 10 && received["markers"] >= 10 && received["events"] >= 1 &&
               received["tf"] >= 5 && table_stamp;
      },
      15.0);
  {
    std::lock_guard<std::mutex> lock(mutex);
    ASSERT_TRUE(arrived) << received["bricks"] << " bricks, " << received["markers"] << " markers, "
                         << received["events"] << " events, " << received["tf"]
                         << " tf, table frame " << (table_stamp ? "" : "not ") << "on /tf_static";
    for (const auto& [topic, distance] : worst)
      EXPECT_LE(distance, period) << topic << ": a stamp " << distance
                                  << " s from the latest /clock";
    // In sim time: not after the clock, far from wall time.
    EXPECT_GE(table_stamp->toSec(), 0.0);
    EXPECT_LE(table_stamp->toSec(), clock) << "the table frame on /tf_static";
  }
  // A service response: compared with the latest /clock once it is back.
  const client::Reply<GetBricks::Response> get = sim_->getBricks();
  ASSERT_TRUE(get.reached) << get.message;
  std::lock_guard<std::mutex> lock(mutex);
  EXPECT_LE(std::abs(get.response.header.stamp.toSec() - clock), period) << "~get_bricks";
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

// A latched /tf_static message is replaced by the publisher's next one:
// after a removal or a reset the node's message must be the current set, so
// that a listener that joins later does not resolve a brick that went
// (docs/ros_interface.md, "Topics").
TEST_F(ConventionsNode, RemovedBricksLeaveTheLatchedStaticSet) {
  ASSERT_TRUE(setPaused(false));
  ASSERT_TRUE(place("gone", 0.4, -0.25, 0.0039).success);
  ASSERT_TRUE(place("stays", 0.4, 0.25, 0.0039).success);
  // At rest, both join the static set (sent at most once a second).
  std::set<std::string> frames = waitForStaticFrame(nh_, "sim1/gone", true, 10.0);
  ASSERT_EQ(frames.count("sim1/gone"), 1u) << "the resting brick never reached /tf_static";
  ASSERT_TRUE(sim_->removeBrick("gone").ok);
  frames = waitForStaticFrame(nh_, "sim1/gone", false, 5.0);
  EXPECT_EQ(frames.count("sim1/gone"), 0u) << "the removed brick is still on /tf_static";
  EXPECT_EQ(frames.count("sim1/stays"), 1u);
  EXPECT_EQ(frames.count("sim1/table"), 1u);
  // A tf2 listener that starts now cannot resolve it, and still has the table.
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);
  std::string error;
  ASSERT_TRUE(buffer.canTransform("world", "sim1/stays", ros::Time(0), ros::Duration(5.0), &error))
      << error;
  EXPECT_FALSE(buffer.canTransform("world", "sim1/gone", ros::Time(0), ros::Duration(1.0)));
}

TEST_F(ConventionsNode, ResetEmptiesTheLatchedStaticSet) {
  ASSERT_TRUE(setPaused(false));
  ASSERT_TRUE(place("before_reset", -0.4, -0.25, 0.0039).success);
  std::set<std::string> frames = waitForStaticFrame(nh_, "sim1/before_reset", true, 10.0);
  ASSERT_EQ(frames.count("sim1/before_reset"), 1u) << "the resting brick never reached /tf_static";
  ASSERT_TRUE(sim_->reset("").ok);
  frames = waitForStaticFrame(nh_, "sim1/before_reset", false, 5.0);
  // The empty table: its frame alone.
  EXPECT_EQ(frames, std::set<std::string>{"sim1/table"});
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);
  std::string error;
  ASSERT_TRUE(buffer.canTransform("world", "sim1/table", ros::Time(0), ros::Duration(5.0), &error))
      << error;
  EXPECT_FALSE(buffer.canTransform("world", "sim1/before_reset", ros::Time(0), ros::Duration(1.0)));
}

}  // namespace
}  // namespace brick_stack_sim

int main(int argc, char** argv) {
  return brick_stack_sim::test::runNodeTests(argc, argv, "test_conventions_node");
}
