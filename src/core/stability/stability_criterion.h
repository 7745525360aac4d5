#pragma once

#include <vector>

#include "stability/stability_model.h"

namespace brick_stack_sim {

class SupportGraph;

/// The rule that tells stable from unstable, over the parts every freezing
/// model shares (support graph, rest tracking, contact classification).
/// The COM-above rule of the thesis is one; an exact equilibrium LP another.
class StabilityCriterion {
 public:
  virtual ~StabilityCriterion() = default;

  /// Fills what `stability->supports` (its candidate patches) means for
  /// `brick` resting there alone: hulls, COM-above, margin.
  virtual void evaluate(const BodyMotion& brick, BrickStability* stability) const = 0;
  /// Whether `brick`, evaluated as `stability`, may join the stack as it is;
  /// when it may, `decision` says how (stable or leaning) and why.
  virtual bool admits(const BodyMotion& brick, const BrickStability& stability,
                      FreezeDecision* decision) const = 0;
  /// Judges one component of `graph` after a change, its bricks in load
  /// order (each after all it carries): updates each node's stability and
  /// returns the bricks that cannot stay, with their reasons.
  virtual std::vector<WakeDecision> check(SupportGraph* graph,
                                          const std::vector<BodyHandle>& load_order) const = 0;
};

}  // namespace brick_stack_sim
