#include "bullet/apart_pair_dispatcher.h"

#include <cmath>
#include <cstring>
#include <iterator>
#include <limits>

#include "bullet/turn_bound.h"

namespace brick_stack_sim {

namespace {

static_assert(sizeof(btScalar) == sizeof(btBroadphasePair::m_internalInfo1),
              "a pair's budget is kept in its spare word");

/// The summed travel below which the pair is passed over [m]; zero: none.
btScalar thresholdOf(const btBroadphasePair& pair) {
  btScalar threshold;
  std::memcpy(&threshold, &pair.m_internalInfo1, sizeof threshold);
  return threshold;
}

void setThreshold(btBroadphasePair* pair, btScalar threshold) {
  std::memcpy(&pair->m_internalInfo1, &threshold, sizeof threshold);
}

/// How far a point within `radius` [m] of a body's origin can have moved
/// from pose `from` to `to` [m]: the translation plus the turn's bound
/// times the radius. A pose that did not change moved nothing, whatever the
/// radius (the floor's plane has no finite one).
btScalar farthestMove(const btTransform& from, const btTransform& to, btScalar radius) {
  const btScalar moved = (to.getOrigin() - from.getOrigin()).length();
  if (to.getBasis() == from.getBasis()) return moved;
  return moved + turnBound(to.getBasis(), from.getBasis()) * radius;
}

}  // namespace

ApartPairDispatcher::ApartPairDispatcher(btCollisionConfiguration* configuration)
    : btCollisionDispatcher(configuration) {
  setNearCallback(&ApartPairDispatcher::nearCallback);
}

void ApartPairDispatcher::dispatchAllCollisionPairs(btOverlappingPairCache* pairs,
                                                    const btDispatcherInfo& info,
                                                    btDispatcher* dispatcher) {
  trackTravel();
  btCollisionDispatcher::dispatchAllCollisionPairs(pairs, info, dispatcher);
}

void ApartPairDispatcher::nearCallback(btBroadphasePair& pair, btCollisionDispatcher& dispatcher,
                                       const btDispatcherInfo& info) {
  auto& self = static_cast<ApartPairDispatcher&>(dispatcher);
  const bool discrete = info.m_dispatchFunc == btDispatcherInfo::DISPATCH_DISCRETE;
  const btScalar threshold = thresholdOf(pair);
  if (discrete && self.world_ && threshold > 0 && self.travelOf(pair) < threshold) {
    ++self.passed_over_;
    return;
  }
  setThreshold(&pair, 0);
  self.current_ = discrete ? &pair : nullptr;
  defaultNearCallback(pair, dispatcher, info);
  self.current_ = nullptr;
}

void ApartPairDispatcher::keepApart(btScalar budget) {
  if (!current_ || !world_ || !(budget > 0)) return;
  const btScalar travel = travelOf(*current_);
  if (std::isfinite(travel) && std::isfinite(budget)) setThreshold(current_, travel + budget);
}

void ApartPairDispatcher::trackTravel() {
  if (!world_) return;
  ++dispatch_;
  const btCollisionObjectArray& objects = world_->getCollisionObjectArray();
  for (int i = 0; i < objects.size(); ++i) {
    const btCollisionObject* object = objects[i];
    const btBroadphaseProxy* proxy = object->getBroadphaseHandle();
    if (!proxy) continue;
    const auto [entry, added] = motion_.try_emplace(proxy->m_uniqueId);
    Motion& motion = entry->second;
    const btTransform& pose = object->getWorldTransform();
    if (added) {
      btVector3 centre;
      btScalar radius;
      object->getCollisionShape()->getBoundingSphere(centre, radius);
      motion.radius = centre.length() + radius;
    } else {
      motion.travel += farthestMove(motion.last, pose, motion.radius);
    }
    motion.last = pose;
    motion.seen = dispatch_;
  }
  // Bodies that left the world took their pairs with them.
  if (motion_.size() > 2 * static_cast<std::size_t>(objects.size()) + 64) {
    for (auto it = motion_.begin(); it != motion_.end();)
      it = it->second.seen == dispatch_ ? std::next(it) : motion_.erase(it);
  }
}

btScalar ApartPairDispatcher::travelOf(const btBroadphasePair& pair) const {
  const auto first = motion_.find(pair.m_pProxy0->m_uniqueId);
  const auto second = motion_.find(pair.m_pProxy1->m_uniqueId);
  if (first == motion_.end() || second == motion_.end())
    return std::numeric_limits<btScalar>::infinity();
  return first->second.travel + second->second.travel;
}

}  // namespace brick_stack_sim
