// The node started by sim.launch, driven through its services: requests that
// should work do, bad ones are refused with a message and change nothing.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <future>
#include <thread>
#include <utility>

#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>
#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include "node_fixture.h"

namespace {

using namespace brick_stack_sim;

constexpr double kHalfHeight = 0.0039;  ///< Half a KAPLA thickness [m]: a brick lying on the table.
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

class NodeServices : public test::NodeFixture {
 protected:
  void SetUp() override {
    NodeFixture::SetUp();
    if (HasFatalFailure()) return;
    // Every test starts from a running node and an empty table.
    ASSERT_TRUE(setPaused(false));
    const client::Reply<ResetScene::Response> reset = sim_->reset();
    ASSERT_TRUE(reset.reached) << reset.message;
    ASSERT_TRUE(reset.response.success) << reset.response.message;
    ASSERT_TRUE(bricks().empty());
  }

  std::optional<Brick> brick(const std::string& id) {
    for (const Brick& b : bricks())
      if (b.id == id) return b;
    return std::nullopt;
  }

  /// Expects a refusal that says something, for the request named `what`.
  template <typename Response>
  void expectRefused(const Response& response, const std::string& what) {
    EXPECT_FALSE(response.success) << what << " was accepted";
    EXPECT_FALSE(response.message.empty()) << what << " refused without a message";
  }
};

TEST_F(NodeServices, PlaceGetRemove) {
  const PlaceBrick::Response placed = place("a", 0.05, -0.03, kHalfHeight);
  ASSERT_TRUE(placed.success) << placed.message;
  EXPECT_EQ(placed.id, "a");
  const std::optional<Brick> a = brick("a");
  ASSERT_TRUE(a);
  EXPECT_EQ(a->type, "kapla");
  EXPECT_NEAR(a->pose.position.x, 0.05, 1e-3);
  EXPECT_NEAR(a->pose.position.y, -0.03, 1e-3);
  EXPECT_NEAR(a->pose.position.z, kHalfHeight, 1e-3);
  EXPECT_NEAR(a->size.x, 0.117, 1e-9);
  EXPECT_GT(a->mass, 0.0);

  // No id: the world names it.
  const PlaceBrick::Response unnamed = place("", -0.2, 0.2, kHalfHeight);
  ASSERT_TRUE(unnamed.success) << unnamed.message;
  EXPECT_FALSE(unnamed.id.empty());
  EXPECT_TRUE(brick(unnamed.id));

  RemoveBrick remove;
  remove.request.id = "a";
  ASSERT_TRUE(call(remove).success) << remove.response.message;
  EXPECT_FALSE(brick("a"));
  EXPECT_EQ(bricks().size(), 1u);

  // Removing it again: refused, nothing else touched.
  expectRefused(call(remove), "removing an unknown id");
  EXPECT_EQ(bricks().size(), 1u);
}

TEST_F(NodeServices, BadPlacementsAreRefusedAndChangeNothing) {
  ASSERT_TRUE(place("a", 0.0, 0.0, kHalfHeight).success);

  PlaceBrick srv;
  auto base = [&] {
    srv.request = PlaceBrick::Request();
    srv.request.id = "b";
    srv.request.type = "kapla";
    srv.request.pose.position.x = 0.3;
    srv.request.pose.position.z = kHalfHeight;
    srv.request.pose.orientation.w = 1.0;
  };
  base();
  srv.request.pose.position.y = kNaN;
  expectRefused(call(srv), "NaN position");
  EXPECT_NE(srv.response.message.find("pose.position.y"), std::string::npos)
      << srv.response.message;
  base();
  srv.request.twist.angular.x = std::numeric_limits<double>::infinity();
  expectRefused(call(srv), "Inf angular velocity");
  base();
  srv.request.pose.orientation.w = 2.0;
  expectRefused(call(srv), "non-unit quaternion");
  EXPECT_NE(srv.response.message.find("orientation"), std::string::npos) << srv.response.message;
  base();
  srv.request.pose.orientation.w = 0.0;
  expectRefused(call(srv), "zero quaternion");
  base();
  srv.request.type = "no_such_type";
  expectRefused(call(srv), "unknown type");
  EXPECT_NE(srv.response.message.find("no_such_type"), std::string::npos) << srv.response.message;
  base();
  srv.request.id = "a";
  expectRefused(call(srv), "duplicate id");
  base();
  srv.request.pose.position.x = 0.01;  // inside brick a
  expectRefused(call(srv), "pose inside another brick");
  base();
  srv.request.pose.position.z = -0.01;
  expectRefused(call(srv), "pose under the table");
  base();
  srv.request.id = "not valid!";
  expectRefused(call(srv), "invalid id");
  // Finite but absurd, and names the scene's fixed bodies own.
  for (double far : {1e300, -1e300, 10.5}) {
    base();
    srv.request.pose.position.x = far;
    expectRefused(call(srv), "x = " + std::to_string(far));
    EXPECT_NE(srv.response.message.find("outside the world box"), std::string::npos)
        << srv.response.message;
  }
  base();
  srv.request.pose.position.z = 1e300;
  expectRefused(call(srv), "z = 1e300");
  for (const char* reserved : {"floor", "Table", "WORLD"}) {
    base();
    srv.request.id = reserved;
    expectRefused(call(srv), std::string("id ") + reserved);
    EXPECT_NE(srv.response.message.find("is reserved"), std::string::npos) << srv.response.message;
  }
  base();
  srv.request.id = "b" + std::string(10239, 'x');
  expectRefused(call(srv), "10 kB id");
  EXPECT_LT(srv.response.message.size(), 300u) << "the refusal echoes the whole id";

  const std::vector<Brick> after = bricks();
  ASSERT_EQ(after.size(), 1u);
  EXPECT_EQ(after[0].id, "a");
  EXPECT_NEAR(after[0].pose.position.x, 0.0, 1e-3);
  EXPECT_NEAR(after[0].pose.position.z, kHalfHeight, 1e-3);

  // The same request without its fault is accepted: the refusals were about the fault.
  base();
  EXPECT_TRUE(call(srv).success) << srv.response.message;
}

TEST_F(NodeServices, NearUnitQuaternionIsAccepted) {
  PlaceBrick srv;
  srv.request.id = "q";
  srv.request.pose.position.z = kHalfHeight;
  srv.request.pose.orientation.z = 0.7071;  // 90 degrees about z, four digits
  srv.request.pose.orientation.w = 0.7071;
  ASSERT_TRUE(call(srv).success) << srv.response.message;
  const std::optional<Brick> q = brick("q");
  ASSERT_TRUE(q);
  const auto& o = q->pose.orientation;
  EXPECT_NEAR(std::sqrt(o.x * o.x + o.y * o.y + o.z * o.z + o.w * o.w), 1.0, 1e-9);
  EXPECT_NEAR(std::abs(o.z), std::sqrt(0.5), 1e-3);
}

TEST_F(NodeServices, PlacedBrickIsPublishedOnTopicAndTf) {
  std::mutex mutex;
  std::optional<Brick> seen;
  ros::Subscriber sub = sim_->subscribeBricks(
      [&](const BrickArray::ConstPtr& msg) {
        std::lock_guard<std::mutex> lock(mutex);
        EXPECT_EQ(msg->header.frame_id, "world");
        for (const Brick& b : msg->bricks)
          if (b.id == "tf_brick") seen = b;
      },
      10);
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);

