#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "physics/body_handle.h"

namespace brick_stack_sim {

class BulletScene;

/// A moving brick and how far it may travel within the coming step [m].
struct MoverReach {
  BodyHandle mover = 0;
  double travel = 0.0;
};

/// A moving brick that may reach a frozen one within the coming step.
struct ColliderApproach {
  BodyHandle mover = 0;
  BodyHandle frozen = 0;
};

/// Frozen bricks as colliders that cost nothing while nothing comes near.
/// Bullet loops over every collision object of its world each step (AABB
/// update, island union-find), so a frozen brick waits in an AABB tree of its
/// own and is added to Bullet's world, as a static collider, only while some
/// moving brick could reach it.
class DormantColliders {
 public:
  explicit DormantColliders(BulletScene* scene);
  ~DormantColliders();
  DormantColliders(const DormantColliders&) = delete;
  DormantColliders& operator=(const DormantColliders&) = delete;

  /// A brick just made static, out of Bullet's world, starts waiting here.
  void add(BodyHandle frozen);
  /// `source`'s frozen bricks, with when a mover last came near each, and
  /// its list of those in Bullet's world; the caller has copied their
  /// bodies into this scene and added those to its world.
  void copyFrom(const DormantColliders& source);
  /// It stops being a frozen collider: out of the tree and of Bullet's world.
  void remove(BodyHandle frozen);
  /// A frozen brick was moved (an impact slid it): its box in the tree follows.
  void refresh(BodyHandle frozen);
  bool contains(BodyHandle handle) const;
  std::size_t size() const;
  /// The frozen bricks currently in Bullet's world, in the order they came in.
  const std::vector<BodyHandle>& inWorld() const { return in_world_; }

  /// Frozen bricks whose boxes overlap `low`..`high` [m], in handle order
  /// (placement order: the tree's own order depends on its history).
  std::vector<BodyHandle> near(const Eigen::Vector3d& low, const Eigen::Vector3d& high) const;

  /// Brings into Bullet's world every frozen brick that a mover may reach
  /// (its box grown by its travel) during step `step`; returns who may reach
  /// whom. Bricks are added in handle order: Bullet's contact order follows
  /// the order bodies are added, and runs must be reproducible.
  std::vector<ColliderApproach> bringWithinReach(const std::vector<MoverReach>& movers,
                                                 std::uint64_t step);
  /// Sends back to the tree the bricks no mover has come near for a while,
  /// so a brick rocking at a frozen brick's edge does not cost a removal and
  /// an insertion every step.
  void sendBackIdle(std::uint64_t step);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::vector<BodyHandle> in_world_;
};

}  // namespace brick_stack_sim
