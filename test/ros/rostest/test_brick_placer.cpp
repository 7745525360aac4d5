// The brick placer started by teleop.launch, driven as RViz drives it: a
// MENU_SELECT feedback with the ghost's pose on <placer>/feedback. What it
// did is read back from the simulator (~get_bricks) and from /rosout.
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Log.h>
#include <visualization_msgs/InteractiveMarkerFeedback.h>
#include <visualization_msgs/InteractiveMarkerInit.h>
#include <visualization_msgs/InteractiveMarkerUpdate.h>

#include "brick_stack_sim/teleop/brick_placer.h"
#include "node_fixture.h"
#include "support/kapla.h"

namespace {

using namespace brick_stack_sim;
using visualization_msgs::InteractiveMarkerFeedback;
using visualization_msgs::InteractiveMarkerInit;
using visualization_msgs::InteractiveMarkerUpdate;

constexpr char kPlacerNode[] = "/brick_placer";
constexpr double kThickness = test::kKaplaThickness;
/// How long the placer may take to act on a feedback [s] of wall time.
constexpr double kActionTimeout = 10.0;

using test::poseAt;

double yawOf(const geometry_msgs::Quaternion& q) {
  return std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
}

class BrickPlacer : public test::NodeFixture {
 protected:
  void SetUp() override {
    NodeFixture::SetUp();
    if (HasFatalFailure()) return;
    const std::string placer = kPlacerNode;
    init_sub_ = nh_.subscribe<InteractiveMarkerInit>(
        placer + "/update_full", 10, [this](const InteractiveMarkerInit::ConstPtr& msg) {
          std::lock_guard<std::mutex> lock(mutex_);
          for (const auto& marker : msg->markers)
            if (marker.name == teleop::kGhostMarker) menu_ = marker.menu_entries;
        });
    update_sub_ = nh_.subscribe<InteractiveMarkerUpdate>(
        placer + "/update", 100, [this](const InteractiveMarkerUpdate::ConstPtr& msg) {
          std::lock_guard<std::mutex> lock(mutex_);
          for (const auto& p : msg->poses)
            if (p.name == teleop::kGhostMarker) ghost_poses_.push_back(p.pose);
          for (const auto& marker : msg->markers)
            if (marker.name == teleop::kGhostMarker) ghost_poses_.push_back(marker.pose);
        });
    rosout_sub_ = nh_.subscribe<rosgraph_msgs::Log>(
        "/rosout", 1000, [this](const rosgraph_msgs::Log::ConstPtr& msg) {
          std::lock_guard<std::mutex> lock(mutex_);
          if (msg->name == kPlacerNode && msg->level == rosgraph_msgs::Log::WARN)
            warnings_.push_back(msg->msg);
        });
    feedback_ = nh_.advertise<InteractiveMarkerFeedback>(placer + "/feedback", 10);
    ASSERT_TRUE(waitFor(
        [this] {
          std::lock_guard<std::mutex> lock(mutex_);
          return !menu_.empty();
        },
        60.0))
        << "the placer's menu never arrived on " << placer << "/update_full";
    ASSERT_TRUE(waitFor([this] { return feedback_.getNumSubscribers() > 0; }, 30.0));
    ASSERT_TRUE(waitFor([this] { return rosout_sub_.getNumPublishers() > 0; }, 30.0));

    // Every test starts from a running simulator, an empty table and the
    // placer's ghost of type kapla.
    ASSERT_TRUE(setPaused(false));
    const client::Reply<ResetScene::Response> reset = sim_->reset();
    ASSERT_TRUE(reset.reached) << reset.message;
    ASSERT_TRUE(reset.response.success) << reset.response.message;
    select("kapla", poseAt(0.0, 0.0, 0.1), teleop::kTypeMenu);
  }

  /// The id of the menu entry `title` (under the entry `parent`, if given).
  /// MenuHandler shows check boxes as a "[x] " or "[ ] " in front of the title.
  uint32_t entry(const std::string& title, const std::string& parent = "") {
    std::lock_guard<std::mutex> lock(mutex_);
    uint32_t parent_id = 0;
    if (!parent.empty()) {
      for (const auto& e : menu_)
        if (e.title == parent) parent_id = e.id;
    }
    for (const auto& e : menu_) {
      const bool named = e.title == title || e.title == "[x] " + title || e.title == "[ ] " + title;
      if (named && (parent.empty() || e.parent_id == parent_id)) return e.id;
    }
    ADD_FAILURE() << "no menu entry '" << title << "'";
    return 0;
  }