  ASSERT_TRUE(place("tf_brick", 0.1, 0.05, kHalfHeight).success);
  ASSERT_TRUE(waitFor(
      [&] {
        std::lock_guard<std::mutex> lock(mutex);
        return seen.has_value();
      },
      10.0))
      << "tf_brick never appeared on ~bricks";
  {
    std::lock_guard<std::mutex> lock(mutex);
    EXPECT_NEAR(seen->pose.position.x, 0.1, 1e-3);
    EXPECT_NEAR(seen->pose.position.y, 0.05, 1e-3);
  }

  std::string error;
  ASSERT_TRUE(buffer.canTransform("world", "tf_brick", ros::Time(0), ros::Duration(10.0), &error))
      << error;
  const geometry_msgs::TransformStamped transform =
      buffer.lookupTransform("world", "tf_brick", ros::Time(0));
  EXPECT_NEAR(transform.transform.translation.x, 0.1, 1e-3);
  EXPECT_NEAR(transform.transform.translation.y, 0.05, 1e-3);
  EXPECT_NEAR(transform.transform.translation.z, kHalfHeight, 1e-3);
}

TEST_F(NodeServices, EventsArriveForPlacementAndRemoval) {
  std::mutex mutex;
  std::vector<StabilityEvent> events;
  ros::Subscriber sub = sim_->subscribeEvents(
      [&](const StabilityEvent::ConstPtr& msg) {
        std::lock_guard<std::mutex> lock(mutex);
        events.push_back(*msg);
      },
      100);
  ASSERT_TRUE(waitFor([&] { return sub.getNumPublishers() > 0; }, 10.0));
  auto has = [&](const std::string& id, uint8_t kind) {
    std::lock_guard<std::mutex> lock(mutex);
    for (const StabilityEvent& e : events)
      if (e.brick_id == id && e.kind == kind) return true;
    return false;
  };

  ASSERT_TRUE(place("ev", -0.1, 0.1, kHalfHeight).success);
  EXPECT_TRUE(waitFor([&] { return has("ev", StabilityEvent::SPAWNED); }, 10.0))
      << "no spawned event for ev";
  RemoveBrick remove;
  remove.request.id = "ev";
  ASSERT_TRUE(call(remove).success);
  EXPECT_TRUE(waitFor([&] { return has("ev", StabilityEvent::REMOVED); }, 10.0))
      << "no removed event for ev";
  // A refused placement is not an event.
  EXPECT_FALSE(place("ev2", 0.0, 0.0, -1.0).success);
  ros::WallDuration(0.3).sleep();
  EXPECT_FALSE(has("ev2", StabilityEvent::SPAWNED));
}

