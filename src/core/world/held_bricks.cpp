#include "world/held_bricks.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "brick_stack_sim/core/geometry/box_geometry.h"
#include "world/impacts.h"
#include "world/placement_check.h"
#include "world/world_state.h"

namespace brick_stack_sim {

namespace {

/// Rounds of pushing the hand's pose out of what stops it: one obstacle
/// can push it into another (a corner of brick and table).
constexpr int kBlockingRounds = 3;
/// A press below this is none [N]: a ten-thousandth of a KAPLA's weight,
/// far above what a hand resting flush on a brick presses by rounding.
constexpr double kLeastPress = 1e-5;

/// One step of the hand: where it gets to, and the move and turn that take
/// it there.
struct HandStep {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  Eigen::Vector3d move = Eigen::Vector3d::Zero();  ///< [m]
  Eigen::AngleAxisd turn = Eigen::AngleAxisd::Identity();
};

/// One step from `from` toward `to`, no farther than `max_distance` [m]
/// and `max_angle` [rad].
HandStep stepToward(const Eigen::Isometry3d& from, const Eigen::Isometry3d& to, double max_distance,
                    double max_angle) {
  HandStep step;
  step.move = to.translation() - from.translation();
  if (step.move.norm() > max_distance) step.move *= max_distance / step.move.norm();
  step.turn = Eigen::AngleAxisd(Eigen::Quaterniond(to.linear() * from.linear().transpose()));
  if (step.turn.angle() > M_PI)
    step.turn = Eigen::AngleAxisd(2.0 * M_PI - step.turn.angle(), -step.turn.axis());
  step.turn.angle() = std::min(step.turn.angle(), max_angle);
  step.pose.translation() = from.translation() + step.move;
  step.pose.linear() = (Eigen::Quaterniond(step.turn) * Eigen::Quaterniond(from.linear()))
                           .normalized()
                           .toRotationMatrix();
  return step;
}

/// A frozen brick that stopped the hand, and the normal of the face it
/// stopped it at (unit, from the brick towards the hand).
struct Stop {
  BodyHandle brick = 0;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
};

/// Pushes `pose` of the held brick out of the frozen bricks in `blocking`,
/// the table and the floor; `stops` receives the frozen bricks it was
/// pushed out of.
void pushOut(const WorldState& w, const BrickRecord& held, const std::vector<BodyHandle>& blocking,
             Eigen::Isometry3d* pose, std::vector<Stop>* stops) {
  for (int round = 0; round < kBlockingRounds; ++round) {
    bool moved = false;
    std::vector<BodyHandle> obstacles = blocking;
    obstacles.push_back(kTableHandle);
    for (BodyHandle obstacle : obstacles) {
      const BrickRecord* record = isGround(obstacle) ? nullptr : w.bricks.find(obstacle);
      if (!isGround(obstacle) && (!record || !isFrozen(record->mode))) continue;
      ClosestPoints nearest;
      if (!w.scene.closestPoints(held.handle, *pose, obstacle, &nearest) || nearest.distance >= 0.0)
        continue;
      pose->translation() -= nearest.distance * nearest.normal;
      moved = true;
      const bool known = std::any_of(stops->begin(), stops->end(),
                                     [&](const Stop& stop) { return stop.brick == obstacle; });
      if (!isGround(obstacle) && !known) stops->push_back(Stop{obstacle, nearest.normal});
    }
    // The floor is a plane: nothing may sink below it.
    const double lowest = bounds(held.type.placed(*pose)).min().z();
    const double floor = -w.options.table.height;
    if (lowest < floor) {
      pose->translation().z() += floor - lowest;
      moved = true;
    }
    if (!moved) return;
  }
}

/// The hand is a spring to its target: stopped short of it by a frozen
/// brick, it presses on that brick with the held options' stiffness times
/// how far the target lies beyond, along the face's normal, at most their
/// largest force, spread over the face where they touch. The press is
/// added to `presses` as the contact a solver would have applied, so that
/// the stability model measures it like any other load.
void pressOn(const WorldState& w, const BrickRecord& held, const Eigen::Isometry3d& pose,
             const Stop& stop, std::vector<PairContact>* presses) {
  const HeldOptions& hand = w.options.held;
  const double beyond = (pose.translation() - held.held_target.translation()).dot(stop.normal);
  const double force = std::min(hand.stiffness * beyond, hand.max_force);
  if (!(force > kLeastPress)) return;
  std::vector<PairContact> touching;
  appendContacts(w, held.handle, held.type.friction, held.type.placed(pose), stop.brick, true,
                 &touching);
  std::vector<Eigen::Vector3d> points;
  for (const PairContact& contact : touching)
    points.insert(points.end(), contact.points.begin(), contact.points.end());
  if (points.empty()) {
    ClosestPoints nearest;
    if (!w.scene.closestPoints(held.handle, pose, stop.brick, &nearest)) return;
    points.push_back(nearest.on_b);
  }
  PairContact press;
  press.a = held.handle;
  press.b = stop.brick;
  press.normal = stop.normal;
  press.points = points;
  const double impulse = force * w.options.time_step / static_cast<double>(points.size());
  for (const Eigen::Vector3d& point : points)
    press.manifold.push_back(
        ContactPoint{point, stop.normal, 0.0, impulse, Eigen::Vector3d::Zero()});
  presses->push_back(std::move(press));
}

}  // namespace

void moveHeldBricks(WorldState* w) {
  w->presses.clear();
  const double dt = w->options.time_step;
  const HeldOptions& limits = w->options.held;
  // A copy: an impact may change the sets.
  const std::vector<BrickRecord*> held = w->sets.held();
  for (BrickRecord* brick : held) {
    const HandStep step = stepToward(w->scene.pose(brick->handle), brick->held_target,
                                     limits.max_linear_speed * dt, limits.max_angular_speed * dt);
    Eigen::Isometry3d to = step.pose;
    Striker striker{
        brick->handle,  std::numeric_limits<double>::infinity(),     to,
        step.move / dt, step.turn.axis() * (step.turn.angle() / dt), brick->type.restitution};
    if (!striker.spin.allFinite()) striker.spin.setZero();

    std::vector<BodyHandle> near;
    const Eigen::Isometry3d from = w->scene.pose(brick->handle);
    if (w->model) {
      // All it passes on the way, not just where it ends.
      Eigen::AlignedBox3d reach = bounds(brick->type.placed(to));
      reach.extend(bounds(brick->type.placed(from)));
      const Eigen::Vector3d margin =
          Eigen::Vector3d::Constant(w->options.stability.contact_distance);
      near = w->dormant.near(reach.min() - margin, reach.max() + margin);
    }
    std::vector<Impact> impacts;
    std::vector<double> overlaps;
    for (BodyHandle frozen : near) {
      // A fast hand is judged where it first meets each brick on its way.
      Striker at = striker;
      at.pose = partWay(from, to, firstContactOnTheWay(*w, striker, from, frozen));
      Impact impact;
      double overlap = 0.0;
      if (findImpact(*w, at, frozen, &impact, &overlap)) {
        impacts.push_back(impact);
        overlaps.push_back(overlap);
      }
    }
    carryOutImpacts(w, impacts, &overlaps);
    // What it meets on the way and stays frozen stops it there.
    double stop = 1.0;
    for (BodyHandle frozen : near) {
      const BrickRecord* record = w->bricks.find(frozen);
      if (record && isFrozen(record->mode))
        stop = std::min(stop, firstContactOnTheWay(*w, striker, from, frozen));
    }
    if (stop < 1.0) to = partWay(from, to, stop);
    // What stays frozen where the hand would be stops it there, and bears
    // the hand's press.
    std::vector<Stop> stops;
    pushOut(*w, *brick, near, &to, &stops);
    for (const Stop& stop : stops) pressOn(*w, *brick, to, stop, &w->presses);
    w->scene.moveKinematic(brick->handle, to);
    brick->last_good_pose = to;
  }
}

}  // namespace brick_stack_sim
