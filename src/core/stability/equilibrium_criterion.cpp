#include "stability/equilibrium_criterion.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "stability/support_evaluation.h"
#include "stability/support_graph.h"
#include "util/text_format.h"

namespace brick_stack_sim {

namespace {

/// The statics problem of a set of bricks, built from their patches.
class StaticsAssembly {
 public:
  /// `brick` is a free body; returns its index.
  int addFree(BodyHandle brick, double mass, const Eigen::Vector3d& com) {
    index_[brick] = static_cast<int>(bodies_.size());
    bodies_.push_back(StaticsBody{mass, com, false});
    return index_[brick];
  }
  /// The contacts of free body `body` on `patches`; a supporter that is not
  /// a free body is fixed (the ground, or a frozen brick taken as immovable).
  void addPatches(int body, const std::vector<SupportPatch>& patches) {
    for (const SupportPatch& patch : patches) {
      auto supporter = index_.find(patch.supporter);
      const int other = supporter == index_.end() ? kStaticsGround : supporter->second;
      for (std::size_t i = 0; i < patch.points.size(); ++i)
        contacts_.push_back(StaticsContact{body, other, patch.points[i], patch.normals[i],
                                           patch.friction});
    }
  }
  const std::vector<StaticsBody>& bodies() const { return bodies_; }
  const std::vector<StaticsContact>& contacts() const { return contacts_; }

 private:
  std::map<BodyHandle, int> index_;
  std::vector<StaticsBody> bodies_;
  std::vector<StaticsContact> contacts_;
};

std::string percent(double fraction) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g %%", 100.0 * fraction);
  return text;
}

}  // namespace

EquilibriumCriterion::EquilibriumCriterion(const StabilityOptions& options, BodyNamer name_of)
    : options_(options), name_of_(name_of), com_(options, std::move(name_of)) {}

void EquilibriumCriterion::evaluate(const BodyMotion& brick, BrickStability* stability) const {
  com_.evaluate(brick, stability);
}

bool EquilibriumCriterion::leans(const BrickStability& stability) const {
  // A side contact whose normal points down onto the brick is something
  // resting on it (a counterweight), not something it leans on.
  const double from_above = -std::cos(options_.support_normal_tolerance);
  for (const SupportPatch& patch : stability.side_contacts)
    for (const Eigen::Vector3d& normal : patch.normals)
      if (normal.z() > from_above) return true;
  return false;
}

FreezeDecision EquilibriumCriterion::admitted(const BodyMotion& brick,
                                              const BrickStability& stability) const {
  FreezeDecision decision;
  decision.brick = brick.handle;
  decision.kind = leans(stability) ? BrickState::kLeaning : BrickState::kStable;
  decision.margin = stability.margin;
  decision.supporters = supportersOf(stability);
  std::string names;
  for (BodyHandle supporter : decision.supporters)
    names += (names.empty() ? "" : ", ") + name_of_(supporter);
  decision.reason = std::string(decision.kind == BrickState::kLeaning ? "leans on " : "rests on ") +
                    names + ": contact forces within friction balance it (statics)";
  return decision;
}

bool EquilibriumCriterion::stands(const std::vector<BodyMotion>& bricks,
                                  const std::vector<const BrickStability*>& stability) const {
  StaticsAssembly assembly;
  for (const BodyMotion& brick : bricks) assembly.addFree(brick.handle, brick.mass, brick.com);
  for (std::size_t i = 0; i < bricks.size(); ++i) {
    assembly.addPatches(static_cast<int>(i), stability[i]->supports);
    assembly.addPatches(static_cast<int>(i), stability[i]->side_contacts);
  }
  const StaticsSolution solution = solveStatics(assembly.bodies(), assembly.contacts(), statics_);
  return solution.solved && solution.feasible;
}

bool EquilibriumCriterion::admits(const BodyMotion& brick, const BrickStability& stability,
                                  FreezeDecision* decision) const {
  // Resting with its COM over its supports is an equilibrium of vertical
  // forces: no LP needed. Without side contacts the LP of one brick on
  // fixed supporters says no more than that.
  if (com_.admits(brick, stability, decision)) return true;
  if (stability.side_contacts.empty()) return false;
  if (!stands({brick}, {&stability})) return false;
  *decision = admitted(brick, stability);
  return true;
}

bool EquilibriumCriterion::admitsGroup(const std::vector<BodyMotion>& group,
                                       const std::vector<BrickStability>& stability,
                                       std::vector<FreezeDecision>* decisions) const {
  std::vector<const BrickStability*> members;
  for (const BrickStability& s : stability) members.push_back(&s);
  if (!stands(group, members)) return false;
  decisions->clear();
  for (std::size_t i = 0; i < group.size(); ++i) {
    decisions->push_back(admitted(group[i], stability[i]));
    decisions->back().reason += ", with " + std::to_string(group.size() - 1) +
                                " brick(s) placed with it";
  }
  return true;
}

std::vector<WakeDecision> EquilibriumCriterion::check(
    SupportGraph* graph, const std::vector<BodyHandle>& component) const {
  // The COM rule fills what the markers show; where it finds nothing
  // unstable, vertical forces alone balance every brick.
  std::vector<WakeDecision> by_com = com_.check(graph, component);
  if (by_com.empty()) return by_com;
  StaticsAssembly assembly;
  for (BodyHandle handle : component) {
    const SupportGraph::Node& node = *graph->find(handle);
    assembly.addFree(handle, node.mass, node.com);
  }
  for (std::size_t i = 0; i < component.size(); ++i) {
    const SupportGraph::Node& node = *graph->find(component[i]);
    assembly.addPatches(static_cast<int>(i), node.supports);
    assembly.addPatches(static_cast<int>(i), node.side_contacts);
  }
  const StaticsSolution solution = solveStatics(assembly.bodies(), assembly.contacts(), statics_);
  // A solver failure keeps the COM rule's answer: never freeze on no answer.
  if (!solution.solved) return by_com;
  std::vector<WakeDecision> unstable;
  for (std::size_t i = 0; i < component.size(); ++i) {
    if (solution.imbalance[i] <= 0.0) continue;
    const SupportGraph::Node& node = *graph->find(component[i]);
    unstable.push_back(WakeDecision{
        component[i], WakeCause::kOutsideSupport, component[i], node.stability.margin,
        "no contact forces within friction balance it (statics: " +
            percent(solution.imbalance[i]) + " of a brick's weight unbalanced)"});
  }
  return unstable;
}

}  // namespace brick_stack_sim
