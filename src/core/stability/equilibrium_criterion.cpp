#include "stability/equilibrium_criterion.h"

#include "stability/statics_assembly.h"
#include "util/text_format.h"

namespace brick_stack_sim {

std::vector<WakeDecision> EquilibriumCriterion::check(
    SupportGraph* graph, const std::vector<BodyHandle>& component) const {
  std::vector<WakeDecision> by_com = ComCriterion::check(graph, component);
  if (by_com.empty()) return by_com;
  StaticsAssembly assembly(options());
  for (BodyHandle handle : component) {
    const SupportGraph::Node& node = *graph->find(handle);
    assembly.addFree(handle, node.mass, node.com);
  }
  for (std::size_t i = 0; i < component.size(); ++i) {
    const SupportGraph::Node& node = *graph->find(component[i]);
    assembly.addPatches(static_cast<int>(i), node.supports);
    assembly.addPatches(static_cast<int>(i), node.side_contacts);
  }
  const StaticsSolution solution = assembly.solve();
  // A solver failure keeps the COM rule's answer: never freeze on no answer.
  if (!solution.solved) return by_com;
  std::vector<std::vector<ContactForce>> forces = assembly.contactForces(solution);
  for (std::size_t i = 0; i < component.size(); ++i)
    graph->find(component[i])->stability.contact_forces = std::move(forces[i]);
  std::vector<WakeDecision> unstable;
  for (std::size_t i = 0; i < component.size(); ++i) {
    if (solution.imbalance[i] <= 0.0) continue;
    const SupportGraph::Node& node = *graph->find(component[i]);
    unstable.push_back(WakeDecision{
        component[i], WakeCause::kOutsideSupport, component[i], node.stability.margin,
        "no contact forces within friction balance it (statics: " + percent(solution.imbalance[i]) +
            " of a brick's weight unbalanced)"});
  }
  return unstable;
}

}  // namespace brick_stack_sim
