#include "stability/balanced_components.h"

#include <algorithm>

#include "stability/statics_assembly.h"

namespace brick_stack_sim {

namespace {

/// Components kept at a time: a pile has a few large ones, and the what-ifs
/// of the bricks that would join them pose one-off components of their own.
constexpr std::size_t kComponentsKept = 32;

bool samePoints(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i] != b[i]) return false;
  return true;
}

bool samePatches(const std::vector<SupportPatch>& a, const std::vector<SupportPatch>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].supporter != b[i].supporter || a[i].friction != b[i].friction ||
        !samePoints(a[i].points, b[i].points) || !samePoints(a[i].normals, b[i].normals))
      return false;
  }
  return true;
}

bool sameLoads(const std::vector<PointForce>& a, const std::vector<PointForce>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].force != b[i].force || a[i].point != b[i].point) return false;
  return true;
}

}  // namespace

std::uint64_t BalancedComponents::keyOf(const std::vector<BodyHandle>& sorted_bricks) {
  std::uint64_t key = 0xcbf29ce484222325ull;
  for (BodyHandle brick : sorted_bricks) key = (key ^ brick) * 0x100000001b3ull;
  return key;
}

void BalancedComponents::keep(const SupportGraph& graph, const std::vector<BodyHandle>& component) {
  std::vector<BodyHandle> sorted = component;
  std::sort(sorted.begin(), sorted.end());
  if (kept_.size() >= kComponentsKept && !kept_.count(keyOf(sorted))) kept_.clear();
  Component& kept = kept_[keyOf(sorted)];
  kept.clear();
  for (BodyHandle handle : sorted) {
    const SupportGraph::Node& node = *graph.find(handle);
    kept.push_back(Brick{handle, node.com, node.mass, node.leaning, node.supports,
                         node.side_contacts, node.stability.external_loads,
                         node.stability.contact_forces});
  }
}

void BalancedComponents::forget(const std::vector<BodyHandle>& component) {
  std::vector<BodyHandle> sorted = component;
  std::sort(sorted.begin(), sorted.end());
  kept_.erase(keyOf(sorted));
}

bool BalancedComponents::stillBalanced(SupportGraph* graph,
                                       const std::vector<BodyHandle>& component,
                                       const StabilityOptions& options, double load_factor) {
  std::vector<BodyHandle> sorted = component;
  std::sort(sorted.begin(), sorted.end());
  const auto found = kept_.find(keyOf(sorted));
  if (found == kept_.end()) return false;
  Component& kept = found->second;
  Local local;
  if (!reachOfChangedLoads(*graph, sorted, kept, options, &local)) return false;
  if (!local.reached.empty() && !solveLocally(*graph, sorted, local, options, load_factor, &kept))
    return false;
  for (std::size_t i = 0; i < sorted.size(); ++i)
    graph->find(sorted[i])->stability.contact_forces = kept[i].forces;
  return true;
}

std::ptrdiff_t BalancedComponents::indexIn(const std::vector<BodyHandle>& sorted,
                                           BodyHandle handle) {
  const auto at = std::lower_bound(sorted.begin(), sorted.end(), handle);
  return at != sorted.end() && *at == handle ? at - sorted.begin() : -1;
}

bool BalancedComponents::reachOfChangedLoads(const SupportGraph& graph,
                                             const std::vector<BodyHandle>& sorted,
                                             const Component& kept, const StabilityOptions& options,
                                             Local* local) {
  if (kept.size() != sorted.size()) return false;
  // The same bricks where they were, on the same contacts; whose loads changed.
  local->in.assign(sorted.size(), 0);
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    const SupportGraph::Node& node = *graph.find(sorted[i]);
    const Brick& brick = kept[i];
    if (brick.handle != sorted[i] || brick.com != node.com || brick.mass != node.mass ||
        brick.leaning != node.leaning || !samePatches(brick.supports, node.supports) ||
        !samePatches(brick.side_contacts, node.side_contacts))
      return false;
    if (!sameLoads(brick.loads, node.stability.external_loads)) {
      local->in[i] = 1;
      local->reached.push_back(i);
    }
  }
  // What a changed load reaches going down: the bricks it rests or leans on.
  for (std::size_t next = 0; next < local->reached.size(); ++next) {
    const SupportGraph::Node& node = *graph.find(sorted[local->reached[next]]);
    const auto reach = [&](const SupportPatch& patch) {
      const std::ptrdiff_t below = indexIn(sorted, patch.supporter);
      if (below < 0 || local->in[below]) return;
      local->in[below] = 1;
      local->reached.push_back(static_cast<std::size_t>(below));
    };
    for (const SupportPatch& patch : node.supports) reach(patch);
    for (const SupportPatch& patch : node.side_contacts)
      if (leansOn(patch, options)) reach(patch);
  }
  std::sort(local->reached.begin(), local->reached.end());
  return true;
}

bool BalancedComponents::solveLocally(const SupportGraph& graph,
                                      const std::vector<BodyHandle>& sorted, const Local& local,
                                      const StabilityOptions& options, double load_factor,
                                      Component* kept) {
  const auto left_out = [&](BodyHandle handle) {
    const std::ptrdiff_t other = indexIn(sorted, handle);
    return other >= 0 && !local.in[other];
  };
  StaticsAssembly assembly(options);
  for (std::size_t i : local.reached) {
    const SupportGraph::Node& node = *graph.find(sorted[i]);
    assembly.addFree(sorted[i], node.mass, node.com);
  }
  // Contacts with the bricks left out push with the kept forces; those
  // among the local bricks and with the ground are the problem's. Every
  // brick a local one rests or leans on is local; a contact with one left
  // out is from above, which addPatches leaves out with a fixed body.
  for (std::size_t body = 0; body < local.reached.size(); ++body) {
    const std::size_t i = local.reached[body];
    const SupportGraph::Node& node = *graph.find(sorted[i]);
    const int free = static_cast<int>(body);
    assembly.addPatches(free, node.supports);
    assembly.addPatches(free, node.side_contacts);
    for (const PointForce& load : node.stability.external_loads)
      assembly.addLoad(free, PointForce{load_factor * load.force, load.point});
    for (const ContactForce& force : (*kept)[i].forces)
      if (left_out(force.other)) assembly.addLoad(free, PointForce{force.force, force.point});
  }
  ++local_solves_;
  const StaticsSolution solution = assembly.solve(&basis_);
  if (!solution.solved || !solution.feasible) return false;
  std::vector<std::vector<ContactForce>> forces = assembly.contactForces(solution);
  for (std::size_t body = 0; body < local.reached.size(); ++body) {
    Brick& brick = (*kept)[local.reached[body]];
    std::vector<ContactForce> kept_outside;
    for (const ContactForce& force : brick.forces)
      if (left_out(force.other)) kept_outside.push_back(force);
    brick.forces = std::move(forces[body]);
    brick.forces.insert(brick.forces.end(), kept_outside.begin(), kept_outside.end());
    brick.loads = graph.find(brick.handle)->stability.external_loads;
  }
  return true;
}

}  // namespace brick_stack_sim