TEST_F(NodeServices, PauseAndStep) {
  const StepSimulation::Response running = step(10);
  expectRefused(running, "step while running");

  ASSERT_TRUE(setPaused(true));
  // A brick dropped from 5 cm stays in the air while paused...
  ASSERT_TRUE(place("drop", 0.0, 0.0, 0.05).success);
  const StepSimulation::Response first = step(1);
  ASSERT_TRUE(first.success) << first.message;
  ros::WallDuration(0.3).sleep();
  std::optional<Brick> drop = brick("drop");
  ASSERT_TRUE(drop);
  EXPECT_GT(drop->pose.position.z, 0.0499);

  // ... and falls while stepped: 250 steps of 1 ms are exactly 0.25 s.
  const StepSimulation::Response second = step(250);
  ASSERT_TRUE(second.success) << second.message;
  EXPECT_NEAR(second.sim_time - first.sim_time, 0.25, 1e-9);
  drop = brick("drop");
  ASSERT_TRUE(drop);
  EXPECT_LT(drop->pose.position.z, 0.04);

  // Bad step counts are refused and do not move the clock.
  expectRefused(step(0), "0 steps");
  expectRefused(step(2000000), "2e6 steps");
  const StepSimulation::Response third = step(1);
  ASSERT_TRUE(third.success);
  EXPECT_NEAR(third.sim_time - second.sim_time, 0.001, 1e-9);

  // Enough steps for the brick to land on the table.
  ASSERT_TRUE(step(1000).success);
  drop = brick("drop");
  ASSERT_TRUE(drop);
  EXPECT_NEAR(drop->pose.position.z, kHalfHeight, 1e-3);

  ASSERT_TRUE(setPaused(false));
  expectRefused(step(1), "step after resuming");
}

