#include "brick_stack_sim/core/world/brick_world.h"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <cmath>

#include "bullet/contact_reader.h"
#include "stability/contact_classifier.h"
#include "stability/rigid_block_statics.h"
#include "stability/stability_registry.h"
#include "util/text_format.h"
#include "world/held_bricks.h"
#include "world/impacts.h"
#include "world/numerical_guard.h"
#include "world/placement_check.h"
#include "world/placement_statics.h"
#include "world/world_state.h"

namespace brick_stack_sim {

namespace {

using Clock = std::chrono::steady_clock;

/// Runs `stage` and adds its wall time to `*seconds`.
template <typename Stage>
void timed(double* seconds, Stage&& stage) {
  const Clock::time_point start = Clock::now();
  stage();
  *seconds += std::chrono::duration<double>(Clock::now() - start).count();
}

/// What the stages of one step share (Box2D's b2StepContext).
struct StepContext {
  std::uint64_t awake = 0;      ///< Movers Bullet has not put to sleep.
  bool advance_bullet = false;  ///< Stage 1 runs.
  bool run_model = false;       ///< Stages 2 to 5 run.
};

/// Anything whose bounding box comes within this of a removed brick may rest
/// on or lean against it and is woken [m]: a few too many cost a few steps,
/// one missed would float.
constexpr double kTouchingReach = 1e-3;
/// Resting contacts stay in Bullet's manifolds when a frozen brick is this
/// much nearer than a mover's reach [m].
constexpr double kColliderMargin = 1e-3;

// --- the stages of a step ------------------------------------------------------

/// Frozen bricks that movers may reach within this step come into Bullet's
/// world, and the model judges the blows before Bullet resolves them.
void prepareFrozenColliders(WorldState* w) {
  // How far a mover can get within this step. Its own speed is not enough:
  // gravity adds g dt during the step, and a collision inside the step can
  // hand it up to twice the speed of the fastest brick that may hit it. CCD
  // does not help against a body that is not in Bullet's world.
  double fastest = 0.0;
  for (const BrickRecord* mover : w->sets.movers()) {
    fastest = std::max(fastest,
                       w->scene.linearSpeed(mover->handle) +
                           w->scene.angularSpeed(mover->handle) * mover->type.halfExtents().norm());
  }
  const double dt = w->options.time_step;
  const double travel = (2.0 * fastest + w->options.gravity * dt) * dt + kColliderMargin;
  std::vector<MoverReach> reaches;
  for (const BrickRecord* mover : w->sets.movers()) reaches.push_back({mover->handle, travel});
  const std::vector<ColliderApproach> near = w->dormant.bringWithinReach(reaches, w->cost.steps);
  w->dormant.sendBackIdle(w->cost.steps);
  strikeFrozenBricks(w, near);
}

/// Stage 1: Bullet advances the awake bricks; the guard repairs NaN and
/// runaway speeds and marks bricks that fell off.
void advanceBullet(WorldState* w, const StepContext& step) {
  moveHeldBricks(w);
  if (w->model) prepareFrozenColliders(w);
  w->scene.step(w->options.time_step);
  ++w->cost.bullet_steps;
  w->cost.awake_brick_steps += step.awake;
  guardMovers(w);
}

/// Stage 2: the touching pairs, with flush faces refined into their exact
/// overlap. Only a brick at rest can join the stack, and only a frozen
/// brick in Bullet's world can bear a mover's load: while every mover is
/// faster than the rest speeds and far from the stack (a pile in the air),
/// nothing is read.
void readStepContacts(WorldState* w) {
  const StabilityOptions& rest = w->options.stability;
  const bool any_resting =
      std::any_of(w->sets.movers().begin(), w->sets.movers().end(), [&](const BrickRecord* b) {
        return w->scene.linearSpeed(b->handle) < rest.rest_linear_speed &&
               w->scene.angularSpeed(b->handle) < rest.rest_angular_speed;
      });
  if (!any_resting && w->dormant.inWorld().empty() && w->presses.empty()) {
    w->contacts.clear();
    return;
  }
  readContacts(w->scene, rest.contact_distance, &w->contacts);
  refineFlushPatches([w](BodyHandle handle) { return w->boxOf(handle); }, rest, &w->contacts);
  w->contacts.insert(w->contacts.end(), w->presses.begin(), w->presses.end());
}

/// Stages 3 to 5: the model updates its support graph from the movers and
/// contacts, judges the components that changed, and the world freezes and
/// wakes what it decides (events are emitted as they are applied).
void runStabilityModel(WorldState* w) {
  StabilityInput input;
  input.dt = w->options.time_step;
  input.gravity = w->options.gravity;
  input.contacts = &w->contacts;
  input.movers.reserve(w->sets.movers().size());
  for (const BrickRecord* brick : w->sets.movers()) input.movers.push_back(w->motionOf(*brick));
  decide(w, input);
  ++w->cost.stability_updates;
}

}  // namespace

// --- the decision path: every call of the model goes through decide() -------

void applyDecisions(WorldState* w, const StabilityDecisions& decisions) {
  // Whatever the model described anew, decisions or not (a brick placed on
  // the stack changes the load on every frozen brick under it).
  if (w->model) {
    for (BodyHandle handle : w->model->takeRedescribed())
      if (BrickRecord* brick = w->bricks.find(handle)) brick->changed_at = w->revision;
  }
  if (decisions.empty()) return;
  // Contacts read before bodies changed hands would name bricks that moved
  // in or out of Bullet's world; the next Bullet step reads them afresh.
  w->contacts.clear();
  w->model_changed = true;
  for (const FreezeDecision& d : decisions.freeze) {
    BrickRecord* brick = w->bricks.find(d.brick);
    if (!brick) continue;
    w->sets.transfer(brick, frozenMode(d.kind));
    brick->changed_at = w->revision;
    w->emit(SimEventKind::kFrozen, brick->id, d.reason);
  }
  for (const WakeDecision& d : decisions.wake) {
    BrickRecord* brick = w->bricks.find(d.brick);
    if (!brick) continue;
    w->sets.transfer(brick, BrickMode::kDynamic);
    brick->changed_at = w->revision;
    if (d.repeats) ++w->cost.wake_cycles;
    w->emit(SimEventKind::kWoken, brick->id, d.reason);
  }
}

/// Hands `input` to the model and applies what it decides; returns the
/// decisions (empty without a model).
StabilityDecisions decide(WorldState* w, const StabilityInput& input) {
  StabilityDecisions decisions;
  if (!w->model) return decisions;
  w->model->decide(input, &decisions);
  applyDecisions(w, decisions);
  return decisions;
}

// --- step ------------------------------------------------------------------------

void BrickWorld::step() {
  WorldState& w = *state_;
  StepContext step;
  for (const BrickRecord* brick : w.sets.movers()) step.awake += w.scene.isActive(brick->handle);
  ++w.cost.steps;
  w.placed_at_rest.clear();
  // Plain Bullet (mode none) is the baseline and always steps; with a model,
  // a world where nothing is awake has nothing for Bullet to do.
  // A held brick moves, and pushes what it touches, only in Bullet's steps.
  step.advance_bullet = !w.model || step.awake > 0 || !w.sets.held().empty();
  // Nothing moved and nothing is pending: the model would find what it found.
  step.run_model = w.model && (step.advance_bullet || w.model_changed);
  // A step that neither moves Bullet nor runs the model changes no brick:
  // a publisher of a settled world then finds nothing to look at.
  if (step.advance_bullet || step.run_model) ++w.revision;

  // 1. Advance Bullet for the awake bricks.
  if (step.advance_bullet) timed(&w.cost.bullet_seconds, [&] { advanceBullet(&w, step); });
  // Before the model reads contacts: a lost brick is no longer in the world.
  std::vector<std::pair<std::string, std::string>> left_world;
  left_world.swap(w.left_world);
  for (const auto& [id, reason] : left_world) remove(id, SimEventKind::kLost, reason);
  if (step.run_model) {
    w.model_changed = false;
    // 2. Read contacts: only after a Bullet step (a model that runs without
    //    one looks at the contacts it already has).
    if (step.advance_bullet) timed(&w.cost.contact_seconds, [&] { readStepContacts(&w); });
    // 3.-5. Support graph, judgement of changed components, freeze / wake.
    timed(&w.cost.stability_seconds, [&] { runStabilityModel(&w); });
  }
  // 6. Events were emitted by the stages; takeEvents() hands them out.
  assert(checkInvariants().ok);
}

bool BrickWorld::settled() const {
  const WorldState& w = *state_;
  if (!w.model || w.model_changed || !w.sets.held().empty()) return false;
  return std::none_of(w.sets.movers().begin(), w.sets.movers().end(),
                      [&w](const BrickRecord* brick) { return w.scene.isActive(brick->handle); });
}

// --- requests --------------------------------------------------------------------

BrickWorld::BrickWorld(std::unique_ptr<WorldState> state) : state_(std::move(state)) {}
BrickWorld::~BrickWorld() = default;

Status BrickWorld::create(const WorldOptions& options, const BrickTypeLibrary& types,
                          std::unique_ptr<BrickWorld>* world, double start_time) {
  world->reset();
  if (Status valid = validate(options); !valid) return valid;
  if (!std::isfinite(start_time) || start_time < 0.0)
    return Status::error("start time must be finite and >= 0 s");
  if (types.empty()) return Status::error("no brick types: a world needs at least one");
  for (const std::string& name : types.names()) {
    if (Status valid = validateBrickType(*types.find(name)); !valid) return valid;
  }
  auto state = std::make_unique<WorldState>(options, types, start_time);
  WorldState* w = state.get();
  state->model =
      createStabilityModel(options.stability, [w](BodyHandle handle) { return w->nameOf(handle); });
  world->reset(new BrickWorld(std::move(state)));
  return Status::success();
}

Status BrickWorld::checkPlacement(const BrickPlacement& placement) const {
  return brick_stack_sim::checkPlacement(*state_, placement);
}

Status BrickWorld::addBrick(const BrickPlacement& placement, std::string* assigned_id) {
  if (Status ok = checkPlacement(placement); !ok) return ok;
  WorldState& w = *state_;
  ++w.revision;
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
  if (assigned_id) *assigned_id = brick->id;
  w.model_changed = true;
  w.sets.enter(brick);
  if (w.model && placement.linear_velocity.isZero() && placement.angular_velocity.isZero()) {
    Eigen::Vector3d low, high;
    w.scene.bounds(brick->handle, &low, &high);
    StabilityInput input;
    input.placed.push_back(
        {BodyMotion{brick->handle, placement.pose.translation(), brick->type.mass,
                    Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()},
         restingContacts(w, brick->handle, brick->type.friction, w.boxOf(brick->handle), low,
                         high)});
    decide(&w, input);
    if (brick->mode == BrickMode::kDynamic) w.placed_at_rest.push_back(brick->handle);
  }
  return Status::success();
}

Status BrickWorld::removeBrick(const std::string& id) {
  return remove(id, SimEventKind::kRemoved, "removed by request");
}

Status BrickWorld::remove(const std::string& id, SimEventKind kind, const std::string& reason) {
  WorldState& w = *state_;
  ++w.revision;
  BrickRecord* brick = w.bricks.find(id);
  if (!brick) return Status::error("no brick with id " + quotedId(id));
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
  w.contacts.clear();
  w.model_changed = true;
  w.bricks.erase(brick);
  if (kind == SimEventKind::kLost) ++w.cost.lost;
  w.emit(kind, id, reason, std::move(woken));
  return Status::success();
}

Status BrickWorld::applyImpulse(const std::string& id, const Eigen::Vector3d& impulse,
                                const Eigen::Vector3d& point) {
  WorldState& w = *state_;
  ++w.revision;
  BrickRecord* brick = w.bricks.find(id);
  if (!brick) return Status::error("no brick with id " + quotedId(id));
  if (!impulse.allFinite()) return Status::error("impulse is not finite");
  if (!point.allFinite()) return Status::error("point of application is not finite");
  if (brick->mode == BrickMode::kHeld)
    return Status::error("brick " + quotedId(id) + " is held: move it through the held target");
  const BodyHandle h = brick->handle;
  const double outside = (point - nearestPointIn(w.boxOf(h), point)).norm();
  if (outside > kPushPointTolerance)
    return Status::error("point of application " + formatVector(point) + " is " +
                         millimetres(outside) + " outside brick " + quotedId(id) + " (at most " +
                         millimetres(kPushPointTolerance) + ")");
  // The speeds the push leaves the brick with, before Bullet sees it: a push
  // that would launch it past the placement limits is refused, not repaired.
  const Eigen::Vector3d lever = point - w.scene.centreOfMass(h);
  const Eigen::Matrix3d rotation = w.scene.pose(h).linear();
  const Eigen::Matrix3d inverse_inertia =
      rotation * brick->type.inertia.cwiseInverse().asDiagonal() * rotation.transpose();
  const bool frozen = isFrozen(brick->mode);
  const Eigen::Vector3d velocity =
      (frozen ? Eigen::Vector3d::Zero() : w.scene.linearVelocity(h)) + impulse / brick->type.mass;
  const Eigen::Vector3d spin = (frozen ? Eigen::Vector3d::Zero() : w.scene.angularVelocity(h)) +
                               inverse_inertia * lever.cross(impulse);
  if (velocity.norm() > w.options.max_linear_speed)
    return Status::error("impulse would leave the brick at " + std::to_string(velocity.norm()) +
                         " m/s, over the limit of " + std::to_string(w.options.max_linear_speed));
  if (spin.norm() > w.options.max_angular_speed)
    return Status::error("impulse would leave the brick spinning at " +
                         std::to_string(spin.norm()) + " rad/s, over the limit of " +
                         std::to_string(w.options.max_angular_speed));
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
  ++w.revision;
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
  StabilityInput input;
  input.grasped.push_back(brick->handle);
  std::vector<std::string> woken;
  for (const WakeDecision& d : decide(&w, input).wake) woken.push_back(w.nameOf(d.brick));
  w.placed_at_rest.erase(
      std::remove(w.placed_at_rest.begin(), w.placed_at_rest.end(), brick->handle),
      w.placed_at_rest.end());
  w.sets.transfer(brick, BrickMode::kHeld);
  brick->held_target = w.scene.pose(brick->handle);
  w.contacts.clear();
  w.model_changed = true;
  w.emit(SimEventKind::kGrasped, id, "held at " + formatVector(brick->held_target.translation()),
         std::move(woken));
  return Status::success();
}

Status BrickWorld::setHeldTarget(const Eigen::Isometry3d& target) {
  WorldState& w = *state_;
  ++w.revision;
  if (w.sets.held().empty()) return Status::error("no brick is held: grasp one first");
  BrickRecord* brick = w.sets.held().front();
  if (Status pose = checkPose(w, target, brick->type.halfExtents(), "target "); !pose) return pose;
  brick->held_target = target;
  return Status::success();
}

std::string BrickWorld::heldBrick() const {
  return state_->sets.held().empty() ? std::string() : state_->sets.held().front()->id;
}

Status BrickWorld::releaseBrick(const std::string& id, const Eigen::Vector3d& linear_velocity,
                                const Eigen::Vector3d& angular_velocity) {
  WorldState& w = *state_;
  ++w.revision;
  BrickRecord* brick = w.bricks.find(id);
  if (!brick) return Status::error("no brick with id " + quotedId(id));
  if (brick->mode != BrickMode::kHeld)
    return Status::error("brick " + quotedId(id) + " is not held");
  if (Status velocity = checkVelocity(w, linear_velocity, angular_velocity, "release "); !velocity)
    return velocity;
  w.sets.transfer(brick, BrickMode::kDynamic);
  w.scene.setVelocity(brick->handle, linear_velocity, angular_velocity);
  w.contacts.clear();
  w.model_changed = true;
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
  const OrientedBox box{placement.pose, type.halfExtents()};
  const Eigen::AlignedBox3d extent = bounds(box);
  // A handle no brick has yet: the one this brick would get.
  const BodyHandle handle = w.next_serial;
  const BodyMotion brick{handle, placement.pose.translation(), type.mass, Eigen::Vector3d::Zero(),
                         Eigen::Vector3d::Zero()};
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

// --- state -----------------------------------------------------------------------

double BrickWorld::time() const { return state_->time(); }
const WorldOptions& BrickWorld::options() const { return state_->options; }
const BrickTypeLibrary& BrickWorld::types() const { return state_->types; }
const CostCounters& BrickWorld::cost() const { return state_->cost; }
std::size_t BrickWorld::brickCount() const { return state_->bricks.size(); }

namespace {

BrickSnapshot snapshotOf(const WorldState& w, const BrickRecord& brick) {
  BrickSnapshot s;
  s.id = brick.id;
  s.type = brick.type.name;
  s.pose = w.scene.pose(brick.handle);
  s.linear_velocity = w.scene.linearVelocity(brick.handle);
  s.angular_velocity = w.scene.angularVelocity(brick.handle);
  s.size = brick.type.size;
  s.mass = brick.type.mass;
  s.state = toState(brick.mode);
  s.asleep = brick.mode == BrickMode::kDynamic && !w.scene.isActive(brick.handle);
  s.fell_off = brick.fell_off;
  // Without a stability model a brick carries only itself.
  s.com_above = s.pose.translation();
  s.mass_above = s.mass;
  BrickStability stability;
  if (w.model && w.model->describe(brick.handle, &stability)) {
    s.com_above = stability.com_above;
    s.mass_above = stability.mass_above;
    s.margin = stability.margin;
    for (const SupportPatch& patch : stability.supports)
      s.supported_by.push_back(w.nameOf(patch.supporter));
  }
  s.placed_pose = brick.placed_pose;
  s.placed_at = brick.placed_at;
  s.serial = brick.handle;
  return s;
}

}  // namespace

std::vector<BrickSnapshot> BrickWorld::snapshot() const {
  std::vector<BrickSnapshot> result;
  result.reserve(state_->bricks.size());
  for (const auto& brick : state_->bricks.all()) result.push_back(snapshotOf(*state_, *brick));
  return result;
}

std::uint64_t BrickWorld::revision() const { return state_->revision; }

std::vector<BrickSnapshot> BrickWorld::snapshotChangedSince(std::uint64_t revision,
                                                            std::vector<unsigned>* serials) const {
  const WorldState& w = *state_;
  std::vector<BrickSnapshot> changed;
  if (serials) {
    serials->clear();
    serials->reserve(w.bricks.size());
  }
  // A mover may have moved in any step; a frozen brick has not, unless it
  // was frozen, or described anew, since.
  const bool anything = w.revision > revision;
  for (const auto& brick : w.bricks.all()) {
    if (serials) serials->push_back(brick->handle);
    if (isFrozen(brick->mode) ? brick->changed_at > revision : anything)
      changed.push_back(snapshotOf(w, *brick));
  }
  return changed;
}

bool BrickWorld::find(const std::string& id, BrickSnapshot* brick) const {
  const BrickRecord* found = state_->bricks.find(id);
  if (!found) return false;
  if (brick) *brick = snapshotOf(*state_, *found);
  return true;
}

bool BrickWorld::supportGeometry(const std::string& id, SupportGeometry* geometry) const {
  const WorldState& w = *state_;
  const BrickRecord* found = w.bricks.find(id);
  BrickStability stability;
  if (!found || !w.model || !w.model->describe(found->handle, &stability)) return false;
  SupportGeometry result;
  for (const SupportPatch& patch : stability.supports) {
    SupportGeometry::Patch out;
    out.supporter = w.nameOf(patch.supporter);
    for (const Eigen::Vector2d& corner : patch.hull)
      out.polygon.emplace_back(corner.x(), corner.y(), patch.height);
    result.patches.push_back(std::move(out));
  }
  for (const Eigen::Vector2d& corner : stability.combined_hull)
    result.combined_hull.emplace_back(corner.x(), corner.y(), stability.support_height);
  result.com_above = stability.com_above;
  result.margin = stability.margin;
  // Statics balances weights in its own g; forces scale with the world's.
  const double to_world_gravity = w.options.gravity / StaticsOptions().gravity;
  for (const ContactForce& force : stability.contact_forces)
    result.contact_forces.push_back(
        SupportGeometry::ContactForce{w.nameOf(force.other), force.point, force.normal,
                                      to_world_gravity * force.force, force.friction});
  *geometry = std::move(result);
  return true;
}

std::vector<SimEvent> BrickWorld::takeEvents() {
  std::vector<SimEvent> events;
  events.swap(state_->events);
  return events;
}

Status BrickWorld::checkInvariants() const {
  return state_->sets.checkInvariants(state_->bricks.records());
}

}  // namespace brick_stack_sim
