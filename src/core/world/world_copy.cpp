// BrickWorld::copy: a second world in this one's state, for what-ifs that
// run on while the original goes on (a plan simulated off the node's lock).
#include <memory>
#include <string>
#include <vector>

#include "brick_stack_sim/core/world/brick_world.h"
#include "world/world_state.h"

namespace brick_stack_sim {

bool BrickWorld::copiesExactly() const {
  // Bullet's contact caches (the impulses it warm-starts from) are not
  // copied: they exist only between bodies that move in its world.
  return state_->sets.movers().empty() && state_->sets.held().empty();
}

std::unique_ptr<BrickWorld> BrickWorld::copy() const {
  const WorldState& from = *state_;
  auto state = std::make_unique<WorldState>(from.options, from.types, from.start_time);
  WorldState* to = state.get();
  if (from.model)
    to->model = from.model->clone([to](BodyHandle handle) { return to->nameOf(handle); });
  for (const auto& brick : from.bricks.all()) {
    BrickRecord* record = to->bricks.add(std::make_unique<BrickRecord>(*brick));
    to->scene.copyBrick(record->handle, record->type, from.scene);
  }
  // Bullet numbers bodies as they come into its world, and that order is
  // the order in which it pairs and solves them.
  for (BodyHandle handle : from.scene.worldOrder()) to->scene.addToWorld(handle);
  to->dormant.copyFrom(from.dormant);
  for (const BrickRecord* mover : from.sets.movers())
    to->sets.adopt(to->bricks.find(mover->handle));
  for (const BrickRecord* held : from.sets.held()) to->sets.adopt(to->bricks.find(held->handle));
  to->contacts = from.contacts;
  to->presses = from.presses;
  to->model_changed = from.model_changed;
  to->judgement_pending = from.judgement_pending;
  to->placed_at_rest = from.placed_at_rest;
  to->next_serial = from.next_serial;
  to->revision = from.revision;
  to->stamps = from.stamps;
  to->stamps_from = from.stamps_from;
  to->cost = from.cost;
  return std::unique_ptr<BrickWorld>(new BrickWorld(std::move(state)));
}

Status BrickWorld::copyInMode(const std::string& mode, std::unique_ptr<BrickWorld>* copy) const {
  WorldOptions options = state_->options;
  options.stability.mode = mode;
  std::unique_ptr<BrickWorld> world;
  if (Status created = create(options, state_->types, &world, time()); !created) return created;
  std::vector<BrickPlacement> placements;
  for (const BrickSnapshot& brick : snapshot())
    placements.push_back(BrickPlacement{brick.id, brick.type, brick.pose, brick.linear_velocity,
                                        brick.angular_velocity});
  const std::vector<Status> placed = world->addBricks(placements);
  for (std::size_t i = 0; i < placed.size(); ++i) {
    if (!placed[i])
      return Status::error("cannot rebuild the world in mode " + mode + ": brick " +
                           placements[i].id + " was refused: " + placed[i].message);
  }
  world->takeEvents();
  *copy = std::move(world);
  return Status::success();
}

}  // namespace brick_stack_sim
