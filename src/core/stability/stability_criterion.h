#pragma once

#include <memory>
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
  /// A criterion in this one's exact state (a warm-started solver's basis
  /// included), naming bodies with `name_of`.
  virtual std::unique_ptr<StabilityCriterion> clone(BodyNamer name_of) const = 0;

  /// Fills what `stability->supports` (its candidate patches) means for
  /// `brick` resting there alone: hulls, COM-above, margin.
  virtual void evaluate(const BodyMotion& brick, BrickStability* stability) const = 0;
  /// Whether `brick`, evaluated as `stability`, may join the stack as it is;
  /// when it may, `decision` says how (stable or leaning) and why.
  virtual bool admits(const BodyMotion& brick, const BrickStability& stability,
                      FreezeDecision* decision) const = 0;
  /// Judges one component of `graph` after a change (its bricks in handle
  /// order): updates each node's stability and returns the bricks that
  /// cannot stay, with their reasons.
  virtual std::vector<WakeDecision> check(SupportGraph* graph,
                                          const std::vector<BodyHandle>& component) const = 0;

  /// Whether it judges side contacts (leaning): the model then gathers them
  /// (BrickStability::side_contacts) and may ask it about groups.
  virtual bool usesSideContacts() const { return false; }
  /// Whether `group`, bricks at rest that touch each other and none of
  /// which `admits` alone (the planks of a V, a plank and its counterweight),
  /// may join the stack together, their supports among frozen bricks, the
  /// ground and each other as given; when they may, one decision per member,
  /// in the group's order. When they may not, `cannot_stay` (when given)
  /// names the members that must move whatever the others do (a collapse
  /// mechanism); empty when the criterion cannot tell.
  virtual bool admitsGroup(const std::vector<BodyMotion>& /*group*/,
                           const std::vector<BrickStability>& /*stability*/,
                           std::vector<FreezeDecision>* /*decisions*/,
                           std::vector<BodyHandle>* /*cannot_stay*/ = nullptr) const {
    return false;
  }
  /// Whether check() finds a component stable wherever the COM rule passes
  /// on every brick of it: a what-if may then skip check() when the rule
  /// passes on each brick a new load reaches (comRuleBearsPlacement).
  virtual bool trustsComRulePasses() const { return false; }
};

}  // namespace brick_stack_sim
