// A pile of planks dropped from a lattice must only lose energy and keep
// every brick in the world and on the table, in every mode; with a stability
// model it must come to rest; and where a mode stops simulating a brick at
// rest, the brick must stay exactly where Bullet left it.
//
// What "at rest" means depends on the mode. With a stability model (com,
// equilibrium) the model freezes a brick that rests stably: its state
// becomes kStable or kLeaning, its Bullet body turns static, its velocities
// zero. Plain Bullet (mode none) freezes nothing and every brick stays
// kDynamic; its equivalent is Bullet's own deactivation: an island of bodies
// slower than the sleeping thresholds for the sleeping time is put to sleep
// (the snapshot's `asleep`), which zeroes its velocities and stops
// integrating it. Bullet puts an island to sleep before it integrates the
// step, so a brick falls asleep exactly where the step before left it.
//
// The model freezes a brick inside step(), after Bullet has advanced it in
// that step: the pose Bullet computed last is never reported while the
// brick is still dynamic. So the pose at a freeze is checked against a
// plain-Bullet twin, bit-identical to the model's world up to its first
// freeze (exact), and at every freeze against the pose reported one step
// earlier (at most one step at the rest speeds away); from then on it is
// checked against itself, exactly, for as long as the brick stays frozen.

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/scene/generators.h"
#include "brick_stack_sim/core/simulation/scene_player.h"
#include "brick_stack_sim/core/world/brick_world.h"
#include "support/kapla.h"
#include "support/modes.h"

namespace brick_stack_sim {
namespace {

// 40 planks over 4 x 2 cells, five layers: planks land on each other, lean
// and slide off, yet one mode runs in about a second of wall time.
constexpr int kPileBricks = 40;
constexpr int kPileColumns = 4;
constexpr int kPileRows = 2;
constexpr unsigned kPileSeed = 7;
/// Enough to land (the top layer drops from 0.19 m), settle, and then stay below
/// Bullet's sleeping thresholds for its sleeping time (2 s) [s].
constexpr double kSettleTime = 5.0;

PileParams pileParams() {
  PileParams params;
  params.bricks = kPileBricks;
  params.columns = kPileColumns;
  params.rows = kPileRows;
  params.seed = kPileSeed;
  return params;
}

/// The height of the highest centre the pile drops from [m]: nothing falls upwards.
double dropHeight() {
  const PileParams params = pileParams();
  const int layers = (params.bricks - 1) / (params.columns * params.rows);
  return params.base_height + layers * params.layer_height;
}

/// A world with `options` and the whole pile placed, in the air, at time 0.
std::unique_ptr<BrickWorld> droppedPile(const WorldOptions& options) {
  std::vector<ScheduledBrick> bricks;
  const Status generated = generatePile(pileParams(), test::packageTypes(), &bricks);
  EXPECT_TRUE(generated.ok) << generated.message;
  std::unique_ptr<BrickWorld> world = test::makeWorld(options);
  ScenePlayer player(bricks, world->time());
  EXPECT_TRUE(player.placeDue(world.get()).empty());
  EXPECT_TRUE(player.done());  // the pile is placed at one instant
  return world;
}

std::unique_ptr<BrickWorld> droppedPile(const std::string& mode) {
  return droppedPile(test::optionsFor(mode));
}

bool frozen(BrickState state) {
  return state == BrickState::kStable || state == BrickState::kLeaning;
}

/// Whether `mode` runs a stability model, which freezes bricks at rest.
bool freezes(const std::string& mode) {
  const std::vector<std::string> models = test::modelModes();
  return std::find(models.begin(), models.end(), mode) != models.end();
}

/// At rest as the mode knows it: frozen by the model; in plain Bullet, put
/// to sleep by Bullet, which zeroes the velocities of a sleeping island.
bool atRest(const BrickSnapshot& brick, bool model) {
  if (model) return frozen(brick.state);
  return brick.state == BrickState::kDynamic && brick.asleep && brick.linear_velocity.isZero(0.0) &&
         brick.angular_velocity.isZero(0.0);
}

/// The world's events, kept for the failure messages: what the model said
/// about a brick is the diagnosis when it does not come to rest.
class EventLog {
 public:
  void take(BrickWorld* world) {
    for (SimEvent& event : world->takeEvents()) events_.push_back(std::move(event));
  }
  int count(SimEventKind kind) const {
    return static_cast<int>(std::count_if(events_.begin(), events_.end(),
                                          [kind](const SimEvent& e) { return e.kind == kind; }));
  }
  /// The last `last` events that name `id`, oldest first, one a line.
  std::string about(const std::string& id, std::size_t last = 4) const {
    std::vector<const SimEvent*> found;
    for (const SimEvent& event : events_) {
      const bool affected =
          std::find(event.affected.begin(), event.affected.end(), id) != event.affected.end();
      if (event.brick_id == id || affected) found.push_back(&event);
    }
    std::ostringstream text;
    for (std::size_t i = found.size() > last ? found.size() - last : 0; i < found.size(); ++i)
      text << "\n    t=" << found[i]->time << " s " << toString(found[i]->kind) << " "
           << found[i]->brick_id << ": " << found[i]->reason;
    return text.str();
  }

