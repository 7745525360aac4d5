#pragma once

#include <map>
#include <set>
#include <vector>

#include "brick_stack_sim/core/geometry/load_distribution.h"
#include "stability/stability_model.h"
#include "brick_stack_sim/core/world/world_options.h"

namespace brick_stack_sim {

/// The thesis's basic stack stability model (chapter 3.3), with its loads
/// transmitted where they act (see distributeLoad) instead of its equation 10.
///
/// A moving brick at rest whose own COM lies inside the hull of its support
/// patches on frozen bricks or the table is frozen. The frozen bricks form a
/// support graph; whenever a component of it changes, the loads are passed
/// from the top down: each brick's COM-above is the resultant of its own weight
/// and the loads it receives, and a brick whose COM-above leaves its support
/// hull is woken together with everything it carries.
class ComStabilityModel : public StabilityModel {
 public:
  explicit ComStabilityModel(const StabilityOptions& options);

  void update(double dt, const std::vector<BodyMotion>& movers,
              const std::vector<PairContact>& contacts, StabilityDecisions* decisions) override;
  void placedAtRest(const BodyMotion& brick, const std::vector<PairContact>& contacts,
                    StabilityDecisions* decisions) override;
  void remove(BodyHandle brick, StabilityDecisions* decisions) override;
  void wake(BodyHandle brick, WakeCause cause, StabilityDecisions* decisions) override;
  void clear() override;
  bool describe(BodyHandle brick, BrickStability* stability) const override;

 private:
  /// A frozen brick: where it rests and, after a pass, what it carries.
  struct Node {
    Eigen::Vector3d com = Eigen::Vector3d::Zero();
    double mass = 0.0;
    std::vector<SupportPatch> supports;
    std::set<BodyHandle> carries;  // frozen bricks resting on it
    std::vector<LoadShare> received;
    BrickStability stability;
  };
  /// A moving brick: how long it has been at rest and its candidate supports.
  struct Mover {
    double rest_time = 0.0;
    BrickStability stability;
  };

  /// Support patches of a moving brick on frozen bricks or the ground.
  std::vector<SupportPatch> candidateSupports(
      const BodyMotion& body, const std::vector<const PairContact*>& contacts) const;
  void freeze(const BodyMotion& body, std::vector<SupportPatch> supports, double margin,
              StabilityDecisions* decisions);
  /// Wakes `brick` and, recursively, everything it carries.
  void wakeWithLoad(BodyHandle brick, const WakeDecision& first, StabilityDecisions* decisions);
  void runPasses(StabilityDecisions* decisions);
  /// Top-down load pass over one component; returns the bricks found unstable.
  std::vector<WakeDecision> passComponent(const std::vector<BodyHandle>& component);
  std::vector<BodyHandle> componentOf(BodyHandle start, std::set<BodyHandle>* seen) const;

  StabilityOptions options_;
  std::map<BodyHandle, Node> frozen_;
  std::map<BodyHandle, Mover> movers_;
  std::set<BodyHandle> dirty_;
};

/// Fills the hull, height and combined figures of `stability` from its supports
/// and evaluates `load_point` (the COM-above) against the combined hull.
void evaluateSupport(const Eigen::Vector3d& load_point, BrickStability* stability);

}  // namespace brick_stack_sim
