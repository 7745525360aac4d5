// Held bricks through the node: ~grasp_brick, ~held_target, ~release_brick
// and ~push_brick, against a running node in mode com.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <geometry_msgs/PoseStamped.h>
#include <gtest/gtest.h>
#include <ros/ros.h>

#include "node_fixture.h"
#include "support/kapla.h"

namespace brick_stack_sim {
namespace {

using test::kKaplaThickness;

class HeldBrickNode : public test::NodeFixture {
 protected:
  void SetUp() override {
    NodeFixture::SetUp();
    if (HasFatalFailure()) return;
    const ros::Publisher& target = sim_->advertiseHeldTarget();
    ASSERT_TRUE(setPaused(true));
    ResetScene reset;
    ASSERT_TRUE(call(reset).success) << reset.response.message;
    ASSERT_TRUE(waitFor([&target] { return target.getNumSubscribers() > 0; }, 10.0))
        << "the node does not subscribe to ~held_target";
  }

  /// A frozen two-per-layer tower through ~place_brick.
  void buildTower(int layers) {
    for (int i = 0; i < 2 * layers; ++i) {
      const BrickPlacement brick = test::towerBrick(i);
      const Eigen::Vector3d& p = brick.pose.translation();
      const double yaw = std::atan2(brick.pose.linear()(1, 0), brick.pose.linear()(0, 0));
      ASSERT_TRUE(place(brick.id, p.x(), p.y(), p.z(), yaw).success) << brick.id;
    }
    step(50);
  }

  GraspBrick::Response grasp(const std::string& id) {
    GraspBrick srv;
    srv.request.id = id;
    return call(srv);
  }

  ReleaseBrick::Response release(const std::string& id, double vx = 0.0) {
    ReleaseBrick srv;
    srv.request.id = id;
    srv.request.twist.linear.x = vx;
    return call(srv);
  }

  /// Publishes a target and gives the node time to take it before the next
  /// ~step (both go through its one spinner, in no guaranteed order).
  void aim(double x, double y, double z, double yaw = 0.0, const std::string& frame = "world") {
    geometry_msgs::PoseStamped target;
    target.header.frame_id = frame;
    target.pose.position.x = x;
    target.pose.position.y = y;
    target.pose.position.z = z;
    target.pose.orientation.z = std::sin(yaw / 2);
    target.pose.orientation.w = std::cos(yaw / 2);
    sim_->publishHeldTarget(target);
    ros::WallDuration(0.05).sleep();
  }

  Brick brick(const std::string& id) {
    for (const Brick& b : bricks())
      if (b.id == id) return b;
    ADD_FAILURE() << "no brick " << id;
    return Brick();
  }

