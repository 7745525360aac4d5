#pragma once

#include "stability/com_criterion.h"
#include "stability/rigid_block_statics.h"

namespace brick_stack_sim {

/// Exact rigid-block statics (mode `equilibrium`): a set of frozen bricks
/// stands when contact forces with non-negative normals inside the friction
/// cones balance every brick (solveStatics). No rule of thumb decides
/// support: a plank held only by a counterweight, a bridge that two towers
/// carry whatever a third supporter does, a V of planks, all stand when
/// statics says so.
///
/// Bricks join as in the COM rule (ComCriterion), whose check runs first on
/// every changed component and fills what the markers show: where it finds
/// every brick balanced, that is an equilibrium and the LP is skipped.
/// Where it finds a brick that cannot stay, the LP of the whole component,
/// every brick free, decides. When it has no solution, the bricks that
/// wake are those that, with all they hold, cannot stand on the rest held
/// fixed: never one the statics shows to be held by what is under it.
class EquilibriumCriterion : public ComCriterion {
 public:
  using ComCriterion::ComCriterion;

  std::vector<WakeDecision> check(SupportGraph* graph,
                                  const std::vector<BodyHandle>& component) const override;

 private:
  /// Whether `brick` with everything resting or leaning on it, directly or
  /// not, stands with every other body held fixed. Each check spends its
  /// number of bricks from `budget`; false once that is spent.
  bool standsOnTheRest(const SupportGraph& graph, BodyHandle brick, std::size_t* budget) const;

  /// The last component LP's basis: a structure that grows brick by brick
  /// is re-solved from it (a warm start) rather than from scratch.
  mutable StaticsBasis basis_;
};

}  // namespace brick_stack_sim
