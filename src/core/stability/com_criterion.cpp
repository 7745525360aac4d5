#include "stability/com_criterion.h"

#include "stability/support_evaluation.h"
#include "stability/support_graph.h"
#include "util/text_format.h"

namespace brick_stack_sim {

ComCriterion::ComCriterion(const StabilityOptions& options, BodyNamer name_of)
    : options_(options), name_of_(std::move(name_of)) {}

void ComCriterion::evaluate(const BodyMotion& brick, BrickStability* stability) const {
  evaluateSupport(brick.com, stability);
}

bool ComCriterion::admits(const BodyMotion& brick, const BrickStability& stability,
                          FreezeDecision* decision) const {
  if (stability.supports.empty() || stability.margin <= options_.min_margin) return false;
  *decision = FreezeDecision{brick.handle, BrickState::kStable, stability.margin, {}, ""};
  std::string on;
  for (const SupportPatch& patch : stability.supports) {
    decision->supporters.push_back(patch.supporter);
    on += (on.empty() ? "" : ", ") + name_of_(patch.supporter);
  }
  decision->reason = "rests stably on " + on + " (margin " + millimetres(stability.margin) + ")";
  return true;
}

WakeDecision ComCriterion::outsideSupport(BodyHandle brick, double margin) const {
  return WakeDecision{brick, WakeCause::kOutsideSupport, brick, margin,
                      "COM-above left its support: margin " + millimetres(margin)};
}

std::vector<WakeDecision> ComCriterion::check(SupportGraph* graph,
                                              const std::vector<BodyHandle>& component) const {
  std::vector<BodyHandle> load_order, cyclic;
  graph->loadOrder(component, &load_order, &cyclic);
  std::vector<WakeDecision> unstable;
  // Each brick's loads arrive from the bricks it carries, all before its own
  // turn in the load order, and are summed in the order they arrive.
  for (BodyHandle handle : load_order) graph->find(handle)->received.clear();
  std::vector<LoadShare> shares;
  for (BodyHandle handle : load_order) {
    SupportGraph::Node& node = *graph->find(handle);
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
      unstable.push_back(outsideSupport(handle, node.stability.margin));
      continue;
    }
    std::vector<Polygon2d> patches;
    for (const SupportPatch& patch : node.supports) patches.push_back(patch.hull);
    if (distributeLoad(mass, com_above.head<2>(), patches, &shares) ==
        LoadSplitRule::kUnsupported) {
      unstable.push_back(outsideSupport(handle, node.stability.margin));
      continue;
    }
    for (std::size_t i = 0; i < node.supports.size(); ++i) {
      const BodyHandle supporter = node.supports[i].supporter;
      SupportGraph::Node* below = graph->find(supporter);
      if (!below) continue;  // the table carries anything
      below->received.push_back(shares[i]);
    }
  }
  // No order in which loads flow down: nothing can be said to carry them.
  for (BodyHandle handle : cyclic)
    unstable.push_back(WakeDecision{handle, WakeCause::kSupportCycle, handle, 0.0,
                                    "its supports form a cycle"});
  return unstable;
}

}  // namespace brick_stack_sim
