#include "stability/placement_load.h"

#include <algorithm>
#include <unordered_map>
#include <vector>

#include "brick_stack_sim/core/geometry/load_distribution.h"
#include "brick_stack_sim/core/geometry/polygon2d.h"

namespace brick_stack_sim {

namespace {

/// A brick below the new one, while the new load flows down.
struct LoadedBrick {
  const SupportGraph::Node* node = nullptr;
  /// Shares from bricks that the new load reaches, the new brick included.
  std::vector<LoadShare> received;
  /// Its carriers that the new load reaches and that have not passed their share yet.
  int waiting_for = 0;
};

/// What the COM rule may take for granted on a brick: its load acts
/// straight down and reaches it through its supports only.
bool loadedAsTheRuleAssumes(const SupportGraph::Node& node) {
  return !node.leaning && node.pushes.empty() && node.stability.external_loads.empty() &&
         node.received.size() == node.received_from.size();
}

/// Splits `mass` acting at `point` over the support patches of `supports`;
/// false when no combination of them carries it.
bool splitOver(double mass, const Eigen::Vector2d& point, const std::vector<SupportPatch>& supports,
               std::vector<LoadShare>* shares) {
  std::vector<Polygon2d> hulls;
  hulls.reserve(supports.size());
  for (const SupportPatch& patch : supports) hulls.push_back(patch.hull);
  return distributeLoad(mass, point, hulls, shares) != LoadSplitRule::kUnsupported;
}

/// The frozen bricks a weight on `supports` reaches: those supporters and
/// theirs, down, each with how many of its carriers among them pass it a
/// share first. False when one of them is not loaded as the rule assumes.
bool reachedBy(const SupportGraph& graph, const std::vector<SupportPatch>& supports,
               std::unordered_map<BodyHandle, LoadedBrick>* below) {
  std::vector<BodyHandle> frontier;
  for (const SupportPatch& patch : supports) frontier.push_back(patch.supporter);
  while (!frontier.empty()) {
    const BodyHandle handle = frontier.back();
    frontier.pop_back();
    if (isGround(handle) || below->count(handle)) continue;
    const SupportGraph::Node* node = graph.find(handle);
    if (!node || !loadedAsTheRuleAssumes(*node)) return false;
    (*below)[handle].node = node;
    for (const SupportPatch& patch : node->supports) frontier.push_back(patch.supporter);
  }
  for (auto& [handle, loaded] : *below)
    for (BodyHandle carried : loaded.node->carries) loaded.waiting_for += below->count(carried);
  return true;
}

}  // namespace

bool comRuleBearsPlacement(const SupportGraph& graph, const BodyMotion& brick,
                           const BrickStability& stability, double min_margin) {
  if (graph.hasChanges() || !stability.side_contacts.empty() || !stability.external_loads.empty() ||
      stability.supports.empty() || !(stability.margin > min_margin))
    return false;
  std::unordered_map<BodyHandle, LoadedBrick> below;
  if (!reachedBy(graph, stability.supports, &below)) return false;

  std::vector<LoadShare> shares;
  std::vector<BodyHandle> ready;
  // Passes `mass` at `point` (its COM at `height`) down `supports` from `from`.
  const auto passDown = [&](BodyHandle from, double mass, const Eigen::Vector3d& point,
                            const std::vector<SupportPatch>& supports) {
    if (!splitOver(mass, point.head<2>(), supports, &shares)) return false;
    for (std::size_t i = 0; i < supports.size(); ++i) {
      const auto found = below.find(supports[i].supporter);
      if (found == below.end()) continue;  // the ground carries anything
      LoadShare share = shares[i];
      share.height = point.z();
      found->second.received.push_back(share);
      if (from != brick.handle && --found->second.waiting_for == 0) ready.push_back(found->first);
    }
    return true;
  };
  if (!passDown(brick.handle, brick.mass, brick.com, stability.supports)) return false;
  for (const auto& [handle, loaded] : below)
    if (loaded.waiting_for == 0) ready.push_back(handle);

  std::size_t judged = 0;
  while (!ready.empty()) {
    const BodyHandle handle = ready.back();
    ready.pop_back();
    const LoadedBrick& loaded = below.at(handle);
    const SupportGraph::Node& node = *loaded.node;
    // COM-above, as massAbove() sums it: its own weight, what bricks the
    // new weight does not reach left on it, and the new shares.
    double mass = node.mass;
    Eigen::Vector3d moment = node.mass * node.com;
    const auto add = [&](const LoadShare& share) {
      mass += share.mass;
      moment += share.mass * Eigen::Vector3d(share.point.x(), share.point.y(), share.height);
    };
    for (std::size_t i = 0; i < node.received.size(); ++i)
      if (!below.count(node.received_from[i])) add(node.received[i]);
    for (const LoadShare& share : loaded.received) add(share);
    const Eigen::Vector3d com_above = moment / mass;
    if (!(signedDistance(node.stability.combined_hull, com_above.head<2>()) > min_margin))
      return false;
    if (!passDown(handle, mass, com_above, node.supports)) return false;
    ++judged;
  }
  // A brick never ready waits on a cycle of supports.
  return judged == below.size();
}

}  // namespace brick_stack_sim
