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
                       std::vector<SupportPatch> supports, std::vector<SupportPatch> side_contacts,
                       bool leaning) {
  Node& node = nodes_[brick];
  node.leaning = leaning;
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

void SupportGraph::addCarried(BodyHandle carrier, SupportPatch patch) {
  auto upper = nodes_.find(patch.supporter);
  auto below = nodes_.find(carrier);
  if (upper == nodes_.end() || below == nodes_.end()) return;
  const BodyHandle brick = patch.supporter;
  patch.supporter = carrier;
  for (Eigen::Vector3d& normal : patch.normals) normal = -normal;
  std::vector<SupportPatch>& supports = upper->second.supports;
  // In supporter order, as every patch list.
  auto at = std::find_if(supports.begin(), supports.end(), [&](const SupportPatch& existing) {
    return existing.supporter >= carrier;
  });
  if (at != supports.end() && at->supporter == carrier) {
    at->points.insert(at->points.end(), patch.points.begin(), patch.points.end());
    at->normals.insert(at->normals.end(), patch.normals.begin(), patch.normals.end());
  } else {
    supports.insert(at, std::move(patch));
  }
  below->second.carries.insert(brick);
  dirty_.insert(carrier);
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

std::vector<std::pair<BodyHandle, BodyHandle>> SupportGraph::withLoad(BodyHandle brick) const {
  std::vector<std::pair<BodyHandle, BodyHandle>> found;
  std::set<BodyHandle> seen;
  std::deque<std::pair<BodyHandle, BodyHandle>> queue{{brick, brick}};  // (brick, reached from)
  while (!queue.empty()) {
    const auto [handle, carried_by] = queue.front();
    queue.pop_front();
    const Node* node = find(handle);
    if (!node || !seen.insert(handle).second) continue;  // reached through another path
    for (BodyHandle upper : node->carries) queue.emplace_back(upper, handle);
    for (BodyHandle leaning : node->leaned_on_by) queue.emplace_back(leaning, handle);
    found.emplace_back(handle, carried_by);
  }
  return found;
}

std::vector<SupportGraph::Detached> SupportGraph::detachWithLoad(BodyHandle brick) {
  std::vector<Detached> detached;
  for (const auto& [handle, carried_by] : withLoad(brick)) {
    auto it = nodes_.find(handle);
    Node node = std::move(it->second);
    nodes_.erase(it);
    unlinkFromSupporters(handle, node);
    dirty_.erase(handle);
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

std::set<BodyHandle> SupportGraph::eraseAndUnlink(BodyHandle brick) {
  const std::set<BodyHandle> neighbours = erase(brick);
  const auto touches_brick = [brick](const SupportPatch& patch) {
    return patch.supporter == brick;
  };
  for (BodyHandle neighbour : neighbours) {
    auto found = nodes_.find(neighbour);
    if (found == nodes_.end()) continue;
    Node& node = found->second;
    node.supports.erase(std::remove_if(node.supports.begin(), node.supports.end(), touches_brick),
                        node.supports.end());
    node.side_contacts.erase(
        std::remove_if(node.side_contacts.begin(), node.side_contacts.end(), touches_brick),
        node.side_contacts.end());
    dirty_.insert(neighbour);
  }
  return neighbours;
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
  for (const std::vector<BodyHandle>& component : components)
    redescribed_.insert(redescribed_.end(), component.begin(), component.end());
  return components;
}

std::vector<BodyHandle> SupportGraph::takeRedescribed() {
  std::vector<BodyHandle> taken;
  taken.swap(redescribed_);
  return taken;
}

namespace {

/// Strongly connected components (Tarjan), iteratively: a tower of
/// thousands of bricks is a path that deep. `edges[i]` lists the vertices i
/// passes load to; returns each vertex's component number.
std::vector<int> stronglyConnected(const std::vector<std::vector<int>>& edges) {
  const int n = static_cast<int>(edges.size());
  std::vector<int> index(n, -1), low(n, 0), component(n, -1), stack;
  std::vector<bool> on_stack(n, false);
  int next_index = 0, next_component = 0;
  std::vector<std::pair<int, std::size_t>> calls;  // (vertex, next edge)
  for (int root = 0; root < n; ++root) {
    if (index[root] >= 0) continue;
    calls.emplace_back(root, 0);
    while (!calls.empty()) {
      auto& [v, edge] = calls.back();
      if (edge == 0 && index[v] < 0) {
        index[v] = low[v] = next_index++;
        stack.push_back(v);
        on_stack[v] = true;
      }
      if (edge < edges[v].size()) {
        const int w = edges[v][edge++];
        if (index[w] < 0) {
          calls.emplace_back(w, 0);
        } else if (on_stack[w]) {
          low[v] = std::min(low[v], index[w]);
        }
        continue;
      }
      if (low[v] == index[v]) {
        for (int w = -1; w != v;) {
          w = stack.back();
          stack.pop_back();
          on_stack[w] = false;
          component[w] = next_component;
        }
        ++next_component;
      }
      const int finished = v;
      calls.pop_back();
      if (!calls.empty())
        low[calls.back().first] = std::min(low[calls.back().first], low[finished]);
    }
  }
  return component;
}

}  // namespace

std::vector<std::vector<BodyHandle>> SupportGraph::loadOrder(
    const std::vector<BodyHandle>& component, const LeaningTest& leans_on) const {
  std::map<BodyHandle, int> position;
  for (std::size_t i = 0; i < component.size(); ++i) position[component[i]] = static_cast<int>(i);
  // Who passes load to whom: supporters in order, then what a leaning brick leans on.
  std::vector<std::vector<int>> edges(component.size());
  for (std::size_t i = 0; i < component.size(); ++i) {
    const Node& node = nodes_.at(component[i]);
    auto to = [&](const SupportPatch& patch) {
      auto it = position.find(patch.supporter);
      if (it != position.end()) edges[i].push_back(it->second);
    };
    for (const SupportPatch& patch : node.supports) to(patch);
    if (node.leaning)
      for (const SupportPatch& patch : node.side_contacts)
        if (leans_on(patch)) to(patch);
  }
  // A brick resting on a leaning one shares its group (an edge back makes
  // them one): how a leaning brick takes a load is for statics to say, not
  // for a split of the load among supporters.
  for (std::size_t i = 0; i < component.size(); ++i) {
    for (const SupportPatch& patch : nodes_.at(component[i]).supports) {
      auto it = position.find(patch.supporter);
      if (it != position.end() && nodes_.at(patch.supporter).leaning)
        edges[it->second].push_back(static_cast<int>(i));
    }
  }
  const std::vector<int> group_of = stronglyConnected(edges);
  const int group_count =
      group_of.empty() ? 0 : *std::max_element(group_of.begin(), group_of.end()) + 1;
  std::vector<std::vector<BodyHandle>> groups(group_count);
  std::vector<int> waiting_for(group_count, 0);
  for (std::size_t i = 0; i < component.size(); ++i) {
    groups[group_of[i]].push_back(component[i]);  // in handle order, as the component
    for (int j : edges[i])
      if (group_of[j] != group_of[i]) ++waiting_for[group_of[j]];
  }
  // Kahn's algorithm from the top: a group is ready once every group
  // passing it load has passed it.
  std::deque<int> ready;
  std::vector<bool> queued(group_count, false);
  for (std::size_t i = 0; i < component.size(); ++i) {
    const int group = group_of[i];
    if (waiting_for[group] == 0 && !queued[group]) {
      queued[group] = true;
      ready.push_back(group);
    }
  }
  std::vector<std::vector<BodyHandle>> order;
  while (!ready.empty()) {
    const int group = ready.front();
    ready.pop_front();
    for (BodyHandle handle : groups[group]) {
      const int i = position.at(handle);
      for (int j : edges[i])
        if (group_of[j] != group && --waiting_for[group_of[j]] == 0) ready.push_back(group_of[j]);
    }
    order.push_back(std::move(groups[group]));
  }
  return order;
}

std::vector<BodyHandle> SupportGraph::bricks() const {
  std::vector<BodyHandle> handles;
  handles.reserve(nodes_.size());
  for (const auto& entry : nodes_) handles.push_back(entry.first);
  return handles;
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
