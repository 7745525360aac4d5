#pragma once

#include <vector>

#include "brick_stack_sim/core/status.h"
#include "world/brick_record.h"

namespace brick_stack_sim {

class BulletScene;
class DormantColliders;

/// The sets a brick's mode puts it in, after Box2D's solver sets: the movers
/// (dynamic bodies in Bullet's world, in placement order), the dormant
/// colliders (frozen static bodies, in Bullet's world only while a mover is
/// near) and the held bricks (kinematic bodies in Bullet's world). A brick
/// changes mode only through transfer(), which moves it between the sets and
/// changes its Bullet body to match.
class BrickSets {
 public:
  BrickSets(BulletScene* scene, DormantColliders* dormant) : scene_(scene), dormant_(dormant) {}

  /// A new brick, whose dynamic body the scene has just added to Bullet's
  /// world, joins the movers (the newest serial: last in placement order).
  void enter(BrickRecord* brick);
  /// A copied brick joins the set of its mode as it is, its body already
  /// copied (frozen: the dormant colliders copy it themselves); in the
  /// order the source's sets hold them (movers(), held()).
  void adopt(BrickRecord* brick);
  /// Moves `brick` to `mode`. A brick entering kDynamic starts at rest and
  /// awake, and its pose becomes its last good one.
  void transfer(BrickRecord* brick, BrickMode mode);
  /// A brick leaving the world leaves every set and Bullet's world (its body
  /// is the scene's to destroy).
  void leave(BrickRecord* brick);

  const std::vector<BrickRecord*>& movers() const { return movers_; }
  const std::vector<BrickRecord*>& held() const { return held_; }

  /// Every brick is in exactly the sets its mode says, with the Bullet body
  /// its mode needs; the message names the first brick that is not.
  /// Checked after every step in debug builds, and by the tests.
  Status checkInvariants(const std::vector<const BrickRecord*>& bricks) const;

 private:
  void leaveSet(BrickRecord* brick);
  void enterSet(BrickRecord* brick, BrickMode mode);

  BulletScene* scene_;
  DormantColliders* dormant_;
  std::vector<BrickRecord*> movers_;
  std::vector<BrickRecord*> held_;
};

}  // namespace brick_stack_sim