  /// What RViz sends when the user picks `title` in the ghost's menu while
  /// the ghost is at `ghost`.
  void select(const std::string& title, const geometry_msgs::Pose& ghost,
              const std::string& parent = "") {
    const uint32_t id = entry(title, parent);
    InteractiveMarkerFeedback feedback;
    feedback.header.frame_id = "world";
    feedback.header.stamp = ros::Time::now();
    feedback.client_id = "/test_brick_placer";
    feedback.marker_name = teleop::kGhostMarker;
    feedback.event_type = InteractiveMarkerFeedback::MENU_SELECT;
    feedback.menu_entry_id = id;
    feedback.pose = ghost;
    feedback_.publish(feedback);
  }

  /// What RViz sends while the user drags the ghost.
  void drag(const geometry_msgs::Pose& ghost) {
    InteractiveMarkerFeedback feedback;
    feedback.header.frame_id = "world";
    feedback.header.stamp = ros::Time::now();
    feedback.client_id = "/test_brick_placer";
    feedback.marker_name = teleop::kGhostMarker;
    feedback.control_name = "body";
    feedback.event_type = InteractiveMarkerFeedback::POSE_UPDATE;
    feedback.pose = ghost;
    feedback_.publish(feedback);
  }

  std::optional<Brick> brick(const std::string& id) {
    for (const Brick& b : bricks())
      if (b.id == id) return b;
    return std::nullopt;
  }

  /// Waits until brick `id` satisfies `done`.
  bool waitForBrick(const std::string& id, const std::function<bool(const Brick&)>& done) {
    return waitFor(
        [&] {
          const std::optional<Brick> b = brick(id);
          return b && done(*b);
        },
        kActionTimeout);
  }

  /// The first brick that is not in `before`, once the placer has placed it.
  std::optional<Brick> newBrick(const std::vector<Brick>& before) {
    std::optional<Brick> found;
    waitFor(
        [&] {
          for (const Brick& b : bricks()) {
            bool known = false;
            for (const Brick& old : before) known = known || old.id == b.id;
            if (!known) found = b;
          }
          return found.has_value();
        },
        kActionTimeout);
    return found;
  }

  bool warned(const std::string& text) {
    return waitFor(
        [&] {
          std::lock_guard<std::mutex> lock(mutex_);
          for (const std::string& w : warnings_)
            if (w.find(text) != std::string::npos) return true;
          return false;
        },
        kActionTimeout);
  }

