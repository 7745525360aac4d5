// ~bricks with bricks_delta and ~markers by id, through the node: a client
// that applies every message in order must end with exactly the state
// ~get_bricks returns (bit for bit), and a viewer that applied every marker
// array with exactly what a viewer that joins afresh is shown, whose boxes
// stand where ~get_bricks says. The scene makes bricks freeze, wake (a
// push, a removal under a load), fall off the table and go, and is reset.
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <ros/ros.h>
#include <ros/serialization.h>
#include <unistd.h>
#include <visualization_msgs/MarkerArray.h>

#include "node_fixture.h"
#include "support/marker_viewer.h"

namespace {

using namespace brick_stack_sim;
using visualization_msgs::Marker;
using visualization_msgs::MarkerArray;

/// This test's own program: run again with kFreshClientFlag, it is a client
/// that joins now. A second subscriber in this process would share the
/// process's one connection to the topic, and so never be a new subscriber
/// to the node.
std::string program_path;
constexpr char kFreshClientFlag[] = "--fresh-client";

constexpr double kTableHalfX = 0.6;         ///< The default 1.2 x 0.8 m table [m].
constexpr double kKaplaThickness = 0.0078;  ///< [m]

template <typename M>
std::string bytes(const M& message) {
  const uint32_t size = ros::serialization::serializationLength(message);
  std::string buffer(size, '\0');
  ros::serialization::OStream stream(reinterpret_cast<uint8_t*>(&buffer[0]), size);
  ros::serialization::serialize(stream, message);
  return buffer;
}

template <typename M>
M fromBytes(std::string buffer) {
  M message;
  ros::serialization::IStream stream(reinterpret_cast<uint8_t*>(&buffer[0]),
                                     static_cast<uint32_t>(buffer.size()));
  ros::serialization::deserialize(stream, message);
  return message;
}

/// A client of ~bricks that applies each message as BrickArray.msg says.
class DeltaClient {
 public:
  explicit DeltaClient(client::SimClient& sim)
      : sub_(sim.subscribeBricks([this](const BrickArray::ConstPtr& msg) { apply(*msg); }, 1000)) {}

  std::map<std::string, Brick> state() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return bricks_;
  }
  int messages(std::uint8_t kind) const {
    std::lock_guard<std::mutex> lock(mutex_);
    return kind == BrickArray::FULL ? full_ : deltas_;
  }
  int gaps() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return gaps_;
  }
  std::uint8_t firstKind() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return first_kind_;
  }
  ros::Subscriber& subscriber() { return sub_; }

 private:
  void apply(const BrickArray& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (full_ + deltas_ == 0) first_kind_ = msg.kind;
    // Deltas follow each other without a gap (the queue is long enough).
    if (msg.kind == BrickArray::DELTA && full_ + deltas_ > 0 && msg.sequence != sequence_ + 1)
      ++gaps_;
    sequence_ = msg.sequence;
    if (msg.kind == BrickArray::FULL) {
      ++full_;
      bricks_.clear();
    } else {
      ++deltas_;
      for (const std::string& id : msg.removed) bricks_.erase(id);
    }
    for (const Brick& brick : msg.bricks) bricks_[brick.id] = brick;
  }

  mutable std::mutex mutex_;
  std::map<std::string, Brick> bricks_;
  int full_ = 0, deltas_ = 0, gaps_ = 0;
  std::uint32_t sequence_ = 0;
  std::uint8_t first_kind_ = 255;
  ros::Subscriber sub_;
};

class ViewerClient {
 public:
  explicit ViewerClient(client::SimClient& sim)
      : sub_(sim.subscribeMarkers(
            [this](const MarkerArray::ConstPtr& msg) {
              std::lock_guard<std::mutex> lock(mutex_);
              viewer_.apply(*msg);
              ++arrays_;
            },
            1000)) {}
  test::MarkerViewer viewer() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return viewer_;
  }
  int arrays() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return arrays_;
  }

 private:
  mutable std::mutex mutex_;
  test::MarkerViewer viewer_;
  int arrays_ = 0;
  ros::Subscriber sub_;
};

class NodeUpdates : public test::NodeFixture {
 protected:
  void SetUp() override {
    NodeFixture::SetUp();
    if (HasFatalFailure()) return;
    ASSERT_TRUE(setPaused(true));
    deltas_ = std::make_unique<DeltaClient>(*sim_);
    viewer_ = std::make_unique<ViewerClient>(*sim_);
    ASSERT_TRUE(waitFor(
        [&] { return deltas_->messages(BrickArray::FULL) > 0 && viewer_->arrays() > 0; }, 20.0))
        << "no first message on ~bricks or ~markers";
  }

