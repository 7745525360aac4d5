#pragma once

#include <cstdint>
#include <unordered_map>

#include <btBulletCollisionCommon.h>

namespace brick_stack_sim {

/// Bullet's collision dispatcher, which leaves alone the pairs that are
/// still too far apart to touch.
///
/// The broadphase pairs bodies whose bounding boxes overlap. A tilted plank's
/// box is many times the plank, and in a pile most pairs are planks whose
/// boxes overlap while the planks are several millimetres apart: a box-box
/// test, a manifold refresh and the pair's bodies and algorithm fetched from
/// memory every step, for no contact. Here a pair whose test found no point
/// and whose separating-axis gap exceeds the distance at which a point can
/// be made (its manifold's contact breaking threshold) gets that excess as
/// a budget. Every body's travel is tracked from its pose at each
/// dispatch: the distance its farthest point can have moved (translation
/// plus turn times its bounding radius). The two boxes cannot have closed
/// their gap by more than the sum of their travels, so while that sum
/// stays within the budget the pair is passed over without touching its
/// bodies or its algorithm, and no point it could have had is lost. Any
/// change of a pose counts: a step, a kinematic (held) brick moved, a
/// frozen brick slid, a teleport.
///
/// The budget is set by the pair's algorithm (FlushBoxBoxAlgorithm calls
/// keepApart() while it processes the pair) and is kept in the pair's
/// spare word (btBroadphasePair::m_internalInfo1, which the hashed pair
/// cache leaves to its user; a new pair starts at zero, no budget).
class ApartPairDispatcher : public btCollisionDispatcher {
 public:
  explicit ApartPairDispatcher(btCollisionConfiguration* configuration);

  /// The world whose bodies' travel is tracked. Until it is set (and while
  /// it is null), no pair is passed over. A body's travel is tracked from
  /// its pose at the dispatches that watched it, so a pose changed while
  /// nothing watched still counts once watching resumes.
  void watch(const btCollisionWorld* world) { world_ = world; }

  void dispatchAllCollisionPairs(btOverlappingPairCache* pairs, const btDispatcherInfo& info,
                                 btDispatcher* dispatcher) override;

  /// The pair being processed may be passed over until its two bodies have
  /// travelled `budget` [m] between them. Called by its algorithm; ignored
  /// outside a dispatch.
  void keepApart(btScalar budget);

  /// Pair visits passed over since the dispatcher was made.
  std::uint64_t passedOver() const { return passed_over_; }

 private:
  /// What is known of a body's motion.
  struct Motion {
    btTransform last;        ///< Its pose at the last dispatch.
    btScalar radius = 0;     ///< Of a sphere about its origin holding its shape [m].
    btScalar travel = 0;     ///< How far its farthest point may have moved, summed [m].
    std::uint64_t seen = 0;  ///< The dispatch it was last in the world.
  };

  static void nearCallback(btBroadphasePair& pair, btCollisionDispatcher& dispatcher,
                           const btDispatcherInfo& info);
  /// Adds each body's motion since the last dispatch to its travel.
  void trackTravel();
  /// The summed travel of the pair's two bodies [m]; infinite when one is not tracked.
  btScalar travelOf(const btBroadphasePair& pair) const;

  const btCollisionWorld* world_ = nullptr;
  /// By broadphase proxy id: a body that leaves the world and comes back
  /// gets a new proxy, and new pairs.
  std::unordered_map<int, Motion> motion_;
  std::uint64_t dispatch_ = 0;
  btBroadphasePair* current_ = nullptr;  ///< The pair being processed.
  std::uint64_t passed_over_ = 0;
};

}  // namespace brick_stack_sim
