// Message <-> core conversions: every non-finite or non-unit input is refused
// with the field named; snapshots and events reach the messages unchanged.
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "brick_stack_sim/ros/conversions.h"
#include "brick_stack_sim/ros/markers.h"
#include "support/kapla.h"

namespace brick_stack_sim {
namespace ros_adapter {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

PlaceBrick::Request validRequest() {
  PlaceBrick::Request request;
  request.id = "b0";
  request.type = "kapla";
  request.pose.position.x = 0.1;
  request.pose.position.y = -0.2;
  request.pose.position.z = 0.0039;
  request.pose.orientation.w = 1.0;
  return request;
}

/// Every number field of a PlaceBrick request, by the name the error must give.
std::vector<std::pair<std::string, std::function<double&(PlaceBrick::Request&)>>> requestFields() {
  using R = PlaceBrick::Request;
  return {
      {"pose.position.x", [](R& r) -> double& { return r.pose.position.x; }},
      {"pose.position.y", [](R& r) -> double& { return r.pose.position.y; }},
      {"pose.position.z", [](R& r) -> double& { return r.pose.position.z; }},
      {"pose.orientation.x", [](R& r) -> double& { return r.pose.orientation.x; }},
      {"pose.orientation.y", [](R& r) -> double& { return r.pose.orientation.y; }},
      {"pose.orientation.z", [](R& r) -> double& { return r.pose.orientation.z; }},
      {"pose.orientation.w", [](R& r) -> double& { return r.pose.orientation.w; }},
      {"twist.linear.x", [](R& r) -> double& { return r.twist.linear.x; }},
      {"twist.linear.y", [](R& r) -> double& { return r.twist.linear.y; }},
      {"twist.linear.z", [](R& r) -> double& { return r.twist.linear.z; }},
      {"twist.angular.x", [](R& r) -> double& { return r.twist.angular.x; }},
      {"twist.angular.y", [](R& r) -> double& { return r.twist.angular.y; }},
      {"twist.angular.z", [](R& r) -> double& { return r.twist.angular.z; }},
  };
}

TEST(Conversions, ValidPlaceRequest) {
  PlaceBrick::Request request = validRequest();
  request.twist.linear.x = 1.5;
  request.twist.angular.z = -2.0;
  BrickPlacement placement;
  const Status status = fromMsg(request, &placement);
  ASSERT_TRUE(status.ok) << status.message;
  EXPECT_EQ(placement.id, "b0");
  EXPECT_EQ(placement.type, "kapla");
  EXPECT_TRUE(placement.pose.translation().isApprox(Eigen::Vector3d(0.1, -0.2, 0.0039)));
  EXPECT_TRUE(placement.pose.linear().isApprox(Eigen::Matrix3d::Identity()));
  EXPECT_EQ(placement.linear_velocity, Eigen::Vector3d(1.5, 0, 0));
  EXPECT_EQ(placement.angular_velocity, Eigen::Vector3d(0, 0, -2.0));
}

TEST(Conversions, RefusesNaNAndInfInEveryField) {
  for (const auto& [name, field] : requestFields()) {
    for (double bad : {kNaN, kInf, -kInf}) {
      PlaceBrick::Request request = validRequest();
      field(request) = bad;
      BrickPlacement placement;
      placement.id = "untouched";
      const Status status = fromMsg(request, &placement);
      EXPECT_FALSE(status.ok) << name << " = " << bad << " accepted";
      EXPECT_NE(status.message.find(name), std::string::npos)
          << "message does not name " << name << ": " << status.message;
      EXPECT_EQ(placement.id, "untouched") << "output written on refusal";
    }
  }
}

TEST(Conversions, RefusesNonUnitQuaternions) {
  for (const auto& [x, y, z, w] : std::vector<std::array<double, 4>>{
           {0, 0, 0, 0}, {0, 0, 0, 2}, {0, 0, 0, 0.99}, {1, 1, 1, 1}, {0, 0, 0.7071, 0.6}}) {
    PlaceBrick::Request request = validRequest();
    request.pose.orientation.x = x;
    request.pose.orientation.y = y;
    request.pose.orientation.z = z;
    request.pose.orientation.w = w;
    BrickPlacement placement;
    const Status status = fromMsg(request, &placement);
    EXPECT_FALSE(status.ok) << x << " " << y << " " << z << " " << w << " accepted";
    EXPECT_NE(status.message.find("pose.orientation"), std::string::npos) << status.message;
  }
}

TEST(Conversions, NormalisesNearUnitQuaternions) {
  PlaceBrick::Request request = validRequest();
  // 90 degrees about z, typed with four digits: norm 0.99999..., within 1e-3.
  request.pose.orientation.z = 0.7071;
  request.pose.orientation.w = 0.7071;
  BrickPlacement placement;
  ASSERT_TRUE(fromMsg(request, &placement).ok);
  const Eigen::Matrix3d r = placement.pose.linear();
  EXPECT_NEAR((r.transpose() * r - Eigen::Matrix3d::Identity()).norm(), 0.0, 1e-12);
  EXPECT_NEAR(r.determinant(), 1.0, 1e-12);
  EXPECT_TRUE((r * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d::UnitY(), 1e-9));

  request.pose.orientation.z = 0.0;
  request.pose.orientation.w = 1.0009;  // just inside the tolerance
  ASSERT_TRUE(fromMsg(request, &placement).ok);
  EXPECT_NEAR((placement.pose.linear() - Eigen::Matrix3d::Identity()).norm(), 0.0, 1e-12);
}

TEST(Conversions, PushRequest) {
  PushBrick::Request request;
  request.id = "b0";
  request.impulse.x = 0.001;
  request.point.z = 0.004;
  Eigen::Vector3d impulse, point;
  ASSERT_TRUE(fromMsg(request, &impulse, &point).ok);
  EXPECT_EQ(impulse, Eigen::Vector3d(0.001, 0, 0));
  EXPECT_EQ(point, Eigen::Vector3d(0, 0, 0.004));
  request.impulse.y = kNaN;
  Status status = fromMsg(request, &impulse, &point);
  EXPECT_FALSE(status.ok);
  EXPECT_NE(status.message.find("impulse.y"), std::string::npos) << status.message;
  request.impulse.y = 0.0;
  request.point.x = kInf;
  status = fromMsg(request, &impulse, &point);
  EXPECT_FALSE(status.ok);
  EXPECT_NE(status.message.find("point.x"), std::string::npos) << status.message;
}

BrickSnapshot sampleSnapshot() {
  BrickSnapshot brick;
  brick.id = "b7";
  brick.type = "kapla";
  brick.pose = Eigen::Translation3d(0.01, 0.02, 0.0117) *
               Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized());
  brick.linear_velocity = Eigen::Vector3d(0.1, -0.2, 0.3);
  brick.angular_velocity = Eigen::Vector3d(-1, 2, -3);
  brick.size = Eigen::Vector3d(0.117, 0.0234, 0.0078);
  brick.mass = 0.0119;
  brick.state = BrickState::kLeaning;
  brick.asleep = true;
  brick.fell_off = true;
  brick.com_above = Eigen::Vector3d(0.01, 0.0, 0.02);
  brick.mass_above = 0.0357;
  brick.supported_by = {"table", "b3"};
  brick.margin = -0.002;
  brick.placed_at = 4.25;
  brick.serial = 7;
  return brick;
}

TEST(Conversions, SnapshotToMessageRoundTrip) {
  const BrickSnapshot brick = sampleSnapshot();
  Brick msg;
  ASSERT_TRUE(toMsg(brick, &msg).ok);
  EXPECT_EQ(msg.id, "b7");
  EXPECT_EQ(msg.type, "kapla");
  Eigen::Isometry3d pose;
  ASSERT_TRUE(fromMsg(msg.pose, "pose", &pose).ok);  // the published quaternion is unit
  EXPECT_TRUE(pose.isApprox(brick.pose, 1e-12));
  EXPECT_EQ(msg.twist.linear.y, -0.2);
  EXPECT_EQ(msg.twist.angular.z, -3.0);
  EXPECT_EQ(msg.size.x, 0.117);
  EXPECT_EQ(msg.size.z, 0.0078);
  EXPECT_EQ(msg.mass, 0.0119);
  EXPECT_EQ(msg.state, Brick::LEANING);
  EXPECT_TRUE(msg.asleep);
  EXPECT_TRUE(msg.fell_off);
  EXPECT_EQ(msg.com_above.z, 0.02);
  EXPECT_EQ(msg.mass_above, 0.0357);
  EXPECT_EQ(msg.supported_by, (std::vector<std::string>{"table", "b3"}));
  EXPECT_EQ(msg.margin, -0.002);
  EXPECT_EQ(msg.placed_at, 4.25);
}

// The stability fields of Brick.msg as the real stability layer fills them:
// a two-layer tower, each value from hand statics.
TEST(Conversions, FrozenTowerBricksAreStableWithTheirSupportsAndLoads) {
  auto world = test::makeWorld(test::optionsFor("com"));
  for (int i = 0; i < 4; ++i) ASSERT_TRUE(world->addBrick(test::towerBrick(i)).ok) << i;
  BrickPlacement falling = test::towerBrick(0);
  falling.id = "falling";
  falling.pose.translation() = Eigen::Vector3d(0.3, 0.2, 0.05);
  ASSERT_TRUE(world->addBrick(falling).ok);
  test::runFor(world.get(), 0.05);  // 12 mm of fall: still in the air

  double brick_mass = 0.0;
  for (const BrickSnapshot& snapshot : world->snapshot()) {
    Brick msg;
    const Status converted = toMsg(snapshot, &msg);
    ASSERT_TRUE(converted.ok) << converted.message;
    EXPECT_EQ(msg.com_above.x, snapshot.com_above.x()) << snapshot.id;
    EXPECT_EQ(msg.com_above.z, snapshot.com_above.z()) << snapshot.id;
    EXPECT_EQ(msg.mass_above, snapshot.mass_above) << snapshot.id;
    if (!snapshot.supported_by.empty()) {
      EXPECT_EQ(msg.margin, snapshot.margin) << snapshot.id;
    }
    EXPECT_EQ(msg.supported_by, snapshot.supported_by) << snapshot.id;
    brick_mass = msg.mass;
    if (msg.id == "falling") {
      EXPECT_EQ(msg.state, Brick::DYNAMIC);
      EXPECT_TRUE(msg.supported_by.empty());
      EXPECT_EQ(msg.margin, 0.0) << "resting on nothing: no hull to measure";
      continue;
    }
    EXPECT_EQ(msg.state, Brick::STABLE) << msg.id;
    // Both layers rest on a hull 23.4 mm wide across their COM-above.
    EXPECT_NEAR(msg.margin, test::kKaplaWidth / 2, 1e-4) << msg.id;
    std::vector<std::string> supporters = msg.supported_by;
    std::sort(supporters.begin(), supporters.end());
    if (msg.id == "t0" || msg.id == "t1") {
      EXPECT_EQ(supporters, std::vector<std::string>{"table"}) << msg.id;
      // Itself plus half of each upper brick, by symmetry.
      EXPECT_NEAR(msg.mass_above, 2 * msg.mass, 1e-9) << msg.id;
    } else {
      EXPECT_EQ(supporters, (std::vector<std::string>{"t0", "t1"})) << msg.id;
      EXPECT_NEAR(msg.mass_above, msg.mass, 1e-9) << msg.id;  // carries nothing
      EXPECT_NEAR(msg.com_above.x, msg.pose.position.x, 1e-6) << msg.id;
      EXPECT_NEAR(msg.com_above.y, msg.pose.position.y, 1e-6) << msg.id;
      EXPECT_NEAR(msg.com_above.z, msg.pose.position.z, 1e-6) << msg.id;
    }
  }
  EXPECT_NEAR(brick_mass, 0.0119, 1e-9);
}

TEST(Conversions, NonFiniteSnapshotIsNotConverted) {
  const std::vector<std::function<void(BrickSnapshot&)>> spoil = {
      [](BrickSnapshot& b) { b.pose.translation().x() = kNaN; },
      [](BrickSnapshot& b) { b.pose.linear()(1, 2) = kInf; },
      [](BrickSnapshot& b) { b.linear_velocity.z() = kNaN; },
      [](BrickSnapshot& b) { b.angular_velocity.x() = -kInf; },
      [](BrickSnapshot& b) { b.com_above.y() = kNaN; },
      [](BrickSnapshot& b) { b.mass_above = kNaN; },
      [](BrickSnapshot& b) { b.margin = kInf; },
      [](BrickSnapshot& b) { b.margin = -kInf; },
      [](BrickSnapshot& b) {
        b.supported_by.clear();  // resting on nothing: the core says 0, never -inf
        b.margin = -kInf;
      },
      [](BrickSnapshot& b) {
        b.supported_by.clear();
        b.margin = kNaN;
      },
  };
  for (std::size_t i = 0; i < spoil.size(); ++i) {
    BrickSnapshot brick = sampleSnapshot();
    spoil[i](brick);
    Brick msg;
    EXPECT_FALSE(toMsg(brick, &msg).ok) << "spoiled field " << i << " converted";
  }
}

TEST(Conversions, EventToMessage) {
  SimEvent event;
  event.time = 2.5;
  event.kind = SimEventKind::kFellOff;
  event.brick_id = "b2";
  event.reason = "centre 0.03 m below the table top";
  event.affected = {"b3", "b4"};
  const StabilityEvent msg = toMsg(event);
  EXPECT_EQ(msg.kind, StabilityEvent::FELL_OFF);
  EXPECT_EQ(msg.brick_id, "b2");
  EXPECT_EQ(msg.reason, event.reason);
  EXPECT_EQ(msg.affected, event.affected);
  event.kind = SimEventKind::kSpawned;
  EXPECT_EQ(toMsg(event).kind, StabilityEvent::SPAWNED);
  event.kind = SimEventKind::kNonFinite;
  EXPECT_EQ(toMsg(event).kind, StabilityEvent::NONFINITE);
}

TEST(Markers, OneCubePerBrickAfterDeleteAll) {
  std::vector<BrickSnapshot> bricks(3, sampleSnapshot());
  bricks[0].serial = 0;
  bricks[0].state = BrickState::kStable;
  bricks[0].fell_off = false;
  bricks[1].serial = 4;
  bricks[1].state = BrickState::kDynamic;
  bricks[1].fell_off = false;
  bricks[1].asleep = false;
  bricks[2].serial = 9;
  bricks[2].pose.translation().z() = kNaN;  // left out, not sent to RViz
  const auto array = makeBrickMarkers(bricks, "world", ros::Time(3.0));
  // DELETEALL, a box per finite brick, and one list of their outlines.
  ASSERT_EQ(array.markers.size(), 4u);
  EXPECT_EQ(array.markers[0].action, visualization_msgs::Marker::DELETEALL);
  std::vector<const visualization_msgs::Marker*> boxes;
  for (std::size_t i = 1; i < array.markers.size(); ++i) {
    const auto& marker = array.markers[i];
    EXPECT_EQ(marker.header.frame_id, "world");
    if (marker.ns == "brick_edges") {
      EXPECT_EQ(marker.type, visualization_msgs::Marker::LINE_LIST);
      continue;
    }
    EXPECT_EQ(marker.type, visualization_msgs::Marker::CUBE);
    EXPECT_EQ(marker.ns, "bricks");
    EXPECT_EQ(marker.scale.x, 0.117);
    EXPECT_EQ(marker.color.a, 1.0f);
    boxes.push_back(&marker);
  }
  ASSERT_EQ(boxes.size(), 2u);
  EXPECT_EQ(boxes[0]->id, 0);
  EXPECT_EQ(boxes[1]->id, 4);
  const auto& stable = boxes[0]->color;
  const auto& dynamic = boxes[1]->color;
  EXPECT_TRUE(stable.r != dynamic.r || stable.g != dynamic.g || stable.b != dynamic.b);
}

TEST(Markers, StatesAreDistinguishable) {
  BrickSnapshot brick = sampleSnapshot();
  brick.fell_off = false;
  brick.asleep = false;
  std::vector<BrickLook> looks;
  brick.state = BrickState::kDynamic;
  looks.push_back(brickLook(brick));
  brick.asleep = true;
  looks.push_back(brickLook(brick));
  brick.asleep = false;
  brick.state = BrickState::kStable;
  looks.push_back(brickLook(brick));
  brick.state = BrickState::kLeaning;
  looks.push_back(brickLook(brick));
  brick.state = BrickState::kHeld;
  looks.push_back(brickLook(brick));
  brick.fell_off = true;
  looks.push_back(brickLook(brick));
  for (std::size_t i = 0; i < looks.size(); ++i) {
    for (std::size_t j = i + 1; j < looks.size(); ++j) {
      EXPECT_NE(looks[i], looks[j]) << i << " " << j;
      const auto a = brickColor(looks[i]);
      const auto b = brickColor(looks[j]);
      EXPECT_GT(std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b), 0.2f)
          << "colours " << i << " and " << j << " too close";
    }
  }
}

}  // namespace
}  // namespace ros_adapter
}  // namespace brick_stack_sim
