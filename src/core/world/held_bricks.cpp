#include "world/held_bricks.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "brick_stack_sim/core/geometry/box_geometry.h"
#include "world/impacts.h"
#include "world/world_state.h"

namespace brick_stack_sim {

namespace {

/// Rounds of pushing the hand's pose out of what stops it: one obstacle
/// can push it into another (a corner of brick and table).
constexpr int kBlockingRounds = 3;

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

/// Pushes `pose` of the held brick out of the frozen bricks in `blocking`,
/// the table and the floor.
void pushOut(const WorldState& w, const BrickRecord& held, const std::vector<BodyHandle>& blocking,
             Eigen::Isometry3d* pose) {
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
    }
    // The floor is a plane: nothing may sink below it.
    const double lowest = bounds(OrientedBox{*pose, held.type.halfExtents()}).min().z();
    const double floor = -w.options.table.height;
    if (lowest < floor) {
      pose->translation().z() += floor - lowest;
      moved = true;
    }
    if (!moved) return;
  }
}

}  // namespace

void moveHeldBricks(WorldState* w) {
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
    if (w->model) {
      const Eigen::AlignedBox3d reach = bounds(OrientedBox{to, brick->type.halfExtents()});
      const Eigen::Vector3d margin =
          Eigen::Vector3d::Constant(w->options.stability.contact_distance);
      near = w->dormant.near(reach.min() - margin, reach.max() + margin);
    }
    std::vector<Impact> impacts;
    std::vector<double> overlaps;
    for (BodyHandle frozen : near) {
      Impact impact;
      double overlap = 0.0;
      if (findImpact(*w, striker, frozen, &impact, &overlap)) {
        impacts.push_back(impact);
        overlaps.push_back(overlap);
      }
    }
    carryOutImpacts(w, impacts, &overlaps);
    // What stays frozen where the hand would be stops it there.
    pushOut(*w, *brick, near, &to);
    w->scene.moveKinematic(brick->handle, to);
    brick->last_good_pose = to;
  }
}

}  // namespace brick_stack_sim