TEST_F(NodeServices, ResetWithUnknownSceneChangesNothing) {
  ASSERT_TRUE(place("keep", 0.1, 0.1, kHalfHeight).success);
  ResetScene reset;
  reset.request.scene = "no_such_scene_1234";
  expectRefused(call(reset), "unknown scene");
  const std::vector<Brick> after = bricks();
  ASSERT_EQ(after.size(), 1u);
  EXPECT_EQ(after[0].id, "keep");

  reset.request.scene = "";
  ASSERT_TRUE(call(reset).success) << reset.response.message;
  EXPECT_TRUE(bricks().empty());
}

TEST_F(NodeServices, HostileScenesAreRefusedAtOnceAndChangeNothing) {
  // /dev/zero was once read until the node was killed for memory, and a
  // FIFO blocked the whole node until someone wrote to it.
  ASSERT_TRUE(place("keep", 0.1, 0.1, kHalfHeight).success);
  const std::string dir = ::testing::TempDir() + "/hostile_scenes_" + std::to_string(getpid());
  ASSERT_EQ(mkdir(dir.c_str(), 0755), 0);
  const std::string fifo = dir + "/fifo.yaml";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0644), 0);
  const std::string sparse = dir + "/sparse.yaml";  // 1 GB of nothing, no disk used
  std::FILE* created = std::fopen(sparse.c_str(), "w");
  ASSERT_NE(created, nullptr);
  std::fclose(created);
  ASSERT_EQ(truncate(sparse.c_str(), 1LL << 30), 0);
  const std::pair<std::string, std::string> cases[] = {
      {"/dev/zero", "not a regular file"},
      {fifo, "not a regular file"},
      {dir, "is a directory"},
      {sparse, "more than the limit"},
  };
  for (const auto& [scene, expected] : cases) {
    // From a thread: a node that blocks must fail the test, not hang it.
    ResetScene reset;
    reset.request.scene = scene;
    std::promise<bool> answered;
    std::thread caller([&] {
      const client::Reply<ResetScene::Response> reply = sim_->reset(reset.request.scene);
      reset.response = reply.response;
      answered.set_value(reply.reached);
    });
    std::future<bool> answer = answered.get_future();
    const bool in_time = answer.wait_for(std::chrono::seconds(5)) == std::future_status::ready;
    if (!in_time) {
      // Unblock a node stuck on the FIFO so that the test can end.
      std::FILE* writer = std::fopen(fifo.c_str(), "w");
      if (writer) std::fclose(writer);
    }
    caller.join();
    ASSERT_TRUE(in_time) << "~reset of " << scene << " did not answer within 5 s";
    ASSERT_TRUE(answer.get());
    expectRefused(reset.response, "scene " + scene);
    EXPECT_NE(reset.response.message.find(expected), std::string::npos) << reset.response.message;
  }
  const std::vector<Brick> after = bricks();
  ASSERT_EQ(after.size(), 1u);
  EXPECT_EQ(after[0].id, "keep");
  std::remove(fifo.c_str());
  std::remove(sparse.c_str());
  rmdir(dir.c_str());
}

TEST_F(NodeServices, ASceneOverTheBrickCapIsRefusedBeforeItIsBuilt) {
  // 3.4 kB asking for 5 million bricks: the node once answered only
  // "responded with an error: b'std::bad_alloc'".
  ASSERT_TRUE(place("keep", 0.1, 0.1, kHalfHeight).success);
  const std::vector<Brick> before = bricks();
  const std::string path = ::testing::TempDir() + "/over_cap_" + std::to_string(getpid()) + ".yaml";
  std::FILE* file = std::fopen(path.c_str(), "w");
  ASSERT_NE(file, nullptr);
  std::fputs("generator:\n", file);
  for (int i = 0; i < 50; ++i)
    std::fputs("  - {name: tower, layers: 10000, bricks_per_layer: 2, grid: [5, 1]}\n", file);
  std::fclose(file);
  ResetScene reset;
  reset.request.scene = path;
  ASSERT_TRUE(test::callWithin(sim_, reset, 5.0)) << "~reset of 5 million bricks took over 5 s";
  expectRefused(reset.response, "a scene over scene_max_bricks");
  EXPECT_NE(reset.response.message.find("generator 2 (tower) would bring the scene to 200000 "
                                        "bricks: at most 100000 (scene_max_bricks)"),
            std::string::npos)
      << reset.response.message;
  const std::vector<Brick> after = bricks();
  ASSERT_EQ(after.size(), 1u);
  EXPECT_EQ(after[0].id, "keep");
  // Untouched by the refused reset. In plain Bullet a brick placed at rest
  // drifts by picometres, the solver's residual, until Bullet puts it to
  // sleep: a reset would have moved or removed it.
  EXPECT_NEAR(after[0].pose.position.x, before[0].pose.position.x, 1e-9);
  EXPECT_NEAR(after[0].pose.position.y, before[0].pose.position.y, 1e-9);
  std::remove(path.c_str());
}