  /// The delta client's state equals ~get_bricks bit for bit, and the
  /// viewer equals a viewer that joins now; its boxes are ~get_bricks'.
  void expectClientsAreUpToDate(const std::string& after) {
    std::map<std::string, std::string> expected;
    const std::vector<Brick> now = bricks();
    for (const Brick& brick : now) expected[brick.id] = bytes(brick);
    auto applied = [&] {
      std::map<std::string, std::string> got;
      for (const auto& [id, brick] : deltas_->state()) got[id] = bytes(brick);
      return got;
    };
    // Paused: the last publish showed this state; it may still be on its way.
    EXPECT_TRUE(waitFor([&] { return applied() == expected; }, 5.0))
        << after << ": the applied deltas hold " << applied().size() << " bricks, ~get_bricks "
        << expected.size() << (applied().size() == expected.size() ? " (some differ)" : "");

    test::MarkerViewer shown;
    BrickArray fresh_bricks;
    joinAfresh(after, &shown, &fresh_bricks);
    if (HasFatalFailure()) return;
    EXPECT_EQ(viewer_->viewer().differences(shown), "")
        << after << ": the viewer that applied every update differs from a fresh one";
    EXPECT_EQ(fresh_bricks.kind, BrickArray::FULL) << after;
    EXPECT_EQ(bytes(fresh_bricks.bricks), bytes(now)) << after << ": a late client's first ~bricks";
    std::size_t boxes = 0;
    for (const auto& [key, marker] : shown.shown()) boxes += key.first == "bricks";
    EXPECT_EQ(boxes, now.size()) << after;
    for (const Brick& brick : now) {
      bool found = false;
      for (const auto& [key, marker] : shown.shown()) {
        if (key.first != "bricks") continue;
        if (bytes(marker.pose) == bytes(brick.pose)) found = true;
      }
      EXPECT_TRUE(found) << after << ": no box where ~get_bricks has " << brick.id;
    }
  }

  /// What a client that joins now receives first: the marker array (into
  /// `viewer`) and the bricks, from a process of its own.
  void joinAfresh(const std::string& after, test::MarkerViewer* viewer, BrickArray* bricks) {
    const std::string path = "/tmp/brick_stack_sim_fresh_" + std::to_string(::getpid()) + "_" +
                             std::to_string(++fresh_clients_);
    const std::string command = program_path + " " + kFreshClientFlag + " " + path +
                                " __name:=fresh_client_" + std::to_string(fresh_clients_);
    ASSERT_EQ(std::system(command.c_str()), 0) << after << ": " << command;
    std::ifstream file(path, std::ios::binary);
    std::string markers_bytes, bricks_bytes;
    std::uint32_t size = 0;
    ASSERT_TRUE(file.read(reinterpret_cast<char*>(&size), sizeof size)) << after;
    markers_bytes.resize(size);
    file.read(&markers_bytes[0], size);
    ASSERT_TRUE(file.read(reinterpret_cast<char*>(&size), sizeof size)) << after;
    bricks_bytes.resize(size);
    file.read(&bricks_bytes[0], size);
    ASSERT_TRUE(file) << after;
    std::remove(path.c_str());
    viewer->apply(fromBytes<MarkerArray>(markers_bytes));
    *bricks = fromBytes<BrickArray>(bricks_bytes);
  }

  bool remove(const std::string& id) { return sim_->removeBrick(id).ok; }

  std::unique_ptr<DeltaClient> deltas_;
  std::unique_ptr<ViewerClient> viewer_;
  int fresh_clients_ = 0;
};

TEST_F(NodeUpdates, AppliedDeltasAndMarkerUpdatesEqualTheStateFromScratch) {
  const client::Reply<ResetScene::Response> reset = sim_->reset("tower10");
  ASSERT_TRUE(reset.ok) << reset.message;
  ASSERT_TRUE(step(2000).success);  // placed, settled, frozen
  for (const Brick& brick : bricks()) ASSERT_EQ(brick.state, Brick::STABLE) << brick.id;
  expectClientsAreUpToDate("the tower frozen");

  // One plank tips off the table's edge and falls to the floor; one lands
  // on the tower and freezes there.
  ASSERT_TRUE(place("over", kTableHalfX + 0.005, 0.0, kKaplaThickness / 2).success);
  ASSERT_TRUE(place("landing", 0.0, -0.0475, 10 * kKaplaThickness + 0.02).success);
  ASSERT_TRUE(step(1500).success);
  const std::vector<Brick> after_fall = bricks();
  bool fell = false, landed = false;
  for (const Brick& brick : after_fall) {
    fell |= brick.id == "over" && brick.fell_off;
    landed |= brick.id == "landing" && brick.state == Brick::STABLE;
  }
  EXPECT_TRUE(fell) << "'over' did not fall off the table";
  EXPECT_TRUE(landed) << "'landing' did not freeze on the tower";
  expectClientsAreUpToDate("a plank fallen off, one landed");

  // A removal under the load wakes everything above; a push wakes one more.
  ASSERT_TRUE(remove("b2"));
  PushBrick::Request push;
  push.id = "landing";
  push.impulse.y = 0.01;
  const client::Reply<PushBrick::Response> pushed = sim_->pushBrick(push);
  ASSERT_TRUE(pushed.ok) << pushed.message;
  ASSERT_TRUE(step(50).success);
  expectClientsAreUpToDate("mid-collapse");
  ASSERT_TRUE(step(2000).success);
  expectClientsAreUpToDate("after the collapse");
  ASSERT_TRUE(remove("over") && remove("b7"));
  expectClientsAreUpToDate("removals while paused");

  // A reset: every brick goes, a new world with the same ids comes.
  const client::Reply<ResetScene::Response> again = sim_->reset("tower10");
  ASSERT_TRUE(again.ok) << again.message;
  ASSERT_TRUE(step(500).success);
  expectClientsAreUpToDate("after the reset");

  EXPECT_EQ(deltas_->messages(BrickArray::FULL), 1) << "a FULL message after the first";
  EXPECT_EQ(deltas_->gaps(), 0) << "deltas whose sequence skipped one";
  EXPECT_GT(deltas_->messages(BrickArray::DELTA), 10);
}

