#include "bullet/brick_dynamics_world.h"

#include <chrono>
#include <vector>

#include "bullet/time_of_impact.h"

namespace brick_stack_sim {

namespace {

/// Adds the wall time of its scope to `*total`.
class StageTimer {
 public:
  using Clock = std::chrono::steady_clock;
  explicit StageTimer(Clock::duration* total) : total_(total), start_(Clock::now()) {}
  ~StageTimer() { *total_ += Clock::now() - start_; }
  StageTimer(const StageTimer&) = delete;
  StageTimer& operator=(const StageTimer&) = delete;

 private:
  Clock::duration* total_;
  Clock::time_point start_;
};

/// Every body whose box overlaps the box it is given.
struct Overlapping : public btBroadphaseAabbCallback {
  std::vector<const btCollisionObject*> bodies;
  bool process(const btBroadphaseProxy* proxy) override {
    bodies.push_back(static_cast<const btCollisionObject*>(proxy->m_clientObject));
    return true;
  }
};

}  // namespace

void BrickDynamicsWorld::updateBodyAabb(btCollisionObject* object) {
  if (object->isStaticObject()) {
    updateSingleAabb(object);
    return;
  }
  const btCollisionShape& shape = *object->getCollisionShape();
  const btScalar reach = shape.getContactBreakingThreshold(gContactBreakingThreshold);
  const btVector3 grow(reach, reach, reach);
  btVector3 low, high;
  shape.getAabb(object->getWorldTransform(), low, high);
  // As Bullet does with continuous detection on: the box covers where the
  // body was interpolated from too.
  if (getDispatchInfo().m_useContinuous) {
    btVector3 from_low, from_high;
    shape.getAabb(object->getInterpolationWorldTransform(), from_low, from_high);
    low.setMin(from_low);
    high.setMax(from_high);
  }
  m_broadphasePairCache->setAabb(object->getBroadphaseHandle(), low - grow, high + grow,
                                 m_dispatcher1);
}

BulletStageSeconds BrickDynamicsWorld::stageSeconds() const {
  auto seconds = [](Clock::duration ticks) { return std::chrono::duration<double>(ticks).count(); };
  return BulletStageSeconds{seconds(ticks_.broadphase), seconds(ticks_.narrowphase),
                            seconds(ticks_.islands), seconds(ticks_.solver),
                            seconds(ticks_.integration)};
}

void BrickDynamicsWorld::updateAabbs() {
  const StageTimer timer(&ticks_.broadphase);
  for (int i = 0; i < m_collisionObjects.size(); ++i) {
    btCollisionObject* object = m_collisionObjects[i];
    if (m_forceUpdateAllAabbs || object->isActive()) updateBodyAabb(object);
  }
}

void BrickDynamicsWorld::computeOverlappingPairs() {
  const StageTimer timer(&ticks_.broadphase);
  btDiscreteDynamicsWorld::computeOverlappingPairs();
}

void BrickDynamicsWorld::performDiscreteCollisionDetection() {
  const Clock::duration broadphase_before = ticks_.broadphase;
  const Clock::time_point start = Clock::now();
  btDiscreteDynamicsWorld::performDiscreteCollisionDetection();
  ticks_.narrowphase += (Clock::now() - start) - (ticks_.broadphase - broadphase_before);
}

void BrickDynamicsWorld::calculateSimulationIslands() {
  const StageTimer timer(&ticks_.islands);
  btDiscreteDynamicsWorld::calculateSimulationIslands();
}

void BrickDynamicsWorld::solveConstraints(btContactSolverInfo& solver_info) {
  const StageTimer timer(&ticks_.solver);
  btDiscreteDynamicsWorld::solveConstraints(solver_info);
}

void BrickDynamicsWorld::predictUnconstraintMotion(btScalar time_step) {
  const StageTimer timer(&ticks_.integration);
  btDiscreteDynamicsWorld::predictUnconstraintMotion(time_step);
}

bool BrickDynamicsWorld::sweeps(const btRigidBody& body, const btTransform& predicted) {
  const btScalar threshold = body.getCcdSquareMotionThreshold();
  const btCollisionShape& shape = *body.getCollisionShape();
  return threshold > 0 && (shape.isConvex() || shape.isCompound()) &&
         (predicted.getOrigin() - body.getWorldTransform().getOrigin()).length2() > threshold;
}

bool BrickDynamicsWorld::firstHit(btRigidBody* body, const btTransform& to, Hit* hit) const {
  const btTransform& from = body->getWorldTransform();
  const btVector3 motion = to.getOrigin() - from.getOrigin();
  const btCollisionShape& shape = *body->getCollisionShape();
  btVector3 low, high;
  shape.getAabb(from, low, high);
  btVector3 swept_low = low, swept_high = high;
  swept_low.setMin(low + motion);
  swept_high.setMax(high + motion);
  Overlapping near;
  m_broadphasePairCache->aabbTest(swept_low, swept_high, near);
  // What it closes on by less than this in the step, the discrete contact
  // handles (a brick sliding fast along the table) [m].
  const btScalar least_approach = btScalar(0.5) * body->getCcdMotionThreshold();
  const btBroadphaseProxy& own = *body->getBroadphaseHandle();
  bool found = false;
  for (const btCollisionObject* other : near.bodies) {
    if (other == body || !other->hasContactResponse()) continue;
    const btBroadphaseProxy& proxy = *other->getBroadphaseHandle();
    if (!(proxy.m_collisionFilterGroup & own.m_collisionFilterMask) ||
        !(own.m_collisionFilterGroup & proxy.m_collisionFilterMask) ||
        !m_dispatcher1->needsCollision(body, other) || !m_dispatcher1->needsResponse(body, other))
      continue;
    btScalar fraction = 1;
    SurfaceGap gap;
    const bool meets =
        timeOfImpactOfShapes(shape, from, to, *other->getCollisionShape(),
                             other->getWorldTransform(), kImpactTolerance, &fraction, &gap);
    if (!meets || (found && !(fraction < hit->fraction)) ||
        motion.dot(gap.normal) >= -least_approach)
      continue;
    *hit = Hit{other, fraction, gap.on_b, gap.normal};
    found = true;
  }
  return found;
}

bool BrickDynamicsWorld::moves(const btRigidBody& body) {
  return body.isActive() && !body.isStaticOrKinematicObject();
}

bool BrickDynamicsWorld::stepHits(btRigidBody* body, btScalar time_step, btTransform* predicted,
                                  Hit* hit) const {
  body->setHitFraction(1);
  if (!moves(*body)) return false;
  body->predictIntegratedTransform(time_step, *predicted);
  return sweeps(*body, *predicted) && firstHit(body, *predicted, hit);
}

void BrickDynamicsWorld::createPredictiveContacts(btScalar time_step) {
  const StageTimer timer(&ticks_.integration);
  releasePredictiveContacts();
  for (int i = 0; i < m_nonStaticRigidBodies.size(); ++i) {
    btRigidBody* body = m_nonStaticRigidBodies[i];
    btTransform predicted;
    Hit hit;
    if (!stepHits(body, time_step, &predicted, &hit)) continue;
    // A contact the solver keeps it from closing by more than the gap:
    // what it strikes takes the blow in this step, as on touching.
    const btVector3 travel =
        (predicted.getOrigin() - body->getWorldTransform().getOrigin()) * hit.fraction;
    // Two faces meet all over their overlap, and the cast names one corner
    // of it: the blow acts where the line through the centre of mass along
    // the normal crosses the face, or a face-on hit would set it spinning.
    const btVector3 centre = body->getCenterOfMassPosition() + travel;
    const btVector3 on_other = centre - (centre - hit.point).dot(hit.normal) * hit.normal;
    const btVector3 on_body = on_other - travel;  // the point that meets, where it is now
    btPersistentManifold* manifold = m_dispatcher1->getNewManifold(body, hit.other);
    m_predictiveManifolds.push_back(manifold);
    btManifoldPoint point(body->getWorldTransform().invXform(on_body),
                          hit.other->getWorldTransform().invXform(on_other), hit.normal,
                          travel.dot(-hit.normal));
    btManifoldPoint& added = manifold->getContactPoint(manifold->addManifoldPoint(point, true));
    // No bounce before they touch: the contact of the next step bounces.
    added.m_combinedRestitution = 0;
    added.m_combinedFriction = gCalculateCombinedFrictionCallback(body, hit.other);
    added.m_positionWorldOnA = on_body;
    added.m_positionWorldOnB = on_other;
  }
}

void BrickDynamicsWorld::integrateTransforms(btScalar time_step) {
  const StageTimer timer(&ticks_.integration);
  for (int i = 0; i < m_nonStaticRigidBodies.size(); ++i) {
    btRigidBody* body = m_nonStaticRigidBodies[i];
    btTransform predicted;
    Hit hit;
    // What the solver could not stop in time ends its step where it meets.
    if (stepHits(body, time_step, &predicted, &hit))
      body->predictIntegratedTransform(time_step * hit.fraction, predicted);
    if (moves(*body)) body->proceedToTransform(predicted);
  }
}

}  // namespace brick_stack_sim
