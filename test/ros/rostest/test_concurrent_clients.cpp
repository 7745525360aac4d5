// Eight clients call the node at once while a ninth steps it: every answer
// must equal the answer to the same call made when the clients take turns,
// one whole script after another, with no stepping. Each client builds,
// queries and takes down towers in a region of the table of its own, so its
// answers depend only on its own calls; anything else (a lost update, a
// request served against a half-changed world, a data race) shows as a
// different answer or a different final set of bricks.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <ros/ros.h>

#include "brick_stack_sim/ros/interface_names.h"
#include "node_fixture.h"

namespace {

using namespace brick_stack_sim;

constexpr int kClients = 8;
constexpr int kLayers = 6;
constexpr double kPlankHeight = 0.0078;  ///< A KAPLA plank lying flat [m].
constexpr double kCallTimeout = 30.0;    ///< [s] a call that takes longer means a hang
/// Bricks placed exactly at rest may settle by a few micrometres while the
/// node steps; the statics of a query move with them by as much.
constexpr double kMarginTolerance = 5e-4;  ///< [m]

/// What one call answered, in the terms that must not depend on timing.
struct Answer {
  std::string call;  ///< What was asked, for the failure message.
  bool success = false;
  std::string message;  ///< Sim times cut off: they differ between the runs.
  std::string id;
  bool stable = false;
  double margin = 0.0;                    ///< [m] of a query
  std::vector<std::string> own_bricks;    ///< Of get_bricks: the caller's ids.
  std::vector<std::string> supported_by;  ///< Of a query
};

/// "placed c1_0 at t=1.234 s" and "placed c1_0 at t=0.000 s" are one answer.
std::string withoutTime(const std::string& message) {
  const std::size_t at = message.find(" at t=");
  return at == std::string::npos ? message : message.substr(0, at);
}

/// One client: its own connections, its own region, its own ids.
class Client {
 public:
  // The client library's persistent connections, as a planner calling this
  // often should have: roscpp's one-connection-per-call clients fail now and
  // then when many calls overlap (the server drops the connection on
  // POLLRDHUP before it answers), about once in ten runs of this test.
  explicit Client(int index) : index_(index), sim_(std::make_shared<client::SimClient>()) {
    // Eight regions 0.3 m by 0.4 m on the 1.2 m by 0.8 m table.
    x_ = -0.45 + 0.3 * (index % 4);
    y_ = index < 4 ? -0.2 : 0.2;
  }

  /// The script: in each round a tower of alternating planks is built, with a
  /// duplicate id, an overlap, a NaN and an off-centre query per layer on the
  /// way, then taken down from the top with a few bad removals. At the end
  /// one plank is left on the table.
  std::vector<Answer> run(int rounds) {
    std::vector<Answer> answers;
    for (int round = 0; round < rounds; ++round) {
      const std::string prefix = name() + "_r" + std::to_string(round) + "_";
      for (int layer = 0; layer < kLayers; ++layer) {
        const double z = kPlankHeight * (layer + 0.5);
        answers.push_back(place(prefix + std::to_string(layer), x_, y_, z, layer));
        if (layer == 1) answers.push_back(place(prefix + "0", x_, y_, 0.3, 0));  // duplicate
        if (layer == 2) answers.push_back(place(prefix + "overlap", x_, y_, z, layer));
        if (layer == 3)
          answers.push_back(place(prefix + "nan", std::numeric_limits<double>::quiet_NaN(), y_,
                                  z + kPlankHeight, 0));
        // Off-centre by 0 to 50 mm along the plank below: stable, then not.
        const double offset = 0.01 * ((layer + round) % 6);
        const bool along_x = (layer + 1) % 2 == 0;
        answers.push_back(query(x_ + (along_x ? offset : 0.0), y_ + (along_x ? 0.0 : offset),
                                z + kPlankHeight, layer + 1));
        answers.push_back(ownBricks());
      }
      answers.push_back(remove(name() + "_no_such_brick"));
      for (int layer = kLayers - 1; layer >= 0; --layer) {
        answers.push_back(remove(prefix + std::to_string(layer)));
        if (layer == kLayers - 1) answers.push_back(remove(prefix + std::to_string(layer)));
      }
      answers.push_back(ownBricks());
    }
    // One brick stays: the final worlds are compared on them.
    answers.push_back(place(name() + "_kept", x_, y_, kPlankHeight / 2, index_));
    return answers;
  }

