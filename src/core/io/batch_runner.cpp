#include "brick_stack_sim/core/io/batch_runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "brick_stack_sim/core/simulation/simulation.h"
#include "io/json_writer.h"

namespace brick_stack_sim {

namespace {

/// Sim time after which a scene's last brick has had time to settle [s].
constexpr double kDefaultSettleTime = 5.0;

BrickOutcome outcomeOf(const BrickSnapshot& brick) {
  BrickOutcome outcome;
  outcome.brick = brick;
  outcome.displacement = (brick.pose.translation() - brick.placed_pose.translation()).norm();
  outcome.rotation =
      Eigen::AngleAxisd(brick.placed_pose.linear().transpose() * brick.pose.linear()).angle();
  return outcome;
}

}  // namespace

double RunReport::maxDisplacement() const {
  double largest = 0.0;
  for (const BrickOutcome& b : bricks) largest = std::max(largest, b.displacement);
  return largest;
}

Status findBadSceneBricks(const Scene& scene, const BrickTypeLibrary& types,
                          const WorldOptions& world, std::vector<BadSceneBrick>* bad) {
  bad->clear();
  WorldOptions options = world;
  if (scene.table) options.table = *scene.table;
  BrickTypeLibrary scene_types = types;
  if (Status merged = mergeSceneTypes(scene, &scene_types); !merged) return merged;
  std::unique_ptr<BrickWorld> empty;
  if (Status created = BrickWorld::create(options, scene_types, &empty); !created) return created;
  for (std::size_t i = 0; i < scene.bricks.size(); ++i) {
    if (Status alone = empty->checkPlacement(scene.bricks[i].placement); !alone)
      bad->push_back(BadSceneBrick{i, alone.message});
  }
  return Status::success();
}

Status runScene(const Scene& scene, const BrickTypeLibrary& types, const RunOptions& options,
                RunReport* report) {
  const double last_placement = scene.bricks.empty() ? 0.0 : scene.bricks.back().at;
  const double duration = options.duration.value_or(last_placement + kDefaultSettleTime);
  if (!std::isfinite(duration) || duration < 0.0)
    return Status::error("duration must be finite and >= 0 s");
  std::unique_ptr<Simulation> simulation;
  if (Status created = Simulation::create(options.world, types, &simulation); !created)
    return created;
  const auto wall_start = std::chrono::steady_clock::now();
  if (Status reset = simulation->reset(scene); !reset) return reset;
  const BrickWorld& world = simulation->world();
  const auto steps = static_cast<std::uint64_t>(std::llround(duration / world.options().time_step));
  for (std::uint64_t i = 0; i < steps; ++i) {
    simulation->step();
    if (options.observer) options.observer(world);
  }
  RunReport result;
  result.scene = scene.name;
  result.world = world.options();
  result.wall_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  result.sim_time = world.time();
  result.cost = world.cost();
  result.refused = simulation->takeRefused();
  result.scheduled = scene.bricks.size() - simulation->player().pending();
  for (const BrickSnapshot& brick : world.snapshot()) result.bricks.push_back(outcomeOf(brick));
  result.events = simulation->takeEvents();
  *report = std::move(result);
  return Status::success();
}

namespace {

// toJson's parts, one per section of the report, written in the order the
// report's readers (scripts/, the benchmark tables) expect.

/// The run's settings and counters: everything that is one number per run.
void writeRunSummary(const RunReport& r, JsonWriter& json) {
  json.key("scene").value(r.scene);
  json.key("mode").value(r.world.stability.mode);
  json.key("time_step").value(r.world.time_step);
  json.key("iterations").value(static_cast<unsigned long long>(r.world.solver_iterations));
  json.key("sleeping").value(r.world.sleeping.enabled);
  json.key("sim_time").value(r.sim_time);
  json.key("wall_time").value(r.wall_time);
  json.key("steps").value(static_cast<unsigned long long>(r.cost.steps));
  json.key("nonfinite").value(static_cast<unsigned long long>(r.cost.nonfinite));
  json.key("blowups").value(static_cast<unsigned long long>(r.cost.blowups));
  json.key("wake_cycles").value(static_cast<unsigned long long>(r.cost.wake_cycles));
  json.key("scheduled").value(static_cast<unsigned long long>(r.scheduled));
  json.key("lost").value(static_cast<unsigned long long>(r.lost()));
  json.key("missing").value(static_cast<unsigned long long>(r.missing()));
}

/// What the run cost: counts that are reproducible, then the stages' wall
/// times, which are not.
void writeRunCost(const RunReport& r, JsonWriter& json) {
  json.key("cost").beginObject();
  json.key("bullet_steps").value(static_cast<unsigned long long>(r.cost.bullet_steps));
  json.key("awake_brick_steps").value(static_cast<unsigned long long>(r.cost.awake_brick_steps));
  json.key("stability_updates").value(static_cast<unsigned long long>(r.cost.stability_updates));
  json.endObject();
  // Wall time of each stage, like wall_time not reproducible between runs.
  json.key("stage_seconds").beginObject();
  json.key("bullet").value(r.cost.bullet_seconds);
  json.key("contacts").value(r.cost.contact_seconds);
  json.key("stability").value(r.cost.stability_seconds);
  json.endObject();
}

/// Each brick's final pose and how far it ended from where it was placed.
void writeBrickOutcomes(const RunReport& r, JsonWriter& json) {
  json.key("bricks").beginArray();
  for (const BrickOutcome& outcome : r.bricks) {
    const BrickSnapshot& b = outcome.brick;
    const Eigen::Quaterniond q(b.pose.linear());
    const double orientation[4] = {q.x(), q.y(), q.z(), q.w()};
    json.beginObject();
    json.key("id").value(b.id);
    json.key("type").value(b.type);
    json.key("placed_at").value(b.placed_at);
    json.key("position").numbers(b.pose.translation().data(), 3);
    json.key("orientation").numbers(orientation, 4);
    json.key("state").value(toString(b.state));
    json.key("fell_off").value(b.fell_off);
    json.key("displacement").value(outcome.displacement);
    json.key("rotation").value(outcome.rotation);
    json.endObject();
  }
  json.endArray();
}

/// The events of the run in order; "affected" only where there were any.
void writeEvents(const RunReport& r, JsonWriter& json) {
  json.key("events").beginArray();
  for (const SimEvent& e : r.events) {
    json.beginObject();
    json.key("t").value(e.time);
    json.key("kind").value(toString(e.kind));
    json.key("brick").value(e.brick_id);
    json.key("reason").value(e.reason);
    if (!e.affected.empty()) {
      json.key("affected").beginArray();
      for (const std::string& id : e.affected) json.value(id);
      json.endArray();
    }
    json.endObject();
  }
  json.endArray();
}

/// The scene's placements that the world refused, and why.
void writeRefused(const RunReport& r, JsonWriter& json) {
  json.key("refused").beginArray();
  for (const RefusedPlacement& refused : r.refused) {
    json.beginObject();
    json.key("t").value(refused.t);
    json.key("brick").value(refused.id);
    json.key("reason").value(refused.reason);
    json.endObject();
  }
  json.endArray();
}

}  // namespace

std::string toJson(const RunReport& r) {
  JsonWriter json;
  json.beginObject();
  writeRunSummary(r, json);
  writeRunCost(r, json);
  json.key("max_displacement").value(r.maxDisplacement());
  writeBrickOutcomes(r, json);
  writeEvents(r, json);
  writeRefused(r, json);
  json.endObject();
  return json.str() + "\n";
}

}  // namespace brick_stack_sim
