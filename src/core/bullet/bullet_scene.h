#pragma once
// The only face of Bullet to the rest of the core: bodies are named by
// BodyHandle and speak Eigen. Files that include a Bullet header live in this
// folder; this header includes none.

#include <cstdint>
#include <memory>
#include <vector>

#include <Eigen/Geometry>

#include "brick_stack_sim/core/types/brick.h"
#include "brick_stack_sim/core/types/brick_type.h"
#include "brick_stack_sim/core/types/bullet_stage_seconds.h"
#include "brick_stack_sim/core/types/world_options.h"
#include "physics/body_handle.h"

class btCollisionDispatcher;

namespace brick_stack_sim {

/// Where two bodies are nearest, or deepest inside each other.
struct ClosestPoints {
  /// Signed distance of the surfaces [m]: < 0 when they overlap (the depth).
  double distance = 0.0;
  Eigen::Vector3d on_b = Eigen::Vector3d::Zero();     ///< The nearest point of b [m], world.
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< Unit, from b towards a.
};

/// How Bullet treats a body.
enum class BodyDynamics : unsigned char {
  kDynamic,    ///< Simulated: mass, velocity, gravity.
  kStatic,     ///< A collider without mass (a frozen brick).
  kKinematic,  ///< Moved from outside; pushes what it touches (a held brick).
};

/// Bullet's dynamics world for bricks on a table, in double precision, tuned
/// for 8 mm bricks (the reason for each setting is next to it in the .cpp):
/// the table (a finite box whose top face is z = 0) and a floor under it, and
/// one rigid body per brick. A body exists from addBrick() to removeBrick();
/// whether Bullet's world holds it (steps it, or collides with it) is a
/// separate matter, decided by the caller.
class BulletScene {
 public:
  explicit BulletScene(const WorldOptions& options);
  ~BulletScene();
  BulletScene(const BulletScene&) = delete;
  BulletScene& operator=(const BulletScene&) = delete;

  /// Creates a dynamic body at the placement's pose and velocities [m, m/s,
  /// rad/s] and adds it to Bullet's world. Handles are brick serials: dense.
  void addBrick(BodyHandle handle, const BrickType& type, const BrickPlacement& placement);
  /// Takes the body out of Bullet's world and destroys it.
  void removeBrick(BodyHandle handle);
  /// The body `handle` of `source`, of `type`, in its exact state (pose,
  /// velocities, dynamics, activation and sleeping timer, bit for bit), out
  /// of Bullet's world: the caller adds it (worldOrder()).
  void copyBrick(BodyHandle handle, const BrickType& type, const BulletScene& source);
  /// The bricks in Bullet's world in the order Bullet numbered them as they
  /// came in, which orders its pairs and contacts: a copy that adds them in
  /// this order solves them in the same order.
  std::vector<BodyHandle> worldOrder() const;

  void addToWorld(BodyHandle handle);       ///< No-op when already in.
  void removeFromWorld(BodyHandle handle);  ///< No-op when not in.
  bool inWorld(BodyHandle handle) const;

  // A body changes dynamics only while out of Bullet's world: Bullet files
  // static, kinematic and dynamic bodies in different broadphase groups when
  // they are added.
  /// Mass and inertia of its type back, at rest.
  void makeDynamic(BodyHandle handle, const BrickType& type);
  /// At rest, without mass: a collider that never moves.
  void makeStatic(BodyHandle handle);
  /// Without mass, moved from outside, never put to sleep.
  void makeKinematic(BodyHandle handle);
  BodyDynamics dynamics(BodyHandle handle) const;

  /// Makes a dynamic body active now (sleeping allowed again later only when
  /// the world sleeps at all), as a just-woken brick needs.
  void wakeUp(BodyHandle handle);
  /// Bullet's activate(true): a sleeping body joins the next step.
  void activate(BodyHandle handle);
  bool isActive(BodyHandle handle) const;

  Eigen::Isometry3d pose(BodyHandle handle) const;           ///< [m], world
  Eigen::Vector3d centreOfMass(BodyHandle handle) const;     ///< [m], world
  Eigen::Vector3d linearVelocity(BodyHandle handle) const;   ///< [m/s]
  Eigen::Vector3d angularVelocity(BodyHandle handle) const;  ///< [rad/s]
  /// Speeds in Bullet's own arithmetic, so thresholds compare the same bits
  /// whether Bullet or Eigen holds the vector [m/s], [rad/s].
  double linearSpeed(BodyHandle handle) const;
  double angularSpeed(BodyHandle handle) const;
  /// The bricks in Bullet's world whose broadphase boxes (a little larger
  /// than their bounds) overlap `low`..`high` [m], in handle order: what a
  /// placement may touch among the bodies Bullet holds, found through its
  /// tree in time that follows what is near, not how many bodies there are.
  std::vector<BodyHandle> inWorldNear(const Eigen::Vector3d& low,
                                      const Eigen::Vector3d& high) const;
  /// The body's bounding box at its pose, collision margin included [m].
  void bounds(BodyHandle handle, Eigen::Vector3d* low, Eigen::Vector3d* high) const;

  /// Puts the body back at `pose`, at rest and without pending forces (the
  /// numerical guard's repair).
  void restoreAtRest(BodyHandle handle, const Eigen::Isometry3d& pose);
  /// Sets the velocities of a dynamic body [m/s], [rad/s], world.
  void setVelocity(BodyHandle handle, const Eigen::Vector3d& linear,
                   const Eigen::Vector3d& angular);
  /// Where a kinematic body is to be at the end of the coming step: Bullet
  /// derives its velocity from the move, so what it pushes gets that speed.
  void moveKinematic(BodyHandle handle, const Eigen::Isometry3d& pose);
  /// Puts a static body (a frozen brick) at `pose` [m]; its bounds follow.
  void moveStatic(BodyHandle handle, const Eigen::Isometry3d& pose);
  /// The nearest points of a brick `a`, as it would be at `pose_a`, and a
  /// brick or the table `b` where it is (GJK, or EPA when they overlap),
  /// whether or not Bullet's world holds them. False for the floor (a plane)
  /// or when GJK fails.
  bool closestPoints(BodyHandle a, const Eigen::Isometry3d& pose_a, BodyHandle b,
                     ClosestPoints* points) const;

  /// How far along its way from `from` to `to` a brick `a` first touches
  /// the brick or table `b` where it is (the fraction of the way, in a
  /// straight line, its orientation `from`'s): continuous collision for a
  /// check that looks only at where a fast brick ends a step. False when it
  /// never touches it on the way, for the floor, or when the cast fails.
  bool firstContact(BodyHandle a, const Eigen::Isometry3d& from, const Eigen::Isometry3d& to,
                    BodyHandle b, double* fraction) const;

  /// An impulse [N s] at a world point [m].
  void applyImpulse(BodyHandle handle, const Eigen::Vector3d& impulse,
                    const Eigen::Vector3d& point);

  /// Exactly one step of `dt` [s]: no substeps, no interpolation.
  void step(double dt);
  /// Wall time of the stages of the last step() [s]; zero before the first.
  BulletStageSeconds lastStepStageSeconds() const;

  /// The contact manifolds of the last step, for the contact reader.
  const btCollisionDispatcher& dispatcher() const;

  /// Whether the narrowphase passes over pairs still too far apart to touch
  /// (ApartPairDispatcher; on from the start). Either way the steps give
  /// the same bits; off, every pair is tested at every step, to compare.
  void passOverApartPairs(bool enabled);
  /// Pair visits the narrowphase passed over so far.
  std::uint64_t apartPairsPassedOver() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace brick_stack_sim