TEST_F(NodeServices, MessagesCountAndCutWhatTheyRepeat) {
  ASSERT_TRUE(place("one", 0.1, 0.1, kHalfHeight).success);
  const client::Reply<GetBricks::Response> got = sim_->getBricks();
  ASSERT_TRUE(got.reached) << got.message;
  EXPECT_EQ(got.response.message.rfind("1 brick at t=", 0), 0u) << got.response.message;

  // sim.launch looks in scene_dir and then in the package's scenes/, by
  // default one directory: it is listed once.
  ResetScene reset;
  reset.request.scene = "no_such_scene_5678";
  expectRefused(call(reset), "unknown scene");
  const std::string& message = reset.response.message;
  const std::size_t open = message.find("no_such_scene_5678.yaml in [");
  ASSERT_NE(open, std::string::npos) << message;
  EXPECT_EQ(message.find(',', open), std::string::npos) << message;

  // A 10 kB name is cut, not echoed back whole.
  reset.request.scene = std::string(10240, 'x');
  expectRefused(call(reset), "a 10 kB scene name");
  EXPECT_LT(reset.response.message.size(), 1000u) << reset.response.message.size();
  EXPECT_NE(reset.response.message.find("(10240 characters)"), std::string::npos)
      << reset.response.message;
  ASSERT_EQ(bricks().size(), 1u);
}

TEST_F(NodeServices, ResetPlaysSceneOnTime) {
  std::string scene_path;
  ASSERT_TRUE(ros::NodeHandle("~").getParam("scene_path", scene_path));
  ASSERT_TRUE(place("old", 0.1, 0.1, kHalfHeight).success);
  ASSERT_TRUE(setPaused(true));
  ResetScene reset;
  reset.request.scene = scene_path;
  ASSERT_TRUE(call(reset).success) << reset.response.message;
  EXPECT_EQ(reset.response.bricks_scheduled, 2u);
  // s0 is due at once, s1 half a second of sim time later; "old" is gone.
  EXPECT_FALSE(brick("old"));
  EXPECT_TRUE(brick("s0"));
  EXPECT_FALSE(brick("s1"));
  ASSERT_TRUE(step(400).success);
  EXPECT_FALSE(brick("s1")) << "placed before its time";
  ASSERT_TRUE(step(200).success);
  EXPECT_TRUE(brick("s1")) << "not placed at its time";
}

