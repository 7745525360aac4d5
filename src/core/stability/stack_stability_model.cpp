#include "stability/stack_stability_model.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "stability/contact_classifier.h"
#include "stability/impact_rule.h"
#include "stability/statics_assembly.h"
#include "stability/support_evaluation.h"
#include "util/text_format.h"

namespace brick_stack_sim {

namespace {

/// A measured load changes what a frozen brick bears when its total force
/// or moment moves by more than this fraction of the brick's weight (and of
/// its weight times a millimetre): loads of bricks at rest jitter far less,
/// and a check per step for nothing would cost a tower its settled price.
constexpr double kLoadChange = 0.01;
constexpr double kLoadLever = 1e-3;  ///< [m]
/// A brick moving across a frozen one changes its load a little every
/// step; judging the component again each step costs a statics LP a step
/// for a leaning one. A change is taken into its statics at most once in
/// this many steps, unless it is this large (a brick landing, a hand
/// pressing) or the load went.
constexpr std::uint64_t kLoadRejudgeSteps = 10;
constexpr double kLoadJump = 0.25;
/// A brick the model woke has moved once its centre of mass is this far
/// from where it was woken [m]: a brick held where it is moves a few
/// micrometres, one that tipped or slid a visible distance.
constexpr double kMovedAway = 1e-3;
/// A brick that has not moved since the model woke it freezes again only
/// when statics holds with every measured load this much larger [-]: the
/// loads of moving bricks jitter, and statics at its limit would wake it
/// again at the next jitter.
constexpr double kRefreezeLoadFactor = 1.1;

/// The total force and its moment about `about` of `loads`.
std::pair<Eigen::Vector3d, Eigen::Vector3d> resultantOf(const std::vector<PointForce>& loads,
                                                        const Eigen::Vector3d& about) {
  Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
  for (const PointForce& load : loads) {
    force += load.force;
    moment += (load.point - about).cross(load.force);
  }
  return {force, moment};
}

/// How much the loads on a brick changed: the larger of the change of
/// their force over its weight and of their moment over its weight times
/// kLoadLever [-].
double loadChange(const std::vector<PointForce>& before, const std::vector<PointForce>& now,
                  const Eigen::Vector3d& com, double weight) {
  const auto [force_before, moment_before] = resultantOf(before, com);
  const auto [force_now, moment_now] = resultantOf(now, com);
  return std::max((force_now - force_before).norm() / weight,
                  (moment_now - moment_before).norm() / (weight * kLoadLever));
}

}  // namespace

void StackStabilityModel::join(SupportGraph* graph, const BodyMotion& body, bool leaning,
                               BrickStability stability, const StabilityOptions& options) {
  std::vector<SupportPatch> side_contacts, carried;
  for (SupportPatch& patch : stability.side_contacts)
    (leansOn(patch, options) || !graph->contains(patch.supporter) ? side_contacts : carried)
        .push_back(std::move(patch));
  graph->add(body.handle, body.com, body.mass, std::move(stability.supports),
             std::move(side_contacts), leaning);
  graph->find(body.handle)->stability.external_loads = std::move(stability.external_loads);
  for (SupportPatch& patch : carried) graph->addCarried(body.handle, std::move(patch));
}

StackStabilityModel::StackStabilityModel(const StabilityOptions& options, BodyNamer name_of,
                                         std::unique_ptr<StabilityCriterion> criterion)
    : options_(options),
      name_of_(std::move(name_of)),
      criterion_(std::move(criterion)),
      rest_(options) {}

StackStabilityModel::StackStabilityModel(const StackStabilityModel& other, BodyNamer name_of)
    : options_(other.options_),
      name_of_(name_of),
      criterion_(other.criterion_->clone(std::move(name_of))),
      graph_(other.graph_),
      rest_(other.rest_),
      loads_(other.loads_),
      resting_(other.resting_),
      steps_(other.steps_),
      loads_judged_at_(other.loads_judged_at_),
      unjudged_(other.unjudged_),
      touched_by_(other.touched_by_) {}

std::unique_ptr<StabilityModel> StackStabilityModel::clone(BodyNamer name_of) const {
  return std::unique_ptr<StabilityModel>(new StackStabilityModel(*this, std::move(name_of)));
}

void StackStabilityModel::decide(const StabilityInput& input, StabilityDecisions* decisions) {
  // Bullet has moved them: what was placed at rest is no longer where it was.
  if (input.dt > 0.0) {
    unjudged_.clear();
    touched_by_.clear();
  }
  for (BodyHandle removed : input.removed) forget(removed, "removed", decisions);
  for (BodyHandle grasped : input.grasped) forget(grasped, "grasped", decisions);
  for (const RestingPlacement& slid : input.slid) slide(slid, decisions);
  for (BodyHandle pushed : input.pushed) {
    if (graph_.contains(pushed))
      wakeWithLoad(WakeDecision{pushed, WakeCause::kPushed, pushed, 0.0, "pushed"}, &graph_, &rest_,
                   decisions);
  }
  for (const RestingPlacement& placed : input.placed) placeAtRest(placed, decisions);
  if (input.dt > 0.0) ++steps_;
  if (input.dt > 0.0 && input.contacts) measureLoads(input);
  advanceMovers(input, decisions);
  applyLoads();
  if (!input.more_to_come) settle(&graph_, &rest_, decisions, input.contacts ? &input : nullptr);
}

bool StackStabilityModel::wokenInPlace(const BodyMotion& body) const {
  const RestTracker::Mover* mover = rest_.find(body.handle);
  return mover && mover->woken && (body.com - mover->woken_at).norm() < kMovedAway;
}

bool StackStabilityModel::moves(BodyHandle body) const {
  return !std::binary_search(resting_.begin(), resting_.end(), body);
}

bool StackStabilityModel::pressedByAMover(BodyHandle brick) const {
  return !loads_.on(brick, [this](BodyHandle source) { return moves(source); }).empty();
}

bool StackStabilityModel::pressedByMovers(const SupportGraph& what_if) const {
  for (BodyHandle brick : what_if.bricks())
    if (pressedByAMover(brick)) return true;
  return false;
}

void StackStabilityModel::unloadJoiners(SupportGraph* what_if,
                                        const std::vector<BodyHandle>& joiners) const {
  const auto joins = [&](BodyHandle source) {
    return std::binary_search(joiners.begin(), joiners.end(), source);
  };
  const auto stays_out = [&](BodyHandle source) { return !joins(source); };
  for (BodyHandle brick : what_if->bricks()) {
    if (loads_.on(brick, joins).empty()) continue;
    what_if->find(brick)->stability.external_loads = loads_.on(brick, stays_out);
  }
}

void StackStabilityModel::measureLoads(const StabilityInput& input) {
  resting_.clear();
  for (const BodyMotion& body : input.movers)
    if (rest_.atRest(body)) resting_.push_back(body.handle);
  std::sort(resting_.begin(), resting_.end());
  const int window = static_cast<int>(std::lround(options_.rest_time / input.dt));
  loads_.record(
      *input.contacts, input.dt, window, StaticsOptions().gravity / input.gravity,
      [&](BodyHandle brick) {
        return graph_.contains(brick) ||
               std::binary_search(resting_.begin(), resting_.end(), brick);
      },
      [&](BodyHandle body) { return !graph_.canSupport(body); });
}

void StackStabilityModel::applyLoads() {
  for (BodyHandle brick : loads_.takeTouched()) {
    SupportGraph::Node* node = graph_.find(brick);
    if (!node) {
      loads_judged_at_.erase(brick);
      continue;
    }
    std::vector<PointForce> loads = loads_.on(brick);
    const double change = loadChange(node->stability.external_loads, loads, node->com,
                                     node->mass * StaticsOptions().gravity);
    if (!(change > kLoadChange)) continue;
    auto judged = loads_judged_at_.find(brick);
    if (judged != loads_judged_at_.end() && steps_ < judged->second + kLoadRejudgeSteps &&
        change < kLoadJump && !loads.empty())
      continue;  // in a few steps; touched again while its load is measured
    loads_judged_at_[brick] = steps_;
    node->stability.external_loads = std::move(loads);
    graph_.touch(brick);
  }
}

void StackStabilityModel::forget(BodyHandle brick, const char* what_happened,
                                 StabilityDecisions* decisions) {
  rest_.erase(brick);
  unjudged_.erase(brick);
  touched_by_.erase(brick);
  loads_.forget(brick);
  for (BodyHandle upper : graph_.erase(brick)) {
    wakeWithLoad(WakeDecision{upper, WakeCause::kSupporterRemoved, brick, 0.0,
                              "its supporter " + name_of_(brick) + " was " + what_happened},
                 &graph_, &rest_, decisions);
  }
}

void StackStabilityModel::advanceMovers(const StabilityInput& input,
                                        StabilityDecisions* decisions) {
  const ContactIndex index(input.contacts);
  std::vector<const BodyMotion*> resting;
  // At the shared tick the bricks at rest now whose window has not filled
  // yet may join a group too: in a settling pile some plank always crosses
  // the rest speeds somewhere, and a group judged without the planks that
  // prop it is refused (of 687 planks asked, 584 moved in the mechanism;
  // with them, 731 stood). Alone they wait for their window.
  std::vector<const BodyMotion*> props;
  const bool shared_tick = atSharedTick(input.dt);
  for (const BodyMotion& body : input.movers) {
    RestTracker::Mover& mover = rest_.advance(body, input.dt);
    mover.stability = BrickStability();
    mover.stability.mass_above = body.mass;
    // A moving brick cannot join the stack; its supports are not worth a hull.
    if (rest_.atRest(body))
      mover.stability.supports =
          supportPatches(body, index.of(body.handle), frozenOrGround(graph_), options_);
    criterion_->evaluate(body, &mover.stability);
    if (mover.rest_time >= std::max(options_.rest_time, mover.next_judgement))
      resting.push_back(&body);
    else if (shared_tick && mover.rest_time > 0.0)
      props.push_back(&body);
  }
  // A brick at rest on one that freezes now may freeze in the same step: a
  // stack placed at once joins from the bottom up without a step per layer.
  for (bool froze = true; froze;) {
    froze = false;
    for (const BodyMotion*& body : resting) {
      if (!body) continue;
      RestTracker::Mover& mover = rest_.record(body->handle);
      BrickStability& stability = mover.stability;
      FreezeDecision decision;
      if (!evaluateMover(*body, index.of(body->handle), &stability, &decision)) continue;
      const bool in_place = wokenInPlace(*body);
      if (in_place && !standsWithMargin(*body, stability, decision)) {
        // Where statics woke it, it waits for what changed to show: another
        // rest window, then statics is asked again.
        mover.rest_time = 0.0;
        continue;
      }
      freeze(*body, std::move(decision), stability, decisions);
      body = nullptr;
      froze = true;
    }
  }
  admitRestingGroups(index, &resting, props, decisions);
  // What was refused is asked again at a tick shared by every mover.
  const double wait = untilSharedTick(input.dt);
  for (const BodyMotion* body : resting) {
    if (!body) continue;
    RestTracker::Mover& mover = rest_.record(body->handle);
    mover.next_judgement = mover.rest_time + wait;
  }
}

std::uint64_t StackStabilityModel::restWindowSteps(double dt) const {
  return std::max<std::uint64_t>(1,
                                 static_cast<std::uint64_t>(std::llround(options_.rest_time / dt)));
}

bool StackStabilityModel::atSharedTick(double dt) const {
  return dt > 0.0 && steps_ % (2 * restWindowSteps(dt)) == 0;
}

double StackStabilityModel::untilSharedTick(double dt) const {
  // One to three rest windows on, at a tick of the model's clock shared by
  // every mover: bricks that only stand together are then due together,
  // and their group is judged. On clocks of their own they were refused
  // one by one for ever; on ticks one window apart, asked every other one,
  // bricks first refused in odd and even windows never met.
  if (!(dt > 0.0)) return options_.rest_time;
  const std::uint64_t window = restWindowSteps(dt);
  const std::uint64_t period = 2 * window;
  const std::uint64_t tick = ((steps_ + window) / period + 1) * period;
  // Half a step short, so that sums of dt that round differently still
  // fall due in the tick's step.
  return (static_cast<double>(tick - steps_) - 0.5) * dt;
}

void StackStabilityModel::freeze(const BodyMotion& body, FreezeDecision decision,
                                 BrickStability stability, StabilityDecisions* decisions) {
  const bool in_place = wokenInPlace(body);
  join(&graph_, body, decision.kind == BrickState::kLeaning, std::move(stability), options_);
  // Woken again, it is a wake/refreeze cycle.
  graph_.find(body.handle)->refrozen_in_place = in_place;
  rest_.erase(body.handle);
  // Its weight now passes through the stack, not through the engine.
  loads_.forgetSource(body.handle);
  decisions->freeze.push_back(std::move(decision));
}

bool StackStabilityModel::standsWithMargin(const BodyMotion& body, const BrickStability& stability,
                                           const FreezeDecision& decision) const {
  // Exact statics in every mode: the COM rule may pass what statics woke;
  // with every load measured on it, those of bricks at rest on it too
  // (frozen, it will bear them). While a brick that moves still presses
  // on what it would join, what statics says now may not hold a step on.
  BrickStability loaded = stability;
  loaded.external_loads = loads_.on(body.handle);
  SupportGraph what_if = joinedCopy(body, loaded, decision);
  unloadJoiners(&what_if, {body.handle});
  if (pressedByMovers(what_if)) return false;
  const StaticsSolution solution =
      assembleStatics(what_if, what_if.bricks(), options_, kRefreezeLoadFactor).solve();
  return solution.solved && solution.feasible;
}

SupportGraph StackStabilityModel::joinedCopy(const BodyMotion& body,
                                             const BrickStability& stability,
                                             const FreezeDecision& decision) const {
  SupportGraph what_if = graph_.componentsOf(supportersOf(stability));
  join(&what_if, body, decision.kind == BrickState::kLeaning, stability, options_);
  return what_if;
}

void StackStabilityModel::wakeWithLoad(const WakeDecision& first, SupportGraph* graph,
                                       RestTracker* rest, StabilityDecisions* decisions) const {
  // The model's own judgement, not a push, a blow or a removal from outside.
  const bool judged = first.cause == WakeCause::kOutsideSupport ||
                      first.cause == WakeCause::kSupportCycle || first.cause == WakeCause::kCarried;
  for (SupportGraph::Detached& detached : graph->detachWithLoad(first.brick)) {
    if (rest) {
      // Until its next step it carries only itself, where it was frozen.
      RestTracker::Mover& mover = rest->restart(detached.brick);
      mover.stability.com_above = detached.node.com;
      mover.stability.mass_above = detached.node.mass;
      mover.woken = judged;
      mover.woken_at = detached.node.com;
    }
    if (detached.brick == first.brick) {
      decisions->wake.push_back(first);
    } else {
      decisions->wake.push_back(
          WakeDecision{detached.brick, WakeCause::kCarried, detached.carried_by, 0.0,
                       "carried by " + name_of_(detached.carried_by) + ", which was woken"});
    }
    WakeDecision& woken = decisions->wake.back();
    woken.repeats = judged && detached.node.refrozen_in_place;
    if (woken.repeats)
      woken.reason += " (again, where it had frozen without moving: a wake/refreeze cycle)";
  }
}

void StackStabilityModel::settle(SupportGraph* graph, RestTracker* rest,
                                 StabilityDecisions* decisions, const StabilityInput* input) const {
  // Each round wakes at least one brick or finds nothing: it ends.
  while (graph->hasChanges()) {
    std::vector<WakeDecision> unstable;
    for (const std::vector<BodyHandle>& component : graph->takeChangedComponents()) {
      if (component.empty()) continue;
      std::vector<WakeDecision> found = criterion_->check(graph, component);
      if (!found.empty() && input && standsWithSourcesAtRest(graph, component, *input)) continue;
      unstable.insert(unstable.end(), found.begin(), found.end());
    }
    for (const WakeDecision& decision : unstable) wakeWithLoad(decision, graph, rest, decisions);
  }
}

bool StackStabilityModel::standsWithSourcesAtRest(SupportGraph* graph,
                                                  const std::vector<BodyHandle>& component,
                                                  const StabilityInput& input) const {
  std::vector<BodyHandle> sources;
  for (BodyHandle brick : component)
    for (BodyHandle source : loads_.sourcesOn(brick))
      if (!moves(source) && !graph->contains(source)) sources.push_back(source);
  if (sources.empty()) return false;
  std::sort(sources.begin(), sources.end());
  sources.erase(std::unique(sources.begin(), sources.end()), sources.end());
  std::vector<BodyMotion> bodies;
  for (BodyHandle source : sources) {
    const auto body = std::find_if(input.movers.begin(), input.movers.end(),
                                   [&](const BodyMotion& mover) { return mover.handle == source; });
    if (body == input.movers.end()) return false;
    bodies.push_back(*body);
  }
  // Each is loaded by every source outside the group, at rest or not: it
  // carries what rests on it into the component.
  const ContactLoads::BodyTest outside = [&](BodyHandle source) {
    return !std::binary_search(sources.begin(), sources.end(), source);
  };
  const ContactIndex index(input.contacts);
  std::vector<BrickStability> stability;
  if (!evaluateGroup(bodies, index, &outside, &stability)) return false;
  SupportGraph what_if = graph->componentsOf(component);
  unloadJoiners(&what_if, sources);
  for (std::size_t i = 0; i < bodies.size(); ++i)
    join(&what_if, bodies[i], leans(stability[i], options_), stability[i], options_);
  // Only the component's bricks are asked about: a brick at rest that
  // cannot stay is the engine's to move, and moves nothing frozen here
  // unless the check names it too.
  for (const WakeDecision& woken : criterion_->check(&what_if, what_if.bricks()))
    if (!std::binary_search(sources.begin(), sources.end(), woken.brick)) return false;
  // What the markers show of it: the check that holds, its measured loads kept.
  for (BodyHandle brick : component) {
    BrickStability& stability = graph->find(brick)->stability;
    std::vector<PointForce> loads = std::move(stability.external_loads);
    stability = what_if.find(brick)->stability;
    stability.external_loads = std::move(loads);
  }
  return true;
}

bool StackStabilityModel::describe(BodyHandle brick, BrickStability* stability) const {
  if (const SupportGraph::Node* node = graph_.find(brick)) {
    *stability = node->stability;
    return true;
  }
  if (const RestTracker::Mover* mover = rest_.find(brick)) {
    *stability = mover->stability;
    return true;
  }
  return false;
}

}  // namespace brick_stack_sim
