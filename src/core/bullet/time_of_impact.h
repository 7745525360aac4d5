#pragma once

#include <utility>
#include <vector>

#include <btBulletDynamicsCommon.h>

namespace brick_stack_sim {

/// A cast has met what it strikes once their surfaces are this close [m]:
/// far below a brick's dimensions, far above GJK's rounding.
constexpr btScalar kImpactTolerance = 1e-5;

/// Where two convex shapes are nearest, their surfaces (margins included).
struct SurfaceGap {
  btScalar distance = 0;  ///< < 0 when they overlap [m].
  btVector3 normal;       ///< Unit, from b towards a, world.
  btVector3 on_b;         ///< The nearest point of b's surface, world.
};

/// The gap between `a` at `at_a` and `b` at `at_b` (GJK, EPA when they
/// overlap). False when GJK fails.
bool surfaceGap(const btConvexShape& a, const btTransform& at_a, const btConvexShape& b,
                const btTransform& at_b, SurfaceGap* gap);

/// The first time `a`, carried in a straight line from `from` to `to` (its
/// orientation `from`'s), comes within `tolerance` [m] of `b` at `at_b`:
/// the fraction of the way, and the gap there. Conservative advancement:
/// for a translation the gap is a convex function of the way, so each step
/// of gap over closing speed stays short of the first contact. Bullet's own
/// btContinuousConvexCollision stops 1 mm short (a hard-coded radius for
/// game-sized bodies), an eighth of a KAPLA's thickness. False when it
/// never comes that close on the way.
bool timeOfImpact(const btConvexShape& a, const btTransform& from, const btTransform& to,
                  const btConvexShape& b, const btTransform& at_b, btScalar tolerance,
                  btScalar* fraction, SurfaceGap* gap);

/// timeOfImpact() against a static plane (the floor), exactly: the point of
/// `a` deepest along the plane's normal reaches it (at once when it is
/// already below it: a half-space is never passed through).
bool timeOfImpactWithPlane(const btConvexShape& a, const btTransform& from, const btTransform& to,
                           const btStaticPlaneShape& plane, const btTransform& at_plane,
                           btScalar* fraction, SurfaceGap* gap);

/// The convex pieces of `shape` at `at`: the shape itself when convex, a
/// compound's children (at their places) when compound, none otherwise.
std::vector<std::pair<const btConvexShape*, btTransform>> convexPieces(
    const btCollisionShape& shape, const btTransform& at);

/// surfaceGap() of any two shapes made of convex pieces: the least over
/// the pairs of pieces. False when no pair could be measured.
bool surfaceGapOfShapes(const btCollisionShape& a, const btTransform& at_a,
                        const btCollisionShape& b, const btTransform& at_b, SurfaceGap* gap);

/// timeOfImpact() (or timeOfImpactWithPlane() against a plane `b`) of any
/// shapes made of convex pieces: the earliest over the pairs of pieces.
bool timeOfImpactOfShapes(const btCollisionShape& a, const btTransform& from, const btTransform& to,
                          const btCollisionShape& b, const btTransform& at_b, btScalar tolerance,
                          btScalar* fraction, SurfaceGap* gap);

}  // namespace brick_stack_sim
