// BrickWorld::snapshotChangedSince: a publisher that asks only for what
// changed must never miss a change. Each test replays a scene with
// placements, settling, a brick landing on a tower, an impact, a push, a
// removal and a held brick, and after every request and every step
// compares the whole world (snapshot() and supportGeometry() of every
// brick) with what it was at the previous look: every brick that differs
// must be among those reported. And the report must be worth having: a
// settled world reports nothing, and a change to one tower does not report
// the other (with a stability model: plain Bullet freezes nothing).

#include <map>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/world/brick_world.h"
#include "support/kapla.h"
#include "support/modes.h"

namespace brick_stack_sim {
namespace {

constexpr int kLayers = 6;
/// Tower B stands this far from tower A along x [m]: well apart.
constexpr double kTowerSpacing = 0.3;

bool sameBits(const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return a == b; }

/// Everything a publisher shows of a brick, exactly.
bool sameSnapshot(const BrickSnapshot& a, const BrickSnapshot& b) {
  return a.id == b.id && a.serial == b.serial && a.pose.matrix() == b.pose.matrix() &&
         sameBits(a.linear_velocity, b.linear_velocity) &&
         sameBits(a.angular_velocity, b.angular_velocity) && a.state == b.state &&
         a.asleep == b.asleep && a.fell_off == b.fell_off && sameBits(a.com_above, b.com_above) &&
         a.mass_above == b.mass_above && a.supported_by == b.supported_by && a.margin == b.margin;
}

bool sameGeometry(const SupportGeometry& a, const SupportGeometry& b) {
  if (a.patches.size() != b.patches.size() || a.contact_forces.size() != b.contact_forces.size())
    return false;
  for (std::size_t i = 0; i < a.patches.size(); ++i)
    if (a.patches[i].supporter != b.patches[i].supporter ||
        a.patches[i].polygon != b.patches[i].polygon)
      return false;
  for (std::size_t i = 0; i < a.contact_forces.size(); ++i) {
    const SupportGeometry::ContactForce &f = a.contact_forces[i], &g = b.contact_forces[i];
    if (f.other != g.other || f.point != g.point || f.normal != g.normal || f.force != g.force ||
        f.friction != g.friction)
      return false;
  }
  return a.combined_hull == b.combined_hull && a.com_above == b.com_above && a.margin == b.margin;
}

/// What a brick shows: its snapshot and, when the model describes it, its geometry.
struct Shown {
  BrickSnapshot snapshot;
  bool described = false;
  SupportGeometry geometry;
};

class ChangeTracking : public testing::TestWithParam<std::string> {
 protected:
  void SetUp() override { world_ = test::makeWorld(test::optionsFor(GetParam())); }

  std::map<unsigned, Shown> everything() const {
    std::map<unsigned, Shown> shown;
    for (const BrickSnapshot& brick : world_->snapshot()) {
      Shown& entry = shown[brick.serial];
      entry.snapshot = brick;
      entry.described = world_->supportGeometry(brick.id, &entry.geometry);
    }
    return shown;
  }

  /// Checks the report against the whole world, then takes the world as seen.
  /// Returns the ids reported as changed.
  std::set<std::string> look(const std::string& after) {
    std::vector<unsigned> serials;
    const std::vector<BrickSnapshot> changed =
        world_->snapshotChangedSince(seen_revision_, &serials);
    const std::map<unsigned, Shown> now = everything();
    std::set<unsigned> reported;
    std::set<std::string> ids;
    for (const BrickSnapshot& brick : changed) {
      reported.insert(brick.serial);
      ids.insert(brick.id);
      const auto found = now.find(brick.serial);
      if (found == now.end()) {
        ADD_FAILURE() << after << ": reported " << brick.id << ", which is not in the world";
        continue;
      }
      EXPECT_TRUE(sameSnapshot(brick, found->second.snapshot))
          << after << ": the report's snapshot of " << brick.id << " is not snapshot()'s";
    }
    // Asked without serials, the world finds the changes from its log of
    // them instead of walking every brick; it must find the same ones.
    std::vector<unsigned> quick;
    for (const BrickSnapshot& brick : world_->snapshotChangedSince(seen_revision_))
      quick.push_back(brick.serial);
    EXPECT_EQ(quick, std::vector<unsigned>(reported.begin(), reported.end()))
        << after << ": asked without serials, the world reports other bricks";
    std::vector<unsigned> expected_serials;
    for (const auto& [serial, shown] : now) expected_serials.push_back(serial);
    EXPECT_EQ(serials, expected_serials) << after;
    EXPECT_TRUE(std::is_sorted(
        changed.begin(), changed.end(),
        [](const BrickSnapshot& a, const BrickSnapshot& b) { return a.serial < b.serial; }))
        << after << ": not in placement order";
    for (const auto& [serial, shown] : now) {
      const auto before = seen_.find(serial);
      const bool differs =
          before == seen_.end() || !sameSnapshot(before->second.snapshot, shown.snapshot) ||
          before->second.described != shown.described ||
          (shown.described && !sameGeometry(before->second.geometry, shown.geometry));
      if (differs) {
        ++differences_;
        EXPECT_TRUE(reported.count(serial))
            << after << ": " << shown.snapshot.id << " (" << toString(shown.snapshot.state)
            << ") changed and was not reported";
      }
    }
    seen_ = now;
    seen_revision_ = world_->revision();
    return ids;
  }

