// ~simulate_plan against the node: a plan runs on a copy that leaves the live
// world alone, bit for bit, and foretells it bit for bit when the copy is
// exact; its verdict agrees with statics; bad plans are refused by name; and
// plans past ~max_concurrent_plans are refused at once while the ones under
// way leave ~get_bricks answered (plan.test: one plan at a time;
// plan_concurrent.test: two, which must also agree bit for bit).
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <future>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <ros/ros.h>

#include "brick_stack_sim/ros/interface_names.h"
#include "call_within.h"
#include "node_fixture.h"
#include "support/kapla.h"

namespace {

using namespace brick_stack_sim;
using test::kKaplaLength;
using test::kKaplaThickness;
using test::kKaplaWidth;
using test::kTowerOffset;

constexpr int kTowerLayers = 10;
/// Height of the tower's top face [m].
constexpr double kTowerTop = kTowerLayers * kKaplaThickness;
/// A call that takes longer means the node hangs: the test fails instead [s].
constexpr double kCallTimeout = 120.0;

using test::poseAt;
using test::within;

/// A brick of layer `layer` of the two-per-layer tower (test::towerSlot),
/// `lift` [m] above where it rests.
geometry_msgs::Pose towerPose(int layer, int slot, double lift = 0.0) {
  const test::TowerSlot s = test::towerSlot(layer, slot);
  return poseAt(s.x, s.y, s.z + lift, s.yaw);
}

PlanStep placeStep(double at, const std::string& id, const geometry_msgs::Pose& pose) {
  PlanStep step;
  step.action = PlanStep::PLACE;
  step.at = at;
  step.id = id;
  step.type = "kapla";
  step.pose = pose;
  return step;
}

PlanStep actionStep(std::uint8_t action, double at, const std::string& id = "") {
  PlanStep step;
  step.action = action;
  step.at = at;
  step.id = id;
  return step;
}

/// Every number of two bricks' poses and twists, their ids and states, bit for bit.
void expectSameBits(const Brick& a, const Brick& b, const std::string& what) {
  EXPECT_EQ(a.id, b.id) << what;
  EXPECT_EQ(a.state, b.state) << what << " " << a.id;
  const auto& p = a.pose;
  const auto& q = b.pose;
  EXPECT_TRUE(p.position.x == q.position.x && p.position.y == q.position.y &&
              p.position.z == q.position.z && p.orientation.x == q.orientation.x &&
              p.orientation.y == q.orientation.y && p.orientation.z == q.orientation.z &&
              p.orientation.w == q.orientation.w)
      << what << ": the pose of " << a.id << " differs in its bits";
  const auto& u = a.twist;
  const auto& v = b.twist;
  EXPECT_TRUE(u.linear.x == v.linear.x && u.linear.y == v.linear.y && u.linear.z == v.linear.z &&
              u.angular.x == v.angular.x && u.angular.y == v.angular.y &&
              u.angular.z == v.angular.z)
      << what << ": the twist of " << a.id << " differs in its bits";
}

void expectSameBits(const std::vector<Brick>& a, const std::vector<Brick>& b,
                    const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) expectSameBits(a[i], b[i], what);
}

std::vector<Brick> planBricks(const SimulatePlan::Response& response) {
  std::vector<Brick> bricks;
  for (const PlanBrick& brick : response.bricks) bricks.push_back(brick.brick);
  return bricks;
}

/// The sim time a ~get_bricks message names ("20 bricks at t=12.345 s") [s].
double messageTime(const std::string& message) {
  const std::size_t at = message.find("t=");
  return at == std::string::npos ? std::nan("") : std::stod(message.substr(at + 2));
}

class PlanNode : public test::NodeFixture {
 protected:
  void SetUp() override {
    NodeFixture::SetUp();
    if (HasFatalFailure()) return;
    // Every test starts paused on an empty table: what it steps, it knows.
    ASSERT_TRUE(setPaused(true));
    const client::Reply<ResetScene::Response> reset = sim_->reset();
    ASSERT_TRUE(reset.ok) << reset.message;
  }

  /// A frozen tower of kTowerLayers layers on the table centre, placed at one
  /// instant through ~place_brick and judged at the next step.
  void buildFrozenTower() {
    for (int i = 0; i < 2 * kTowerLayers; ++i) {
      PlaceBrick::Request place;
      place.id = "t" + std::to_string(i);
      place.type = "kapla";
      place.pose = towerPose(i / 2, i % 2);
      const client::Reply<PlaceBrick::Response> placed = sim_->placeBrick(place);
      ASSERT_TRUE(placed.ok) << placed.message;
    }
    ASSERT_TRUE(step(100).success);
    for (const Brick& brick : bricks())
      ASSERT_NE(brick.state, Brick::DYNAMIC) << brick.id << " of the tower is not frozen";
  }

