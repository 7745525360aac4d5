// What BrickWorld tells of its bricks: snapshots, what changed since a
// revision, and the support geometry the model describes.
#include "brick_stack_sim/core/world/brick_world.h"

#include <algorithm>

#include "stability/rigid_block_statics.h"
#include "stability/stability_model.h"
#include "world/world_state.h"

namespace brick_stack_sim {

std::uint64_t BrickWorld::revision() const { return state_->revision; }

std::vector<std::string> BrickWorld::brickIds() const {
  std::vector<std::string> ids;
  ids.reserve(state_->bricks.size());
  for (const auto& brick : state_->bricks.all()) ids.push_back(brick->id);
  return ids;
}

namespace {

BrickSnapshot snapshotOf(const WorldState& w, const BrickRecord& brick) {
  BrickSnapshot s;
  s.id = brick.id;
  s.type = brick.type.name;
  s.pose = w.scene.pose(brick.handle);
  s.linear_velocity = w.scene.linearVelocity(brick.handle);
  s.angular_velocity = w.scene.angularVelocity(brick.handle);
  s.size = brick.type.size;
  s.solid = brick.type.solid;
  s.mass = brick.type.mass;
  s.state = toState(brick.mode);
  s.asleep = brick.mode == BrickMode::kDynamic && !w.scene.isActive(brick.handle);
  s.fell_off = brick.fell_off;
  // Without a stability model a brick carries only itself.
  s.com_above = s.pose.translation();
  s.mass_above = s.mass;
  BrickStability stability;
  if (w.model && w.model->describe(brick.handle, &stability)) {
    s.com_above = stability.com_above;
    s.mass_above = stability.mass_above;
    s.margin = stability.margin;
    for (const SupportPatch& patch : stability.supports)
      s.supported_by.push_back(w.nameOf(patch.supporter));
  }
  s.placed_pose = brick.placed_pose;
  s.placed_at = brick.placed_at;
  s.serial = brick.handle;
  return s;
}

}  // namespace

std::vector<BrickSnapshot> BrickWorld::snapshot() const {
  std::vector<BrickSnapshot> result;
  result.reserve(state_->bricks.size());
  for (const auto& brick : state_->bricks.all()) result.push_back(snapshotOf(*state_, *brick));
  return result;
}

std::vector<BrickSnapshot> BrickWorld::snapshotChangedSince(std::uint64_t revision,
                                                            std::vector<unsigned>* serials) const {
  const WorldState& w = *state_;
  std::vector<BrickSnapshot> changed;
  // A mover may have moved in any step; a frozen brick has not, unless it
  // was frozen, or described anew, since.
  const bool anything = w.revision > revision;
  if (!serials && revision >= w.stamps_from) {
    // The movers and the stamped bricks, without a walk over every brick.
    std::vector<const BrickRecord*> candidates;
    if (anything) {
      candidates.assign(w.sets.movers().begin(), w.sets.movers().end());
      candidates.insert(candidates.end(), w.sets.held().begin(), w.sets.held().end());
    }
    for (auto stamp = w.firstStampAfter(revision); stamp != w.stamps.end(); ++stamp) {
      const BrickRecord* brick = w.bricks.find(stamp->second);
      if (brick && isFrozen(brick->mode)) candidates.push_back(brick);
    }
    // Handles are placement serials: their order is placement order.
    const auto by_serial = [](const BrickRecord* a, const BrickRecord* b) {
      return a->handle < b->handle;
    };
    std::sort(candidates.begin(), candidates.end(), by_serial);
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    changed.reserve(candidates.size());
    for (const BrickRecord* brick : candidates) changed.push_back(snapshotOf(w, *brick));
    return changed;
  }
  if (serials) {
    serials->clear();
    serials->reserve(w.bricks.size());
  }
  for (const auto& brick : w.bricks.all()) {
    if (serials) serials->push_back(brick->handle);
    if (isFrozen(brick->mode) ? brick->changed_at > revision : anything)
      changed.push_back(snapshotOf(w, *brick));
  }
  return changed;
}

bool BrickWorld::find(const std::string& id, BrickSnapshot* brick) const {
  const BrickRecord* found = state_->bricks.find(id);
  if (!found) return false;
  if (brick) *brick = snapshotOf(*state_, *found);
  return true;
}

bool BrickWorld::supportGeometry(const std::string& id, SupportGeometry* geometry) const {
  const WorldState& w = *state_;
  const BrickRecord* found = w.bricks.find(id);
  BrickStability stability;
  if (!found || !w.model || !w.model->describe(found->handle, &stability)) return false;
  SupportGeometry result;
  for (const SupportPatch& patch : stability.supports) {
    SupportGeometry::Patch out;
    out.supporter = w.nameOf(patch.supporter);
    for (const Eigen::Vector2d& corner : patch.hull)
      out.polygon.emplace_back(corner.x(), corner.y(), patch.height);
    result.patches.push_back(std::move(out));
  }
  for (const Eigen::Vector2d& corner : stability.combined_hull)
    result.combined_hull.emplace_back(corner.x(), corner.y(), stability.support_height);
  result.com_above = stability.com_above;
  result.margin = stability.margin;
  // Statics balances weights in its own g; forces scale with the world's.
  const double to_world_gravity = w.options.gravity / StaticsOptions().gravity;
  for (const ContactForce& force : stability.contact_forces)
    result.contact_forces.push_back(
        SupportGeometry::ContactForce{w.nameOf(force.other), force.point, force.normal,
                                      to_world_gravity * force.force, force.friction});
  *geometry = std::move(result);
  return true;
}

}  // namespace brick_stack_sim
