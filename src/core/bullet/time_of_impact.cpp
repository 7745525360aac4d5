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
  const btVector3 deepest = from(a.localGetSupportingVertex(from.getBasis().transpose() * -normal));
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

std::vector<std::pair<const btConvexShape*, btTransform>> convexPieces(
    const btCollisionShape& shape, const btTransform& at) {
  std::vector<std::pair<const btConvexShape*, btTransform>> pieces;
  if (shape.isConvex()) {
    pieces.emplace_back(static_cast<const btConvexShape*>(&shape), at);
  } else if (shape.isCompound()) {
    const auto& compound = static_cast<const btCompoundShape&>(shape);
    for (int i = 0; i < compound.getNumChildShapes(); ++i)
      if (compound.getChildShape(i)->isConvex())
        pieces.emplace_back(static_cast<const btConvexShape*>(compound.getChildShape(i)),
                            at * compound.getChildTransform(i));
  }
  return pieces;
}

bool surfaceGapOfShapes(const btCollisionShape& a, const btTransform& at_a,
                        const btCollisionShape& b, const btTransform& at_b, SurfaceGap* gap) {
  bool found = false;
  for (const auto& [piece_a, place_a] : convexPieces(a, at_a)) {
    for (const auto& [piece_b, place_b] : convexPieces(b, at_b)) {
      SurfaceGap candidate;
      if (!surfaceGap(*piece_a, place_a, *piece_b, place_b, &candidate)) continue;
      if (!found || candidate.distance < gap->distance) *gap = candidate;
      found = true;
    }
  }
  return found;
}

bool timeOfImpactOfShapes(const btCollisionShape& a, const btTransform& from, const btTransform& to,
                          const btCollisionShape& b, const btTransform& at_b, btScalar tolerance,
                          btScalar* fraction, SurfaceGap* gap) {
  // The pieces of a keep their places in a while a translates.
  const btTransform moved = to * from.inverse();
  bool found = false;
  for (const auto& [piece_a, start] : convexPieces(a, from)) {
    const btTransform end = a.isConvex() ? to : moved * start;
    btScalar at = 1;
    SurfaceGap candidate;
    bool meets = false;
    if (b.getShapeType() == STATIC_PLANE_PROXYTYPE) {
      meets = timeOfImpactWithPlane(*piece_a, start, end, static_cast<const btStaticPlaneShape&>(b),
                                    at_b, &at, &candidate);
    } else {
      for (const auto& [piece_b, place_b] : convexPieces(b, at_b)) {
        btScalar piece_at = 1;
        SurfaceGap piece_gap;
        if (!timeOfImpact(*piece_a, start, end, *piece_b, place_b, tolerance, &piece_at,
                          &piece_gap) ||
            (meets && !(piece_at < at)))
          continue;
        at = piece_at;
        candidate = piece_gap;
        meets = true;
      }
    }
    if (!meets || (found && !(at < *fraction))) continue;
    *fraction = at;
    *gap = candidate;
    found = true;
  }
  return found;
}

}  // namespace brick_stack_sim
