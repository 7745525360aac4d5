#include "stability/equilibrium_criterion.h"

#include "stability/statics_assembly.h"
#include "util/text_format.h"

namespace brick_stack_sim {

namespace {

/// The statics problem of `bricks`, free, on their patches; every other
/// body fixed.
StaticsAssembly assemble(const SupportGraph& graph, const std::vector<BodyHandle>& bricks,
                         const StabilityOptions& options) {
  StaticsAssembly assembly(options);
  for (BodyHandle handle : bricks) {
    const SupportGraph::Node& node = *graph.find(handle);
    assembly.addFree(handle, node.mass, node.com);
  }
  for (std::size_t i = 0; i < bricks.size(); ++i) {
    const SupportGraph::Node& node = *graph.find(bricks[i]);
    assembly.addPatches(static_cast<int>(i), node.supports);
    assembly.addPatches(static_cast<int>(i), node.side_contacts);
  }
  return assembly;
}

}  // namespace

bool EquilibriumCriterion::standsOnTheRest(const SupportGraph& graph, BodyHandle brick,
                                           std::size_t* budget) const {
  std::vector<BodyHandle> bricks;
  for (const auto& reached : graph.withLoad(brick)) bricks.push_back(reached.first);
  // Past the budget it is taken as failing: woken, as the LP said.
  if (bricks.size() > *budget) return false;
  *budget -= bricks.size();
  const StaticsSolution solution = assemble(graph, bricks, options()).solve();
  return solution.solved && solution.feasible;
}

std::vector<WakeDecision> EquilibriumCriterion::check(
    SupportGraph* graph, const std::vector<BodyHandle>& component) const {
  std::vector<WakeDecision> by_com = ComCriterion::check(graph, component);
  if (by_com.empty()) return by_com;
  const StaticsAssembly assembly = assemble(*graph, component, options());
  const StaticsSolution solution = assembly.solve(&basis_);
  // A solver failure keeps the COM rule's answer: never freeze on no answer.
  if (!solution.solved) return by_com;
  std::vector<std::vector<ContactForce>> forces = assembly.contactForces(solution);
  for (std::size_t i = 0; i < component.size(); ++i)
    graph->find(component[i])->stability.contact_forces = std::move(forces[i]);
  if (solution.feasible) return {};

  // The least imbalance may sit on any brick of a chain that fails as a
  // whole (a couple is the same wherever it acts): on the top brick of a
  // leaning tower, which stands on the brick under it. Woken, such a brick
  // stays where it is and freezes again, for ever. What must move is a
  // brick that, with all it holds, cannot stand on the rest held fixed:
  // among the unbalanced bricks, else among those the COM rule found.
  // The checks together solve at most a few times the component's bricks.
  std::size_t budget = 4 * component.size();
  std::vector<WakeDecision> unstable;
  for (std::size_t i = 0; i < component.size(); ++i) {
    if (solution.imbalance[i] <= 0.0 || standsOnTheRest(*graph, component[i], &budget)) continue;
    const SupportGraph::Node& node = *graph->find(component[i]);
    unstable.push_back(WakeDecision{
        component[i], WakeCause::kOutsideSupport, component[i], node.stability.margin,
        "no contact forces within friction balance it (statics: " + percent(solution.imbalance[i]) +
            " of a brick's weight unbalanced)"});
  }
  if (!unstable.empty()) return unstable;
  for (WakeDecision& decision : by_com) {
    if (!standsOnTheRest(*graph, decision.brick, &budget)) unstable.push_back(std::move(decision));
  }
  if (!unstable.empty()) return unstable;
  // Nothing fails alone (bricks that stand only together): the LP's own
  // answer, rather than keep a structure frozen that statics says falls.
  for (std::size_t i = 0; i < component.size(); ++i) {
    if (solution.imbalance[i] <= 0.0) continue;
    unstable.push_back(
        WakeDecision{component[i], WakeCause::kOutsideSupport, component[i],
                     graph->find(component[i])->stability.margin,
                     "no contact forces within friction balance the structure (statics: " +
                         percent(solution.imbalance[i]) + " of a brick's weight unbalanced here)"});
  }
  return unstable;
}

}  // namespace brick_stack_sim
