// BulletScene's copy of another scene's bodies (BrickWorld::copy).
#include <algorithm>
#include <utility>
#include <vector>

#include "bullet/bullet_scene.h"
#include "bullet/bullet_scene_impl.h"

namespace brick_stack_sim {

void BulletScene::copyBrick(BodyHandle handle, const BrickType& type, const BulletScene& source) {
  const btRigidBody& from = source.impl_->rigid(handle);
  addBrick(handle, type, BrickPlacement{});
  removeFromWorld(handle);
  switch (source.dynamics(handle)) {
    case BodyDynamics::kStatic:
      makeStatic(handle);
      break;
    case BodyDynamics::kKinematic:
      makeKinematic(handle);
      break;
    case BodyDynamics::kDynamic:
      break;
  }
  btRigidBody& to = impl_->rigid(handle);
  to.setCollisionFlags(from.getCollisionFlags());
  to.setWorldTransform(from.getWorldTransform());
  to.setInterpolationWorldTransform(from.getInterpolationWorldTransform());
  to.setLinearVelocity(from.getLinearVelocity());
  to.setAngularVelocity(from.getAngularVelocity());
  to.setInterpolationLinearVelocity(from.getInterpolationLinearVelocity());
  to.setInterpolationAngularVelocity(from.getInterpolationAngularVelocity());
  to.updateInertiaTensor();  // of the orientation just set, as Bullet's own step computes it
  to.forceActivationState(from.getActivationState());
  to.setDeactivationTime(from.getDeactivationTime());
  to.setHitFraction(from.getHitFraction());
}

std::vector<BodyHandle> BulletScene::worldOrder() const {
  std::vector<std::pair<int, BodyHandle>> numbered;
  for (const auto& [handle, body] : impl_->bodies)
    if (body.in_world) numbered.emplace_back(body.rigid->getBroadphaseHandle()->m_uniqueId, handle);
  std::sort(numbered.begin(), numbered.end());
  std::vector<BodyHandle> order;
  for (const auto& entry : numbered) order.push_back(entry.second);
  return order;
}

}  // namespace brick_stack_sim
