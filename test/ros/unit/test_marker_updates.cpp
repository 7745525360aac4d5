// ~markers by id: a viewer that applies MarkerUpdates' arrays in order must
// show exactly the markers built from scratch from the world (makeMarkers of
// every snapshot and support geometry), through a tower's building, a brick
// landing on it, its top knocked off the table, removals and a reset; and a
// settled world must cost no marker at all. BrickMirror must hold exactly
// the world's snapshots after every update.
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "brick_stack_sim/ros/brick_mirror.h"
#include "brick_stack_sim/ros/marker_updates.h"
#include "brick_stack_sim/ros/markers.h"
#include "support/kapla.h"
#include "support/marker_viewer.h"

namespace brick_stack_sim {
namespace ros_adapter {
namespace {

constexpr int kLayers = 10;
/// Loose planks beside the tower: with the tower, more serials than one
/// outline marker holds.
constexpr int kLoosePlanks = 60;
/// Steps between two publishes (30 Hz at the default 1 ms step).
constexpr int kStepsPerPublish = 33;

class MarkerUpdatesTest : public testing::Test {
 protected:
  void SetUp() override {
    world_ = test::makeWorld(test::optionsFor("com"));
    viewer_.apply(updates_.full(mirror_, world_->options().table, ros::Time(0.0)));
  }

  /// One publish: the mirror follows the world, the viewer applies the
  /// update. Returns the number of markers sent.
  std::size_t publish() {
    const BrickMirror::Changes changes = mirror_.update(*world_);
    const ros::Time stamp(world_->time() + 1.0);
    const visualization_msgs::MarkerArray array =
        changes.replaced ? updates_.full(mirror_, world_->options().table, stamp)
                         : updates_.delta(mirror_, changes, stamp);
    viewer_.apply(array);
    return array.markers.size();
  }

  /// The viewer against markers built from scratch from the world itself,
  /// and the mirror against the world's snapshots.
  void expectViewerIsFromScratch(const std::string& after) {
    const std::vector<BrickSnapshot> bricks = world_->snapshot();
    SupportGeometryMap supports;
    for (const BrickSnapshot& brick : bricks) {
      SupportGeometry geometry;
      if (world_->supportGeometry(brick.id, &geometry)) supports.emplace(brick.id, geometry);
    }
    test::MarkerViewer scratch;
    scratch.apply(makeMarkers(bricks, supports, world_->options().table, "world", ros::Time()));
    EXPECT_EQ(viewer_.differences(scratch), "") << after;
    EXPECT_GT(scratch.shown().size(), 10u) << after;

    ASSERT_EQ(mirror_.bricks().size(), bricks.size()) << after;
    for (std::size_t i = 0; i < bricks.size(); ++i) {
      const BrickSnapshot& mirrored = mirror_.bricks()[i].snapshot;
      EXPECT_EQ(mirrored.id, bricks[i].id) << after;
      EXPECT_TRUE(mirrored.pose.matrix() == bricks[i].pose.matrix())
          << after << ": " << bricks[i].id;
      EXPECT_EQ(mirrored.state, bricks[i].state) << after << ": " << bricks[i].id;
      EXPECT_EQ(mirrored.margin, bricks[i].margin) << after << ": " << bricks[i].id;
      EXPECT_TRUE(mirrored.com_above == bricks[i].com_above) << after << ": " << bricks[i].id;
    }
  }

  void runAndPublish(double seconds, const std::string& during) {
    const int publishes =
        static_cast<int>(seconds / (kStepsPerPublish * world_->options().time_step));
    for (int p = 0; p < publishes; ++p) {
      for (int s = 0; s < kStepsPerPublish; ++s) world_->step();
      publish();
      if (p % 10 == 0) expectViewerIsFromScratch(during + ", publish " + std::to_string(p));
    }
    expectViewerIsFromScratch(during + ", at its end");
  }

