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

std::vector<SupportPatch> supportPatches(const BodyMotion& body,
                                         const std::vector<const PairContact*>& contacts,
                                         const SupportGraph& graph,
                                         const StabilityOptions& options) {
  const double vertical = std::cos(options.support_normal_tolerance);
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
    if (!graph.canSupport(supporter)) continue;
    if (contact->approach_speed > options.impact_speed) continue;
    SupportPatch& patch = by_supporter[supporter];
    patch.supporter = supporter;
    patch.points.insert(patch.points.end(), contact->points.begin(), contact->points.end());
  }
  std::vector<SupportPatch> supports;
  for (auto& entry : by_supporter) supports.push_back(std::move(entry.second));
  return supports;
}

void refineFlushPatches(const std::function<OrientedBox(BodyHandle)>& box_of,
                        const StabilityOptions& options, std::vector<PairContact>* contacts) {
  const double vertical = std::cos(options.support_normal_tolerance);
  for (PairContact& pair : *contacts) {
    if (std::abs(pair.normal.z()) < vertical) continue;
    const bool b_below = pair.normal.z() > 0.0;
    std::vector<Eigen::Vector3d> patch;
    if (flushContactPatch(box_of(b_below ? pair.b : pair.a), box_of(b_below ? pair.a : pair.b),
                          options.flush_angle, options.contact_distance, &patch))
      pair.points = std::move(patch);
  }
}

}  // namespace brick_stack_sim
