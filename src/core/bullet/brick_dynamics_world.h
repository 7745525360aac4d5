#pragma once

#include <chrono>

#include <btBulletDynamicsCommon.h>

#include "brick_stack_sim/core/types/bullet_stage_seconds.h"

namespace brick_stack_sim {

/// Bullet's discrete dynamics world with continuous collision detection
/// that sees a brick's own shape. Bullet's own sweeps a sphere of the body's
/// swept-sphere radius along its centre's path, and skips every hit that
/// closes less than btDispatcherInfo::m_allowedCcdPenetration (4 cm) in the
/// step: a KAPLA thrown broadside at 20 to 49 m/s passed through a 7.8 mm
/// brick, the sphere's hit coming when half of the plank was already
/// inside. Here a body that moves more than its CCD motion threshold in a
/// step sweeps its collision shape along its path (its orientation held,
/// as Bullet does): the first face it would meet becomes a predictive
/// contact that the solver keeps it from passing, on whatever it strikes,
/// and its step ends there if it would still pass. A hit that closes less
/// than half the motion threshold, or opens, is left to the discrete
/// collision (a brick sliding fast along the table).
///
/// Its broadphase boxes are also cut to brick scale. Bullet grows every box
/// by gContactBreakingThreshold (2 cm, twice a KAPLA plank's width), so in
/// a pile each plank was paired with some 25 others it did not touch, and
/// every pair cost a box-box test and a manifold each step.
///
/// It also times the stages of its step (BulletStageSeconds): the virtuals
/// that Bullet's step calls are wrapped, two clock reads a call (eight calls
/// a step), so that the profile costs nothing next to the step.
class BrickDynamicsWorld : public btDiscreteDynamicsWorld {
 public:
  using btDiscreteDynamicsWorld::btDiscreteDynamicsWorld;

  /// Sets `object`'s broadphase box: its shape's box grown by the distance
  /// at which Bullet drops a contact point of that shape (its contact
  /// breaking threshold, 1.2 mm for a KAPLA plank). Two boxes grown so
  /// overlap whenever the shapes are close enough for a manifold to keep a
  /// point, so no contact is lost that Bullet would keep. Static bodies keep
  /// Bullet's own growth.
  void updateBodyAabb(btCollisionObject* object);

  /// Wall time of each stage of the steps since resetStageSeconds() [s].
  BulletStageSeconds stageSeconds() const;
  void resetStageSeconds() { ticks_ = StageTicks{}; }

 protected:
  // Broadphase.
  void updateAabbs() override;
  void computeOverlappingPairs() override;
  /// The broadphase (the two above), then the narrowphase: the rest of it.
  void performDiscreteCollisionDetection() override;
  // Islands.
  void calculateSimulationIslands() override;
  // Solver.
  /// Bullet's island building and processing too: they run inside it.
  void solveConstraints(btContactSolverInfo& solver_info) override;
  // Integration, with the continuous collision.
  void predictUnconstraintMotion(btScalar time_step) override;
  void createPredictiveContacts(btScalar time_step) override;
  void integrateTransforms(btScalar time_step) override;

 private:
  using Clock = std::chrono::steady_clock;
  /// BulletStageSeconds in clock ticks: integers, so the narrowphase (the
  /// detection less the broadphase inside it) is exact and never negative.
  struct StageTicks {
    Clock::duration broadphase{}, narrowphase{}, islands{}, solver{}, integration{};
  };
  StageTicks ticks_;

  /// Where `body`'s shape, carried from its pose towards `to` (its
  /// orientation held), first meets another convex body it collides with
  /// (the broadphase's candidates along the way, each where it is now),
  /// closing faster than it may without continuous detection.
  struct Hit {
    const btCollisionObject* other = nullptr;
    btScalar fraction = 1;  ///< Of the motion, when they meet [-].
    btVector3 point;        ///< Where they meet, world.
    btVector3 normal;       ///< Unit, from `other` towards the body, world.
  };
  bool firstHit(btRigidBody* body, const btTransform& to, Hit* hit) const;
  /// Whether `body` moves so far in this step that it sweeps (`predicted`: where it would end).
  static bool sweeps(const btRigidBody& body, const btTransform& predicted);
  /// Whether Bullet integrates `body` (awake, dynamic).
  static bool moves(const btRigidBody& body);
  /// For a body that moves: where it would end the step (`predicted`), and
  /// whether it sweeps into something on the way (`hit`).
  bool stepHits(btRigidBody* body, btScalar time_step, btTransform* predicted, Hit* hit) const;
};

}  // namespace brick_stack_sim
