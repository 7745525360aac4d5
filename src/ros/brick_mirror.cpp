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
         a.type == b.type && a.serial == b.serial;
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

}  // namespace

BrickMirror::Changes BrickMirror::update(const BrickWorld& world) {
  Changes changes;
  changes.replaced = replaced_;
  std::vector<unsigned> serials;
  std::vector<BrickSnapshot> fresh;
  if (replaced_) {
    fresh = world.snapshot();
    changes.removed = std::move(bricks_);
    bricks_.clear();
    replaced_ = false;
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

  // Three lists in placement order: what the mirror had, every serial the
  // world has, and the snapshots of those that may have changed.
  std::vector<MirroredBrick> next;
  next.reserve(serials.size());
  std::size_t old = 0;
  std::size_t read = 0;
  for (unsigned serial : serials) {
    for (; old < bricks_.size() && bricks_[old].snapshot.serial < serial; ++old)
      changes.removed.push_back(std::move(bricks_[old]));
    MirroredBrick* before =
        old < bricks_.size() && bricks_[old].snapshot.serial == serial ? &bricks_[old++] : nullptr;
    const bool read_now = read < fresh.size() && fresh[read].serial == serial;
    if (!read_now) {
      // Unchanged by the world's account, so mirrored already: a brick the
      // mirror has not seen is always among those read.
      if (before) next.push_back(std::move(*before));
      continue;
    }
    MirroredBrick now = mirrored(world, std::move(fresh[read++]));
    if (before && sameSnapshot(before->snapshot, now.snapshot) &&
        before->described == now.described &&
        (!now.described || sameGeometry(before->geometry, now.geometry))) {
      next.push_back(std::move(*before));
      continue;
    }
    changes.changed.push_back(next.size());
    if (!before || before->snapshot.pose.matrix() != now.snapshot.pose.matrix())
      changes.moved.push_back(next.size());
    next.push_back(std::move(now));
  }
  for (; old < bricks_.size(); ++old) changes.removed.push_back(std::move(bricks_[old]));
  bricks_ = std::move(next);
  return changes;
}

}  // namespace ros_adapter
}  // namespace brick_stack_sim
