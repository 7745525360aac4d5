#pragma once

#include <memory>
#include <utility>

#include "stability/balanced_components.h"
#include "stability/rigid_block_statics.h"
#include "stability/stability_criterion.h"
#include "stability/statics_memo.h"
#include "stability/support_graph.h"

namespace brick_stack_sim {

/// The thesis's rule (chapters 3.3 to 3.5) with its loads transmitted where
/// they act (see distributeLoad) instead of its equation 10, and its leaning
/// done by statics.
///
/// A brick at rest whose own COM lies inside the hull of its support patches
/// may join the stack. One that does not, but touches frozen bricks or the
/// ground beside it, joins as leaning when contact forces within friction
/// balance it with those as fixed supports (a small statics LP, any number
/// of contacts); bricks placed at rest together (a V) are judged as a group.
///
/// In a component, loads pass from the top down. A brick's COM-above is
/// where the resultant of its weight and the loads it receives crosses its
/// support plane; it cannot stay when that point leaves its support hull,
/// or when the sideways part exceeds friction. A group of leaning bricks
/// (one plank, or the planks of a V) is balanced by the LP with what it
/// leans on fixed, and passes the LP's contact forces, sideways parts
/// included, to what it leans on: a pushed standing brick or a loaded
/// cantilever tips.
class ComCriterion : public StabilityCriterion {
 public:
  ComCriterion(const StabilityOptions& options, BodyNamer name_of);

  void evaluate(const BodyMotion& brick, BrickStability* stability) const override;
  bool admits(const BodyMotion& brick, const BrickStability& stability,
              FreezeDecision* decision) const override;
  std::vector<WakeDecision> check(SupportGraph* graph,
                                  const std::vector<BodyHandle>& component) const override;
  std::unique_ptr<StabilityCriterion> clone(BodyNamer name_of) const override {
    auto copy = std::make_unique<ComCriterion>(*this);
    copy->rename(std::move(name_of));
    return copy;
  }
  bool usesSideContacts() const override { return true; }
  /// Statics is asked only where the COM rule fails (check()).
  bool trustsComRulePasses() const override { return true; }
  bool admitsGroup(const std::vector<BodyMotion>& group,
                   const std::vector<BrickStability>& stability,
                   std::vector<FreezeDecision>* decisions,
                   std::vector<BodyHandle>* cannot_stay = nullptr) const override;

 protected:
  /// A copy names the bodies of its own world.
  void rename(BodyNamer name_of) { name_of_ = std::move(name_of); }
  /// Every failure the COM rule finds is judged by the statics of the
  /// whole component (mode equilibrium); else only failures in components
  /// where loads are shared, whose split the rule can only guess.
  void judgeEveryFailureByStatics() { statics_on_every_failure_ = true; }

 private:
  /// The COM rule, loads passed down group by group; `shared` is set when
  /// a load is split among several supporters or balanced by statics (a
  /// leaning group): there the rule's split is one of many.
  std::vector<WakeDecision> checkLoadsDown(SupportGraph* graph,
                                           const std::vector<BodyHandle>& component,
                                           bool* shared) const;
  /// Rigid-block statics of the whole component, every brick free: none
  /// wakes when contact forces within friction balance it; else the bricks
  /// of its collapse mechanism. `by_com` when the LP does not solve.
  std::vector<WakeDecision> judgeByStatics(SupportGraph* graph,
                                           const std::vector<BodyHandle>& component,
                                           std::vector<WakeDecision> by_com) const;
  /// One brick that passes its load down its supports: its COM-above from
  /// the loads it receives, judged against its hull; its load split among
  /// its supporters. False (and `unstable`) when it cannot stay.
  bool passLoadDown(SupportGraph* graph, BodyHandle brick, std::vector<LoadShare>* shares,
                    std::vector<WakeDecision>* unstable) const;
  /// A group that holds a leaning brick: balanced by statics with what it
  /// rests or leans on fixed, passing the contact forces on.
  void balanceLeaning(SupportGraph* graph, const std::vector<BodyHandle>& group,
                      std::vector<WakeDecision>* unstable) const;
  /// Whether `bricks` (free), on their patches, with every supporter that
  /// is not one of them fixed, stand.
  bool stands(const std::vector<BodyMotion>& bricks,
              const std::vector<const BrickStability*>& stability) const;
  /// The statics of stands(), from and into `basis` when given.
  StaticsSolution solveFree(const std::vector<BodyMotion>& bricks,
                            const std::vector<const BrickStability*>& stability,
                            StaticsBasis* basis = nullptr) const;
  /// Whether the loads pressing on it from outside the stack leave it
  /// pressed onto its supports, sideways within friction.
  bool loadsHold(const BodyMotion& brick, const BrickStability& stability) const;
  /// Whether a support of it leans further from level than its friction
  /// could hold a vertical load on (then the COM rule's vertical loads are
  /// not an equilibrium, and statics must say whether it rests).
  bool inclined(const BrickStability& stability) const;
  /// Admitted by statics: stable or leaning, and on what.
  FreezeDecision admittedByStatics(const BodyMotion& brick, const BrickStability& stability) const;
  WakeDecision outsideSupport(BodyHandle brick, double margin) const;

  StabilityOptions options_;
  BodyNamer name_of_;
  bool statics_on_every_failure_ = false;
  /// Where the component LPs ended: a structure that grows brick by brick
  /// is re-solved from it (a warm start) rather than from scratch.
  mutable StaticsBasis basis_;
  /// Where the group LPs ended: a group asked again at the next tick, or
  /// with the bricks that cannot stay taken out, is mostly the same problem
  /// (with the other groups' LPs between).
  mutable StaticsBasis group_basis_;
  /// A pile's component is judged again each time a brick joins it, and
  /// its leaning groups far from the newcomer pose the same LPs again.
  mutable StaticsMemo memo_;
  /// The component LPs that balanced: a load change is judged where it acts.
  mutable BalancedComponents balanced_;
};

}  // namespace brick_stack_sim
