#pragma once
// The node's copy of the world's bricks as it last published them, kept up
// to date at a cost that follows what changed: the world says which bricks
// may have changed (BrickWorld::snapshotChangedSince), the mirror reads only
// those and keeps, of them, the ones that really differ. tf, ~bricks and
// ~markers all publish from it.

#include <cstdint>
#include <string>
#include <vector>

#include "brick_stack_sim/Brick.h"
#include "brick_stack_sim/core/types/brick.h"
#include "brick_stack_sim/core/world/brick_world.h"

namespace brick_stack_sim {
namespace ros_adapter {

/// One brick as last published.
struct MirroredBrick {
  BrickSnapshot snapshot;
  /// The stability model describes it (false in mode none): `geometry` holds.
  bool described = false;
  SupportGeometry geometry;
  /// Every number is finite: `msg` holds, and the brick may be published.
  /// A brick that is not is left off every topic (and counts as removed
  /// from ~bricks' deltas) until it is again.
  bool finite = false;
  Brick msg;
};

/// A brick gone from the world since the mirror last read it: what the
/// topics need to take it back (its tf frame, its markers, its id on
/// ~bricks), and no more, since a reset drops thousands at once.
struct RemovedBrick {
  std::string id;
  unsigned serial = 0;
};

class BrickMirror {
 public:
  /// What one update() found.
  struct Changes {
    /// Indices into bricks() of the bricks that are new or differ, rising.
    std::vector<std::size_t> changed;
    /// Of `changed`, those whose pose differs (or that are new).
    std::vector<std::size_t> moved;
    /// The bricks gone since the last update.
    std::vector<RemovedBrick> removed;
    /// The world was replaced (forget() was called): every brick is new.
    bool replaced = false;
  };

  /// Brings the mirror up to `world`, reading only the bricks the world
  /// says may have changed since the last update.
  Changes update(const BrickWorld& world);
  /// The world was replaced (a reset): its revisions and serials start
  /// again, so the next update reads every brick and reports the old ones
  /// removed.
  void forget() { replaced_ = true; }
  /// forget() was called and no update() has followed: the next reads
  /// every brick.
  bool forgotten() const { return replaced_; }
  /// The world was replaced by the one `fresh` mirrors (a mirror brought up
  /// to it before it replaced this one's, away from the world lock): the next
  /// update() reports this mirror's bricks removed and every brick of
  /// `fresh` new, as after forget(), but reads only what changed in the new
  /// world since `fresh` was made.
  void adopt(BrickMirror fresh);

  /// Every brick, in placement order (rising serials).
  const std::vector<MirroredBrick>& bricks() const { return bricks_; }

 private:
  /// update() after adopt().
  Changes adoptedChanges(const BrickWorld& world);

  std::vector<MirroredBrick> bricks_;
  std::uint64_t revision_ = 0;
  bool replaced_ = true;
  /// adopt() was called and no update() has followed.
  bool adopted_ = false;
  /// The bricks of the worlds adopt() replaced, for the next update() to report.
  std::vector<RemovedBrick> adopted_removed_;
};

}  // namespace ros_adapter
}  // namespace brick_stack_sim
