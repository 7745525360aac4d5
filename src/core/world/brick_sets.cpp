#include "world/brick_sets.h"

#include <algorithm>
#include <unordered_map>

#include "bullet/bullet_scene.h"
#include "bullet/dormant_colliders.h"

namespace brick_stack_sim {

namespace {

bool bySerial(const BrickRecord* a, const BrickRecord* b) { return a->handle < b->handle; }

void erase(std::vector<BrickRecord*>* set, const BrickRecord* brick) {
  auto position = std::find(set->begin(), set->end(), brick);
  if (position != set->end()) set->erase(position);
}

}  // namespace

void BrickSets::enter(BrickRecord* brick) {
  brick->mode = BrickMode::kDynamic;
  movers_.push_back(brick);
}

void BrickSets::adopt(BrickRecord* brick) {
  if (brick->mode == BrickMode::kDynamic) movers_.push_back(brick);
  if (brick->mode == BrickMode::kHeld) held_.push_back(brick);
}

void BrickSets::leaveSet(BrickRecord* brick) {
  if (isFrozen(brick->mode)) {
    dormant_->remove(brick->handle);  // out of the tree and of Bullet's world
  } else {
    scene_->removeFromWorld(brick->handle);
    erase(brick->mode == BrickMode::kHeld ? &held_ : &movers_, brick);
  }
}

void BrickSets::enterSet(BrickRecord* brick, BrickMode mode) {
  // Bullet files a body by its dynamics when it is added to the world: each
  // change happens while the body is out of it.
  switch (mode) {
    case BrickMode::kDynamic:
      scene_->makeDynamic(brick->handle, brick->type);
      scene_->addToWorld(brick->handle);
      scene_->wakeUp(brick->handle);
      brick->last_good_pose = scene_->pose(brick->handle);
      movers_.insert(std::lower_bound(movers_.begin(), movers_.end(), brick, bySerial), brick);
      break;
    case BrickMode::kFrozenStable:
    case BrickMode::kFrozenLeaning:
      scene_->makeStatic(brick->handle);
      dormant_->add(brick->handle);
      break;
    case BrickMode::kHeld:
      scene_->makeKinematic(brick->handle);
      scene_->addToWorld(brick->handle);
      held_.push_back(brick);
      break;
  }
}

void BrickSets::transfer(BrickRecord* brick, BrickMode mode) {
  if (mode == brick->mode) return;
  if (isFrozen(mode) && isFrozen(brick->mode)) {  // the same set and body either way
    brick->mode = mode;
    return;
  }
  leaveSet(brick);
  enterSet(brick, mode);
  brick->mode = mode;
}

void BrickSets::leave(BrickRecord* brick) { leaveSet(brick); }

Status BrickSets::checkInvariants(const std::vector<const BrickRecord*>& bricks) const {
  if (!std::is_sorted(movers_.begin(), movers_.end(), bySerial))
    return Status::error("the movers are not in placement order");
  // Counted once, so that the check after every step of a debug build stays
  // linear in the number of bricks.
  std::unordered_map<const BrickRecord*, int> in_movers, in_held;
  for (const BrickRecord* brick : movers_) ++in_movers[brick];
  for (const BrickRecord* brick : held_) ++in_held[brick];
  std::unordered_map<BodyHandle, int> frozen_in_world;
  for (BodyHandle handle : dormant_->inWorld()) ++frozen_in_world[handle];
  auto count = [](const auto& counts, const auto& key) {
    auto found = counts.find(key);
    return found == counts.end() ? 0 : found->second;
  };
  std::size_t dynamic = 0, frozen = 0, held = 0;
  for (const BrickRecord* brick : bricks) {
    const BodyHandle h = brick->handle;
    const int movers = count(in_movers, brick), holding = count(in_held, brick);
    const bool in_dormant = dormant_->contains(h);
    bool consistent = false;
    switch (brick->mode) {
      case BrickMode::kDynamic:
        ++dynamic;
        consistent = movers == 1 && holding == 0 && !in_dormant && scene_->inWorld(h) &&
                     scene_->dynamics(h) == BodyDynamics::kDynamic;
        break;
      case BrickMode::kFrozenStable:
      case BrickMode::kFrozenLeaning:
        ++frozen;
        consistent = movers == 0 && holding == 0 && in_dormant &&
                     scene_->dynamics(h) == BodyDynamics::kStatic &&
                     scene_->inWorld(h) == (count(frozen_in_world, h) == 1);
        break;
      case BrickMode::kHeld:
        ++held;
        consistent = movers == 0 && holding == 1 && !in_dormant && scene_->inWorld(h) &&
                     scene_->dynamics(h) == BodyDynamics::kKinematic;
        break;
    }
    if (!consistent)
      return Status::error("brick '" + brick->id + "' in mode " + toString(brick->mode) +
                           " is not in the sets its mode implies");
  }
  if (dynamic != movers_.size() || held != held_.size() || frozen != dormant_->size())
    return Status::error("the sets hold bricks the world does not know");
  return Status::success();
}

}  // namespace brick_stack_sim