  /// ~simulate_plan, failing the test instead of hanging on a node that never answers.
  SimulatePlan::Response plan(const SimulatePlan::Request& request) {
    std::shared_ptr<client::SimClient> sim = sim_;
    const auto reply = within<client::Reply<SimulatePlan::Response>>(
        kCallTimeout, [sim, request] { return sim->simulatePlan(request); });
    if (!reply) return SimulatePlan::Response();
    EXPECT_TRUE(reply->reached) << reply->message;
    return reply->response;
  }

  /// A plank along x across the tower's top layer (which lies along y at
  /// x = -/+ kTowerOffset), centred at `x`, for 2 s.
  SimulatePlan::Request plankAcrossTheTop(double x) {
    SimulatePlan::Request request;
    request.steps = {placeStep(0.0, "q", poseAt(x, 0.0, kTowerTop + kKaplaThickness / 2, 0.0))};
    return request;
  }
};

TEST_F(PlanNode, AnExactCopyLeavesTheLiveWorldAloneAndForetellsItBitForBit) {
  buildFrozenTower();
  const std::vector<Brick> before = bricks();
  // Two planks on top at once, a third half a second later, a fourth let go
  // 3 mm above its place a second in (Bullet simulates its fall), then a wait.
  SimulatePlan::Request request;
  request.steps = {placeStep(0.0, "p0", towerPose(kTowerLayers, 0)),
                   placeStep(0.0, "p1", towerPose(kTowerLayers, 1)),
                   placeStep(0.5, "p2", towerPose(kTowerLayers + 1, 0)),
                   placeStep(1.0, "p3", towerPose(kTowerLayers + 1, 1, 0.003)),
                   actionStep(PlanStep::WAIT, 1.5)};
  request.duration = 3.0;
  const SimulatePlan::Response foretold = plan(request);
  ASSERT_TRUE(foretold.success) << foretold.message;
  EXPECT_TRUE(foretold.exact_copy) << "a frozen tower is copied exactly";
  EXPECT_TRUE(foretold.stands) << foretold.verdict;
  EXPECT_EQ(foretold.fallen, 0u);
  EXPECT_EQ(foretold.sim_time, 3.0);
  EXPECT_GT(foretold.wall_time, 0.0);
  ASSERT_EQ(foretold.bricks.size(), before.size() + 4);
  for (const PlanBrick& brick : foretold.bricks) {
    EXPECT_FALSE(brick.fell) << brick.brick.id;
    if (brick.brick.id == "p3") {
      EXPECT_NEAR(brick.displacement, 0.003, 0.001);
    }
  }
  // The live world did not see it.
  expectSameBits(bricks(), before, "the live world after the plan");

  // The same steps on the live world: the same bits.
  auto place = [&](const PlanStep& step) {
    PlaceBrick::Request placement;
    placement.id = step.id;
    placement.type = step.type;
    placement.pose = step.pose;
    const client::Reply<PlaceBrick::Response> placed = sim_->placeBrick(placement);
    EXPECT_TRUE(placed.ok) << placed.message;
  };
  place(request.steps[0]);
  place(request.steps[1]);
  ASSERT_TRUE(step(500).success);
  place(request.steps[2]);
  ASSERT_TRUE(step(500).success);
  place(request.steps[3]);
  ASSERT_TRUE(step(2000).success);
  expectSameBits(bricks(), planBricks(foretold), "the live world against the plan");
}