  std::mutex mutex_;
  std::vector<visualization_msgs::MenuEntry> menu_;
  std::vector<geometry_msgs::Pose> ghost_poses_;
  std::vector<std::string> warnings_;
  ros::Subscriber init_sub_, update_sub_, rosout_sub_;
  ros::Publisher feedback_;
};

TEST_F(BrickPlacer, PlaceHereRestsOnTheTable) {
  select(teleop::kPlaceHereEntry, poseAt(0.1, 0.05, 0.08, 0.3));
  const std::optional<Brick> placed = newBrick({});
  ASSERT_TRUE(placed) << "no brick appeared";
  EXPECT_EQ(placed->type, "kapla");
  EXPECT_NEAR(placed->pose.position.x, 0.1, 1e-6);
  EXPECT_NEAR(placed->pose.position.y, 0.05, 1e-6);
  EXPECT_NEAR(placed->pose.position.z, 0.5 * kThickness, 1e-6);
  EXPECT_NEAR(yawOf(placed->pose.orientation), 0.3, 1e-6);
  // Placed at rest exactly on the table: the stability layer froze it at once.
  EXPECT_EQ(placed->state, Brick::STABLE);
}

TEST_F(BrickPlacer, PlaceHereRestsOnABrickPlacedFirst) {
  ASSERT_TRUE(place("base", 0.0, 0.0, 0.5 * kThickness).success);
  const std::vector<Brick> before = bricks();
  // Crosswise over it, 10 cm up.
  select(teleop::kPlaceHereEntry, poseAt(0.02, 0.0, 0.1, M_PI / 2));
  const std::optional<Brick> placed = newBrick(before);
  ASSERT_TRUE(placed) << "no brick appeared";
  EXPECT_NEAR(placed->pose.position.x, 0.02, 1e-6);
  EXPECT_NEAR(placed->pose.position.z, 1.5 * kThickness, 1e-6);
  EXPECT_EQ(placed->state, Brick::STABLE);
  ASSERT_EQ(placed->supported_by.size(), 1u);
  EXPECT_EQ(placed->supported_by[0], "base");
}

TEST_F(BrickPlacer, DropFromHereKeepsThePoseAndFalls) {
  ASSERT_TRUE(setPaused(true));
  select(teleop::kDropFromHereEntry, poseAt(-0.1, -0.1, 0.06));
  const std::optional<Brick> dropped = newBrick({});
  ASSERT_TRUE(dropped) << "no brick appeared";
  EXPECT_NEAR(dropped->pose.position.z, 0.06, 1e-9) << "not placed where the ghost was";
  EXPECT_EQ(dropped->state, Brick::DYNAMIC);
  // 5.6 cm of free fall take 0.11 s; after 0.6 s it lies on the table.
  ASSERT_TRUE(step(600).success);
  const std::vector<Brick> after = bricks();
  ASSERT_EQ(after.size(), 1u);
  EXPECT_NEAR(after[0].pose.position.z, 0.5 * kThickness, 5e-4);
  EXPECT_NEAR(after[0].pose.position.x, -0.1, 5e-3);
  ASSERT_TRUE(setPaused(false));
}

TEST_F(BrickPlacer, TypeMenuChangesTheBrick) {
  select("cube", poseAt(0.15, -0.1, 0.05), teleop::kTypeMenu);
  select(teleop::kPlaceHereEntry, poseAt(0.15, -0.1, 0.05));
  const std::optional<Brick> placed = newBrick({});
  ASSERT_TRUE(placed) << "no brick appeared";
  EXPECT_EQ(placed->type, "cube");
  EXPECT_NEAR(placed->size.x, test::kKaplaWidth, 1e-9);
  EXPECT_NEAR(placed->pose.position.z, 0.5 * test::kKaplaWidth, 1e-6);
}

TEST_F(BrickPlacer, TurnTurnsTheGhostAboutZ) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    ghost_poses_.clear();
  }
  select(teleop::kTurnEntry, poseAt(0.2, 0.1, 0.1, 0.25));
  geometry_msgs::Pose turned;
  ASSERT_TRUE(waitFor(
      [&] {
        std::lock_guard<std::mutex> lock(mutex_);
        if (ghost_poses_.empty()) return false;
        turned = ghost_poses_.back();
        return true;
      },
      kActionTimeout))
      << "the ghost did not move";
  EXPECT_NEAR(yawOf(turned.orientation), 0.25 + M_PI / 2, 1e-6);
  EXPECT_NEAR(turned.position.x, 0.2, 1e-9);
  EXPECT_NEAR(turned.position.z, 0.1, 1e-9);
  EXPECT_TRUE(bricks().empty()) << "turning placed a brick";
}

TEST_F(BrickPlacer, ARefusalIsShownWithTheSimulatorsMessage) {
  ASSERT_TRUE(place("block", 0.0, 0.2, 0.5 * kThickness).success);
  // The simulator's own words for a brick inside "block".
  PlaceBrick direct;
  direct.request.type = "kapla";
  direct.request.pose = poseAt(0.0, 0.2, 0.5 * kThickness);
  ASSERT_FALSE(call(direct).success);
  ASSERT_FALSE(direct.response.message.empty());

  select(teleop::kDropFromHereEntry, poseAt(0.0, 0.2, 0.5 * kThickness));
  EXPECT_TRUE(warned(direct.response.message))
      << "no WARN from the placer with: " << direct.response.message;
  EXPECT_EQ(bricks().size(), 1u);
}

TEST_F(BrickPlacer, ANonFiniteGhostPoseIsRefused) {
  geometry_msgs::Pose bad = poseAt(0.0, 0.0, 0.1);
  bad.position.y = std::numeric_limits<double>::quiet_NaN();
  select(teleop::kPlaceHereEntry, bad);
  EXPECT_TRUE(warned("ghost pose.position.y"));
  ros::WallDuration(0.5).sleep();
  EXPECT_TRUE(bricks().empty());
  // The placer still works.
  select(teleop::kPlaceHereEntry, poseAt(0.0, 0.0, 0.1));
  EXPECT_TRUE(newBrick({}));
}

