// StackStabilityModel's answers about bricks that arrive at rest or are
// struck: a brick placed or slid in at rest, a group placed leaning on each
// other, a blow on a frozen brick, and the question "would this pose stand".
#include "stability/stack_stability_model.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "stability/contact_classifier.h"
#include "stability/impact_rule.h"
#include "stability/placement_load.h"
#include "stability/statics_assembly.h"
#include "stability/support_evaluation.h"
#include "util/text_format.h"

namespace brick_stack_sim {

void StackStabilityModel::slide(const RestingPlacement& slid, StabilityDecisions* decisions) {
  const SupportGraph::Node* node = graph_.find(slid.brick.handle);
  if (!node) return;
  const BrickState was = node->leaning ? BrickState::kLeaning : BrickState::kStable;
  graph_.eraseAndUnlink(slid.brick.handle);
  const ContactIndex index(&slid.contacts);
  BrickStability stability;
  stability.mass_above = slid.brick.mass;
  FreezeDecision decision;
  if (evaluateMover(slid.brick, index.of(slid.brick.handle), &stability, &decision)) {
    join(&graph_, slid.brick, decision.kind == BrickState::kLeaning, std::move(stability),
         options_);
    if (decision.kind != was) decisions->freeze.push_back(std::move(decision));
    return;
  }
  // What it carried lost it as a support; settle() judges them next.
  RestTracker::Mover& mover = rest_.restart(slid.brick.handle);
  mover.stability = stability;
  decisions->wake.push_back(WakeDecision{slid.brick.handle, WakeCause::kStruck, slid.brick.handle,
                                         stability.margin,
                                         "an impact slid it to where it does not rest (margin " +
                                             millimetres(stability.margin) + ")"});
}

void StackStabilityModel::judgeImpacts(const std::vector<Impact>& impacts,
                                       std::vector<ImpactResponse>* responses,
                                       StabilityDecisions* decisions) {
  for (const Impact& impact : impacts) {
    ImpactResponse response;
    response.impact = impact;
    const SupportGraph::Node* node = graph_.find(impact.struck);
    if (!node) {  // woken by an earlier impact of this step: Bullet's now
      responses->push_back(std::move(response));
      continue;
    }
    StruckBrick struck;
    struck.mass = node->mass;
    struck.mass_above = node->stability.mass_above;
    struck.com_above = node->stability.com_above;
    struck.support_hull = node->stability.combined_hull;
    struck.support_height = node->stability.support_height;
    struck.friction = std::numeric_limits<double>::infinity();
    for (const auto* patches : {&node->supports, &node->side_contacts})
      for (const SupportPatch& patch : *patches)
        struck.friction = std::min(struck.friction, patch.friction);
    if (!std::isfinite(struck.friction)) struck.friction = 0.0;
    const ImpactJudgement judgement = judgeImpact(struck, impact, options_.impact_min_slide);
    response.impulse = judgement.impulse;
    response.delivered_energy = judgement.delivered_energy;
    const bool held = !std::isfinite(impact.striker_mass);
    std::ostringstream speed;
    speed.precision(3);
    speed << impact.closing_speed;
    const std::string blow_text = std::string(held ? "pushed by held " : "struck by ") +
                                  name_of_(impact.striker) + " at " + speed.str() +
                                  " m/s: " + describeImpact(judgement);
    if (!judgement.moves()) {
      response.outcome = ImpactResponse::Outcome::kAbsorbed;
      response.reason = blow_text + "; absorbed";
    } else if (judgement.tips || node->carries.empty()) {
      // Nothing rests on it (or all of it tips): Bullet carries the blow on.
      response.outcome = ImpactResponse::Outcome::kWoken;
      response.reason = blow_text + (judgement.tips ? "; tips with its load" : "; woken");
      wakeWithLoad(WakeDecision{impact.struck, WakeCause::kStruck, impact.striker,
                                node->stability.margin, response.reason},
                   &graph_, &rest_, decisions);
    } else {
      // Under a load it slides in place: the deformation stays in the
      // struck brick (thesis 4.2), and what it carries is judged again.
      response.outcome = ImpactResponse::Outcome::kSlid;
      response.slide = judgement.slide * judgement.push_direction;
      response.reason = blow_text + "; slides under its load";
    }
    responses->push_back(std::move(response));
  }
}

std::vector<BodyHandle> StackStabilityModel::carriedBy(BodyHandle brick) const {
  const SupportGraph::Node* node = graph_.find(brick);
  if (!node) return {};
  return std::vector<BodyHandle>(node->carries.begin(), node->carries.end());
}

bool StackStabilityModel::evaluateMover(const BodyMotion& body, ContactSpan contacts,
                                        BrickStability* stability, FreezeDecision* decision) const {
  // A brick at rest on it is judged next, from the bottom up, and its
  // weight then passes through the stack; one that moves presses now.
  stability->external_loads =
      loads_.on(body.handle, [this](BodyHandle source) { return moves(source); });
  stability->supports =
      supportPatches(body, contacts, frozenOrGround(graph_), options_,
                     criterion_->usesSideContacts() ? &stability->side_contacts : nullptr);
  criterion_->evaluate(body, stability);
  return criterion_->admits(body, *stability, decision);
}

void StackStabilityModel::placeAtRest(const RestingPlacement& placed,
                                      StabilityDecisions* decisions) {
  const ContactIndex index(&placed.contacts);
  BrickStability& stability = rest_.record(placed.brick.handle).stability;
  stability = BrickStability();
  stability.mass_above = placed.brick.mass;
  FreezeDecision decision;
  if (evaluateMover(placed.brick, index.of(placed.brick.handle), &stability, &decision)) {
    freeze(placed.brick, std::move(decision), stability, decisions);
    // It may be what a group placed before it was waiting for: the last
    // voussoir of an arch, standing on the table, closes the ring.
    for (const PairContact& contact : placed.contacts) {
      const BodyHandle other = contact.a == placed.brick.handle ? contact.b : contact.a;
      if (unjudged_.count(other)) admitGroupAtRest(other, decisions, &placed.contacts);
    }
    return;
  }
  if (!criterion_->usesSideContacts()) return;
  unjudged_[placed.brick.handle] = placed;
  for (const PairContact& contact : placed.contacts) {
    const BodyHandle other = contact.a == placed.brick.handle ? contact.b : contact.a;
    if (unjudged_.count(other)) touched_by_[other].push_back(placed.brick.handle);
  }
  admitGroupAtRest(placed.brick.handle, decisions);
}

void StackStabilityModel::admitGroupAtRest(BodyHandle newest, StabilityDecisions* decisions,
                                           const std::vector<PairContact>* frozen_contacts) {
  // The unjudged bricks `newest` reaches: a brick placed earlier saw none of
  // the later ones, so each brick's contacts lead to earlier ones and
  // touched_by_ to later ones. Only the group is visited: placing n bricks
  // at once must not cost n^2.
  std::vector<BodyHandle> group{newest};
  std::set<BodyHandle> in_group{newest};
  const auto reach = [&](BodyHandle other) {
    if (unjudged_.count(other) && in_group.insert(other).second) group.push_back(other);
  };
  for (std::size_t next = 0; next < group.size(); ++next) {
    const BodyHandle member = group[next];
    for (const PairContact& contact : unjudged_.at(member).contacts)
      reach(contact.a == member ? contact.b : contact.a);
    const auto later = touched_by_.find(member);
    if (later != touched_by_.end())
      for (BodyHandle other : later->second) reach(other);
  }
  if (group.size() < 2) return;
  std::sort(group.begin(), group.end());
  // Together the contacts of the group (and of a brick frozen since) name
  // every pair of it once, in the order of the members.
  std::vector<PairContact> contacts;
  if (frozen_contacts) contacts = *frozen_contacts;
  for (BodyHandle member : group) {
    const std::vector<PairContact>& own = unjudged_.at(member).contacts;
    contacts.insert(contacts.end(), own.begin(), own.end());
  }
  const ContactIndex index(&contacts);
  std::vector<BodyMotion> bodies;
  for (BodyHandle member : group) bodies.push_back(unjudged_.at(member).brick);
  if (!admitTogether(bodies, index, decisions)) return;
  for (BodyHandle member : group) {
    unjudged_.erase(member);
    touched_by_.erase(member);
  }
}

bool StackStabilityModel::admitTogether(const std::vector<BodyMotion>& bodies,
                                        const ContactIndex& index, StabilityDecisions* decisions) {
  std::vector<BrickStability> stability;
  if (!evaluateGroup(bodies, index, nullptr, &stability)) return false;
  std::vector<FreezeDecision> admitted;
  if (!criterion_->admitsGroup(bodies, stability, &admitted)) return false;
  for (std::size_t i = 0; i < bodies.size(); ++i)
    freeze(bodies[i], std::move(admitted[i]), std::move(stability[i]), decisions);
  return true;
}

bool StackStabilityModel::evaluateGroup(const std::vector<BodyMotion>& bodies,
                                        const ContactIndex& index,
                                        const ContactLoads::BodyTest* presses,
                                        std::vector<BrickStability>* stability) const {
  std::vector<BodyHandle> group;
  for (const BodyMotion& body : bodies) group.push_back(body.handle);
  const auto member = [&](BodyHandle handle) {
    return std::binary_search(group.begin(), group.end(), handle);
  };
  const SupporterTest frozen_or_member = [&](BodyHandle handle) {
    return graph_.canSupport(handle) || member(handle);
  };
  stability->assign(bodies.size(), BrickStability());
  bool held_from_outside = false;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    BrickStability& s = (*stability)[i];
    s.mass_above = bodies[i].mass;
    if (presses) s.external_loads = loads_.on(group[i], *presses);
    s.supports =
        supportPatches(bodies[i], index.of(group[i]), frozen_or_member, options_, &s.side_contacts);
    criterion_->evaluate(bodies[i], &s);
    for (const std::vector<SupportPatch>* patches : {&s.supports, &s.side_contacts})
      for (const SupportPatch& patch : *patches) held_from_outside |= !member(patch.supporter);
  }
  // Bricks that touch nothing but each other cannot balance their weight:
  // no statics to ask (a tower placed in the air).
  return held_from_outside;
}