  void buildScene() {
    for (int i = 0; i < 2 * kLayers; ++i) ASSERT_TRUE(world_->addBrick(test::towerBrick(i)).ok);
    for (int i = 0; i < kLoosePlanks; ++i) {
      const double x = -0.3 + 0.15 * (i % 5);
      const double y = 0.15 + 0.04 * (i / 5);
      ASSERT_TRUE(world_
                      ->addBrick(test::placement("p" + std::to_string(i),
                                                 {x, y, test::kKaplaThickness / 2}))
                      .ok);
    }
    publish();
    expectViewerIsFromScratch("the scene placed");
  }

  std::unique_ptr<BrickWorld> world_;
  BrickMirror mirror_;
  MarkerUpdates updates_{"world"};
  test::MarkerViewer viewer_;
};

TEST_F(MarkerUpdatesTest, AViewerThatAppliesTheUpdatesShowsWhatIsBuiltFromScratch) {
  buildScene();
  runAndPublish(0.5, "settling");

  // A brick dropped on the tower changes the load under it.
  const test::TowerSlot top = test::towerSlot(kLayers, 0);
  ASSERT_TRUE(
      world_->addBrick(test::placement("landing", {top.x, top.y, top.z + 0.02}, top.yaw)).ok);
  runAndPublish(0.5, "the landing");

  // The top three layers knocked off sideways: they fall, some off the table.
  for (int i = 2 * (kLayers - 3); i < 2 * kLayers; ++i) {
    BrickSnapshot brick;
    ASSERT_TRUE(world_->find("t" + std::to_string(i), &brick));
    ASSERT_TRUE(
        world_->applyImpulse(brick.id, Eigen::Vector3d(0.02, 0.0, 0.003), brick.pose.translation())
            .ok);
  }
  runAndPublish(2.0, "the collapse");
  int fell = 0, dynamic = 0;
  for (const BrickSnapshot& brick : world_->snapshot()) {
    fell += brick.fell_off;
    dynamic += brick.state == BrickState::kDynamic;
  }
  EXPECT_GT(fell + dynamic, 3) << "nothing collapsed: the test proved less than it says";

  for (const char* id : {"t0", "p3", "p40", "landing"}) ASSERT_TRUE(world_->removeBrick(id).ok);
  runAndPublish(0.5, "the removals");

  // A reset: a new world, whose serials start again.
  ASSERT_TRUE(
      BrickWorld::create(test::optionsFor("com"), test::packageTypes(), &world_, world_->time())
          .ok);
  mirror_.forget();
  for (int i = 0; i < 2 * 4; ++i) ASSERT_TRUE(world_->addBrick(test::towerBrick(i)).ok);
  publish();
  expectViewerIsFromScratch("the reset");
  runAndPublish(0.5, "after the reset");
}

TEST_F(MarkerUpdatesTest, ASettledWorldSendsNothingAndOneMovingBrickSendsOnlyItsOwn) {
  buildScene();
  runAndPublish(0.5, "settling");
  for (int p = 0; p < 5; ++p) {
    for (int s = 0; s < kStepsPerPublish; ++s) world_->step();
    EXPECT_EQ(publish(), 0u) << "a settled world sent markers";
  }
  BrickSnapshot plank;
  ASSERT_TRUE(world_->find("p0", &plank));
  ASSERT_TRUE(
      world_->applyImpulse("p0", Eigen::Vector3d(0.0, 0.0, 0.002), plank.pose.translation()).ok);
  for (int s = 0; s < kStepsPerPublish; ++s) world_->step();
  // Its box, its outline group, and the support markers it lost: a handful,
  // not the scene's hundreds.
  const std::size_t sent = publish();
  EXPECT_GE(sent, 2u);
  EXPECT_LE(sent, 8u);
  expectViewerIsFromScratch("one plank thrown up");
}

}  // namespace
}  // namespace ros_adapter
}  // namespace brick_stack_sim
