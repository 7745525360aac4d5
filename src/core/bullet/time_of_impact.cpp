#include "bullet/time_of_impact.h"

#include <algorithm>
#include <cmath>

#include <BulletCollision/NarrowPhaseCollision/btGjkEpa2.h>

namespace brick_stack_sim {

namespace {

/// Advancement steps before a cast gives up (a graze that creeps along a
/// face converges slowly; one that needs this many is no blow).
constexpr int kMaxAdvances = 64;

}  // namespace

bool surfaceGap(const btConvexShape& a, const btTransform& at_a, const btConvexShape& b,
                const btTransform& at_b, SurfaceGap* gap) {
  btGjkEpaSolver2::sResults result;
  if (!btGjkEpaSolver2::SignedDistance(&a, at_a, &b, at_b, at_b.getOrigin() - at_a.getOrigin(),
                                       result))
    return false;
  // GJK measures the shapes shrunk by their margins (btBoxShape keeps its
  // outer size and puts the margin inside): the surfaces lie a margin out.
  // It works in a's frame: its normal (from b towards a) is a's local one.
  gap->normal = (at_a.getBasis() * result.normal).normalized();
  gap->distance = result.distance - a.getMargin() - b.getMargin();
  gap->on_b = result.witnesses[1] + b.getMargin() * gap->normal;
  return std::isfinite(gap->distance) && std::isfinite(gap->normal.length2());
}

bool timeOfImpact(const btConvexShape& a, const btTransform& from, const btTransform& to,
                  const btConvexShape& b, const btTransform& at_b, btScalar tolerance,
                  btScalar* fraction, SurfaceGap* gap) {
  const btVector3 motion = to.getOrigin() - from.getOrigin();
  btTransform at_a = from;
  btScalar lambda = 0;
  for (int advance = 0; advance < kMaxAdvances; ++advance) {
    at_a.setOrigin(from.getOrigin() + lambda * motion);
    if (!surfaceGap(a, at_a, b, at_b, gap)) return false;
    if (gap->distance <= tolerance) {
      *fraction = lambda;
      return true;
    }
    const btScalar closing = -motion.dot(gap->normal);
    if (!(closing > 0)) return false;  // moving apart along the nearest direction
    lambda += gap->distance / closing;
    if (lambda > 1) return false;
  }
  return false;
}

bool timeOfImpactWithPlane(const btConvexShape& a, const btTransform& from, const btTransform& to,
                           const btStaticPlaneShape& plane, const btTransform& at_plane,
                           btScalar* fraction, SurfaceGap* gap) {
  const btVector3 normal = at_plane.getBasis() * plane.getPlaneNormal();
  const btScalar offset = plane.getPlaneConstant() + normal.dot(at_plane.getOrigin());
  // The point of a that leads towards the plane (the support includes the
  // margin, which btBoxShape keeps inside its outer size).
  const btVector3 deepest =
      from(a.localGetSupportingVertex(from.getBasis().transpose() * -normal));
  const btScalar distance = normal.dot(deepest) - offset;
  const btScalar closing = -normal.dot(to.getOrigin() - from.getOrigin());
  if (!(closing > 0) || distance > closing) return false;
  // Already through its surface (the discrete contact has not pushed it out
  // yet): it may go no further in.
  *fraction = std::max<btScalar>(distance, 0) / closing;
  gap->distance = 0;
  gap->normal = normal;
  gap->on_b = deepest + *fraction * (to.getOrigin() - from.getOrigin());
  return true;
}

}  // namespace brick_stack_sim