TEST_F(NodeServices, SceneWithItsOwnTableAndTypes) {
  std::string scene_path;
  ASSERT_TRUE(ros::NodeHandle("~").getParam("own_table_scene_path", scene_path));
  ASSERT_TRUE(setPaused(true));
  const double before = step(1).sim_time;
  ResetScene reset;
  reset.request.scene = scene_path;
  ASSERT_TRUE(call(reset).success) << reset.response.message;
  const std::optional<Brick> t0 = brick("t0");
  ASSERT_TRUE(t0) << "the scene's brick was not placed";
  EXPECT_EQ(t0->type, "tiny");
  EXPECT_NEAR(t0->size.x, 0.02, 1e-9);
  // A new world for the scene, but sim time does not jump back.
  const StepSimulation::Response after = step(1);
  ASSERT_TRUE(after.success);
  EXPECT_NEAR(after.sim_time, before + 0.001, 1e-9);
  ASSERT_TRUE(place("t1", 0.05, 0.05, 0.01, 0.0, "tiny").success);

  // An empty reset goes back to the configured world: the scene's type is gone.
  reset.request.scene = "";
  ASSERT_TRUE(call(reset).success) << reset.response.message;
  EXPECT_TRUE(bricks().empty());
  expectRefused(place("t2", 0.0, 0.0, 0.01, 0.0, "tiny"), "a type of a previous scene");
  EXPECT_TRUE(place("k", 0.0, 0.0, kHalfHeight).success);
  EXPECT_GE(step(1).sim_time, after.sim_time + 0.001 - 1e-9);
}

TEST_F(NodeServices, PushBrick) {
  ASSERT_TRUE(setPaused(true));
  ASSERT_TRUE(place("p", 0.0, 0.0, kHalfHeight).success);
  ASSERT_TRUE(step(10).success);
  const double x0 = brick("p")->pose.position.x;

  PushBrick push;
  push.request.id = "p";
  push.request.impulse.x = kNaN;
  expectRefused(call(push), "NaN impulse");
  push.request.impulse.x = 0.005;  // 0.42 m/s for a 11.9 g plank: slides ~2 cm
  push.request.point.z = kHalfHeight;
  push.request.id = "nobody";
  expectRefused(call(push), "push of an unknown id");
  ASSERT_TRUE(step(10).success);
  EXPECT_NEAR(brick("p")->pose.position.x, x0, 1e-4) << "a refused push moved the brick";

  push.request.id = "p";
  ASSERT_TRUE(call(push).success) << push.response.message;
  ASSERT_TRUE(step(300).success);
  EXPECT_GT(brick("p")->pose.position.x - x0, 0.005);
}

TEST_F(NodeServices, QueryPlacementAnswersByStaticsAndChangesNothing) {
  ASSERT_TRUE(place("a", 0.0, 0.0, kHalfHeight).success);
  ASSERT_TRUE(setPaused(true));
  const std::vector<Brick> before = bricks();
  auto query = [&](double x, double z) {
    QueryPlacement srv;
    srv.request.pose.position.x = x;
    srv.request.pose.position.z = z;
    srv.request.pose.orientation.w = 1.0;
    return call(srv);
  };
  // Centred on "a": it rests there. 30 mm along: still over it. 70 mm
  // along: its COM past a's end (58.5 mm), it falls.
  for (double x : {0.0, 0.03}) {
    const QueryPlacement::Response on_top = query(x, 3 * kHalfHeight);
    ASSERT_TRUE(on_top.success) << on_top.message;
    EXPECT_TRUE(on_top.stable) << x << ": " << on_top.message;
    EXPECT_EQ(on_top.state, Brick::STABLE);
    EXPECT_EQ(on_top.supported_by, std::vector<std::string>{"a"});
    // Brick.msg's margin: to the nearest edge of a's top, its long side
    // (half a width, 11.7 mm) or its end (58.5 mm - x).
    EXPECT_NEAR(on_top.margin, std::min(0.0117, 0.0585 - x), 1e-6);
    // Flat, it slides before it tips: mu g.
    EXPECT_NEAR(on_top.acceleration_margin, 0.5 * 9.81, 1e-6);
  }
  const QueryPlacement::Response beyond = query(0.07, 3 * kHalfHeight);
  ASSERT_TRUE(beyond.success) << beyond.message;
  EXPECT_FALSE(beyond.stable);
  EXPECT_FALSE(beyond.message.empty());
  // Bad poses: inside "a", under the table, a NaN.
  expectRefused(query(0.0, kHalfHeight), "a pose inside a brick");
  expectRefused(query(0.3, -0.02), "a pose under the table");
  QueryPlacement nan;
  nan.request.pose.position.x = kNaN;
  nan.request.pose.orientation.w = 1.0;
  expectRefused(call(nan), "a NaN position");
  // Nothing changed: the same bricks, where they were.
  const std::vector<Brick> after = bricks();
  ASSERT_EQ(after.size(), before.size());
  EXPECT_EQ(after[0].id, before[0].id);
  EXPECT_EQ(after[0].pose.position.x, before[0].pose.position.x);
  EXPECT_EQ(after[0].pose.position.z, before[0].pose.position.z);
  ASSERT_TRUE(setPaused(false));
}

