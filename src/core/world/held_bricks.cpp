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

/// One step from `from` toward `to`, no farther than `max_distance` [m]
/// and `max_angle` [rad].
Eigen::Isometry3d stepToward(const Eigen::Isometry3d& from, const Eigen::Isometry3d& to,
                             double max_distance, double max_angle) {
  Eigen::Isometry3d next = from;
  Eigen::Vector3d move = to.translation() - from.translation();
  if (move.norm() > max_distance) move *= max_distance / move.norm();
  next.translation() += move;
  Eigen::AngleAxisd turn(Eigen::Quaterniond(to.linear() * from.linear().transpose()));
  if (turn.angle() > M_PI) turn = Eigen::AngleAxisd(2.0 * M_PI - turn.angle(), -turn.axis());
  turn.angle() = std::min(turn.angle(), max_angle);
  next.linear() = (Eigen::Quaterniond(turn) * Eigen::Quaterniond(from.linear()))
                      .normalized()
                      .toRotationMatrix();
  return next;
}

/// The bounds of `box` grown by `margin` [m].
void boundsOf(const OrientedBox& box, double margin, Eigen::Vector3d* low, Eigen::Vector3d* high) {
  *low = *high = box.pose.translation();
  for (const Eigen::Vector3d& corner : corners(box)) {
    *low = low->cwiseMin(corner);
    *high = high->cwiseMax(corner);
  }
  *low -= Eigen::Vector3d::Constant(margin);
  *high += Eigen::Vector3d::Constant(margin);
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
    const OrientedBox box{*pose, held.type.halfExtents()};
    Eigen::Vector3d low, high;
    boundsOf(box, 0.0, &low, &high);
    const double floor = -w.options.table.height;
    if (low.z() < floor) {
      pose->translation().z() += floor - low.z();
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
    const Eigen::Isometry3d from = w->scene.pose(brick->handle);
    Eigen::Isometry3d to = stepToward(from, brick->held_target, limits.max_linear_speed * dt,
                                      limits.max_angular_speed * dt);
    const Eigen::AngleAxisd turn(Eigen::Quaterniond(to.linear() * from.linear().transpose()));
    Striker striker{brick->handle,
                    std::numeric_limits<double>::infinity(),
                    to,
                    (to.translation() - from.translation()) / dt,
                    turn.axis() * (turn.angle() / dt),
                    brick->type.restitution};
    if (!striker.spin.allFinite()) striker.spin.setZero();

    std::vector<BodyHandle> near;
    if (w->model) {
      Eigen::Vector3d low, high;
      boundsOf(OrientedBox{to, brick->type.halfExtents()}, w->options.stability.contact_distance,
               &low, &high);
      near = w->dormant.near(low, high);
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
