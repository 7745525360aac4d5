#pragma once
// How Bullet's bodies carry their BodyHandle: in the user index.

#include <btBulletDynamicsCommon.h>

#include "physics/body_handle.h"

namespace brick_stack_sim {

// Bullet's user index of the static bodies; bricks carry their serial.
constexpr int kTableUserIndex = -2;
constexpr int kFloorUserIndex = -3;

inline BodyHandle handleOf(const btCollisionObject* object) {
  const int index = object->getUserIndex();
  if (index == kTableUserIndex) return kTableHandle;
  if (index == kFloorUserIndex) return kFloorHandle;
  return static_cast<BodyHandle>(index);
}

}  // namespace brick_stack_sim
