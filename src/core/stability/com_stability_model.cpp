#include "stability/com_stability_model.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <unordered_map>

namespace brick_stack_sim {

namespace {

Eigen::Vector2d horizontal(const Eigen::Vector3d& v) { return v.head<2>(); }

}  // namespace

void evaluateSupport(const Eigen::Vector3d& load_point, BrickStability* s) {
  std::vector<Eigen::Vector2d> all_points;
  double height_sum = 0.0;
  std::size_t point_count = 0;
  for (SupportPatch& patch : s->supports) {
    std::vector<Eigen::Vector2d> projected;
    patch.height = 0.0;
    for (const Eigen::Vector3d& p : patch.points) {
      projected.push_back(horizontal(p));
      patch.height += p.z();
    }
    patch.height /= std::max<std::size_t>(patch.points.size(), 1);
    patch.hull = convexHull(projected);
    all_points.insert(all_points.end(), projected.begin(), projected.end());
    height_sum += patch.height * patch.points.size();
    point_count += patch.points.size();
  }
  s->combined_hull = convexHull(all_points);
  s->support_height = point_count ? height_sum / point_count : 0.0;
  s->com_above = load_point;
  // Resting on nothing has no hull to measure against: margin 0, next to an
  // empty list of supporters, rather than an infinity nobody can publish.
  s->margin = s->supports.empty() ? 0.0 : signedDistance(s->combined_hull, horizontal(load_point));
}

ComStabilityModel::ComStabilityModel(const StabilityOptions& options) : options_(options) {}

void ComStabilityModel::clear() {
  frozen_.clear();
  movers_.clear();
  dirty_.clear();
}

std::vector<SupportPatch> ComStabilityModel::candidateSupports(
    const BodyMotion& body, const std::vector<const PairContact*>& contacts) const {
  const double vertical = std::cos(options_.support_normal_tolerance);
  std::map<BodyHandle, SupportPatch> by_supporter;
  for (const PairContact* contact : contacts) {
    BodyHandle supporter;
    if (contact->a == body.handle && contact->normal.z() >= vertical) {
      supporter = contact->b;  // the normal points from b up to this brick
    } else if (contact->b == body.handle && contact->normal.z() <= -vertical) {
      supporter = contact->a;
    } else {
      continue;  // a side contact, or this brick is the lower one
    }
    // The thesis drops contacts between two unstable bricks: a stack cannot
    // start on a moving brick. Impacts are not support either.
    if (!isGround(supporter) && !frozen_.count(supporter)) continue;
    if (contact->approach_speed > options_.impact_speed) continue;
    SupportPatch& patch = by_supporter[supporter];
    patch.supporter = supporter;
    patch.points.insert(patch.points.end(), contact->points.begin(), contact->points.end());
  }
  std::vector<SupportPatch> supports;
  for (auto& entry : by_supporter) supports.push_back(std::move(entry.second));
  return supports;
}

void ComStabilityModel::update(double dt, const std::vector<BodyMotion>& movers,
                               const std::vector<PairContact>& contacts,
                               StabilityDecisions* decisions) {
  std::unordered_map<BodyHandle, std::vector<const PairContact*>> contacts_of;
  for (const PairContact& contact : contacts) {
    if (contact.points.empty()) continue;
    contacts_of[contact.a].push_back(&contact);
    contacts_of[contact.b].push_back(&contact);
  }
  static const std::vector<const PairContact*> kNoContacts;
  auto contacts_for = [&](BodyHandle handle) -> const std::vector<const PairContact*>& {
    auto found = contacts_of.find(handle);
    return found == contacts_of.end() ? kNoContacts : found->second;
  };
  std::vector<const BodyMotion*> resting;
  for (const BodyMotion& body : movers) {
    Mover& mover = movers_[body.handle];
    const bool at_rest = body.linear_velocity.norm() < options_.rest_linear_speed &&
                         body.angular_velocity.norm() < options_.rest_angular_speed;
    mover.rest_time = at_rest ? mover.rest_time + dt : 0.0;
    mover.stability = BrickStability();
    mover.stability.mass_above = body.mass;
    // A moving brick cannot join the stack; its supports are not worth a hull.
    if (at_rest) mover.stability.supports = candidateSupports(body, contacts_for(body.handle));
    evaluateSupport(body.com, &mover.stability);
    if (mover.rest_time >= options_.rest_time) resting.push_back(&body);
  }
  // A brick at rest on one that freezes now may freeze in the same step: a
  // stack placed at once joins from the bottom up without a step per layer.
  for (bool froze = true; froze;) {
    froze = false;
    for (const BodyMotion*& body : resting) {
      if (!body) continue;
      Mover& mover = movers_[body->handle];
      mover.stability.supports = candidateSupports(*body, contacts_for(body->handle));
      evaluateSupport(body->com, &mover.stability);
      if (mover.stability.supports.empty() || mover.stability.margin <= options_.min_margin)
        continue;
      freeze(*body, mover.stability.supports, mover.stability.margin, decisions);
      body = nullptr;
      froze = true;
    }
  }
  runPasses(decisions);
}

void ComStabilityModel::placedAtRest(const BodyMotion& brick,
                                     const std::vector<PairContact>& contacts,
                                     StabilityDecisions* decisions) {
  std::vector<const PairContact*> own;
  for (const PairContact& contact : contacts)
    if (contact.a == brick.handle || contact.b == brick.handle) own.push_back(&contact);
  Mover& mover = movers_[brick.handle];
  mover.stability = BrickStability();
  mover.stability.mass_above = brick.mass;
  mover.stability.supports = candidateSupports(brick, own);
  evaluateSupport(brick.com, &mover.stability);
  if (mover.stability.supports.empty() || mover.stability.margin <= options_.min_margin) return;
  freeze(brick, mover.stability.supports, mover.stability.margin, decisions);
  runPasses(decisions);
}

void ComStabilityModel::freeze(const BodyMotion& body, std::vector<SupportPatch> supports,
                               double margin, StabilityDecisions* decisions) {
  Node& node = frozen_[body.handle];
  node.com = body.com;
  node.mass = body.mass;
  node.supports = std::move(supports);
  FreezeDecision decision{body.handle, margin, {}};
  for (const SupportPatch& patch : node.supports) {
    decision.supporters.push_back(patch.supporter);
    auto supporter = frozen_.find(patch.supporter);
    if (supporter != frozen_.end()) supporter->second.carries.insert(body.handle);
  }
  movers_.erase(body.handle);
  dirty_.insert(body.handle);
  decisions->freeze.push_back(std::move(decision));
}

void ComStabilityModel::wakeWithLoad(BodyHandle brick, const WakeDecision& first,
                                     StabilityDecisions* decisions) {
  std::deque<WakeDecision> queue{first};
  queue.front().brick = brick;
  while (!queue.empty()) {
    const WakeDecision decision = queue.front();
    queue.pop_front();
    auto it = frozen_.find(decision.brick);
    if (it == frozen_.end()) continue;  // already woken through another path
    Node node = std::move(it->second);
    frozen_.erase(it);
    for (const SupportPatch& patch : node.supports) {
      auto supporter = frozen_.find(patch.supporter);
      if (supporter == frozen_.end()) continue;
      supporter->second.carries.erase(decision.brick);
      dirty_.insert(patch.supporter);  // its load changed
    }
    dirty_.erase(decision.brick);
    // Until its next step it carries only itself, where it was frozen.
    Mover& mover = movers_[decision.brick];
    mover = Mover();
    mover.stability.com_above = node.com;
    mover.stability.mass_above = node.mass;
    decisions->wake.push_back(decision);
    for (BodyHandle upper : node.carries)
      queue.push_back(WakeDecision{upper, WakeCause::kCarried, decision.brick, 0.0});
  }
}

void ComStabilityModel::remove(BodyHandle brick, StabilityDecisions* decisions) {
  movers_.erase(brick);
  auto it = frozen_.find(brick);
  if (it == frozen_.end()) return;
  const std::set<BodyHandle> carried = it->second.carries;
  for (const SupportPatch& patch : it->second.supports) {
    auto supporter = frozen_.find(patch.supporter);
    if (supporter == frozen_.end()) continue;
    supporter->second.carries.erase(brick);
    dirty_.insert(patch.supporter);
  }
  frozen_.erase(it);
  dirty_.erase(brick);
  for (BodyHandle upper : carried)
    wakeWithLoad(upper, WakeDecision{upper, WakeCause::kSupporterRemoved, brick, 0.0}, decisions);
  runPasses(decisions);
}

void ComStabilityModel::wake(BodyHandle brick, WakeCause cause, StabilityDecisions* decisions) {
  if (!frozen_.count(brick)) return;
  wakeWithLoad(brick, WakeDecision{brick, cause, brick, 0.0}, decisions);
  runPasses(decisions);
}

std::vector<BodyHandle> ComStabilityModel::componentOf(BodyHandle start,
                                                       std::set<BodyHandle>* seen) const {
  std::vector<BodyHandle> component;
  std::deque<BodyHandle> queue{start};
  seen->insert(start);
  while (!queue.empty()) {
    const BodyHandle handle = queue.front();
    queue.pop_front();
    auto it = frozen_.find(handle);
    if (it == frozen_.end()) continue;
    component.push_back(handle);
    auto visit = [&](BodyHandle next) {
      if (!isGround(next) && seen->insert(next).second) queue.push_back(next);
    };
    for (const SupportPatch& patch : it->second.supports) visit(patch.supporter);
    for (BodyHandle upper : it->second.carries) visit(upper);
  }
  std::sort(component.begin(), component.end());
  return component;
}

void ComStabilityModel::runPasses(StabilityDecisions* decisions) {
  // Waking can unload a counterweight and tip a brick below, so passes repeat
  // until nothing changes; each round wakes at least one brick, so it ends.
  while (!dirty_.empty()) {
    std::set<BodyHandle> seen;
    std::vector<std::vector<BodyHandle>> components;
    for (BodyHandle handle : dirty_)
      if (!seen.count(handle)) components.push_back(componentOf(handle, &seen));
    dirty_.clear();
    std::vector<WakeDecision> unstable;
    for (const auto& component : components) {
      if (component.empty()) continue;
      auto found = passComponent(component);
      unstable.insert(unstable.end(), found.begin(), found.end());
    }
    for (const WakeDecision& decision : unstable) wakeWithLoad(decision.brick, decision, decisions);
  }
}

std::vector<WakeDecision> ComStabilityModel::passComponent(
    const std::vector<BodyHandle>& component) {
  std::map<BodyHandle, int> waiting_for;  // uppers not yet passed
  std::deque<BodyHandle> ready;
  for (BodyHandle handle : component) {
    Node& node = frozen_.at(handle);
    node.received.clear();
    waiting_for[handle] = static_cast<int>(node.carries.size());
    if (node.carries.empty()) ready.push_back(handle);
  }
  std::vector<WakeDecision> unstable;
  std::vector<LoadShare> shares;
  while (!ready.empty()) {
    const BodyHandle handle = ready.front();
    ready.pop_front();
    waiting_for.erase(handle);
    Node& node = frozen_.at(handle);
    // COM-above: the resultant of its own weight and the loads it receives,
    // each where it acts. Heights only place the marker ray: mass-weighted.
    double mass = node.mass;
    Eigen::Vector3d moment = node.mass * node.com;
    for (const LoadShare& load : node.received) {
      mass += load.mass;
      moment.head<2>() += load.mass * load.point;
    }
    Eigen::Vector3d com_above = moment / mass;
    com_above.z() = node.com.z();
    node.stability.frozen = true;
    node.stability.mass_above = mass;
    node.stability.supports = node.supports;
    evaluateSupport(com_above, &node.stability);
    node.supports = node.stability.supports;  // keep the hulls
    if (node.stability.margin <= options_.min_margin) {
      unstable.push_back(
          WakeDecision{handle, WakeCause::kOutsideSupport, handle, node.stability.margin});
    } else {
      std::vector<Polygon2d> patches;
      for (const SupportPatch& patch : node.supports) patches.push_back(patch.hull);
      const LoadSplitRule rule = distributeLoad(mass, horizontal(com_above), patches, &shares);
      if (rule == LoadSplitRule::kUnsupported) {
        unstable.push_back(
            WakeDecision{handle, WakeCause::kOutsideSupport, handle, node.stability.margin});
      } else {
        for (std::size_t i = 0; i < node.supports.size(); ++i) {
          const BodyHandle supporter = node.supports[i].supporter;
          auto below = frozen_.find(supporter);
          if (below == frozen_.end()) continue;  // the table carries anything
          below->second.received.push_back(shares[i]);
        }
      }
    }
    for (const SupportPatch& patch : node.supports) {
      auto it = waiting_for.find(patch.supporter);
      if (it != waiting_for.end() && --it->second == 0) ready.push_back(patch.supporter);
    }
  }
  // Whatever still waits is part of a cycle: no order in which loads flow down.
  for (const auto& [handle, count] : waiting_for)
    unstable.push_back(WakeDecision{handle, WakeCause::kSupportCycle, handle, 0.0});
  return unstable;
}

bool ComStabilityModel::describe(BodyHandle brick, BrickStability* stability) const {
  if (auto it = frozen_.find(brick); it != frozen_.end()) {
    *stability = it->second.stability;
    return true;
  }
  if (auto it = movers_.find(brick); it != movers_.end()) {
    *stability = it->second.stability;
    return true;
  }
  return false;
}

}  // namespace brick_stack_sim
