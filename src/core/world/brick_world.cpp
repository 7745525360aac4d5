#include "brick_stack_sim/core/world/brick_world.h"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <cmath>

#include "bullet/contact_reader.h"
#include "stability/contact_classifier.h"
#include "stability/rest_tracker.h"
#include "stability/stability_registry.h"
#include "util/text_format.h"
#include "world/held_bricks.h"
#include "world/impacts.h"
#include "world/numerical_guard.h"
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

/// Resting contacts stay in Bullet's manifolds when a frozen brick is this
/// much nearer than a mover's reach [m].
constexpr double kColliderMargin = 1e-3;

// --- the stages of a step ------------------------------------------------------

/// Frozen bricks that movers may reach within this step come into Bullet's
/// world, and the model judges the blows before Bullet resolves them.
void prepareFrozenColliders(WorldState* w) {
  // Nothing frozen, nothing to bring: a pile in the air pays nothing here.
  if (w->dormant.size() == 0) return;
  // How far a mover can get within this step. Its own speed is not enough:
  // gravity adds g dt during the step, and a collision inside the step can
  // hand it up to twice the speed of the fastest brick that may hit it. CCD
  // does not help against a body that is not in Bullet's world.
  double fastest = 0.0;
  for (const BrickRecord* mover : w->sets.movers())
    fastest = std::max(fastest, w->fastestPointSpeed(*mover));
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
  w->cost.bullet_stages += w->scene.lastStepStageSeconds();
  ++w->cost.bullet_steps;
  w->cost.awake_brick_steps += step.awake;
  guardMovers(w);
}

/// Stage 2: the touching pairs, with flush faces refined into their exact
/// overlap. Only a brick at rest can join the stack, and only a frozen
/// brick in Bullet's world can bear a mover's load: while every mover is
/// faster than the rest speeds and far from the stack (a pile in the air),
/// nothing is read. A pair's patch is judged only for a brick of it at
/// rest (the loads come from the engine's points): a landing pile's pairs
/// of bricks still tumbling are not clipped.
void readStepContacts(WorldState* w) {
  const StabilityOptions& rest = w->options.stability;
  std::vector<BodyHandle> resting;
  for (const BrickRecord* b : w->sets.movers())
    if (slowerThanRestSpeeds(w->motionOf(*b), rest)) resting.push_back(b->handle);
  if (resting.empty() && w->dormant.inWorld().empty() && w->presses.empty()) {
    w->contacts.clear();
    return;
  }
  std::sort(resting.begin(), resting.end());
  const auto at_rest = [&resting](BodyHandle handle) {
    return std::binary_search(resting.begin(), resting.end(), handle);
  };
  readContacts(w->scene, rest.contact_distance, &w->contacts);
  refineFlushPatches(
      [w](BodyHandle handle) { return w->solidOf(handle); }, rest, &w->contacts,
      [&at_rest](const PairContact& pair) { return at_rest(pair.a) || at_rest(pair.b); });
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

// --- step ------------------------------------------------------------------------

void BrickWorld::step() {
  WorldState& w = *state_;
  judgePlacements();  // bricks placed at one instant stand or fall before Bullet moves them
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

// --- the world ----------------------------------------------------------------

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

double BrickWorld::time() const { return state_->time(); }
const WorldOptions& BrickWorld::options() const { return state_->options; }
const BrickTypeLibrary& BrickWorld::types() const { return state_->types; }
const CostCounters& BrickWorld::cost() const { return state_->cost; }
std::size_t BrickWorld::brickCount() const { return state_->bricks.size(); }

std::vector<SimEvent> BrickWorld::takeEvents() {
  std::vector<SimEvent> events;
  events.swap(state_->events);
  return events;
}

Status BrickWorld::checkInvariants() const {
  return state_->sets.checkInvariants(state_->bricks.records());
}

}  // namespace brick_stack_sim
