#include "stability/contact_classifier.h"

#include <cmath>
#include <map>

#include "stability/support_graph.h"

namespace brick_stack_sim {

ContactIndex::ContactIndex(const std::vector<PairContact>* contacts) {
  if (!contacts) return;
  for (const PairContact& contact : *contacts) {
    if (contact.points.empty()) continue;
    by_body_[contact.a].push_back(&contact);
    by_body_[contact.b].push_back(&contact);
  }
}

const std::vector<const PairContact*>& ContactIndex::of(BodyHandle handle) const {
  static const std::vector<const PairContact*> kNoContacts;
  auto found = by_body_.find(handle);
  return found == by_body_.end() ? kNoContacts : found->second;
}

namespace {

void addToPatch(const PairContact& contact, const Eigen::Vector3d& towards_body,
                BodyHandle supporter, std::map<BodyHandle, SupportPatch>* by_supporter) {
  SupportPatch& patch = (*by_supporter)[supporter];
  patch.supporter = supporter;
  patch.friction = contact.friction;
  patch.points.insert(patch.points.end(), contact.points.begin(), contact.points.end());
  patch.normals.insert(patch.normals.end(), contact.points.size(), towards_body);
}

std::vector<SupportPatch> inOrder(std::map<BodyHandle, SupportPatch>* by_supporter) {
  std::vector<SupportPatch> patches;
  for (auto& entry : *by_supporter) patches.push_back(std::move(entry.second));
  return patches;
}

}  // namespace

std::vector<SupportPatch> supportPatches(const BodyMotion& body,
                                         const std::vector<const PairContact*>& contacts,
                                         const SupporterTest& can_support,
                                         const StabilityOptions& options,
                                         std::vector<SupportPatch>* side_contacts) {
  const double vertical = std::cos(options.support_normal_tolerance);
  std::map<BodyHandle, SupportPatch> below, beside;
  for (const PairContact* contact : contacts) {
    const bool is_a = contact->a == body.handle;
    if (!is_a && contact->b != body.handle) continue;
    const BodyHandle other = is_a ? contact->b : contact->a;
    // The normal points from b to a: turned to point at this brick.
    const Eigen::Vector3d towards_body = is_a ? contact->normal : Eigen::Vector3d(-contact->normal);
    // The thesis drops contacts between two unstable bricks: a stack cannot
    // start on a moving brick. Impacts are not support either.
    if (!can_support(other)) continue;
    if (contact->approach_speed > options.impact_speed) continue;
    if (towards_body.z() >= vertical) {
      addToPatch(*contact, towards_body, other, &below);
    } else if (side_contacts) {
      addToPatch(*contact, towards_body, other, &beside);
    }
  }
  if (side_contacts) *side_contacts = inOrder(&beside);
  return inOrder(&below);
}

SupporterTest frozenOrGround(const SupportGraph& graph) {
  return [&graph](BodyHandle handle) { return graph.canSupport(handle); };
}

void refineFlushPatches(const std::function<PlacedSolid(BodyHandle)>& solid_of,
                        const StabilityOptions& options, std::vector<PairContact>* contacts,
                        const std::function<bool(const PairContact&)>& wanted) {
  const double vertical = std::cos(options.support_normal_tolerance);
  for (PairContact& pair : *contacts) {
    if (std::abs(pair.normal.z()) < vertical || (wanted && !wanted(pair))) continue;
    const bool b_below = pair.normal.z() > 0.0;
    std::vector<Eigen::Vector3d> patch;
    if (flushContactPatch(solid_of(b_below ? pair.b : pair.a), solid_of(b_below ? pair.a : pair.b),
                          options.flush_angle, options.contact_distance, &patch))
      pair.points = std::move(patch);
  }
}

}  // namespace brick_stack_sim
