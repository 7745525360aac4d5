// BrickWorld's requests: each checks everything first and refuses with the
// world unchanged, then records its change (WorldState::recordChange) and
// makes it.
#include "brick_stack_sim/core/world/brick_world.h"

#include <algorithm>

#include "stability/stability_model.h"
#include "util/text_format.h"
#include "world/placement_check.h"
#include "world/placement_statics.h"
#include "world/world_state.h"

namespace brick_stack_sim {

namespace {

/// Anything whose bounding box comes within this of a removed brick may rest
/// on or lean against it and is woken [m]: a few too many cost a few steps,
/// one missed would float.
constexpr double kTouchingReach = 1e-3;

}  // namespace

Status BrickWorld::checkPlacement(const BrickPlacement& placement) const {
  return brick_stack_sim::checkPlacement(*state_, placement);
}

Status BrickWorld::addBrick(const BrickPlacement& placement, std::string* assigned_id,
                            bool more_to_come) {
  if (Status ok = checkPlacement(placement); !ok) return ok;
  BrickRecord* brick = placeBody(placement);
  if (assigned_id) *assigned_id = brick->id;
  judgeAtRest(brick, placement, more_to_come);
  return Status::success();
}

std::vector<Status> BrickWorld::addBricks(const std::vector<BrickPlacement>& placements,
                                          std::vector<std::string>* assigned_ids) {
  std::vector<Status> statuses;
  if (assigned_ids) assigned_ids->assign(placements.size(), std::string());
  for (std::size_t i = 0; i < placements.size(); ++i)
    statuses.push_back(addBrick(placements[i], assigned_ids ? &(*assigned_ids)[i] : nullptr,
                                i + 1 < placements.size()));
  judgePlacements();
  return statuses;
}

void BrickWorld::judgePlacements() {
  WorldState& w = *state_;
  if (!w.model || !w.judgement_pending) return;
  // What the judgement describes anew (every brick's supports and margin)
  // is a change a reader of snapshotChangedSince() has not seen yet.
  w.recordChange(WorldState::Change::kModel);
  decide(&w, StabilityInput());
}

void BrickWorld::judgeAtRest(BrickRecord* brick, const BrickPlacement& placement,
                             bool more_to_come) {
  WorldState& w = *state_;
  if (!w.model || !placement.linear_velocity.isZero() || !placement.angular_velocity.isZero())
    return;
  Eigen::Vector3d low, high;
  w.scene.bounds(brick->handle, &low, &high);
  StabilityInput input;
  input.placed.push_back(
      {BodyMotion{brick->handle, centreOfMassAt(brick->type, placement.pose), brick->type.mass,
                  Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()},
       restingContacts(w, brick->handle, brick->type.friction, w.solidOf(brick->handle), low,
                       high)});
  input.more_to_come = more_to_come;
  decide(&w, input);
  if (brick->mode == BrickMode::kDynamic) w.placed_at_rest.push_back(brick->handle);
}

BrickRecord* BrickWorld::placeBody(const BrickPlacement& placement) {
  WorldState& w = *state_;
  w.recordChange(WorldState::Change::kModel);
  auto record = std::make_unique<BrickRecord>();
  record->id = placement.id.empty() ? w.bricks.freeId(w.next_serial) : placement.id;
  record->type = *w.types.find(placement.type.empty() ? w.types.defaultType() : placement.type);
  record->handle = w.next_serial++;
  record->placed_pose = placement.pose;
  record->placed_at = w.time();
  w.scene.addBrick(record->handle, record->type, placement);
  record->last_good_pose = w.scene.pose(record->handle);
  BrickRecord* brick = w.bricks.add(std::move(record));
  w.emit(SimEventKind::kSpawned, brick->id,
         "placed as '" + brick->type.name + "' at " + formatVector(placement.pose.translation()));
  w.sets.enter(brick);
  return brick;
}

Status BrickWorld::removeBrick(const std::string& id) {
  return remove(id, SimEventKind::kRemoved, "removed by request");
}

Status BrickWorld::remove(const std::string& id, SimEventKind kind, const std::string& reason) {
  WorldState& w = *state_;
  BrickRecord* brick = w.bricks.find(id);
  if (!brick) return Status::error("no brick with id " + quotedId(id));
  w.recordChange(WorldState::Change::kBodies);
  StabilityInput input;
  input.removed.push_back(brick->handle);
  std::vector<std::string> woken;
  for (const WakeDecision& d : decide(&w, input).wake) woken.push_back(w.nameOf(d.brick));
  // Bullet's sleeping movers that rested on it are not the model's to wake.
  Eigen::Vector3d low, high;
  w.scene.bounds(brick->handle, &low, &high);
  const Eigen::AlignedBox3d reach(low.array() - kTouchingReach, high.array() + kTouchingReach);
  for (const BrickRecord* other : w.sets.movers()) {
    if (other == brick) continue;
    Eigen::Vector3d other_low, other_high;
    w.scene.bounds(other->handle, &other_low, &other_high);
    if (!reach.intersects(Eigen::AlignedBox3d(other_low, other_high))) continue;
    if (!w.scene.isActive(other->handle) &&
        std::find(woken.begin(), woken.end(), other->id) == woken.end())
      woken.push_back(other->id);
    w.scene.activate(other->handle);
  }
  w.sets.leave(brick);
  w.placed_at_rest.erase(
      std::remove(w.placed_at_rest.begin(), w.placed_at_rest.end(), brick->handle),
      w.placed_at_rest.end());
  w.scene.removeBrick(brick->handle);
  w.bricks.erase(brick);
  if (kind == SimEventKind::kLost) ++w.cost.lost;
  w.emit(kind, id, reason, std::move(woken));
  return Status::success();
}

Status BrickWorld::applyImpulse(const std::string& id, const Eigen::Vector3d& impulse,
                                const Eigen::Vector3d& point) {
  WorldState& w = *state_;
  BrickRecord* brick = w.bricks.find(id);
  if (!brick) return Status::error("no brick with id " + quotedId(id));
  if (!impulse.allFinite()) return Status::error("impulse is not finite");
  if (!point.allFinite()) return Status::error("point of application is not finite");
  if (brick->mode == BrickMode::kHeld)
    return Status::error("brick " + quotedId(id) + " is held: move it through the held target");
  const BodyHandle h = brick->handle;
  const double outside = (point - nearestPointIn(w.solidOf(h), point)).norm();
  if (outside > kPushPointTolerance)
    return Status::error("point of application " + formatVector(point) + " is " +
                         millimetres(outside) + " outside brick " + quotedId(id) + " (at most " +
                         millimetres(kPushPointTolerance) + ")");
  // The speeds the push leaves the brick with, before Bullet sees it: a push
  // that would launch it past the placement limits is refused, not repaired.
  const Eigen::Vector3d lever = point - w.scene.centreOfMass(h);
  // The principal axes turn with the brick: its pose times its mass frame's.
  const Eigen::Matrix3d rotation = w.scene.pose(h).linear() * brick->type.mass_frame.linear();
  const Eigen::Matrix3d inverse_inertia =
      rotation * brick->type.inertia.cwiseInverse().asDiagonal() * rotation.transpose();
  const bool frozen = isFrozen(brick->mode);
  const Eigen::Vector3d velocity =
      (frozen ? Eigen::Vector3d::Zero() : w.scene.linearVelocity(h)) + impulse / brick->type.mass;
  const Eigen::Vector3d spin = (frozen ? Eigen::Vector3d::Zero() : w.scene.angularVelocity(h)) +
                               inverse_inertia * lever.cross(impulse);
  if (velocity.norm() > w.options.max_linear_speed)
    return Status::error("impulse would leave the brick at " + formatNumber(velocity.norm()) +
                         " m/s, over the limit of " + formatNumber(w.options.max_linear_speed) +
                         " m/s");
  if (spin.norm() > w.options.max_angular_speed)
    return Status::error("impulse would leave the brick spinning at " + formatNumber(spin.norm()) +
                         " rad/s, over the limit of " + formatNumber(w.options.max_angular_speed) +
                         " rad/s");
  w.recordChange(WorldState::Change::kBricks);
  if (frozen) {
    StabilityInput input;
    input.pushed.push_back(h);
    decide(&w, input);
  }
  w.scene.activate(h);
  w.scene.applyImpulse(h, impulse, point);
  return Status::success();
}

Status BrickWorld::graspBrick(const std::string& id) {
  WorldState& w = *state_;
  BrickRecord* brick = w.bricks.find(id);
  if (!brick) return Status::error("no brick with id " + quotedId(id));
  if (!w.sets.held().empty())
    return Status::error("brick '" + w.sets.held().front()->id +
                         "' is already held: release it first (one brick at a time)");
  if (w.model) {
    std::vector<std::string> carried;
    for (BodyHandle upper : w.model->carriedBy(brick->handle)) carried.push_back(w.nameOf(upper));
    if (!carried.empty())
      return Status::error("brick " + quotedId(id) + " carries " + joinNames(carried) +
                           ": grasp or remove what rests on it first");
  }
  w.recordChange(WorldState::Change::kBodies);
  StabilityInput input;
  input.grasped.push_back(brick->handle);
  std::vector<std::string> woken;
  for (const WakeDecision& d : decide(&w, input).wake) woken.push_back(w.nameOf(d.brick));
  w.placed_at_rest.erase(
      std::remove(w.placed_at_rest.begin(), w.placed_at_rest.end(), brick->handle),
      w.placed_at_rest.end());
  w.sets.transfer(brick, BrickMode::kHeld);
  brick->held_target = w.scene.pose(brick->handle);
  w.emit(SimEventKind::kGrasped, id, "held at " + formatVector(brick->held_target.translation()),
         std::move(woken));
  return Status::success();
}

Status BrickWorld::setHeldTarget(const Eigen::Isometry3d& target) {
  WorldState& w = *state_;
  if (w.sets.held().empty()) return Status::error("no brick is held: grasp one first");
  BrickRecord* brick = w.sets.held().front();
  if (Status pose = checkPose(w, target, brick->type, "target "); !pose) return pose;
  w.recordChange(WorldState::Change::kBricks);
  brick->held_target = target;
  return Status::success();
}

std::string BrickWorld::heldBrick() const {
  return state_->sets.held().empty() ? std::string() : state_->sets.held().front()->id;
}

Status BrickWorld::releaseBrick(const std::string& id, const Eigen::Vector3d& linear_velocity,
                                const Eigen::Vector3d& angular_velocity) {
  WorldState& w = *state_;
  BrickRecord* brick = w.bricks.find(id);
  if (!brick) return Status::error("no brick with id " + quotedId(id));
  if (brick->mode != BrickMode::kHeld)
    return Status::error("brick " + quotedId(id) + " is not held");
  if (Status velocity = checkVelocity(w, linear_velocity, angular_velocity, "release "); !velocity)
    return velocity;
  w.recordChange(WorldState::Change::kBodies);
  w.sets.transfer(brick, BrickMode::kDynamic);
  w.scene.setVelocity(brick->handle, linear_velocity, angular_velocity);
  w.emit(SimEventKind::kReleased, id,
         "let go at " + formatVector(w.scene.pose(brick->handle).translation()) + " moving at " +
             formatVector(linear_velocity) + " m/s");
  return Status::success();
}

Status BrickWorld::evaluatePlacement(const BrickPlacement& placement,
                                     PlacementReport* report) const {
  const WorldState& w = *state_;
  if (Status ok = checkPlacement(placement); !ok) return ok;
  const BrickType& type =
      *w.types.find(placement.type.empty() ? w.types.defaultType() : placement.type);
  const PlacedSolid box = type.placed(placement.pose);
  const Eigen::AlignedBox3d extent = bounds(box);
  // A handle no brick has yet: the one this brick would get.
  const BodyHandle handle = w.next_serial;
  const BodyMotion brick{handle, centreOfMassAt(type, placement.pose), type.mass,
                         Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  PlacementReport result;
  const StaticsVerdict statics = judgeAlone(
      brick, touchingBricks(w, handle, type.friction, box, extent.min(), extent.max()), w);
  result.stable = statics.stands;
  result.state = statics.stands ? statics.kind : BrickState::kDynamic;
  result.margin = statics.margin;
  result.acceleration_margin = statics.acceleration_margin;
  for (BodyHandle supporter : statics.touching) result.supported_by.push_back(w.nameOf(supporter));
  result.reason = statics.reason;
  if (statics.stands && w.model) {
    // Its load on the frozen stack below, as the running model sees it.
    const PlacementEvaluation evaluation = w.model->evaluatePlacement(
        brick, restingContacts(w, handle, type.friction, box, extent.min(), extent.max()));
    for (BodyHandle fallen : evaluation.would_fall) result.would_fall.push_back(w.nameOf(fallen));
    if (!result.would_fall.empty()) {
      result.stable = false;
      result.state = BrickState::kDynamic;
      result.reason = evaluation.reason;
    }
  }
  *report = std::move(result);
  return Status::success();
}

}  // namespace brick_stack_sim