  bool hung() const { return hung_; }

 private:
  std::string name() const { return "c" + std::to_string(index_); }

  template <typename Service>
  bool call(Service& srv) {
    if (hung_) return false;
    hung_ = !test::callWithin(sim_, srv, kCallTimeout);
    return !hung_;
  }

  /// Odd layers turned 90 degrees: each plank crosses the one below.
  static geometry_msgs::Pose layerPose(double x, double y, double z, int layer) {
    geometry_msgs::Pose pose;
    pose.position.x = x;
    pose.position.y = y;
    pose.position.z = z;
    pose.orientation.z = layer % 2 ? std::sqrt(0.5) : 0.0;
    pose.orientation.w = layer % 2 ? std::sqrt(0.5) : 1.0;
    return pose;
  }

  Answer place(const std::string& id, double x, double y, double z, int layer) {
    PlaceBrick srv;
    srv.request.id = id;
    srv.request.pose = layerPose(x, y, z, layer);
    Answer answer;
    answer.call = "place " + id;
    if (!call(srv)) return answer;
    answer.success = srv.response.success;
    answer.message = withoutTime(srv.response.message);
    answer.id = srv.response.id;
    return answer;
  }

  Answer query(double x, double y, double z, int layer) {
    QueryPlacement srv;
    srv.request.pose = layerPose(x, y, z, layer);
    Answer answer;
    std::ostringstream what;
    what << "query at (" << x << ", " << y << ", " << z << ")";
    answer.call = what.str();
    if (!call(srv)) return answer;
    answer.success = srv.response.success;
    answer.stable = srv.response.stable;
    answer.margin = srv.response.margin;
    answer.supported_by = srv.response.supported_by;
    std::sort(answer.supported_by.begin(), answer.supported_by.end());
    return answer;
  }

  Answer remove(const std::string& id) {
    RemoveBrick srv;
    srv.request.id = id;
    Answer answer;
    answer.call = "remove " + id;
    if (!call(srv)) return answer;
    answer.success = srv.response.success;
    answer.message = withoutTime(srv.response.message);
    return answer;
  }

  Answer ownBricks() {
    GetBricks srv;
    Answer answer;
    answer.call = ros_adapter::kGetBricksService;
    if (!call(srv)) return answer;
    answer.success = srv.response.success;
    for (const Brick& brick : srv.response.bricks)
      if (brick.id.rfind(name() + "_", 0) == 0) answer.own_bricks.push_back(brick.id);
    std::sort(answer.own_bricks.begin(), answer.own_bricks.end());
    return answer;
  }

  int index_;
  double x_ = 0.0, y_ = 0.0;
  bool hung_ = false;
  /// Shared with the threads of test::callWithin only.
  std::shared_ptr<client::SimClient> sim_;
};

class ConcurrentClients : public test::NodeFixture {
 protected:
  void SetUp() override {
    NodeFixture::SetUp();
    if (HasFatalFailure()) return;
    ros::param::param("~rounds", rounds_, 4);
    ros::param::param("~steps_per_call", steps_per_call_, 2000);
    ASSERT_TRUE(setPaused(true));
  }

  void clearTable() {
    ResetScene clear;
    ASSERT_TRUE(test::callWithin(sim_, clear, kCallTimeout));
    ASSERT_TRUE(clear.response.success) << clear.response.message;
  }

  /// Brick id -> position [m], to compare the final worlds.
  std::map<std::string, geometry_msgs::Point> positions() {
    std::map<std::string, geometry_msgs::Point> result;
    for (const Brick& brick : bricks()) result[brick.id] = brick.pose.position;
    return result;
  }

