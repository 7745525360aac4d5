// The node's ~reset and its initial scene: the scene's world is built off
// the world lock and swapped in under it, so that the other clients are
// answered from the old scene meanwhile and see the new one whole.
#include <malloc.h>

#include <mutex>
#include <sstream>

#include "brick_stack_sim/core/allocation_guard.h"
#include "brick_stack_sim/core/options/parameter_value.h"
#include "brick_stack_sim/ros/node.h"
#include "time_text.h"

namespace brick_stack_sim {
namespace ros_adapter {

namespace {

/// Hands the heap's free pages back to the system. A 10 000-brick world is
/// some 100 MB of small blocks spread over the allocator's per-thread
/// arenas (a service thread builds it, another frees it); glibc returns
/// little of that by itself, so a node reset over and over would keep the
/// high-water mark of every arena. malloc_trim(0) releases the free pages of
/// all arenas.
void releaseFreeMemory() { malloc_trim(0); }

}  // namespace

Status SimNode::loadNamedScene(const std::string& scene_name, Scene* scene) const {
  if (scene_name.empty()) return Status::success();
  // The types of the simulation, not of its current world: they never change.
  if (Status loaded = loadScene(scene_name, options_.config.data.scene_dirs, simulation_->types(),
                                scene, sceneLimits(options_.config.data));
      !loaded)
    return loaded;
  // Refused whole, as a brick outside the world box: tf is the adapter's,
  // the core knows no fixed frame (docs/design.md, "Layers").
  for (const ScheduledBrick& brick : scene->bricks)
    if (Status framed = publisher_->frames().checkBrickId(brick.placement.id); !framed)
      return Status::error("scene '" + scene_name + "': brick " + framed.message);
  return Status::success();
}

Status SimNode::resetWorld(const std::string& scene_name, const Scene& scene,
                           std::string* message) {
  double start = 0.0;
  {
    std::lock_guard<TicketMutex> lock(world_mutex_);
    start = simTime();
    // The timer steps nothing until the swap: the new world's clock starts
    // where the old one stands, and may not go backwards.
    resetting_ = true;
  }
  PreparedReset prepared;
  // Out of memory while building, the old world plays on, and the timer steps it again.
  const Status ready = refuseOnAllocationFailure(
      "building its world", [&] { return simulation_->prepareReset(scene, start, &prepared); });
  // What the publisher and ~get_bricks will show of the new world, read
  // from it while it is still nobody else's.
  BrickMirror published;
  if (ready) published.update(*prepared.world);
  BrickMirror answered = published;
  std::unique_ptr<BrickWorld> replaced;
  {
    std::lock_guard<TicketMutex> lock(world_mutex_);
    resetting_ = false;
    if (!ready)
      return Status::error("scene '" + shortenForMessage(scene_name, 200) + "': " + ready.message);
    replaced = simulation_->applyReset(std::move(prepared));
    publisher_->adopt(std::move(published));
    // ~get_bricks reports no removals: it only needs the new world's bricks.
    answers_ = std::move(answered);
    *message = startNewWorld(scene_name, scene);
  }
  replaced.reset();  // every Bullet body of the old world: no client waits for it
  releaseFreeMemory();
  return Status::success();
}

std::string SimNode::startNewWorld(const std::string& scene_name, const Scene& scene) {
  publisher_->publishEvents();  // the removed events, then the new scene's first placements
  const std::vector<RefusedPlacement> refused = simulation_->takeRefused();
  logRefusedPlacements(refused);
  publisher_->markDirty();
  pacer_.schedulePublish(simTime());
  restartPacing();

  std::ostringstream text;
  if (scene_name.empty()) {
    text << "cleared the table at " << formatTime(simTime());
  } else {
    const std::string& name = scene.name.empty() ? scene_name : scene.name;
    text << "playing scene '" << shortenForMessage(name, 200) << "' from " << formatTime(simTime())
         << ": " << counted(scene.bricks.size(), "brick") << " scheduled";
    if (!refused.empty()) text << ", " << refused.size() << " refused at once (see the log)";
  }
  return text.str();
}

}  // namespace ros_adapter
}  // namespace brick_stack_sim