TEST_F(PlanNode, APlankBeyondItsSupportFallsAndOneWithinStands) {
  buildFrozenTower();
  const std::vector<Brick> before = bricks();
  // Statics by hand: the plank's centre must lie over the outer top plank,
  // whose outer edge is at x = kTowerOffset + w/2 = 58.5 mm (once the centre
  // is past 23.4 mm the plank no longer reaches the inner top plank).
  const double edge = kTowerOffset + kKaplaWidth / 2;
  ASSERT_NEAR(edge, 0.0585, 1e-9);
  const SimulatePlan::Response within_support = plan(plankAcrossTheTop(edge - 0.005));
  ASSERT_TRUE(within_support.success) << within_support.message;
  EXPECT_TRUE(within_support.stands) << within_support.verdict;
  EXPECT_EQ(within_support.fallen, 0u);
  EXPECT_TRUE(within_support.exact_copy);

  const SimulatePlan::Response beyond = plan(plankAcrossTheTop(edge + 0.01));
  ASSERT_TRUE(beyond.success) << beyond.message;
  EXPECT_FALSE(beyond.stands) << beyond.verdict;
  EXPECT_GE(beyond.fallen, 1u);
  EXPECT_NE(beyond.verdict.find("q"), std::string::npos) << beyond.verdict;
  for (const PlanBrick& brick : beyond.bricks)
    if (brick.brick.id == "q") {
      EXPECT_TRUE(brick.fell);
      EXPECT_GT(brick.displacement, 0.01);
    }
  expectSameBits(bricks(), before, "the live world after two plans");
  // The other mode sees the same plank fall; its copy is rebuilt, not exact.
  SimulatePlan::Request in_none = plankAcrossTheTop(edge + 0.01);
  in_none.mode = "none";
  const SimulatePlan::Response none = plan(in_none);
  ASSERT_TRUE(none.success) << none.message;
  EXPECT_FALSE(none.exact_copy);
  EXPECT_FALSE(none.stands) << none.verdict;
}

TEST_F(PlanNode, BadPlansAreRefusedByNameAndChangeNothing) {
  buildFrozenTower();
  const std::vector<Brick> before = bricks();
  SimulatePlan::Request request = plankAcrossTheTop(0.0);
  request.steps.push_back(actionStep(PlanStep::REMOVE, 0.5, "nope"));
  SimulatePlan::Response refused = plan(request);
  EXPECT_FALSE(refused.success);
  EXPECT_NE(refused.message.find("step 2 (remove 'nope' at 0.5 s)"), std::string::npos)
      << refused.message;

  request = plankAcrossTheTop(0.0);
  request.steps.push_back(placeStep(0.2, "n", poseAt(0.3, 0.0, 0.0039, 0.0)));
  request.steps[1].pose.position.x = std::numeric_limits<double>::quiet_NaN();
  refused = plan(request);
  EXPECT_FALSE(refused.success);
  EXPECT_NE(refused.message.find("steps[1].pose.position.x"), std::string::npos) << refused.message;

  request = plankAcrossTheTop(0.0);
  request.mode = "magic";
  refused = plan(request);
  EXPECT_FALSE(refused.success);
  EXPECT_NE(refused.message.find("magic"), std::string::npos) << refused.message;

  request = plankAcrossTheTop(0.0);
  request.steps[0].action = 7;
  refused = plan(request);
  EXPECT_FALSE(refused.success);
  EXPECT_NE(refused.message.find("steps[0].action"), std::string::npos) << refused.message;
  expectSameBits(bricks(), before, "the live world after refused plans");

  // A brick in flight: the copy holds it, but not Bullet's contact caches.
  PlaceBrick::Request thrown;
  thrown.id = "thrown";
  thrown.pose = poseAt(0.3, 0.0, 0.05, 0.0);
  thrown.twist.linear.x = 0.1;
  ASSERT_TRUE(sim_->placeBrick(thrown).ok);
  ASSERT_TRUE(step(10).success);
  const SimulatePlan::Response moving = plan(plankAcrossTheTop(0.0));
  ASSERT_TRUE(moving.success) << moving.message;
  EXPECT_FALSE(moving.exact_copy);
}

/// The wall time a plan of `request`'s kind takes for `sim_seconds` [s],
/// measured once, so that the long plan takes some seconds on any machine.
double wallPerSimSecond(const std::function<SimulatePlan::Response(double)>& run) {
  const double probe = 30.0;
  const SimulatePlan::Response answer = run(probe);
  EXPECT_TRUE(answer.success) << answer.message;
  return std::max(answer.wall_time, 1e-6) / probe;
}

