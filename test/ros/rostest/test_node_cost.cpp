// The node's cost follows what changes: frozen bricks are not sent on /tf at
// every publish, and a client that joins after they froze still receives
// every frozen brick's transform (latched /tf_static) and state (~bricks).
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <ros/ros.h>
#include <tf2_msgs/TFMessage.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include "node_fixture.h"

namespace {

using namespace brick_stack_sim;

constexpr std::size_t kTowerBricks = 20;  ///< scenes/tower10.yaml

class NodeCost : public test::NodeFixture {
 protected:
  void SetUp() override {
    NodeFixture::SetUp();
    if (HasFatalFailure()) return;
    ASSERT_TRUE(setPaused(true));
    const client::Reply<ResetScene::Response> reset = sim_->reset("tower10");
    ASSERT_TRUE(reset.ok) << reset.message;
    // Three seconds of sim time: placed, settled and frozen.
    ASSERT_TRUE(step(3000).success);
    frozen_ = bricks();
    ASSERT_EQ(frozen_.size(), kTowerBricks);
    for (const Brick& brick : frozen_) ASSERT_EQ(brick.state, Brick::STABLE) << brick.id;
    // Running again; the static set goes out within its period (1 s).
    ASSERT_TRUE(setPaused(false));
    ros::WallDuration(1.5).sleep();
  }

  std::vector<Brick> frozen_;
};

TEST_F(NodeCost, ALateClientReceivesEveryFrozenBricksTransformAndState) {
  // Joins now, long after the last brick froze.
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);
  std::mutex mutex;
  BrickArray::ConstPtr first_state;
  ros::Subscriber state_sub = sim_->subscribeBricks(
      [&](const BrickArray::ConstPtr& msg) {
        std::lock_guard<std::mutex> lock(mutex);
        if (!first_state) first_state = msg;
      },
      1);
  ASSERT_TRUE(waitFor(
      [&] {
        for (const Brick& brick : frozen_)
          if (!buffer.canTransform("world", brick.id, ros::Time(0))) return false;
        return true;
      },
      5.0))
      << "not every frozen brick's frame reached a listener that joined late";
  for (const Brick& brick : frozen_) {
    const geometry_msgs::TransformStamped tf =
        buffer.lookupTransform("world", brick.id, ros::Time(0));
    EXPECT_NEAR(tf.transform.translation.x, brick.pose.position.x, 1e-9) << brick.id;
    EXPECT_NEAR(tf.transform.translation.y, brick.pose.position.y, 1e-9) << brick.id;
    EXPECT_NEAR(tf.transform.translation.z, brick.pose.position.z, 1e-9) << brick.id;
    EXPECT_NEAR(tf.transform.rotation.w, brick.pose.orientation.w, 1e-9) << brick.id;
    EXPECT_NEAR(tf.transform.rotation.z, brick.pose.orientation.z, 1e-9) << brick.id;
  }
  ASSERT_TRUE(waitFor(
      [&] {
        std::lock_guard<std::mutex> lock(mutex);
        return first_state != nullptr;
      },
      2.0))
      << "no ~bricks for a client that joined late";
  std::set<std::string> received;
  for (const Brick& brick : first_state->bricks) {
    received.insert(brick.id);
    EXPECT_EQ(brick.state, Brick::STABLE) << brick.id;
  }
  std::set<std::string> expected;
  for (const Brick& brick : frozen_) expected.insert(brick.id);
  EXPECT_EQ(received, expected);
}

TEST_F(NodeCost, FrozenBricksAreNotSentOnTfAgainButAFallingOneIs) {
  std::mutex mutex;
  std::map<std::string, int> sent;  // child frame -> transforms on /tf
  ros::Subscriber tf_sub =
      nh_.subscribe<tf2_msgs::TFMessage>("/tf", 100, [&](const tf2_msgs::TFMessage::ConstPtr& msg) {
        std::lock_guard<std::mutex> lock(mutex);
        for (const auto& transform : msg->transforms) ++sent[transform.child_frame_id];
      });
  ASSERT_TRUE(waitFor([&] { return tf_sub.getNumPublishers() > 0; }, 5.0));
  ros::WallDuration(1.0).sleep();  // a second of running at 30 Hz
  {
    std::lock_guard<std::mutex> lock(mutex);
    EXPECT_TRUE(sent.empty()) << sent.size() << " frozen bricks sent on /tf again, e.g. "
                              << (sent.empty() ? "" : sent.begin()->first);
  }
  // A brick dropped from 30 cm beside the tower falls for a quarter of a
  // second: it is sent at every publish meanwhile, the tower still not.
  ASSERT_TRUE(place("dropped", 0.4, 0.2, 0.3).success);
  ros::WallDuration(0.5).sleep();
  std::lock_guard<std::mutex> lock(mutex);
  EXPECT_GE(sent["dropped"], 5) << "a falling brick was hardly sent on /tf";
  for (const auto& [frame, count] : sent) {
    if (frame != "dropped") {
      EXPECT_EQ(count, 0) << frame << " did not move but was sent on /tf";
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  return brick_stack_sim::test::runNodeTests(argc, argv, "test_node_cost");
}
