#pragma once

#include <cstdint>
#include <string>

#include <Eigen/Geometry>

#include "brick_stack_sim/core/types/brick.h"
#include "brick_stack_sim/core/types/brick_type.h"
#include "physics/body_handle.h"

namespace brick_stack_sim {

/// How the world treats a brick. A brick is in exactly one mode, and only
/// BrickSets::transfer changes it, so the containers a mode implies (Bullet's
/// dynamics and world, the movers, the dormant colliders) never disagree.
enum class BrickMode : unsigned char {
  kDynamic,        ///< Simulated by Bullet; one of the movers.
  kFrozenStable,   ///< A static collider, frozen by the model as stable.
  kFrozenLeaning,  ///< A static collider, held by the model's friction statics.
  kHeld,           ///< Kinematic, moved by a teleop or planner.
};

inline bool isFrozen(BrickMode mode) {
  return mode == BrickMode::kFrozenStable || mode == BrickMode::kFrozenLeaning;
}

/// The state published for a mode (Brick.msg).
BrickState toState(BrickMode mode);
/// The frozen mode of a model's freeze decision (kStable or kLeaning).
BrickMode frozenMode(BrickState kind);
const char* toString(BrickMode mode);

/// One brick of the world.
struct BrickRecord {
  std::string id;
  BrickType type;
  BodyHandle handle = 0;  ///< Its placement serial: placement order, never reused.
  Eigen::Isometry3d placed_pose = Eigen::Isometry3d::Identity();
  double placed_at = 0.0;  ///< [s]
  bool fell_off = false;
  BrickMode mode = BrickMode::kDynamic;  ///< Changed by BrickSets::transfer only.
  /// The last pose known to be finite, restored if Bullet ever produces NaN.
  Eigen::Isometry3d last_good_pose = Eigen::Isometry3d::Identity();
  /// In mode kHeld: where the hand takes it, at a bounded speed.
  Eigen::Isometry3d held_target = Eigen::Isometry3d::Identity();
  /// WorldState::revision when it last changed mode, or the model last
  /// described it anew: what tells a frozen brick that changed from one
  /// that did not (BrickWorld::snapshotChangedSince).
  std::uint64_t changed_at = 0;
};

}  // namespace brick_stack_sim