 private:
  std::vector<SimEvent> events_;
};

/// Steps `world` for the pile's settling time, keeping every event in `log`.
void settle(BrickWorld* world, EventLog* log) {
  const long steps = std::lround(kSettleTime / world->options().time_step);
  for (long i = 0; i < steps; ++i) {
    world->step();
    log->take(world);
  }
}

std::string describe(const BrickSnapshot& brick) {
  std::ostringstream text;
  const Eigen::Vector3d& p = brick.pose.translation();
  text << brick.id << " " << toString(brick.state) << (brick.asleep ? " asleep" : "") << " at ("
       << p.x() << ", " << p.y() << ", " << p.z() << ") m, speed " << brick.linear_velocity.norm()
       << " m/s, spin " << brick.angular_velocity.norm() << " rad/s";
  return text.str();
}

/// On the table top, or on the floor under and around it: nowhere else can
/// a dropped plank come to rest (not in the air, not below the floor).
bool onTableOrFloor(const BrickSnapshot& brick, const TableOptions& table) {
  const Eigen::Vector3d& p = brick.pose.translation();
  const double reach = 0.5 * brick.size.norm();
  const bool over_table = std::abs(p.x()) <= 0.5 * table.size.x() + reach &&
                          std::abs(p.y()) <= 0.5 * table.size.y() + reach;
  const bool on_table = over_table && p.z() > 0.0 && p.z() <= dropHeight();
  const bool on_floor = p.z() > -table.height && p.z() < -table.height + reach &&
                        std::abs(p.x()) < table.size.x() && std::abs(p.y()) < table.size.y();
  return on_table || on_floor;
}

class PileSettles : public testing::TestWithParam<std::string> {};

TEST_P(PileSettles, ADroppedPileEndsAtRestOnTheTableWithNoBrickLost) {
  const std::string mode = GetParam();
  const bool model = freezes(mode);
  std::unique_ptr<BrickWorld> world = droppedPile(mode);
  ASSERT_EQ(world->brickCount(), static_cast<std::size_t>(kPileBricks));
  EventLog log;
  settle(world.get(), &log);
  EXPECT_EQ(world->brickCount(), static_cast<std::size_t>(kPileBricks));
  EXPECT_EQ(log.count(SimEventKind::kLost), 0);
  EXPECT_EQ(log.count(SimEventKind::kRemoved), 0);
  // A repaired NaN or runaway speed is a brick that flew, put back.
  EXPECT_EQ(log.count(SimEventKind::kNonFinite), 0);
  for (const BrickSnapshot& brick : world->snapshot()) {
    ASSERT_TRUE(brick.pose.matrix().allFinite()) << brick.id;
    EXPECT_TRUE(onTableOrFloor(brick, world->options().table)) << describe(brick);
    // Held to the cone in two directions, friction holds a plank across its
    // slip as well as along it, so even plain Bullet brings the pile to
    // rest: every plank still for Bullet's sleeping time. With Bullet's own
    // friction, along the slip alone, the pile creeps (25 of these 40
    // planks still awake after 5 s, one 32 mm on by 20 s). It must stay
    // still, too: a point near rest whose friction swung round with a tiny
    // slip would kick its plank each step and keep its island awake.
    EXPECT_TRUE(atRest(brick, model)) << "in mode " << mode << " at t=" << world->time()
                                      << " s: " << describe(brick) << log.about(brick.id);
  }
  // With a model, a pile at rest costs nothing more: a step only advances the clock.
  if (model) {
    EXPECT_TRUE(world->settled()) << mode;
  }
}

/// The bricks' kinetic energy and potential energy above the table top [J]
/// (a KAPLA is a box: its inertia from its size and mass).
double mechanicalEnergy(const BrickWorld& world) {
  double energy = 0.0;
  for (const BrickSnapshot& brick : world.snapshot()) {
    const Eigen::Vector3d square = brick.size.cwiseProduct(brick.size);
    const Eigen::Vector3d inertia =
        brick.mass / 12.0 *
        Eigen::Vector3d(square.y() + square.z(), square.x() + square.z(), square.x() + square.y());
    const Eigen::Vector3d spin = brick.pose.linear().transpose() * brick.angular_velocity;
    energy += 0.5 * brick.mass * brick.linear_velocity.squaredNorm() +
              0.5 * inertia.dot(spin.cwiseProduct(spin)) +
              brick.mass * world.options().gravity * brick.pose.translation().z();
  }
  return energy;
}

TEST_P(PileSettles, TheDroppedPileOnlyLosesEnergy) {
  // Planks that do not bounce (restitution 0) and rub with friction only
  // lose energy: energy that rises above the lowest it has been is the
  // solver pushing bricks apart, which is what scatters a pile. Only split
  // impulse may lift a brick back out of an overlap it sank into on
  // landing (a plank landing at 1.9 m/s moves 1.9 mm a step): 1 mm of
  // a 6 g plank is 59 uJ. The rise above the lowest energy so far counts
  // what was put in over any stretch of steps; a sum of every step's gain
  // would also count planks at rest bobbing by tens of nanometres a step,
  // which puts nothing in (this pile at rest stays within 2 uJ of one
  // energy for seconds while such a sum grows by hundreds).
  std::unique_ptr<BrickWorld> world = droppedPile(GetParam());
  const double start = mechanicalEnergy(*world);
  double lowest = start, largest_rise = 0.0, energy = start;
  const long steps = std::lround(kSettleTime / world->options().time_step);
  for (long i = 0; i < steps; ++i) {
    world->step();
    energy = mechanicalEnergy(*world);
    lowest = std::min(lowest, energy);
    largest_rise = std::max(largest_rise, energy - lowest);
  }
  const double lost = start - energy;
  EXPECT_GT(lost, 0.0);
  EXPECT_LT(largest_rise, 1e-3 * lost)
      << "rose by " << largest_rise << " J above its lowest while losing " << lost << " J";
}

/// How far a brick moved from `before` to `after`: its centre [m] and its turn [rad].
struct Shift {
  double distance = 0.0;
  double angle = 0.0;
};

Shift shiftBetween(const Eigen::Isometry3d& before, const Eigen::Isometry3d& after) {
  const Eigen::AngleAxisd turn(before.linear().transpose() * after.linear());
  return {(after.translation() - before.translation()).norm(), std::abs(turn.angle())};
}

/// Checks every brick at rest after a step against the step before: one
/// that was at rest already has not moved a bit; one that just came to rest
/// is where Bullet's last step could have taken it. Returns how many came to rest.
int checkRestingPoses(const std::vector<BrickSnapshot>& before,
                      const std::vector<BrickSnapshot>& after, bool model,
                      const WorldOptions& options, double time, const EventLog& log) {
  // The model froze a brick whose speeds after Bullet's step were below the
  // rest speeds, and Bullet had integrated the step with those speeds (its
  // split impulse adds a push only to contacts deeper than its threshold,
  // 0.4 mm, which a brick at rest is not). Bullet puts a brick to sleep
  // without integrating that step.
  const double dt = options.time_step;
  const double max_distance = model ? options.stability.rest_linear_speed * dt : 0.0;
  const double max_angle = model ? options.stability.rest_angular_speed * dt : 0.0;
  int came_to_rest = 0;
  for (std::size_t i = 0; i < after.size(); ++i) {
    const BrickSnapshot &was = before[i], &is = after[i];
    if (!atRest(is, model)) continue;
    const std::string where =
        "at t=" + std::to_string(time) + " s: " + describe(is) + log.about(is.id);
    const Shift shift = shiftBetween(was.pose, is.pose);
    if (atRest(was, model)) {
      EXPECT_TRUE(is.pose.matrix() == was.pose.matrix())
          << "moved by " << shift.distance << " m, " << shift.angle << " rad while at rest "
          << where;
      continue;
    }
    ++came_to_rest;
    EXPECT_LE(shift.distance, max_distance) << "came to rest " << where;
    EXPECT_LE(shift.angle, max_angle) << "came to rest " << where;
    EXPECT_TRUE(is.linear_velocity.isZero(0.0) && is.angular_velocity.isZero(0.0)) << where;
  }
  return came_to_rest;
}

TEST_P(PileSettles, BricksAtRestStayWhereBulletLeftThem) {
  // Frozen (or asleep) until woken, a brick does not move at all. The
  // impact rule may slide a frozen brick visibly, announced by an impact
  // event; nothing in this pile strikes that hard, so a slide here is news.
  const std::string mode = GetParam();
  const bool model = freezes(mode);
  std::unique_ptr<BrickWorld> world = droppedPile(mode);
  EventLog log;
  std::vector<BrickSnapshot> before = world->snapshot();
  int came_to_rest = 0;
  const long steps = std::lround(kSettleTime / world->options().time_step);
  for (long i = 0; i < steps; ++i) {
    world->step();
    log.take(world.get());
    std::vector<BrickSnapshot> after = world->snapshot();
    ASSERT_EQ(after.size(), before.size());
    came_to_rest += checkRestingPoses(before, after, model, world->options(), world->time(), log);
    before = std::move(after);
  }
  // That every brick comes to rest is the test above; here the checks
  // must at least have run.
  EXPECT_GT(came_to_rest, 0) << mode;
}

TEST_P(PileSettles, TheFirstBricksToFreezeAreBitForBitWhereBulletPutThem) {
  const std::string mode = GetParam();
  if (!freezes(mode)) GTEST_SKIP() << "mode " << mode << " freezes nothing";
  std::unique_ptr<BrickWorld> world = droppedPile(mode);
  std::unique_ptr<BrickWorld> twin = droppedPile("none");
  const long steps = std::lround(kSettleTime / world->options().time_step);
  for (long i = 0; i < steps; ++i) {
    world->step();
    twin->step();
    const std::vector<BrickSnapshot> bricks = world->snapshot(), twins = twin->snapshot();
    ASSERT_EQ(bricks.size(), twins.size());
    const bool any_frozen = std::any_of(bricks.begin(), bricks.end(),
                                        [](const BrickSnapshot& b) { return frozen(b.state); });
    // Until a brick freezes, the model only watches: its world is plain
    // Bullet's bit for bit. In the step of the first freeze Bullet moved
    // every brick before the model froze some, so the frozen ones, too,
    // must be where the twin's Bullet put them.
    for (std::size_t b = 0; b < bricks.size(); ++b)
      ASSERT_TRUE(bricks[b].pose.matrix() == twins[b].pose.matrix())
          << "at t=" << world->time() << " s, " << (any_frozen ? "freezing" : "before any freeze")
          << ": " << describe(bricks[b]) << ", in plain Bullet " << describe(twins[b]);
    if (any_frozen) return;
  }
  FAIL() << "no brick froze in " << kSettleTime << " s";
}

INSTANTIATE_TEST_SUITE_P(Modes, PileSettles, testing::ValuesIn(test::allModes()), test::modeName);

}  // namespace
}  // namespace brick_stack_sim
