#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <unordered_map>

#include "stability/contact_loads.h"
#include "stability/rest_tracker.h"
#include "stability/stability_criterion.h"
#include "stability/stability_model.h"
#include "stability/support_graph.h"

namespace brick_stack_sim {

class ContactIndex;
class ContactSpan;

/// A stability model that freezes bricks into a support graph (thesis 3.3),
/// with the rule for stable and unstable left to a criterion. A moving brick
/// at rest for `rest_time` on frozen bricks or the ground joins the stack
/// when the criterion admits it; whenever a component of the graph changes,
/// the criterion judges it, and a brick it finds unstable is woken with
/// everything it carries, until nothing changes (waking a counterweight can
/// tip a brick below).
class StackStabilityModel : public StabilityModel {
 public:
  StackStabilityModel(const StabilityOptions& options, BodyNamer name_of,
                      std::unique_ptr<StabilityCriterion> criterion);

  bool judgesLeaning() const override { return criterion_->usesSideContacts(); }
  bool judgesImpacts() const override { return true; }
  void judgeImpacts(const std::vector<Impact>& impacts, std::vector<ImpactResponse>* responses,
                    StabilityDecisions* decisions) override;
  std::vector<BodyHandle> carriedBy(BodyHandle brick) const override;
  void decide(const StabilityInput& input, StabilityDecisions* decisions) override;
  PlacementEvaluation evaluatePlacement(const BodyMotion& brick,
                                        const std::vector<PairContact>& contacts) const override;
  bool describe(BodyHandle brick, BrickStability* stability) const override;
  std::vector<BodyHandle> takeRedescribed() override { return graph_.takeRedescribed(); }
  std::unique_ptr<StabilityModel> clone(BodyNamer name_of) const override;

 private:
  /// `other`'s exact state, naming bodies with `name_of` (clone()).
  StackStabilityModel(const StackStabilityModel& other, BodyNamer name_of);
  /// `body` joins `graph` on its supports and side contacts. A frozen brick
  /// resting on it from above (it was slid under a bridge) gains it as a
  /// supporter: that brick's load now has one more way down.
  static void join(SupportGraph* graph, const BodyMotion& body, bool leaning,
                   BrickStability stability, const StabilityOptions& options);
  /// A brick left the stack (`what_happened`: "removed", "grasped"): what
  /// it carried wakes.
  void forget(BodyHandle brick, const char* what_happened, StabilityDecisions* decisions);
  /// A frozen brick an impact slid rests anew where it is now, or wakes
  /// when it does not rest there; what it carried is judged again.
  void slide(const RestingPlacement& slid, StabilityDecisions* decisions);
  /// A brick placed at rest joins at once when the criterion admits it,
  /// alone or with the bricks placed at rest at the same instant that it
  /// touches (Bullet cannot hold a V for one step: it is judged now or never).
  void placeAtRest(const RestingPlacement& placed, StabilityDecisions* decisions);
  /// The bricks placed at rest, not yet admitted, that `newest` reaches
  /// through contacts among them: admitted together when the criterion says
  /// so. `frozen_contacts`: those of a brick just frozen that they touch.
  void admitGroupAtRest(BodyHandle newest, StabilityDecisions* decisions,
                        const std::vector<PairContact>* frozen_contacts = nullptr);
  /// The step's contacts: what movers and held bricks press on the frozen
  /// bricks and on the movers at rest.
  void measureLoads(const StabilityInput& input);
  /// Frozen bricks whose measured loads changed take them into their
  /// statics: their components are judged again.
  void applyLoads();
  /// The step's movers: rest times, candidate supports, and freezing from the
  /// bottom up (a brick at rest on one that freezes now may freeze too).
  void advanceMovers(const StabilityInput& input, StabilityDecisions* decisions);
  /// Of the movers at rest that did not freeze alone (`resting`, nulled as
  /// they freeze), the groups that touch each other and something frozen or
  /// the ground: each joins the stack as a whole when the criterion admits
  /// it (a pile's planks leaning on planks that are themselves at rest).
  /// `props`, at rest for less than a window, join the groups they touch;
  /// a group of props alone is not asked.
  void admitRestingGroups(const ContactIndex& index, std::vector<const BodyMotion*>* resting,
                          const std::vector<const BodyMotion*>& props,
                          StabilityDecisions* decisions);
  /// Of `bodies` (in handle order), at rest and touching each other as
  /// `index` says, the part that stands joins the stack: the whole group
  /// when the criterion admits it and the stack it joins still passes its
  /// check; else the group without the members that must move whatever the
  /// others do (the collapse mechanism), asked again, those left out
  /// pressing on it with their measured loads. A group a mover presses on
  /// where it would join (pressedWhereItWouldJoin) waits as a whole, and
  /// statics is not asked. Returns the bricks that froze.
  std::vector<BodyHandle> freezeWhatStands(std::vector<BodyMotion> bodies,
                                           const ContactIndex& index,
                                           std::map<BodyHandle, bool>* pressed_components,
                                           StabilityDecisions* decisions);
  /// Whether a brick that moves presses on a member of `bodies` (evaluated
  /// into `stability`) or on a brick of a frozen component a member rests
  /// or leans on: then the what-if of any group that keeps that member is
  /// pressedByMovers(). `pressed_components` keeps, per frozen brick, its
  /// component's answer for the rest of the step.
  bool pressedWhereItWouldJoin(const std::vector<BodyMotion>& bodies,
                               const std::vector<BrickStability>& stability,
                               std::map<BodyHandle, bool>* pressed_components) const;
  /// `bodies` (in handle order), placed at rest together and touching each
  /// other as `index` says, join the stack together when something frozen
  /// or the ground holds them and the criterion admits them as a group.
  /// True when they froze.
  bool admitTogether(const std::vector<BodyMotion>& bodies, const ContactIndex& index,
                     StabilityDecisions* decisions);
  /// Each of `bodies` (in handle order) evaluated into `stability` on its
  /// contacts in `index` with frozen bricks, the ground and each other,
  /// loaded by what `presses` (when given) says presses on it. False when
  /// nothing outside the group holds it: bricks that touch only each other
  /// cannot balance their weight (a tower placed in the air).
  bool evaluateGroup(const std::vector<BodyMotion>& bodies, const ContactIndex& index,
                     const ContactLoads::BodyTest* presses,
                     std::vector<BrickStability>* stability) const;
  /// Whether the stack, with `bodies` joined as `admitted` says, passes the
  /// check that wakes frozen bricks: a group that rests on frozen bricks
  /// must not freeze only to wake them, and itself, at the next check. The
  /// members the check would wake are added to `cannot_stay`.
  bool standsJoined(const std::vector<BodyMotion>& bodies,
                    const std::vector<BrickStability>& stability,
                    const std::vector<FreezeDecision>& admitted,
                    std::vector<BodyHandle>* cannot_stay) const;
  /// Evaluates `body` on its supports among `contacts` into `stability`;
  /// true (and `decision`) when the criterion admits it.
  bool evaluateMover(const BodyMotion& body, ContactSpan contacts, BrickStability* stability,
                     FreezeDecision* decision) const;
  void freeze(const BodyMotion& body, FreezeDecision decision, BrickStability stability,
              StabilityDecisions* decisions);
  /// A copy of the components `body` would join, admitted as `decision` on
  /// `stability`, with it joined: a what-if. Nothing changes.
  SupportGraph joinedCopy(const BodyMotion& body, const BrickStability& stability,
                          const FreezeDecision& decision) const;
  /// Whether `body` may freeze again where the model woke it: rigid-block
  /// statics of the component it would join, with it, holds with every
  /// measured load a margin larger.
  bool standsWithMargin(const BodyMotion& body, const BrickStability& stability,
                        const FreezeDecision& decision) const;
  /// Wakes `first.brick` and everything it carries; `rest` (when given)
  /// starts each over as a mover.
  void wakeWithLoad(const WakeDecision& first, SupportGraph* graph, RestTracker* rest,
                    StabilityDecisions* decisions) const;
  /// Judges the changed components of `graph` until nothing changes. With
  /// `input` (the step's, `graph` being the model's own), a component the
  /// criterion would wake is asked again with the bricks at rest on it
  /// (standsWithSourcesAtRest).
  void settle(SupportGraph* graph, RestTracker* rest, StabilityDecisions* decisions,
              const StabilityInput* input = nullptr) const;
  /// Whether `component` of `graph` (the model's), with the movers at rest that
  /// press on it joined as free bodies on their contacts (instead of their
  /// measured loads), leaves every brick of it standing; then the stability
  /// the check found is left on its bricks. What bricks at rest press on a
  /// frozen one is statically indeterminate where they also rest elsewhere:
  /// the engine's split of it is one of many, and it jitters.
  bool standsWithSourcesAtRest(SupportGraph* graph, const std::vector<BodyHandle>& component,
                               const StabilityInput& input) const;

