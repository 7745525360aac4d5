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
  PreparedReset prepared;
  if (Status ready = prepareReset(scene, world_->time(), &prepared); !ready) return ready;
  applyReset(std::move(prepared));
  return Status::success();
}

Status Simulation::prepareReset(const Scene& scene, double start_time,
                                PreparedReset* prepared) const {
  // Everything that can fail happens before the current world is touched. A
  // fresh Bullet world keeps no pair cache or warm-starting data, so a scene
  // after a reset runs exactly as in a new simulation.
  // The scene's table and its `friction` (which mergeSceneTypes gives the types).
  const WorldOptions options = sceneWorldOptions(scene, options_);
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
  PreparedReset result;
  if (Status created = BrickWorld::create(options, types, &result.world, start_time); !created)
    return created;
  result.player = ScenePlayer(scene.bricks, start_time);
  result.refused = result.player.placeDue(result.world.get());
  *prepared = std::move(result);
  return Status::success();
}

std::unique_ptr<BrickWorld> Simulation::applyReset(PreparedReset prepared) {
  for (SimEvent& event : world_->takeEvents()) events_.push_back(std::move(event));
  // Removed in placement order so that observers see a deterministic sequence.
  for (std::string& id : world_->brickIds())
    events_.push_back(
        SimEvent{world_->time(), SimEventKind::kRemoved, std::move(id), "scene reset", {}});
  std::unique_ptr<BrickWorld> replaced = std::move(world_);
  world_ = std::move(prepared.world);
  player_ = std::move(prepared.player);
  for (RefusedPlacement& refused : prepared.refused) refused_.push_back(std::move(refused));
  return replaced;
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
