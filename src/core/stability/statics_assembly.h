#pragma once

#include <map>
#include <vector>

#include "stability/rigid_block_statics.h"
#include "stability/stability_model.h"
#include "stability/support_graph.h"

namespace brick_stack_sim {

/// Whether a side contact is one the brick leans on: not something resting
/// on it from above (a counterweight, a plank's edge), whose load reaches the
/// brick through that brick's own supports. Judged on the patch's normals.
bool leansOn(const SupportPatch& side_contact, const StabilityOptions& options);
/// Whether any of a brick's side contacts is one it leans on (leansOn).
bool leans(const BrickStability& stability, const StabilityOptions& options);

/// The statics problem (solveStatics) of some bricks of a stack, built from
/// their support patches: the bricks added are free, every other supporter
/// is fixed (the ground, or a frozen brick taken as immovable).
class StaticsAssembly {
 public:
  explicit StaticsAssembly(const StabilityOptions& options) : options_(options) {}

  /// `brick` is a free body; returns its index.
  int addFree(BodyHandle brick, double mass, const Eigen::Vector3d& com);
  /// A load on free body `body` from outside the problem.
  void addLoad(int body, const PointForce& load);
  /// The contacts of free body `body` on `patches`. A contact from above
  /// with a fixed body is left out: a frozen brick resting on it passes its
  /// load as one (addLoad), and could otherwise hold it down.
  void addPatches(int body, const std::vector<SupportPatch>& patches);

  const std::vector<StaticsBody>& bodies() const { return bodies_; }
  const std::vector<StaticsContact>& contacts() const { return contacts_; }
  /// The body each contact's `b` stands for (a supporter handle).
  BodyHandle otherOf(std::size_t contact) const { return others_[contact]; }
  /// Whether `handle` is a free body of the problem.
  bool isFree(BodyHandle handle) const { return index_.count(handle) > 0; }

  /// With `basis`, starts from it and leaves the answer's basis there (a
  /// warm start: bodies and contacts are named by brick handles).
  StaticsSolution solve(StaticsBasis* basis = nullptr) const;

  /// Per free body (in the order added): the forces it receives in
  /// `solution`, from its own contacts and, with the opposite sign, from
  /// those of the free bodies that touch it. A contact named from both
  /// sides with one normal (a brick on a free brick below, and that brick's
  /// contact with it from above) is one force.
  std::vector<std::vector<ContactForce>> contactForces(const StaticsSolution& solution) const;

 private:
  StabilityOptions options_;
  std::map<BodyHandle, int> index_;
  std::vector<BodyHandle> handles_;  ///< Of each free body.
  std::vector<StaticsBody> bodies_;
  std::vector<StaticsContact> contacts_;
  std::vector<BodyHandle> others_;
  std::vector<std::uint64_t> contact_keys_;  ///< From the two handles and the point's index.
};

/// The statics of `bricks` of `graph`, free, on their patches, with their
/// measured external loads times `load_factor`; every other body fixed.
StaticsAssembly assembleStatics(const SupportGraph& graph, const std::vector<BodyHandle>& bricks,
                                const StabilityOptions& options, double load_factor = 1.0);

}  // namespace brick_stack_sim
