#include "stability/support_graph.h"

#include <algorithm>
#include <deque>

namespace brick_stack_sim {

const SupportGraph::Node* SupportGraph::find(BodyHandle brick) const {
  auto found = nodes_.find(brick);
  return found == nodes_.end() ? nullptr : &found->second;
}

SupportGraph::Node* SupportGraph::find(BodyHandle brick) {
  auto found = nodes_.find(brick);
  return found == nodes_.end() ? nullptr : &found->second;
}

namespace {

bool listsSupporter(const std::vector<SupportPatch>& patches, BodyHandle supporter) {
  return std::any_of(patches.begin(), patches.end(),
                     [&](const SupportPatch& patch) { return patch.supporter == supporter; });
}

}  // namespace

void SupportGraph::add(BodyHandle brick, const Eigen::Vector3d& com, double mass,
                       std::vector<SupportPatch> supports,
                       std::vector<SupportPatch> side_contacts) {
  Node& node = nodes_[brick];
  node.com = com;
  node.mass = mass;
  node.supports = std::move(supports);
  node.side_contacts = std::move(side_contacts);
  // Links both ways: a brick of a group frozen together may already list
  // this one, which did not exist in the graph when it joined.
  auto link = [&](BodyHandle neighbour) {
    auto found = nodes_.find(neighbour);
    if (found == nodes_.end()) return;
    Node& other = found->second;
    if (listsSupporter(node.supports, neighbour)) other.carries.insert(brick);
    if (listsSupporter(node.side_contacts, neighbour)) other.leaned_on_by.insert(brick);
    if (listsSupporter(other.supports, brick)) node.carries.insert(neighbour);
    if (listsSupporter(other.side_contacts, brick)) node.leaned_on_by.insert(neighbour);
  };
  for (const SupportPatch& patch : node.supports) link(patch.supporter);
  for (const SupportPatch& patch : node.side_contacts) link(patch.supporter);
  dirty_.insert(brick);
}

void SupportGraph::unlinkFromSupporters(BodyHandle brick, const Node& node) {
  for (const SupportPatch& patch : node.supports) {
    auto supporter = nodes_.find(patch.supporter);
    if (supporter == nodes_.end()) continue;
    supporter->second.carries.erase(brick);
    dirty_.insert(patch.supporter);  // its load changed
  }
  for (const SupportPatch& patch : node.side_contacts) {
    auto other = nodes_.find(patch.supporter);
    if (other == nodes_.end()) continue;
    other->second.leaned_on_by.erase(brick);
    dirty_.insert(patch.supporter);
  }
}

std::vector<SupportGraph::Detached> SupportGraph::detachWithLoad(BodyHandle brick) {
  std::vector<Detached> detached;
  std::deque<std::pair<BodyHandle, BodyHandle>> queue{{brick, brick}};  // (brick, carried_by)
  while (!queue.empty()) {
    const auto [handle, carried_by] = queue.front();
    queue.pop_front();
    auto it = nodes_.find(handle);
    if (it == nodes_.end()) continue;  // already detached through another path
    Node node = std::move(it->second);
    nodes_.erase(it);
    unlinkFromSupporters(handle, node);
    dirty_.erase(handle);
    for (BodyHandle upper : node.carries) queue.emplace_back(upper, handle);
    for (BodyHandle leaning : node.leaned_on_by) queue.emplace_back(leaning, handle);
    detached.push_back(Detached{handle, carried_by, std::move(node)});
  }
  return detached;
}

std::set<BodyHandle> SupportGraph::erase(BodyHandle brick) {
  auto it = nodes_.find(brick);
  if (it == nodes_.end()) return {};
  std::set<BodyHandle> carried = it->second.carries;
  carried.insert(it->second.leaned_on_by.begin(), it->second.leaned_on_by.end());
  unlinkFromSupporters(brick, it->second);
  nodes_.erase(it);
  dirty_.erase(brick);
  return carried;
}

std::vector<BodyHandle> SupportGraph::componentOf(BodyHandle start,
                                                  std::set<BodyHandle>* seen) const {
  std::vector<BodyHandle> component;
  std::deque<BodyHandle> queue{start};
  seen->insert(start);
  while (!queue.empty()) {
    const BodyHandle handle = queue.front();
    queue.pop_front();
    auto it = nodes_.find(handle);
    if (it == nodes_.end()) continue;
    component.push_back(handle);
    auto visit = [&](BodyHandle next) {
      if (!isGround(next) && seen->insert(next).second) queue.push_back(next);
    };
    for (const SupportPatch& patch : it->second.supports) visit(patch.supporter);
    for (const SupportPatch& patch : it->second.side_contacts) visit(patch.supporter);
    for (BodyHandle upper : it->second.carries) visit(upper);
    for (BodyHandle leaning : it->second.leaned_on_by) visit(leaning);
  }
  std::sort(component.begin(), component.end());
  return component;
}

std::vector<std::vector<BodyHandle>> SupportGraph::takeChangedComponents() {
  std::set<BodyHandle> seen;
  std::vector<std::vector<BodyHandle>> components;
  for (BodyHandle handle : dirty_)
    if (!seen.count(handle)) components.push_back(componentOf(handle, &seen));
  dirty_.clear();
  return components;
}

void SupportGraph::loadOrder(const std::vector<BodyHandle>& component,
                             std::vector<BodyHandle>* order,
                             std::vector<BodyHandle>* cyclic) const {
  // Kahn's algorithm from the top: a brick is ready once everything it
  // carries has passed its load down.
  std::map<BodyHandle, int> waiting_for;
  std::deque<BodyHandle> ready;
  for (BodyHandle handle : component) {
    const Node& node = nodes_.at(handle);
    waiting_for[handle] = static_cast<int>(node.carries.size());
    if (node.carries.empty()) ready.push_back(handle);
  }
  order->clear();
  while (!ready.empty()) {
    const BodyHandle handle = ready.front();
    ready.pop_front();
    waiting_for.erase(handle);
    order->push_back(handle);
    for (const SupportPatch& patch : nodes_.at(handle).supports) {
      auto it = waiting_for.find(patch.supporter);
      if (it != waiting_for.end() && --it->second == 0) ready.push_back(patch.supporter);
    }
  }
  cyclic->clear();
  for (const auto& [handle, count] : waiting_for) cyclic->push_back(handle);
}

SupportGraph SupportGraph::componentsOf(const std::vector<BodyHandle>& seeds) const {
  SupportGraph copy;
  std::set<BodyHandle> seen;
  for (BodyHandle seed : seeds) {
    if (seen.count(seed)) continue;
    for (BodyHandle handle : componentOf(seed, &seen))
      copy.nodes_.emplace(handle, nodes_.at(handle));
  }
  return copy;
}

}  // namespace brick_stack_sim