  StabilityOptions options_;
  BodyNamer name_of_;
  std::unique_ptr<StabilityCriterion> criterion_;
  SupportGraph graph_;
  RestTracker rest_;
  ContactLoads loads_;
  /// The movers at rest in the last step measured, in handle order.
  std::vector<BodyHandle> resting_;
  /// How long [s] a refused mover waits, on a step of `dt` [s], until the
  /// next tick at which every refused mover is asked again.
  double untilSharedTick(double dt) const;
  /// Whether this step, of `dt` [s], is such a tick.
  bool atSharedTick(double dt) const;
  /// Steps of `dt` [s] in a rest window (at least one).
  std::uint64_t restWindowSteps(double dt) const;
  /// Whether the model woke `body` and it has not moved away since.
  bool wokenInPlace(const BodyMotion& body) const;
  /// Whether `body`, a source of measured loads, is not among resting_.
  bool moves(BodyHandle body) const;
  /// Whether a brick that moves presses on a brick of `what_if`: then what
  /// statics says of it now may not hold a step on (a collapse that has not
  /// ended).
  bool pressedByMovers(const SupportGraph& what_if) const;
  /// Whether a load measured on `brick` comes from a brick that moves.
  bool pressedByAMover(BodyHandle brick) const;
  /// Takes off the frozen bricks of `what_if` the loads measured from
  /// `joiners` (handle order), bricks at rest that join it: their weight
  /// now passes through their contacts, and kept as a load too it was
  /// borne twice.
  void unloadJoiners(SupportGraph* what_if, const std::vector<BodyHandle>& joiners) const;
  std::uint64_t steps_ = 0;  ///< Steps the model has seen.
  /// When each frozen brick last took a changed load into its statics.
  std::unordered_map<BodyHandle, std::uint64_t> loads_judged_at_;
  /// Bricks placed at rest since the last step that did not join alone.
  std::map<BodyHandle, RestingPlacement> unjudged_;
  /// For an unjudged brick, the unjudged bricks placed after it that touch
  /// it (its own contacts name only those placed before).
  std::map<BodyHandle, std::vector<BodyHandle>> touched_by_;
};

}  // namespace brick_stack_sim
