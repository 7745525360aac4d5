#include "bullet/contact_reader.h"

#include <algorithm>

#include "bullet/bullet_conversions.h"
#include "bullet/bullet_handles.h"
#include "bullet/bullet_scene.h"

namespace brick_stack_sim {

void readContacts(const BulletScene& scene, double contact_distance,
                  std::vector<PairContact>* contacts) {
  // The pairs of the last read are refilled in place: their point vectors
  // keep their capacity, and a pile's thousands of pairs are not allocated
  // and freed again every step.
  std::size_t used = 0;
  const btCollisionDispatcher& dispatcher = scene.dispatcher();
  const int manifolds = dispatcher.getNumManifolds();
  for (int i = 0; i < manifolds; ++i) {
    const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(i);
    if (manifold->getNumContacts() == 0) continue;
    const btRigidBody* a = btRigidBody::upcast(manifold->getBody0());
    const btRigidBody* b = btRigidBody::upcast(manifold->getBody1());
    if (used == contacts->size()) contacts->emplace_back();
    PairContact& pair = (*contacts)[used];
    pair.a = handleOf(a);
    pair.b = handleOf(b);
    pair.normal = Eigen::Vector3d::UnitZ();
    pair.points.clear();
    pair.manifold.clear();
    pair.approach_speed = 0.0;
    pair.friction = 0.0;
    btVector3 normal_sum(0, 0, 0);
    for (int j = 0; j < manifold->getNumContacts(); ++j) {
      const btManifoldPoint& point = manifold->getContactPoint(j);
      if (point.getDistance() > contact_distance) continue;
      const btVector3 position = 0.5 * (point.getPositionWorldOnA() + point.getPositionWorldOnB());
      const btVector3 relative =
          a->getVelocityInLocalPoint(position - a->getCenterOfMassPosition()) -
          b->getVelocityInLocalPoint(position - b->getCenterOfMassPosition());
      // The normal points from b to a: a negative relative speed along it closes the gap.
      pair.approach_speed = std::max(pair.approach_speed, -relative.dot(point.m_normalWorldOnB));
      pair.points.push_back(convertBtToEigen(position));
      // The solver applies friction along its lateral directions, on a with
      // a positive sign, as it applies the normal impulse.
      const btVector3 friction = point.m_appliedImpulseLateral1 * point.m_lateralFrictionDir1 +
                                 point.m_appliedImpulseLateral2 * point.m_lateralFrictionDir2;
      pair.manifold.push_back(
          ContactPoint{convertBtToEigen(position), convertBtToEigen(point.m_normalWorldOnB),
                       point.getDistance(), point.getAppliedImpulse(), convertBtToEigen(friction)});
      pair.friction = point.m_combinedFriction;
      normal_sum += point.m_normalWorldOnB;
    }
    if (pair.points.empty() || normal_sum.length2() == 0.0) continue;
    pair.normal = convertBtToEigen(normal_sum.normalized());
    ++used;
  }
  contacts->resize(used);
}

}  // namespace brick_stack_sim