  static double distance(const geometry_msgs::Point& a, double x, double y, double z) {
    return std::sqrt((a.x - x) * (a.x - x) + (a.y - y) * (a.y - y) + (a.z - z) * (a.z - z));
  }
};

TEST_F(HeldBrickNode, CarriedSlowlyOntoATowerAndReleasedItEndsFrozenOnIt) {
  const int layers = 4;
  buildTower(layers);
  ASSERT_TRUE(place("hand", 0.3, 0.0, kKaplaThickness / 2).success);
  step(100);
  const GraspBrick::Response grasped = grasp("hand");
  ASSERT_TRUE(grasped.success) << grasped.message;
  EXPECT_EQ(brick("hand").state, Brick::HELD);
  const test::TowerSlot slot = test::towerSlot(layers, 0);
  aim(slot.x, slot.y, slot.z + 0.03, slot.yaw);
  step(1500);
  // Down at 2 cm/s to a millimetre under its resting height: the tower stops it.
  for (double z = slot.z + 0.03; z > slot.z - 0.001; z -= 0.002) {
    aim(slot.x, slot.y, z, slot.yaw);
    step(100);
  }
  EXPECT_NEAR(brick("hand").pose.position.z, slot.z, 2e-4) << "the hand went into the tower";
  const ReleaseBrick::Response released = release("hand");
  ASSERT_TRUE(released.success) << released.message;
  step(500);
  const Brick joined = brick("hand");
  EXPECT_EQ(joined.state, Brick::STABLE);
  EXPECT_NEAR(joined.pose.position.z, slot.z, 2e-4);
  for (const Brick& b : bricks()) {
    if (b.id != "hand") {
      EXPECT_EQ(b.state, Brick::STABLE) << b.id;
    }
  }
}

TEST_F(HeldBrickNode, SweptThroughATowerAtHalfAMetreASecondItKnocksBricksOff) {
  const int layers = 8;
  buildTower(layers);
  const double z = test::towerSlot(4, 0).z;
  ASSERT_TRUE(place("hand", -0.2, 0.0, kKaplaThickness / 2, M_PI / 2).success);
  step(100);
  ASSERT_TRUE(grasp("hand").success);
  aim(-0.2, 0.0, z, M_PI / 2);
  step(500);
  aim(0.2, 0.0, z, M_PI / 2);  // 0.4 m at the default limit of 0.5 m/s
  step(2000);
  int knocked = 0;
  for (const Brick& b : bricks()) {
    if (b.id == "hand") continue;
    const BrickPlacement placed = test::towerBrick(std::stoi(b.id.substr(1)));
    const Eigen::Vector3d& p = placed.pose.translation();
    knocked += distance(b.pose.position, p.x(), p.y(), p.z()) > 0.02;
  }
  EXPECT_GE(knocked, 4);
  EXPECT_NEAR(brick("hand").pose.position.x, 0.2, 1e-6) << "the hand did not get through";
}

TEST_F(HeldBrickNode, BadRequestsAreRefusedWithAMessageAndChangeNothing) {
  buildTower(2);
  ASSERT_TRUE(place("loose", 0.3, 0.0, kKaplaThickness / 2).success);
  step(100);
  const std::vector<Brick> before = bricks();
  auto refused = [](bool success, const std::string& message, const std::string& expected) {
    EXPECT_FALSE(success);
    EXPECT_NE(message.find(expected), std::string::npos) << message;
  };
  GraspBrick::Response r = grasp("ghost");
  refused(r.success, r.message, "no brick");
  r = grasp("t0");
  refused(r.success, r.message, "carries");
  ReleaseBrick::Response rel = release("loose");
  refused(rel.success, rel.message, "not held");
  PushBrick push;
  push.request.id = "loose";
  push.request.impulse.x = 1e-3;
  push.request.point.x = 1.0;  // a metre off: outside the brick
  refused(call(push).success, push.response.message, "outside brick");
  EXPECT_EQ(bricks(), before);

  ASSERT_TRUE(grasp("loose").success);
  step(1);
  const Brick held = brick("loose");
  r = grasp("t3");
  refused(r.success, r.message, "already held");
  rel = release("loose", std::numeric_limits<double>::quiet_NaN());
  refused(rel.success, rel.message, "finite");
  // A NaN target, one in another frame and one under the table are ignored.
  aim(std::numeric_limits<double>::quiet_NaN(), 0.0, 0.1);
  aim(0.3, 0.0, 0.1, 0.0, "map");
  aim(0.3, 0.0, -0.1);
  step(200);
  EXPECT_EQ(brick("loose").pose, held.pose) << "an ignored target moved the held brick";
  EXPECT_EQ(brick("loose").state, Brick::HELD);
}

TEST_F(HeldBrickNode, PushWithoutAPointActsAtTheBricksCentre) {
  ASSERT_TRUE(place("pushed", 0.3, 0.0, kKaplaThickness / 2).success);
  step(100);
  PushBrick push;
  push.request.id = "pushed";
  push.request.impulse.y = 0.0119 * 0.3;  // 0.3 m/s along y, point left empty
  ASSERT_TRUE(call(push).success) << push.response.message;
  step(1);
  const Brick moving = brick("pushed");
  EXPECT_GT(moving.twist.linear.y, 0.2);
  // At the centre: no spin (at the world origin, 0.3 m away, it spun).
  EXPECT_LT(std::abs(moving.twist.angular.z), 1e-6);
}

}  // namespace
}  // namespace brick_stack_sim

int main(int argc, char** argv) {
  return brick_stack_sim::test::runNodeTests(argc, argv, "test_held_brick_node");
}
