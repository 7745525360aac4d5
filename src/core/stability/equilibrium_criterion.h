#pragma once

#include "stability/com_criterion.h"

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
/// every brick free, decides; when it has no solution, the bricks of the
/// collapse mechanism its dual names wake, together.
class EquilibriumCriterion : public ComCriterion {
 public:
  EquilibriumCriterion(const StabilityOptions& options, BodyNamer name_of)
      : ComCriterion(options, std::move(name_of)) {
    judgeEveryFailureByStatics();
  }
  std::unique_ptr<StabilityCriterion> clone(BodyNamer name_of) const override {
    auto copy = std::make_unique<EquilibriumCriterion>(*this);
    copy->rename(std::move(name_of));
    return copy;
  }
};

}  // namespace brick_stack_sim
