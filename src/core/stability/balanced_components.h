#pragma once

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "stability/rigid_block_statics.h"
#include "stability/support_graph.h"

namespace brick_stack_sim {

/// The last contact forces that balanced each component of a stack, kept so
/// that a load change is judged where it acts. A frozen pile's component of
/// hundreds of bricks is judged again whenever a moving brick's load on one
/// of them changes, and its statics LP was the stability stage's cost.
///
/// When a component is judged again with the same bricks on the same
/// contacts and only some of its measured loads changed, the bricks those
/// loads reach going down (what they rest or lean on, to the ground) are
/// solved alone, the other bricks' contacts with them pushing with the kept
/// forces. A solution there, with the kept forces everywhere else, balances
/// every brick of the component: the others receive what they did, and
/// their loads did not change. So "balanced" from the local problem is
/// exact; the local problem having none says nothing, and the whole
/// component is solved.
class BalancedComponents {
 public:
  /// Whether `component` of `graph` is still balanced by the kept forces,
  /// re-solved where its loads (times `load_factor`) changed. When true, it
  /// leaves on every brick the contact forces that balance it (and keeps
  /// them). False when nothing is kept for these bricks and contacts, or
  /// the local problem has no solution.
  bool stillBalanced(SupportGraph* graph, const std::vector<BodyHandle>& component,
                     const StabilityOptions& options, double load_factor);
  /// Keeps the contact forces now on the bricks of `component` (a balanced
  /// solution of all of it), with its bricks, contacts and loads.
  void keep(const SupportGraph& graph, const std::vector<BodyHandle>& component);
  /// Forgets what was kept for `component`'s bricks (it did not balance).
  void forget(const std::vector<BodyHandle>& component);

  std::size_t localSolves() const { return local_solves_; }  ///< Local problems solved.

 private:
  /// One brick as the kept solution saw it.
  struct Brick {
    BodyHandle handle = 0;
    Eigen::Vector3d com = Eigen::Vector3d::Zero();
    double mass = 0.0;
    bool leaning = false;
    std::vector<SupportPatch> supports, side_contacts;
    std::vector<PointForce> loads;
    std::vector<ContactForce> forces;
  };
  /// In handle order.
  using Component = std::vector<Brick>;

  /// The bricks solved locally, by index in the sorted component: flags,
  /// and the indices in order.
  struct Local {
    std::vector<char> in;
    std::vector<std::size_t> reached;
  };

  static std::uint64_t keyOf(const std::vector<BodyHandle>& sorted_bricks);
  /// Index of `handle` in `sorted`, -1 when it is not there (the ground).
  static std::ptrdiff_t indexIn(const std::vector<BodyHandle>& sorted, BodyHandle handle);
  /// The bricks of `sorted` whose loads in `graph` differ from `kept`'s,
  /// with everything they rest or lean on, down to the ground. False when a
  /// brick is not where `kept` has it, or not on the same contacts.
  static bool reachOfChangedLoads(const SupportGraph& graph, const std::vector<BodyHandle>& sorted,
                                  const Component& kept, const StabilityOptions& options,
                                  Local* local);
  /// Statics of the `local` bricks alone, the others' contacts with them
  /// pushing with `kept`'s forces; when it balances, `kept` takes its
  /// forces and the new loads.
  bool solveLocally(const SupportGraph& graph, const std::vector<BodyHandle>& sorted,
                    const Local& local, const StabilityOptions& options, double load_factor,
                    Component* kept);

  /// By the hash of their sorted handles; a few components at a time.
  std::unordered_map<std::uint64_t, Component> kept_;
  /// Where the local problems ended: the next starts there (warm), as the
  /// component LPs do from theirs.
  StaticsBasis basis_;
  std::size_t local_solves_ = 0;
};

}  // namespace brick_stack_sim