  int rounds_ = 4;
  int steps_per_call_ = 2000;
};

TEST_F(ConcurrentClients, AnswersEqualThoseOfTheSameCallsOneAtATime) {
  clearTable();
  std::vector<Client> clients;
  for (int i = 0; i < kClients; ++i) clients.emplace_back(i);

  std::vector<std::vector<Answer>> together(kClients);
  std::atomic<bool> clients_done{false};
  std::atomic<long> steps_taken{0};
  std::atomic<int> step_refusals{0};
  std::thread stepper([&] {
    const auto step_client = std::make_shared<client::SimClient>();
    while (!clients_done) {
      StepSimulation srv;
      srv.request.steps = static_cast<unsigned>(steps_per_call_);
      if (!test::callWithin(step_client, srv, kCallTimeout)) return;
      if (srv.response.success)
        steps_taken += steps_per_call_;
      else
        ++step_refusals;
    }
  });
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::thread> threads;
  for (int i = 0; i < kClients; ++i)
    threads.emplace_back([&, i] { together[i] = clients[i].run(rounds_); });
  for (std::thread& thread : threads) thread.join();
  const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
  clients_done = true;
  stepper.join();
  for (const Client& client : clients) ASSERT_FALSE(client.hung()) << "the node stopped answering";
  EXPECT_EQ(step_refusals, 0) << "a ~step was refused while the node stayed paused";
  EXPECT_GT(steps_taken, 0) << "nothing was stepped while the clients called: nothing was tested";
  const auto world_together = positions();

  // The same scripts, one client after another, nothing stepping.
  clearTable();
  std::vector<std::vector<Answer>> alone(kClients);
  for (int i = 0; i < kClients; ++i) {
    Client client(i);
    alone[i] = client.run(rounds_);
    ASSERT_FALSE(client.hung()) << "the node stopped answering";
  }
  const auto world_alone = positions();

  long calls = 0, accepted = 0;
  double largest_margin_difference = 0.0;
  for (int i = 0; i < kClients; ++i) {
    ASSERT_EQ(together[i].size(), alone[i].size());
    for (std::size_t k = 0; k < alone[i].size(); ++k) {
      const Answer& a = together[i][k];
      const Answer& b = alone[i][k];
      SCOPED_TRACE("client " + std::to_string(i) + ", call " + std::to_string(k) + ": " + b.call);
      ++calls;
      accepted += b.success;
      EXPECT_EQ(a.success, b.success);
      EXPECT_EQ(a.message, b.message);
      EXPECT_EQ(a.id, b.id);
      EXPECT_EQ(a.stable, b.stable);
      EXPECT_EQ(a.supported_by, b.supported_by);
      EXPECT_EQ(a.own_bricks, b.own_bricks);
      EXPECT_NEAR(a.margin, b.margin, kMarginTolerance);
      largest_margin_difference =
          std::max(largest_margin_difference, std::abs(a.margin - b.margin));
    }
  }
  EXPECT_GT(accepted, 0);
  EXPECT_LT(accepted, calls) << "no call was refused: the scripts' bad calls were not made";
  // The towers were taken down; each client's last plank is where it was put.
  ASSERT_EQ(world_together.size(), static_cast<std::size_t>(kClients));
  ASSERT_EQ(world_alone.size(), world_together.size());
  for (const auto& [id, position] : world_alone) {
    ASSERT_EQ(world_together.count(id), 1u) << id;
    const geometry_msgs::Point& other = world_together.at(id);
    EXPECT_NEAR(position.x, other.x, kMarginTolerance) << id;
    EXPECT_NEAR(position.y, other.y, kMarginTolerance) << id;
    EXPECT_NEAR(position.z, other.z, kMarginTolerance) << id;
  }
  std::printf(
      "%d clients, %ld calls (%ld accepted) in %.1f s while %ld steps were taken; largest "
      "margin difference %.3g m\n",
      kClients, calls, accepted, took.count(), steps_taken.load(), largest_margin_difference);
}

}  // namespace

int main(int argc, char** argv) {
  return brick_stack_sim::test::runNodeTests(argc, argv, "test_concurrent_clients");
}