TEST_F(NodeUpdates, ALateClientStartsFromEveryBrickAndEveryMarker) {
  const client::Reply<ResetScene::Response> reset = sim_->reset("tower10");
  ASSERT_TRUE(reset.ok) << reset.message;
  ASSERT_TRUE(step(2000).success);
  const std::vector<Brick> now = bricks();
  // Paused and frozen: nothing changes, yet the late client is served.
  test::MarkerViewer shown;
  BrickArray first;
  joinAfresh("paused and frozen", &shown, &first);
  if (HasFatalFailure()) return;
  EXPECT_EQ(first.kind, BrickArray::FULL);
  EXPECT_EQ(bytes(first.bricks), bytes(now));
  std::size_t boxes = 0;
  for (const auto& [key, marker] : shown.shown()) boxes += key.first == "bricks";
  EXPECT_EQ(boxes, now.size());
}

TEST_F(NodeUpdates, GetBricksByIdsAnswersInTheirOrderAndRefusesUnknownOrRepeatedOnes) {
  const client::Reply<ResetScene::Response> reset = sim_->reset("tower10");
  ASSERT_TRUE(reset.ok) << reset.message;
  ASSERT_TRUE(step(100).success);
  std::map<std::string, std::string> all;
  for (const Brick& brick : bricks()) all[brick.id] = bytes(brick);
  const std::vector<std::string> ids = {"b5", "b0", "b19"};
  const client::Reply<GetBricks::Response> some = sim_->getBricks(ids);
  ASSERT_TRUE(some.reached) << some.message;
  ASSERT_TRUE(some.response.success) << some.response.message;
  ASSERT_EQ(some.response.bricks.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(some.response.bricks[i].id, ids[i]);
    EXPECT_EQ(bytes(some.response.bricks[i]), all[ids[i]]);
  }
  for (const std::vector<std::string>& bad :
       {std::vector<std::string>{"b1", "nope"}, std::vector<std::string>{"b1", "b1"}}) {
    const client::Reply<GetBricks::Response> refused = sim_->getBricks(bad);
    ASSERT_TRUE(refused.reached) << refused.message;
    EXPECT_FALSE(refused.response.success);
    EXPECT_TRUE(refused.response.bricks.empty());
    EXPECT_NE(refused.response.message.find(bad.back() == "nope" ? "nope" : "twice"),
              std::string::npos)
        << refused.response.message;
  }
}

}  // namespace

/// The client that joins now: its first ~markers array and first ~bricks
/// message, written to `path` (length and bytes each).
int runFreshClient(int argc, char** argv, const std::string& path) {
  ros::init(argc, argv, "fresh_client");
  client::SimClient sim;
  std::mutex mutex;
  std::optional<MarkerArray> markers;
  std::optional<BrickArray> bricks;
  ros::Subscriber markers_sub = sim.subscribeMarkers(
      [&](const MarkerArray::ConstPtr& msg) {
        std::lock_guard<std::mutex> lock(mutex);
        // A delta published before its connection was served is not its start.
        if (!markers && !msg->markers.empty() && msg->markers.front().action == Marker::DELETEALL)
          markers = *msg;
      },
      10);
  ros::Subscriber bricks_sub = sim.subscribeBricks(
      [&](const BrickArray::ConstPtr& msg) {
        std::lock_guard<std::mutex> lock(mutex);
        if (!bricks && msg->kind == BrickArray::FULL) bricks = *msg;
      },
      10);
  ros::AsyncSpinner spinner(1);
  spinner.start();
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(20.0);
  auto arrived = [&] {
    std::lock_guard<std::mutex> lock(mutex);
    return markers && bricks;
  };
  while (!arrived() && ros::WallTime::now() < end) ros::WallDuration(0.01).sleep();
  if (!arrived()) return 1;
  std::lock_guard<std::mutex> lock(mutex);
  std::ofstream file(path, std::ios::binary);
  for (const std::string& buffer : {bytes(*markers), bytes(*bricks)}) {
    const std::uint32_t size = static_cast<std::uint32_t>(buffer.size());
    file.write(reinterpret_cast<const char*>(&size), sizeof size);
    file.write(buffer.data(), size);
  }
  return file ? 0 : 1;
}

int main(int argc, char** argv) {
  program_path = argv[0];
  for (int i = 1; i + 1 < argc; ++i)
    if (std::string(argv[i]) == kFreshClientFlag) return runFreshClient(argc, argv, argv[i + 1]);
  return brick_stack_sim::test::runNodeTests(argc, argv, "test_node_updates");
}
