// StackStabilityModel's groups of movers at rest: bricks of a pile that
// lean on each other and only stand together. Of such a group the part
// statics holds freezes; the members that cannot stay are left to Bullet
// and asked again later.
#include <algorithm>
#include <map>
#include <set>

#include "stability/contact_classifier.h"
#include "stability/stack_stability_model.h"
#include "stability/support_evaluation.h"

namespace brick_stack_sim {

namespace {

/// How many times a group refused is asked again at once without the
/// bricks that cannot stay. Each round is an LP of the whole group; what
/// is still refused after them is asked at the next tick, when the rest
/// may have settled.
constexpr int kWithoutMechanismRounds = 4;

}  // namespace

void StackStabilityModel::admitRestingGroups(const ContactIndex& index,
                                             std::vector<const BodyMotion*>* resting,
                                             const std::vector<const BodyMotion*>& props,
                                             StabilityDecisions* decisions) {
  // The candidates: at rest and not admitted alone, those waiting where
  // statics woke them too: what holds such a brick now may be a partner at
  // rest, which it alone cannot count on, so alone it is refused for ever.
  // Each is found by its handle: at its index in `resting` (and due), or
  // among `props` (no index).
  constexpr std::size_t kProp = static_cast<std::size_t>(-1);
  struct Candidate {
    const BodyMotion* body;
    std::size_t resting_index;
  };
  std::map<BodyHandle, Candidate> candidate;
  for (std::size_t i = 0; i < resting->size(); ++i)
    if (const BodyMotion* body = (*resting)[i]) candidate[body->handle] = Candidate{body, i};
  for (const BodyMotion* body : props) candidate[body->handle] = Candidate{body, kProp};
  std::map<BodyHandle, bool> pressed_components;
  std::set<BodyHandle> seen;
  for (const auto& entry : candidate) {
    const BodyHandle start = entry.first;
    if (!seen.insert(start).second) continue;
    std::vector<BodyHandle> group{start};
    for (std::size_t next = 0; next < group.size(); ++next) {
      for (const PairContact* contact : index.of(group[next])) {
        const BodyHandle other = contact->a == group[next] ? contact->b : contact->a;
        if (candidate.count(other) && seen.insert(other).second) group.push_back(other);
      }
    }
    if (group.size() < 2 || std::none_of(group.begin(), group.end(), [&](BodyHandle member) {
          return candidate.at(member).resting_index != kProp;
        }))
      continue;
    std::sort(group.begin(), group.end());
    std::vector<BodyMotion> bodies;
    for (BodyHandle member : group) bodies.push_back(*candidate.at(member).body);
    for (BodyHandle frozen :
         freezeWhatStands(std::move(bodies), index, &pressed_components, decisions)) {
      const std::size_t at = candidate.at(frozen).resting_index;
      if (at != kProp) (*resting)[at] = nullptr;
    }
  }
}

std::vector<BodyHandle> StackStabilityModel::freezeWhatStands(
    std::vector<BodyMotion> bodies, const ContactIndex& index,
    std::map<BodyHandle, bool>* pressed_components, StabilityDecisions* decisions) {
  // The rest must stand without the bricks left out, which may fall away,
  // and bear their weight where they stay: each presses on the members it
  // touches with its measured load. A brick at rest that is not due yet
  // is not counted on, as a brick at rest is not when one under it is
  // judged: bricks are judged from the bottom up.
  std::vector<BodyHandle> left_out;
  const ContactLoads::BodyTest presses = [&](BodyHandle source) {
    return moves(source) || std::binary_search(left_out.begin(), left_out.end(), source);
  };
  for (int round = 0; round <= kWithoutMechanismRounds && bodies.size() >= 2; ++round) {
    std::vector<BrickStability> stability;
    if (!evaluateGroup(bodies, index, &presses, &stability)) break;
    // Where a mover presses on what a member would join, standsJoined()
    // refuses every group that keeps that member, after its LPs: on a
    // landing pile, most of what large groups were asked. Such a group
    // waits as a whole, unasked; those members stay the same however
    // many others are left out.
    if (round == 0 && pressedWhereItWouldJoin(bodies, stability, pressed_components)) break;
    std::vector<FreezeDecision> admitted;
    std::vector<BodyHandle> cannot_stay;
    if (criterion_->admitsGroup(bodies, stability, &admitted, &cannot_stay) &&
        standsJoined(bodies, stability, admitted, &cannot_stay)) {
      std::vector<BodyHandle> frozen;
      for (std::size_t i = 0; i < bodies.size(); ++i) {
        frozen.push_back(bodies[i].handle);
        freeze(bodies[i], std::move(admitted[i]), std::move(stability[i]), decisions);
      }
      return frozen;
    }
    // Without what must move the rest may stand; if all of it must move,
    // or the criterion cannot say what, the group waits as a whole.
    std::sort(cannot_stay.begin(), cannot_stay.end());
    const auto must_move = [&](const BodyMotion& body) {
      return std::binary_search(cannot_stay.begin(), cannot_stay.end(), body.handle);
    };
    const std::size_t before = bodies.size();
    bodies.erase(std::remove_if(bodies.begin(), bodies.end(), must_move), bodies.end());
    if (bodies.size() == before || bodies.empty()) break;
    left_out.insert(left_out.end(), cannot_stay.begin(), cannot_stay.end());
    std::sort(left_out.begin(), left_out.end());
  }
  return {};
}

bool StackStabilityModel::pressedWhereItWouldJoin(
    const std::vector<BodyMotion>& bodies, const std::vector<BrickStability>& stability,
    std::map<BodyHandle, bool>* pressed_components) const {
  // What a freeze merges is never pressed (standsJoined), and a pressed
  // component is merged with nothing: the answers hold for a whole step's
  // groups.
  const auto component_pressed = [&](BodyHandle frozen) {
    if (auto known = pressed_components->find(frozen); known != pressed_components->end())
      return known->second;
    std::set<BodyHandle> seen;
    const std::vector<BodyHandle> component = graph_.componentOf(frozen, &seen);
    const bool any = std::any_of(component.begin(), component.end(),
                                 [this](BodyHandle brick) { return pressedByAMover(brick); });
    for (BodyHandle brick : component) (*pressed_components)[brick] = any;
    return any;
  };
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (pressedByAMover(bodies[i].handle)) return true;
    for (BodyHandle supporter : supportersOf(stability[i]))
      if (graph_.contains(supporter) && component_pressed(supporter)) return true;
  }
  return false;
}