PlacementEvaluation StackStabilityModel::evaluatePlacement(
    const BodyMotion& brick, const std::vector<PairContact>& contacts) const {
  PlacementEvaluation result;
  const ContactIndex index(&contacts);
  BrickStability stability;
  stability.mass_above = brick.mass;
  FreezeDecision decision;
  const bool admitted = evaluateMover(brick, index.of(brick.handle), &stability, &decision);
  result.margin = stability.margin;
  result.supporters = supportersOf(stability);
  if (!admitted) {
    result.reason = stability.supports.empty()
                        ? "it would rest on nothing that is frozen or the ground"
                        : "it would not rest stably: margin " + millimetres(stability.margin);
    return result;
  }
  // Where the COM rule bears its weight on every brick below, the criterion
  // would find nothing to wake; elsewhere the what-if is judged in full, on a
  // copy of the components it joins.
  if (criterion_->trustsComRulePasses() &&
      comRuleBearsPlacement(graph_, brick, stability, options_.min_margin)) {
    result.stable = true;
    result.kind = decision.kind;
    result.reason = decision.reason;
    return result;
  }
  SupportGraph what_if = joinedCopy(brick, stability, decision);
  StabilityDecisions consequences;
  settle(&what_if, nullptr, &consequences);
  for (const WakeDecision& woken : consequences.wake)
    if (woken.brick != brick.handle) result.would_fall.push_back(woken.brick);
  std::sort(result.would_fall.begin(), result.would_fall.end());
  const bool itself_falls =
      std::any_of(consequences.wake.begin(), consequences.wake.end(),
                  [&](const WakeDecision& woken) { return woken.brick == brick.handle; });
  result.stable = !itself_falls && result.would_fall.empty();
  result.kind = result.stable ? decision.kind : BrickState::kDynamic;
  if (result.stable) {
    result.reason = decision.reason;
  } else {
    const WakeDecision& first = consequences.wake.front();
    result.reason = "its load would tip " + name_of_(first.brick) + ": " + first.reason;
  }
  return result;
}

}  // namespace brick_stack_sim
