#pragma once

#include "stability/com_criterion.h"
#include "stability/rigid_block_statics.h"

namespace brick_stack_sim {

/// Exact rigid-block statics (mode `equilibrium`): a set of frozen bricks
/// stands when contact forces with non-negative normals inside the friction
/// cones balance every brick (solveStatics). No rule of thumb decides
/// support: a plank held only by a counterweight, a bridge that two towers
/// carry whatever a third supporter does, a V of planks, all stand when
/// statics says so. The COM rule runs first on every component and fills
/// what the markers show: where it finds every brick resting stably on
/// vertical forces alone, that is an equilibrium and the LP is skipped.
class EquilibriumCriterion : public StabilityCriterion {
 public:
  EquilibriumCriterion(const StabilityOptions& options, BodyNamer name_of);

  void evaluate(const BodyMotion& brick, BrickStability* stability) const override;
  bool admits(const BodyMotion& brick, const BrickStability& stability,
              FreezeDecision* decision) const override;
  std::vector<WakeDecision> check(SupportGraph* graph,
                                  const std::vector<BodyHandle>& component) const override;
  bool usesSideContacts() const override { return true; }
  bool admitsGroup(const std::vector<BodyMotion>& group,
                   const std::vector<BrickStability>& stability,
                   std::vector<FreezeDecision>* decisions) const override;

 private:
  /// Whether `bricks` (free), on their patches, with every supporter that
  /// is not one of them fixed, stand.
  bool stands(const std::vector<BodyMotion>& bricks,
              const std::vector<const BrickStability*>& stability) const;
  /// Whether it leans on something (a side contact other than a brick resting on it).
  bool leans(const BrickStability& stability) const;
  FreezeDecision admitted(const BodyMotion& brick, const BrickStability& stability) const;

  StabilityOptions options_;
  BodyNamer name_of_;
  ComCriterion com_;
  StaticsOptions statics_;
};

}  // namespace brick_stack_sim
