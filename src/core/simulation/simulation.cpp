#include "brick_stack_sim/core/simulation/simulation.h"

#include "util/text_format.h"

namespace brick_stack_sim {

Simulation::Simulation(const WorldOptions& options, const BrickTypeLibrary& types)
    : options_(options), types_(types) {}

Status Simulation::create(const WorldOptions& options, const BrickTypeLibrary& types,
                          std::unique_ptr<Simulation>* simulation) {
  simulation->reset();
  std::unique_ptr<Simulation> result(new Simulation(options, types));
  if (Status created = BrickWorld::create(options, types, &result->world_); !created)
    return created;
  *simulation = std::move(result);
  return Status::success();
}

Status Simulation::reset(const Scene& scene) {
  // Everything that can fail happens before the current world is touched. A
  // fresh Bullet world keeps no pair cache or warm-starting data, so a scene
  // after a reset runs exactly as in a new simulation.
  WorldOptions options = options_;
  if (scene.table) options.table = *scene.table;
  // A scene is refused whole rather than brick by brick at its times: a
  // brick outside the world box is a typo in the file, not an event.
  for (const ScheduledBrick& brick : scene.bricks) {
    const Eigen::Vector3d& centre = brick.placement.pose.translation();
    if (!insideWorld(options, centre))
      return Status::error("brick " + quotedId(brick.placement.id) + " at " + formatVector(centre) +
                           " lies outside the world box: " + describeWorldBox(options));
  }
  BrickTypeLibrary types = types_;
  if (Status merged = mergeSceneTypes(scene, &types); !merged) return merged;
  std::unique_ptr<BrickWorld> replacement;
  if (Status created = BrickWorld::create(options, types, &replacement, world_->time()); !created)
    return created;

  for (SimEvent& event : world_->takeEvents()) events_.push_back(std::move(event));
  // Removed in placement order so that observers see a deterministic sequence.
  for (const BrickSnapshot& brick : world_->snapshot())
    events_.push_back(
        SimEvent{world_->time(), SimEventKind::kRemoved, brick.id, "scene reset", {}});
  world_ = std::move(replacement);
  player_ = ScenePlayer(scene.bricks, world_->time());
  for (RefusedPlacement& refused : player_.placeDue(world_.get()))
    refused_.push_back(std::move(refused));
  return Status::success();
}

void Simulation::step() {
  world_->step();
  if (player_.done()) return;
  for (RefusedPlacement& refused : player_.placeDue(world_.get()))
    refused_.push_back(std::move(refused));
}

std::vector<SimEvent> Simulation::takeEvents() {
  std::vector<SimEvent> events;
  events.swap(events_);
  for (SimEvent& event : world_->takeEvents()) events.push_back(std::move(event));
  return events;
}

std::vector<RefusedPlacement> Simulation::takeRefused() {
  std::vector<RefusedPlacement> refused;
  refused.swap(refused_);
  return refused;
}

}  // namespace brick_stack_sim
