#include "world/world_state.h"

#include <algorithm>

#include "brick_stack_sim/core/types/table_solid.h"

namespace brick_stack_sim {

void WorldState::recordChange(Change change) {
  ++revision;
  if (change == Change::kBricks) return;
  model_changed = true;
  if (change == Change::kBodies) contacts.clear();
}

std::vector<std::pair<std::uint64_t, BodyHandle>>::const_iterator WorldState::firstStampAfter(
    std::uint64_t revision) const {
  return std::upper_bound(stamps.begin(), stamps.end(), revision,
                          [](std::uint64_t at, const auto& stamp) { return at < stamp.first; });
}

void WorldState::stampChanged(BrickRecord* brick) {
  brick->changed_at = revision;
  stamps.emplace_back(revision, brick->handle);
  // Beyond twice the bricks, the older half goes, cut between revisions: a
  // reader that saw a revision before the cut walks every brick instead.
  if (stamps.size() <= 2 * bricks.size() + 64) return;
  stamps_from = stamps[stamps.size() / 2].first;
  stamps.erase(stamps.cbegin(), firstStampAfter(stamps_from));
}

BrickRecord* BrickRegistry::add(std::unique_ptr<BrickRecord> brick) {
  BrickRecord* record = brick.get();
  by_id_[record->id] = record;
  by_handle_[record->handle] = record;
  bricks_.push_back(std::move(brick));  // the newest serial: the end keeps the order
  return record;
}

void BrickRegistry::erase(BrickRecord* brick) {
  by_id_.erase(brick->id);
  by_handle_.erase(brick->handle);
  bricks_.erase(std::find_if(bricks_.begin(), bricks_.end(),
                             [brick](const auto& entry) { return entry.get() == brick; }));
}

BrickRecord* BrickRegistry::find(const std::string& id) const {
  auto found = by_id_.find(id);
  return found == by_id_.end() ? nullptr : found->second;
}

BrickRecord* BrickRegistry::find(BodyHandle handle) const {
  auto found = by_handle_.find(handle);
  return found == by_handle_.end() ? nullptr : found->second;
}

std::vector<const BrickRecord*> BrickRegistry::records() const {
  std::vector<const BrickRecord*> result;
  result.reserve(bricks_.size());
  for (const auto& brick : bricks_) result.push_back(brick.get());
  return result;
}

std::string BrickRegistry::freeId(unsigned serial) const {
  for (unsigned n = serial;; ++n) {
    std::string candidate = "brick_" + std::to_string(n);
    if (!by_id_.count(candidate)) return candidate;
  }
}

WorldState::WorldState(const WorldOptions& world_options, const BrickTypeLibrary& brick_types,
                       double start)
    : options(world_options),
      types(brick_types),
      start_time(start),
      table_solid(tableSolid(world_options.table)),
      floor_solid(boxSolid(Eigen::Vector3d(1e3, 1e3, 0.5))),
      scene(world_options),
      dormant(&scene),
      sets(&scene, &dormant) {}

void WorldState::emit(SimEventKind kind, const std::string& id, std::string reason,
                      std::vector<std::string> affected) {
  events.push_back(SimEvent{time(), kind, id, std::move(reason), std::move(affected)});
}

std::string WorldState::nameOf(BodyHandle handle) const {
  if (handle == kTableHandle) return "table";
  if (handle == kFloorHandle) return "floor";
  const BrickRecord* brick = bricks.find(handle);
  return brick ? brick->id : "brick#" + std::to_string(handle);
}

PlacedSolid WorldState::solidOf(BodyHandle handle) const {
  PlacedSolid placed;
  if (handle == kTableHandle) {
    placed.solid = &table_solid;
    placed.pose = tablePose(options.table);
  } else if (handle == kFloorHandle) {
    placed.solid = &floor_solid;
    placed.pose.translation().z() = -options.table.height - 0.5;
  } else {
    placed = bricks.find(handle)->type.placed(scene.pose(handle));
  }
  return placed;
}

double WorldState::frictionOf(BodyHandle handle) const {
  return isGround(handle) ? options.table.friction : bricks.find(handle)->type.friction;
}

Eigen::Vector3d centreOfMassAt(const BrickType& type, const Eigen::Isometry3d& pose) {
  return pose * type.mass_frame.translation();
}

BodyMotion WorldState::motionOf(const BrickRecord& brick) const {
  return BodyMotion{brick.handle, scene.centreOfMass(brick.handle), brick.type.mass,
                    scene.linearVelocity(brick.handle), scene.angularVelocity(brick.handle)};
}

double WorldState::fastestPointSpeed(const BrickRecord& brick) const {
  return scene.linearSpeed(brick.handle) +
         scene.angularSpeed(brick.handle) * brick.type.reachFromCentreOfMass();
}

}  // namespace brick_stack_sim
