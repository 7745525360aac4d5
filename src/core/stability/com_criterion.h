#pragma once

#include "stability/stability_criterion.h"

namespace brick_stack_sim {

/// The thesis's basic rule (chapter 3.3) with its loads transmitted where
/// they act (see distributeLoad) instead of its equation 10. A brick at rest
/// whose own COM lies inside the hull of its support patches may join the
/// stack; in a component, loads pass from the top down, each brick's
/// COM-above being the resultant of its own weight and the loads it
/// receives, and a brick whose COM-above leaves its support hull cannot stay.
class ComCriterion : public StabilityCriterion {
 public:
  ComCriterion(const StabilityOptions& options, BodyNamer name_of);

  void evaluate(const BodyMotion& brick, BrickStability* stability) const override;
  bool admits(const BodyMotion& brick, const BrickStability& stability,
              FreezeDecision* decision) const override;
  std::vector<WakeDecision> check(SupportGraph* graph,
                                  const std::vector<BodyHandle>& component) const override;

 private:
  WakeDecision outsideSupport(BodyHandle brick, double margin) const;

  StabilityOptions options_;
  BodyNamer name_of_;
};

}  // namespace brick_stack_sim