bool StackStabilityModel::standsJoined(const std::vector<BodyMotion>& bodies,
                                       const std::vector<BrickStability>& stability,
                                       const std::vector<FreezeDecision>& admitted,
                                       std::vector<BodyHandle>* cannot_stay) const {
  std::vector<BodyHandle> supporters;
  for (const BrickStability& s : stability)
    for (BodyHandle supporter : supportersOf(s))
      if (graph_.contains(supporter)) supporters.push_back(supporter);
  SupportGraph what_if = graph_.componentsOf(supporters);
  std::vector<BodyHandle> joiners;
  for (const BodyMotion& body : bodies) joiners.push_back(body.handle);
  std::sort(joiners.begin(), joiners.end());
  unloadJoiners(&what_if, joiners);
  for (std::size_t i = 0; i < bodies.size(); ++i)
    join(&what_if, bodies[i], admitted[i].kind == BrickState::kLeaning, stability[i], options_);
  // While a brick that moves presses on the stack it would join, what
  // statics says now may not hold a step on (a collapse that has not ended).
  if (pressedByMovers(what_if)) return false;
  const std::vector<WakeDecision> woken = criterion_->check(&what_if, what_if.bricks());
  // Joiners the check would wake cannot stay; a frozen brick it would wake
  // is one the whole group must not load.
  for (const WakeDecision& decision : woken)
    if (std::binary_search(joiners.begin(), joiners.end(), decision.brick))
      cannot_stay->push_back(decision.brick);
  return woken.empty();
}

}  // namespace brick_stack_sim