TEST_F(BrickPlacer, GraspDragAndReleaseThroughTheMenu) {
  ASSERT_TRUE(place("near", 0.1, 0.1, 0.5 * kThickness).success);
  ASSERT_TRUE(place("far", -0.15, -0.15, 0.5 * kThickness).success);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    ghost_poses_.clear();
  }
  // The ghost 5 cm above "near" and 2 cm aside: "near" is the nearest centre.
  select(teleop::kGraspEntry, poseAt(0.1, 0.12, 0.05));
  ASSERT_TRUE(waitForBrick("near", [](const Brick& b) { return b.state == Brick::HELD; }))
      << "near was not grasped";
  EXPECT_NE(brick("far")->state, Brick::HELD);
  // The ghost jumped onto the brick.
  ASSERT_TRUE(waitFor(
      [&] {
        std::lock_guard<std::mutex> lock(mutex_);
        return !ghost_poses_.empty() &&
               std::abs(ghost_poses_.back().position.z - 0.5 * kThickness) < 1e-6;
      },
      kActionTimeout))
      << "the ghost did not move onto the grasped brick";

  // Dragging the ghost 5 cm up carries the brick there.
  drag(poseAt(0.1, 0.1, 0.05));
  ASSERT_TRUE(waitForBrick("near", [](const Brick& b) { return b.pose.position.z > 0.0499; }))
      << "the held brick did not follow the ghost";
  const std::optional<Brick> lifted = brick("near");
  EXPECT_EQ(lifted->state, Brick::HELD);
  EXPECT_NEAR(lifted->pose.position.x, 0.1, 1e-4);
  EXPECT_NEAR(lifted->pose.position.y, 0.1, 1e-4);

  // Dragged 5 cm into the table, the target stops where the brick rests on
  // the table top (its half thickness up), and the ghost is put back there.
  {
    std::lock_guard<std::mutex> lock(mutex_);
    ghost_poses_.clear();
  }
  drag(poseAt(0.1, 0.1, -0.05));
  EXPECT_TRUE(waitFor(
      [&] {
        std::lock_guard<std::mutex> lock(mutex_);
        return !ghost_poses_.empty() &&
               std::abs(ghost_poses_.back().position.z - 0.5 * kThickness) < 1e-9;
      },
      kActionTimeout))
      << "the ghost was not kept above the table";
  EXPECT_TRUE(waitForBrick("near", [](const Brick& b) {
    return b.state == Brick::HELD && std::abs(b.pose.position.z - 0.5 * kThickness) < 1e-4;
  })) << "the held brick did not come down onto the table top";

  // Released at rest, it falls back onto the table.
  select(teleop::kReleaseEntry, poseAt(0.1, 0.1, 0.05));
  ASSERT_TRUE(waitForBrick("near", [](const Brick& b) { return b.state != Brick::HELD; }))
      << "near was not released";
  EXPECT_TRUE(waitForBrick("near", [](const Brick& b) {
    return std::abs(b.pose.position.z - 0.5 * kThickness) < 5e-4;
  })) << "near did not fall back onto the table";
  EXPECT_NEAR(brick("near")->pose.position.x, 0.1, 5e-3);

  // With nothing held, Release says so and changes nothing.
  select(teleop::kReleaseEntry, poseAt(0.1, 0.1, 0.05));
  EXPECT_TRUE(warned("no brick is held"));
}

TEST_F(BrickPlacer, AGraspRefusalIsShownWithTheSimulatorsMessage) {
  // A plank carrying a frozen one cannot be grasped.
  ASSERT_TRUE(place("bottom", -0.1, 0.1, 0.5 * kThickness).success);
  ASSERT_TRUE(place("top", -0.1, 0.1, 1.5 * kThickness, M_PI / 2).success);
  ASSERT_TRUE(waitForBrick("top", [](const Brick& b) { return b.state == Brick::STABLE; }));
  GraspBrick direct;
  direct.request.id = "bottom";
  ASSERT_FALSE(call(direct).success);
  ASSERT_FALSE(direct.response.message.empty());

  // Nearer "bottom" (3.9 mm) than "top" (11.7 mm).
  select(teleop::kGraspEntry, poseAt(-0.1, 0.1, 0.0));
  EXPECT_TRUE(warned(direct.response.message))
      << "no WARN from the placer with: " << direct.response.message;
  for (const Brick& b : bricks()) EXPECT_NE(b.state, Brick::HELD) << b.id;
}

}  // namespace

int main(int argc, char** argv) {
  return brick_stack_sim::test::runNodeTests(argc, argv, "test_brick_placer");
}
