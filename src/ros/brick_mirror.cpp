#include "brick_stack_sim/ros/brick_mirror.h"

#include "brick_stack_sim/ros/conversions.h"

namespace brick_stack_sim {
namespace ros_adapter {
namespace {

// Exact comparisons: a brick whose every published number is bit-equal has
// nothing new to show, and anything else is sent.
bool sameSnapshot(const BrickSnapshot& a, const BrickSnapshot& b) {
  return a.pose.matrix() == b.pose.matrix() && a.linear_velocity == b.linear_velocity &&
         a.angular_velocity == b.angular_velocity && a.state == b.state && a.asleep == b.asleep &&
         a.fell_off == b.fell_off && a.com_above == b.com_above && a.mass_above == b.mass_above &&
         a.margin == b.margin && a.supported_by == b.supported_by && a.id == b.id &&
         a.type == b.type && a.serial == b.serial && a.solid == b.solid;
}

bool sameForce(const SupportGeometry::ContactForce& a, const SupportGeometry::ContactForce& b) {
  return a.other == b.other && a.point == b.point && a.normal == b.normal && a.force == b.force &&
         a.friction == b.friction;
}

bool sameGeometry(const SupportGeometry& a, const SupportGeometry& b) {
  if (a.patches.size() != b.patches.size() || a.contact_forces.size() != b.contact_forces.size() ||
      a.combined_hull != b.combined_hull || a.com_above != b.com_above || a.margin != b.margin)
    return false;
  for (std::size_t i = 0; i < a.patches.size(); ++i)
    if (a.patches[i].supporter != b.patches[i].supporter ||
        a.patches[i].polygon != b.patches[i].polygon)
      return false;
  for (std::size_t i = 0; i < a.contact_forces.size(); ++i)
    if (!sameForce(a.contact_forces[i], b.contact_forces[i])) return false;
  return true;
}

MirroredBrick mirrored(const BrickWorld& world, BrickSnapshot snapshot) {
  MirroredBrick brick;
  brick.described = world.supportGeometry(snapshot.id, &brick.geometry);
  brick.finite = toMsg(snapshot, &brick.msg).ok;
  brick.snapshot = std::move(snapshot);
  return brick;
}

RemovedBrick removal(const MirroredBrick& brick) {
  return RemovedBrick{brick.snapshot.id, brick.snapshot.serial};
}

/// Nothing a subscriber sees of the brick differs.
bool unchanged(const MirroredBrick& before, const MirroredBrick& now) {
  return sameSnapshot(before.snapshot, now.snapshot) && before.described == now.described &&
         (!now.described || sameGeometry(before.geometry, now.geometry));
}

// BrickMirror::update's two passes over the mirror after a partial read.

/// Moves the bricks whose serials are not among `serials` (the world's, in
/// rising order) from `bricks` to `removed`. Serials rise in placement
/// order and are never reused: the world's list is the mirror's minus the
/// removed bricks, plus new ones at its end. The mirror is kept in place
/// (a settled scene moves none of its entries).
void dropRemoved(const std::vector<unsigned>& serials, std::vector<MirroredBrick>* bricks,
                 std::vector<RemovedBrick>* removed) {
  std::size_t kept = 0;
  std::size_t next_serial = 0;
  for (std::size_t i = 0; i < bricks->size(); ++i) {
    const unsigned serial = (*bricks)[i].snapshot.serial;
    while (next_serial < serials.size() && serials[next_serial] < serial) ++next_serial;
    if (next_serial < serials.size() && serials[next_serial] == serial) {
      if (kept != i) (*bricks)[kept] = std::move((*bricks)[i]);
      ++kept;
      ++next_serial;
    } else {
      removed->push_back(removal((*bricks)[i]));
    }
  }
  bricks->resize(kept);
}

/// Brings `bricks` up to the snapshots read (`fresh`, in placement order),
/// walked beside the mirror: a brick that differs replaces its entry, a new
/// one is inserted; both are listed in `changes`.
void mergeFresh(const BrickWorld& world, std::vector<BrickSnapshot> fresh,
                std::vector<MirroredBrick>* bricks, BrickMirror::Changes* changes) {
  std::size_t at = 0;
  for (BrickSnapshot& snapshot : fresh) {
    while (at < bricks->size() && (*bricks)[at].snapshot.serial < snapshot.serial) ++at;
    MirroredBrick now = mirrored(world, std::move(snapshot));
    if (at < bricks->size() && (*bricks)[at].snapshot.serial == now.snapshot.serial) {
      MirroredBrick& before = (*bricks)[at];
      if (unchanged(before, now)) continue;
      changes->changed.push_back(at);
      if (before.snapshot.pose.matrix() != now.snapshot.pose.matrix()) changes->moved.push_back(at);
      before = std::move(now);
      continue;
    }
    // New: after every brick the mirror had, since serials only rise.
    bricks->insert(bricks->begin() + static_cast<std::ptrdiff_t>(at), std::move(now));
    changes->changed.push_back(at);
    changes->moved.push_back(at);
  }
}

}  // namespace

void BrickMirror::adopt(BrickMirror fresh) {
  // The bricks last published go; those of a world adopted and replaced
  // again before any update() were never published.
  if (!adopted_)
    for (const MirroredBrick& brick : bricks_) adopted_removed_.push_back(removal(brick));
  bricks_ = std::move(fresh.bricks_);
  revision_ = fresh.revision_;
  replaced_ = fresh.replaced_;
  adopted_ = true;
}

BrickMirror::Changes BrickMirror::update(const BrickWorld& world) {
  if (adopted_) return adoptedChanges(world);
  Changes changes;
  changes.replaced = replaced_;
  std::vector<unsigned> serials;
  std::vector<BrickSnapshot> fresh;
  if (replaced_) {
    fresh = world.snapshot();
    for (const MirroredBrick& brick : bricks_) changes.removed.push_back(removal(brick));
    bricks_ = {};
    replaced_ = false;
  } else if (world.revision() == revision_) {
    return changes;  // nothing happened: not even a walk over the bricks
  } else {
    fresh = world.snapshotChangedSince(revision_, &serials);
  }
  revision_ = world.revision();
  if (changes.replaced) {
    for (BrickSnapshot& snapshot : fresh) {
      changes.changed.push_back(bricks_.size());
      changes.moved.push_back(bricks_.size());
      bricks_.push_back(mirrored(world, std::move(snapshot)));
    }
    return changes;
  }
  dropRemoved(serials, &bricks_, &changes.removed);
  mergeFresh(world, std::move(fresh), &bricks_, &changes);
  return changes;
}

BrickMirror::Changes BrickMirror::adoptedChanges(const BrickWorld& world) {
  adopted_ = false;
  // What changed in the new world since the adopted mirror was made, read as
  // usual; then, as after forget(), every brick is new to the subscribers
  // and the replaced worlds' bricks are gone.
  Changes changes;
  if (replaced_) {  // a mirror adopted before it read its world: read it now
    bricks_.clear();
    for (BrickSnapshot& snapshot : world.snapshot())
      bricks_.push_back(mirrored(world, std::move(snapshot)));
    revision_ = world.revision();
    replaced_ = false;
  } else if (world.revision() != revision_) {
    std::vector<unsigned> serials;
    std::vector<BrickSnapshot> fresh = world.snapshotChangedSince(revision_, &serials);
    revision_ = world.revision();
    dropRemoved(serials, &bricks_, &changes.removed);
    mergeFresh(world, std::move(fresh), &bricks_, &changes);
  }
  changes.removed.insert(changes.removed.begin(), adopted_removed_.begin(), adopted_removed_.end());
  adopted_removed_.clear();
  changes.changed.resize(bricks_.size());
  for (std::size_t i = 0; i < bricks_.size(); ++i) changes.changed[i] = i;
  changes.moved = changes.changed;
  changes.replaced = true;
  return changes;
}

}  // namespace ros_adapter
}  // namespace brick_stack_sim