  void stepAndLook(double seconds, const std::string& during) {
    const long steps = std::lround(seconds / world_->options().time_step);
    for (long i = 0; i < steps; ++i) {
      world_->step();
      look(during + ", step " + std::to_string(i));
    }
  }

  /// Tower `name` ("a" or "b"): its bricks are <name>0, <name>1, ...
  void buildTower(const std::string& name, double x) {
    for (int i = 0; i < 2 * kLayers; ++i) {
      BrickPlacement brick = test::towerBrick(i);
      brick.id = name + std::to_string(i);
      brick.pose.translation().x() += x;
      ASSERT_TRUE(world_->addBrick(brick).ok) << brick.id;
      look("placing " + brick.id);
    }
  }

  std::unique_ptr<BrickWorld> world_;
  std::map<unsigned, Shown> seen_;
  std::uint64_t seen_revision_ = 0;
  long differences_ = 0;  ///< Changes the reports were checked against.
};

bool anyOfTower(const std::set<std::string>& ids, char tower) {
  for (const std::string& id : ids)
    if (id.front() == tower) return true;
  return false;
}

// Bricks placed at one instant (a paused node) are judged as a whole
// later: what that judgement describes (supports, margins, COM-above) is
// a change a publisher must be told of.
TEST_P(ChangeTracking, BricksPlacedAtOneInstantAreReportedWhenJudged) {
  for (int i = 0; i < 2 * kLayers; ++i) {
    ASSERT_TRUE(world_->addBrick(test::towerBrick(i), nullptr, true).ok);
    look("placing t" + std::to_string(i) + " with more to come");
  }
  world_->judgePlacements();
  look("judging the tower as a whole");
  stepAndLook(0.05, "after the judgement");
}

TEST_P(ChangeTracking, EveryChangeIsReportedAndASettledWorldReportsNothing) {
  buildTower("a", 0.0);
  buildTower("b", kTowerSpacing);
  stepAndLook(0.2, "settling");
  // Plain Bullet freezes nothing: every brick may move at every step.
  const bool freezes = GetParam() != "none";
  world_->step();
  if (freezes) {
    EXPECT_TRUE(look("a step of the settled towers").empty())
        << "frozen towers reported as changed: a publisher would resend them";
  }

  // A brick landing on tower A changes the load on every brick under it,
  // and nothing of tower B.
  const test::TowerSlot top = test::towerSlot(kLayers, 0);
  BrickPlacement landing =
      test::placement("a_landing", Eigen::Vector3d(top.x, top.y, top.z + 0.02), top.yaw);
  ASSERT_TRUE(world_->addBrick(landing).ok);
  look("dropping a brick on tower A");
  bool reported_a = false;
  for (int i = 0; i < 100; ++i) {
    world_->step();
    const std::set<std::string> ids = look("the brick landing on A, step " + std::to_string(i));
    if (freezes) {
      EXPECT_FALSE(anyOfTower(ids, 'b')) << "a brick of tower B reported at step " << i;
    }
    reported_a |= anyOfTower(ids, 'a') && ids.size() > 1;
  }
  EXPECT_TRUE(reported_a) << "the landing brick froze without redescribing the tower under it";
  stepAndLook(0.3, "after the landing");

  // A striker thrown at tower A's third layer slides or wakes what it hits.
  const test::TowerSlot third = test::towerSlot(2, 0);
  BrickPlacement striker = test::placement(
      "striker", Eigen::Vector3d(third.x, -test::kTowerOffset - 0.03, third.z + 0.001), third.yaw);
  striker.linear_velocity = Eigen::Vector3d(0.0, 1.5, 0.0);
  ASSERT_TRUE(world_->addBrick(striker).ok);
  look("throwing the striker");
  stepAndLook(0.5, "the impact");

  // A push wakes tower B's top; a removal takes a brick out from under A's load.
  BrickSnapshot b_top;
  ASSERT_TRUE(world_->find("b" + std::to_string(2 * kLayers - 1), &b_top));
  ASSERT_TRUE(
      world_->applyImpulse(b_top.id, Eigen::Vector3d(0.0, 0.0, 0.002), b_top.pose.translation())
          .ok);
  look("pushing " + b_top.id);
  stepAndLook(0.3, "after the push");
  ASSERT_TRUE(world_->removeBrick("b4").ok);
  look("removing b4");
  stepAndLook(0.5, "after the removal");

  // A held brick moves every step while it is held.
  ASSERT_TRUE(world_->graspBrick("striker").ok);
  look("grasping the striker");
  Eigen::Isometry3d target = Eigen::Isometry3d::Identity();
  target.translation() = Eigen::Vector3d(-0.2, 0.1, 0.05);
  ASSERT_TRUE(world_->setHeldTarget(target).ok);
  look("moving the held target");
  stepAndLook(0.2, "while held");
  ASSERT_TRUE(world_->releaseBrick("striker", Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()).ok);
  look("releasing the striker");
  stepAndLook(1.0, "after the release");

  EXPECT_GT(differences_, 1000) << "the scene changed too little to prove anything";
  // A reader that last looked before anything was placed, long ago, is
  // told of every brick.
  EXPECT_EQ(world_->snapshotChangedSince(0).size(), world_->brickCount());
}

INSTANTIATE_TEST_SUITE_P(Modes, ChangeTracking, testing::ValuesIn(test::allModes()),
                         [](const testing::TestParamInfo<std::string>& info) {
                           return info.param;
                         });

}  // namespace
}  // namespace brick_stack_sim