// Many poses in one request: each answered as ~query_placement answers it
// alone, a refusal per pose where it would refuse, in request order.
TEST_F(NodeServices, QueryPlacementsAnswerEachPoseAsQueryPlacementDoes) {
  ASSERT_TRUE(place("a", 0.0, 0.0, kHalfHeight).success);
  ASSERT_TRUE(setPaused(true));
  const std::vector<std::pair<double, double>> spots = {
      {0.0, 3 * kHalfHeight},    // centred on a: stable
      {0.03, 3 * kHalfHeight},   // over a still
      {0.07, 3 * kHalfHeight},   // COM past a's end: falls
      {0.0, kHalfHeight},        // inside a: refused
      {0.3, -0.02},              // under the table: refused
      {kNaN, 3 * kHalfHeight}};  // not finite: refused
  QueryPlacements many;
  for (const auto& [x, z] : spots) {
    geometry_msgs::Pose pose;
    pose.position.x = x;
    pose.position.z = z;
    pose.orientation.w = 1.0;
    many.request.poses.push_back(pose);
  }
  const QueryPlacements::Response answer = call(many);
  ASSERT_TRUE(answer.success) << answer.message;
  ASSERT_EQ(answer.verdicts.size(), spots.size());
  for (std::size_t i = 0; i < spots.size(); ++i) {
    QueryPlacement one;
    one.request.pose = many.request.poses[i];
    const QueryPlacement::Response alone = call(one);
    const PlacementVerdict& verdict = answer.verdicts[i];
    EXPECT_EQ(verdict.valid, alone.success) << i << ": " << verdict.message;
    if (!alone.success) {
      // The same reason; a field is named by its place in the request.
      const std::string why = alone.message.substr(alone.message.find(' '));
      EXPECT_NE(verdict.message.find(why), std::string::npos) << verdict.message;
      continue;
    }
    EXPECT_EQ(verdict.message, alone.message) << i;
    EXPECT_EQ(verdict.stable, alone.stable) << i;
    EXPECT_EQ(verdict.state, alone.state) << i;
    EXPECT_EQ(verdict.margin, alone.margin) << i;
    EXPECT_EQ(verdict.acceleration_margin, alone.acceleration_margin) << i;
    EXPECT_EQ(verdict.supported_by, alone.supported_by) << i;
    EXPECT_EQ(verdict.would_fall, alone.would_fall) << i;
  }
  // By statics, not by the single query: the first two rest on a, the third
  // does not, the last three are refused.
  EXPECT_TRUE(answer.verdicts[0].stable && answer.verdicts[1].stable);
  EXPECT_FALSE(answer.verdicts[2].stable);
  for (std::size_t i = 3; i < spots.size(); ++i) EXPECT_FALSE(answer.verdicts[i].valid) << i;
  // Types: one per pose, one for all, or none; anything else is refused whole.
  many.request.types = {"kapla", "kapla"};
  expectRefused(call(many), "two types for six poses");
  many.request.types = {"no_such_type"};
  const QueryPlacements::Response unknown = call(many);
  ASSERT_TRUE(unknown.success);
  for (const PlacementVerdict& verdict : unknown.verdicts) EXPECT_FALSE(verdict.valid);
  ASSERT_TRUE(setPaused(false));
}

}  // namespace

int main(int argc, char** argv) {
  return brick_stack_sim::test::runNodeTests(argc, argv, "test_node_services");
}
