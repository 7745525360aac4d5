#include "bullet/contact_reader.h"

#include <algorithm>

#include "bullet/bullet_conversions.h"
#include "bullet/bullet_handles.h"
#include "bullet/bullet_scene.h"
#include "bullet/flush_box_box_algorithm.h"

namespace brick_stack_sim {

namespace {

/// Adds `manifold`'s points closer than `contact_distance` to `pair`, and
/// their normals to `normal_sum`.
void appendPoints(const btPersistentManifold& manifold, double contact_distance, PairContact* pair,
                  btVector3* normal_sum) {
  const btRigidBody* a = btRigidBody::upcast(manifold.getBody0());
  const btRigidBody* b = btRigidBody::upcast(manifold.getBody1());
  for (int j = 0; j < manifold.getNumContacts(); ++j) {
    const btManifoldPoint& point = manifold.getContactPoint(j);
    if (point.getDistance() > contact_distance) continue;
    const btVector3 position = 0.5 * (point.getPositionWorldOnA() + point.getPositionWorldOnB());
    const btVector3 relative = a->getVelocityInLocalPoint(position - a->getCenterOfMassPosition()) -
                               b->getVelocityInLocalPoint(position - b->getCenterOfMassPosition());
    // The normal points from b to a: a negative relative speed along it closes the gap.
    pair->approach_speed = std::max(pair->approach_speed, -relative.dot(point.m_normalWorldOnB));
    pair->points.push_back(convertBtToEigen(position));
    // The solver applies friction along its lateral directions, on a with
    // a positive sign, as it applies the normal impulse.
    const btVector3 friction = point.m_appliedImpulseLateral1 * point.m_lateralFrictionDir1 +
                               point.m_appliedImpulseLateral2 * point.m_lateralFrictionDir2;
    pair->manifold.push_back(
        ContactPoint{convertBtToEigen(position), convertBtToEigen(point.m_normalWorldOnB),
                     point.getDistance(), point.getAppliedImpulse(), convertBtToEigen(friction)});
    pair->friction = point.m_combinedFriction;
    *normal_sum += point.m_normalWorldOnB;
  }
}

/// A pair read from two manifolds, at `index` of the contacts read.
struct SplitPair {
  BodyHandle a, b;
  std::size_t index;
  btVector3 normal_sum;
};

/// Gives the split pairs their mean normals once both halves are in, and
/// drops one left with no point close enough, as any other pair would be;
/// returns how many of the first `used` contacts remain.
std::size_t finishSplitPairs(const std::vector<SplitPair>& split, std::size_t used,
                             std::vector<PairContact>* contacts) {
  if (split.empty()) return used;
  std::vector<bool> drop(used, false);
  for (const SplitPair& known : split) {
    PairContact& pair = (*contacts)[known.index];
    if (pair.points.empty() || known.normal_sum.length2() == 0.0)
      drop[known.index] = true;
    else
      pair.normal = convertBtToEigen(known.normal_sum.normalized());
  }
  std::size_t kept = 0;
  for (std::size_t i = 0; i < used; ++i)
    if (!drop[i]) std::swap((*contacts)[kept++], (*contacts)[i]);
  return kept;
}

}  // namespace

void readContacts(const BulletScene& scene, double contact_distance,
                  std::vector<PairContact>* contacts) {
  // The pairs of the last read are refilled in place: their point vectors
  // keep their capacity, and a pile's thousands of pairs are not allocated
  // and freed again every step.
  std::size_t used = 0;
  // A pair whose flush corners fill two manifolds is one pair: its
  // manifolds are few, and found by a search among themselves.
  std::vector<SplitPair> split;
  const btCollisionDispatcher& dispatcher = scene.dispatcher();
  const int manifolds = dispatcher.getNumManifolds();
  for (int i = 0; i < manifolds; ++i) {
    const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(i);
    if (manifold->getNumContacts() == 0) continue;
    const BodyHandle a = handleOf(btRigidBody::upcast(manifold->getBody0()));
    const BodyHandle b = handleOf(btRigidBody::upcast(manifold->getBody1()));
    if (manifold->m_companionIdA == kSplitPatchTag) {
      const auto same = std::find_if(split.begin(), split.end(), [&](const SplitPair& known) {
        return known.a == a && known.b == b;
      });
      if (same != split.end()) {
        appendPoints(*manifold, contact_distance, &(*contacts)[same->index], &same->normal_sum);
        continue;
      }
    }
    if (used == contacts->size()) contacts->emplace_back();
    PairContact& pair = (*contacts)[used];
    pair.a = a;
    pair.b = b;
    pair.normal = Eigen::Vector3d::UnitZ();
    pair.points.clear();
    pair.manifold.clear();
    pair.approach_speed = 0.0;
    pair.friction = 0.0;
    btVector3 normal_sum(0, 0, 0);
    appendPoints(*manifold, contact_distance, &pair, &normal_sum);
    if (manifold->m_companionIdA == kSplitPatchTag) {
      split.push_back(SplitPair{a, b, used, normal_sum});
      ++used;
      continue;
    }
    if (pair.points.empty() || normal_sum.length2() == 0.0) continue;
    pair.normal = convertBtToEigen(normal_sum.normalized());
    ++used;
  }
  used = finishSplitPairs(split, used, contacts);
  contacts->resize(used);
}

}  // namespace brick_stack_sim
