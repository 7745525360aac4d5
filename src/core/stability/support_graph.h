#pragma once

#include <functional>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "brick_stack_sim/core/geometry/load_distribution.h"
#include "stability/stability_model.h"

namespace brick_stack_sim {

/// The frozen bricks and what rests on what (thesis 3.3): each frozen brick
/// with its support patches and the frozen bricks it carries. Every freezing
/// model keeps one; a criterion judges its components. It knows which
/// bricks changed since the last judgement (dirty), the components they
/// belong to, the order in which loads flow down, and takes a brick out with
/// everything it carries.
class SupportGraph {
 public:
  /// A frozen brick: where it rests and what the last check found.
  struct Node {
    Eigen::Vector3d com = Eigen::Vector3d::Zero();  ///< [m]
    double mass = 0.0;                              ///< [kg]
    std::vector<SupportPatch> supports;  ///< One patch per supporter, in supporter order.
    /// Where it leans on or touches frozen bricks or the ground other than
    /// from above (BrickStability::side_contacts); empty for the COM rule.
    std::vector<SupportPatch> side_contacts;
    std::set<BodyHandle> carries;       ///< Frozen bricks resting on it.
    std::set<BodyHandle> leaned_on_by;  ///< Frozen bricks with a side contact on it.
    /// The loads the bricks it carries pass down, where they act, as a
    /// load-passing criterion found them in its last check (kept here, not
    /// rebuilt, so a check allocates nothing for bricks it saw before).
    std::vector<LoadShare> received;
    /// The brick that passed each share of `received`, in the same order.
    std::vector<BodyHandle> received_from;
    /// The forces of frozen leaning bricks on it, sideways parts included,
    /// and the sideways part of what it carries, where they act (the last
    /// check's, as `received`).
    std::vector<PointForce> pushes;
    /// Frozen as leaning: its load passes through its side contacts too.
    bool leaning = false;
    /// It froze again where the model had woken it, without having moved:
    /// if the model wakes it again, that is a wake/refreeze cycle.
    bool refrozen_in_place = false;
    BrickStability stability;
  };

  /// Which side contacts of a leaning brick pass its load (leansOn).
  using LeaningTest = std::function<bool(const SupportPatch&)>;

  /// A brick taken out with the load it carried, and why.
  struct Detached {
    BodyHandle brick = 0;
    BodyHandle carried_by = 0;  ///< For all but the first: the detached brick it rested on.
    Node node;
  };

  bool contains(BodyHandle brick) const { return nodes_.count(brick) > 0; }
  const Node* find(BodyHandle brick) const;
  Node* find(BodyHandle brick);
  /// Frozen, or the table or floor: what a brick may rest on to join the stack.
  bool canSupport(BodyHandle handle) const { return isGround(handle) || contains(handle); }
  std::size_t size() const { return nodes_.size(); }
  /// Every frozen brick, in handle order.
  std::vector<BodyHandle> bricks() const;

  /// `brick` joins, linked under its frozen supporters and beside what its
  /// side contacts touch (both ways: bricks of a group frozen together list
  /// each other); its component is dirty.
  void add(BodyHandle brick, const Eigen::Vector3d& com, double mass,
           std::vector<SupportPatch> supports, std::vector<SupportPatch> side_contacts = {},
           bool leaning = false);
  /// `carrier`, just frozen under the frozen brick `patch.supporter` (a prop
  /// slid under a bridge), becomes one of its supporters: `patch`, seen
  /// from the carrier (normals towards the brick above), joins that brick's
  /// supports. Its component is dirty.
  void addCarried(BodyHandle carrier, SupportPatch patch);
  /// `brick` and, breadth first, everything it carries or that leans on it,
  /// directly or not (what loses its support when it moves), each with the
  /// brick it was reached from (itself for `brick`). Empty when `brick` is
  /// not in the graph.
  std::vector<std::pair<BodyHandle, BodyHandle>> withLoad(BodyHandle brick) const;
  /// Takes withLoad(brick) out of the graph, in that order; their
  /// supporters that stay are dirty (their load changed).
  std::vector<Detached> detachWithLoad(BodyHandle brick);
  /// Takes `brick` alone out (it leaves the world); returns what it carried
  /// or what leaned on it, which stays in the graph without that support.
  std::set<BodyHandle> erase(BodyHandle brick);

  /// Takes `brick` alone out to put it back where it moved (an impact slid
  /// it): what it carried or what leaned on it stays, forgets its contacts
  /// with it and is dirty. Returns those bricks.
  std::set<BodyHandle> eraseAndUnlink(BodyHandle brick);

  /// Something outside the graph changed what `brick` bears (a load from
  /// a body the stack does not hold): its component is judged again.
  void touch(BodyHandle brick) {
    if (contains(brick)) dirty_.insert(brick);
  }

  bool hasChanges() const { return !dirty_.empty(); }
  /// The components holding a brick that changed since the last call, each
  /// in handle order; forgets the changes. Their bricks count as
  /// redescribed: the criterion judging them writes their nodes.
  std::vector<std::vector<BodyHandle>> takeChangedComponents();
  /// Bricks whose node may have changed since the last call, in any order
  /// and maybe more than once: the members of every component handed out
  /// by takeChangedComponents(). Nodes change only in those components (a
  /// change makes its component dirty, and loads flow within it).
  std::vector<BodyHandle> takeRedescribed();
  /// The order in which loads flow down a component: groups of bricks,
  /// each after every group that passes it load. A brick passes load to
  /// its supporters and, when leaning, to what it leans on (`leans_on`).
  /// Bricks that pass load to each other (the planks of a V, a cycle of
  /// supports) share a group, and so does a brick resting on a leaning one
  /// (a level brick on two V's); any other brick is a group of one. Each
  /// group in handle order.
  std::vector<std::vector<BodyHandle>> loadOrder(const std::vector<BodyHandle>& component,
                                                 const LeaningTest& leans_on) const;
  /// A copy of the components that hold `seeds` (the part a what-if query
  /// can touch), with no pending changes.
  SupportGraph componentsOf(const std::vector<BodyHandle>& seeds) const;
  /// The bricks of the component that holds `start` (handle order), without
  /// those already in `seen`, which gains them: a query that needs no copy.
  std::vector<BodyHandle> componentOf(BodyHandle start, std::set<BodyHandle>* seen) const;

 private:
  /// Unlinks `brick` from its supporters, which become dirty.
  void unlinkFromSupporters(BodyHandle brick, const Node& node);

  std::map<BodyHandle, Node> nodes_;
  std::set<BodyHandle> dirty_;
  std::vector<BodyHandle> redescribed_;
};

}  // namespace brick_stack_sim
