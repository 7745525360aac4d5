#include "world/placement_statics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "stability/contact_classifier.h"
#include "stability/rigid_block_statics.h"
#include "stability/statics_assembly.h"
#include "stability/support_evaluation.h"
#include "util/text_format.h"
#include "world/placement_check.h"
#include "world/world_state.h"

namespace brick_stack_sim {

namespace {

// judgeAlone's parts: what the brick touches, and what its verdict says.

/// Every body the brick has a contact with, each once, in handle order.
std::vector<BodyHandle> touchedBodies(const std::vector<PairContact>& contacts) {
  std::vector<BodyHandle> touching;
  for (const PairContact& contact : contacts) touching.push_back(contact.b);
  std::sort(touching.begin(), touching.end());
  touching.erase(std::unique(touching.begin(), touching.end()), touching.end());
  return touching;
}

/// "a, b": the names of `bodies`, as the verdict's reason lists them.
std::string namesOf(const WorldState& w, const std::vector<BodyHandle>& bodies) {
  std::string names;
  for (BodyHandle other : bodies) names += (names.empty() ? "" : ", ") + w.nameOf(other);
  return names;
}

/// How firmly statics holds a brick: the least sideways acceleration,
/// along +-x or +-y, that would move it [m/s^2].
double leastMovingAcceleration(const std::vector<StaticsBody>& bodies,
                               const std::vector<StaticsContact>& statics,
                               const StaticsOptions& options) {
  double least = std::numeric_limits<double>::infinity();
  const Eigen::Vector3d directions[] = {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(-1, 0, 0),
                                        Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, -1, 0)};
  for (const Eigen::Vector3d& direction : directions)
    least = std::min(least, horizontalAccelerationMargin(bodies, statics, direction, options));
  return least;
}

/// The reason of a verdict that it stands: on what, and how firmly.
std::string standsReason(BrickState kind, const std::string& names, double acceleration_margin) {
  char text[64];
  std::snprintf(text, sizeof text, "%.3g m/s^2", acceleration_margin);
  return std::string(kind == BrickState::kStable ? "rests on " : "leans on ") + names +
         " (statics; a sideways acceleration of " + text + " would move it)";
}

}  // namespace

std::vector<PairContact> touchingBricks(const WorldState& w, BodyHandle brick, double friction,
                                        const PlacedSolid& box, const Eigen::Vector3d& low,
                                        const Eigen::Vector3d& high) {
  std::vector<PairContact> contacts;
  appendContacts(w, brick, friction, box, kTableHandle, true, &contacts);
  const Eigen::AlignedBox3d reach(low.array() - w.options.stability.contact_distance,
                                  high.array() + w.options.stability.contact_distance);
  std::vector<BodyHandle> near = w.dormant.near(reach.min(), reach.max());
  for (const BrickRecord* mover : w.sets.movers()) near.push_back(mover->handle);
  for (const BrickRecord* held : w.sets.held()) near.push_back(held->handle);
  std::sort(near.begin(), near.end());
  for (BodyHandle other : near)
    if (other != brick) appendContacts(w, brick, friction, box, other, true, &contacts);
  return contacts;
}

StaticsVerdict judgeAlone(const BodyMotion& brick, const std::vector<PairContact>& contacts,
                          const WorldState& w) {
  StaticsVerdict verdict;
  std::vector<const PairContact*> pointers;
  for (const PairContact& contact : contacts) pointers.push_back(&contact);
  verdict.touching = touchedBodies(contacts);
  // The COM margin of Brick.msg, on what carries it from below.
  BrickStability support;
  support.supports = supportPatches(
      brick, pointers, [](BodyHandle) { return true; }, w.options.stability,
      &support.side_contacts);
  evaluateSupport(brick.com, &support);
  verdict.margin = support.margin;
  // What it touches is held fixed; a brick resting on it from above is
  // left out, as in the running models: held fixed, it could press it down
  // with any force, where in truth it presses with its own weight at most.
  StaticsAssembly assembly(w.options.stability);
  assembly.addFree(brick.handle, brick.mass, brick.com);
  assembly.addPatches(0, support.supports);
  assembly.addPatches(0, support.side_contacts);
  const std::vector<StaticsBody>& bodies = assembly.bodies();
  const std::vector<StaticsContact>& statics = assembly.contacts();

  const std::string names = namesOf(w, verdict.touching);
  if (verdict.touching.empty()) {
    verdict.reason = "it would touch nothing: it would fall";
    return verdict;
  }
  StaticsOptions options;
  options.gravity = w.options.gravity;
  const StaticsSolution solution = solveStatics(bodies, statics, options);
  if (!solution.solved) {
    verdict.reason = "statics could not be solved: " + solution.message;
    return verdict;
  }
  if (!solution.feasible) {
    verdict.reason = "no contact forces within friction hold it on " + names;
    return verdict;
  }
  verdict.stands = true;
  verdict.kind = !support.supports.empty() && support.margin > w.options.stability.min_margin
                     ? BrickState::kStable
                     : BrickState::kLeaning;
  verdict.acceleration_margin = leastMovingAcceleration(bodies, statics, options);
  verdict.reason = standsReason(verdict.kind, names, verdict.acceleration_margin);
  return verdict;
}

}  // namespace brick_stack_sim
