#include "stability/contact_classifier.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "stability/support_graph.h"

namespace brick_stack_sim {

ContactIndex::ContactIndex(const std::vector<PairContact>* contacts) {
  if (!contacts) return;
  std::vector<std::pair<BodyHandle, const PairContact*>> entries;
  entries.reserve(2 * contacts->size());
  for (const PairContact& contact : *contacts) {
    if (contact.points.empty()) continue;
    entries.emplace_back(contact.a, &contact);
    entries.emplace_back(contact.b, &contact);
  }
  // Stable: each body's contacts stay in the step's order.
  std::stable_sort(entries.begin(), entries.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  bodies_.reserve(entries.size());
  contacts_.reserve(entries.size());
  for (const auto& [body, contact] : entries) {
    bodies_.push_back(body);
    contacts_.push_back(contact);
  }
}

ContactSpan ContactIndex::of(BodyHandle handle) const {
  const auto [first, last] = std::equal_range(bodies_.begin(), bodies_.end(), handle);
  const PairContact* const* base = contacts_.data();
  return ContactSpan(base + (first - bodies_.begin()), base + (last - bodies_.begin()));
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

std::vector<SupportPatch> supportPatches(const BodyMotion& body, ContactSpan contacts,
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