TEST_F(PlanNode, PlansPastTheBoundAreRefusedAtOnceAndGetBricksIsAnsweredMeanwhile) {
  int most = 2;
  ros::param::get(sim_->resolve(ros_adapter::kMaxConcurrentPlansParameter), most);
  buildFrozenTower();
  // The long plan: the tower in plain Bullet, and every second a plank
  // dropped from 5 cm beside it, the one before taken away, so that Bullet
  // always has a brick in motion (40 spots on the free table, in turn).
  auto longPlan = [](double duration) {
    SimulatePlan::Request request;
    request.mode = "none";
    for (int i = 0; i + 1 < duration; ++i) {
      if (i > 0)
        request.steps.push_back(actionStep(PlanStep::REMOVE, i, "d" + std::to_string(i - 1)));
      const double x = -0.45 + 0.1 * (i % 10);
      const double y =
          (i / 10) % 4 < 2 ? -0.3 + 0.15 * ((i / 10) % 2) : 0.15 + 0.15 * ((i / 10) % 2);
      request.steps.push_back(placeStep(i, "d" + std::to_string(i), poseAt(x, y, 0.05, M_PI / 2)));
    }
    request.duration = duration;
    return request;
  };
  const double per_second =
      wallPerSimSecond([&](double duration) { return plan(longPlan(duration)); });
  ASSERT_FALSE(HasFailure());
  // Some 8 s of wall time: the ~get_bricks below take about 1.5 s.
  const double duration = std::min(3600.0, std::max(30.0, 8.0 / per_second));
  const SimulatePlan::Request long_request = longPlan(duration);
  std::printf("the long plan: %.0f s of sim time, about %.1f s of wall time\n", duration,
              duration * per_second);

  // The live world runs meanwhile.
  ASSERT_TRUE(setPaused(false));
  // `most` long plans and one more, each from its own connected client.
  std::vector<std::shared_ptr<client::SimClient>> clients;
  for (int i = 0; i <= most; ++i) {
    clients.push_back(std::make_shared<client::SimClient>());
    SimulatePlan::Request warm_up;
    warm_up.duration = 0.001;
    ASSERT_TRUE(clients.back()->simulatePlan(warm_up).ok);
  }
  std::atomic<int> order{0};  // completion order of every call below
  struct Done {
    client::Reply<SimulatePlan::Response> reply;
    int order = 0;
  };
  std::vector<std::future<Done>> plans;
  for (const auto& client : clients)
    plans.push_back(std::async(std::launch::async, [client, &long_request, &order] {
      Done done;
      done.reply = client->simulatePlan(long_request);
      done.order = order++;
      return done;
    }));
  // ~get_bricks from another client while they run: 50 calls, 20 ms apart.
  auto getter = std::make_shared<client::SimClient>();
  std::vector<int> get_order;
  std::vector<double> get_times;
  for (int i = 0; i < 50; ++i) {
    const auto got = within<client::Reply<GetBricks::Response>>(
        kCallTimeout, [getter] { return getter->getBricks(); });
    ASSERT_TRUE(got && got->ok) << (got ? got->message : "no answer");
    get_order.push_back(order++);
    get_times.push_back(messageTime(got->response.message));
    ros::WallDuration(0.02).sleep();
  }
  int accepted = 0, refused = 0, refused_at = -1;
  int first_plan_end = std::numeric_limits<int>::max();
  std::vector<SimulatePlan::Response> answers;
  for (auto& future : plans) {
    ASSERT_EQ(future.wait_for(std::chrono::duration<double>(kCallTimeout)),
              std::future_status::ready)
        << "a plan did not come back";
    const Done done = future.get();
    ASSERT_TRUE(done.reply.reached) << done.reply.message;
    if (done.reply.ok) {
      ++accepted;
      first_plan_end = std::min(first_plan_end, done.order);
      answers.push_back(done.reply.response);
      continue;
    }
    ++refused;
    EXPECT_NE(
        done.reply.message.find(std::to_string(most) + (most == 1 ? " plan is" : " plans are") +
                                " running, the most ~max_concurrent_plans allows"),
        std::string::npos)
        << done.reply.message;
    refused_at = done.order;
  }
  EXPECT_EQ(accepted, most);
  EXPECT_EQ(refused, 1);
  EXPECT_LT(refused_at, first_plan_end) << "the plan past the bound waited for the others";
  // Every ~get_bricks came back before any plan did, and the live clock ran.
  for (int o : get_order) EXPECT_LT(o, first_plan_end) << "a ~get_bricks waited for a plan";
  EXPECT_GT(get_times.back(), get_times.front()) << "the live world stood still during the plans";
  // Plans at once on their own copies: the same bits.
  for (std::size_t i = 1; i < answers.size(); ++i)
    expectSameBits(planBricks(answers[i]), planBricks(answers[0]), "two plans at once");
  ASSERT_TRUE(setPaused(true));
}

}  // namespace

int main(int argc, char** argv) {
  return brick_stack_sim::test::runNodeTests(argc, argv, "test_plan_node");
}
