#include "brick_stack_sim/core/io/batch_runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>

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

/// Finds the bricks that fall during a run (docs/design.md, "The batch
/// runner"). Every brick each step would cost a large scene more than its
/// physics, so it looks every kFallCheckInterval, and only at the bricks
/// that may have moved since its last look: those not frozen, and frozen
/// ones that froze or that the model moved since (snapshotChangedSince).
/// A frozen brick does not move.
class FallWatch {
 public:
  FallWatch(const BrickWorld& world, double distance, double angle)
      : world_(world), distance_(distance), angle_(angle) {}

  void look() {
    for (const BrickSnapshot& brick : world_.snapshotChangedSince(revision_)) {
      if (fell_at_.count(brick.id)) continue;
      if (brick.fell_off || comShift(brick) > distance_ || turn(brick) > angle_)
        record(brick.id, world_.time());
    }
    revision_ = world_.revision();
  }

  /// A brick that left the world box falls at its lost event, unless it was
  /// seen fallen before.
  void lost(const std::vector<SimEvent>& events) {
    for (const SimEvent& event : events)
      if (event.kind == SimEventKind::kLost && !fell_at_.count(event.brick_id))
        record(event.brick_id, event.time);
    std::stable_sort(falls_.begin(), falls_.end(),
                     [](const BrickFall& a, const BrickFall& b) { return a.t < b.t; });
  }

  std::optional<double> fellAt(const std::string& id) const {
    const auto found = fell_at_.find(id);
    if (found == fell_at_.end()) return std::nullopt;
    return found->second;
  }
  std::vector<BrickFall> falls() const { return falls_; }

 private:
  /// How far its centre of mass is from where it was placed [m].
  double comShift(const BrickSnapshot& brick) const {
    const BrickType* type = world_.types().find(brick.type);
    const Eigen::Vector3d com =
        type ? Eigen::Vector3d(type->mass_frame.translation()) : Eigen::Vector3d::Zero();
    return (brick.pose * com - brick.placed_pose * com).norm();
  }
  /// How far it has turned from how it was placed [rad].
  static double turn(const BrickSnapshot& brick) {
    return Eigen::AngleAxisd(brick.placed_pose.linear().transpose() * brick.pose.linear()).angle();
  }
  void record(const std::string& id, double t) {
    fell_at_[id] = t;
    falls_.push_back(BrickFall{id, t});
  }

  const BrickWorld& world_;
  double distance_;
  double angle_;
  std::uint64_t revision_ = 0;
  std::map<std::string, double> fell_at_;
  std::vector<BrickFall> falls_;
};

/// The bricks `scene` places at its first instant, at rest where placed,
/// lowest first (by the bottom of their bounds). A brick placed at rest
/// before the brick it rests on would wait, unjudged, for Bullet to bring
/// it to rest there; bottom up, each finds what carries it already placed.
std::vector<BrickPlacement> firstStructure(const Scene& scene, const BrickTypeLibrary& types) {
  std::vector<std::pair<double, BrickPlacement>> first;
  for (const ScheduledBrick& brick : scene.bricks) {
    if (brick.at != scene.bricks.front().at) break;  // sorted by `at`
    BrickPlacement placement = brick.placement;
    placement.linear_velocity.setZero();
    placement.angular_velocity.setZero();
    const BrickType* type =
        types.find(placement.type.empty() ? types.defaultType() : placement.type);
    const double bottom = type && type->solid ? bounds(type->placed(placement.pose)).min().z()
                                              : placement.pose.translation().z();
    first.emplace_back(bottom, std::move(placement));
  }
  std::stable_sort(first.begin(), first.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<BrickPlacement> placements;
  for (auto& entry : first) placements.push_back(std::move(entry.second));
  return placements;
}

}  // namespace

double RunReport::maxDisplacement() const {
  double largest = 0.0;
  for (const BrickOutcome& b : bricks) largest = std::max(largest, b.displacement);
  return largest;
}

std::size_t RunReport::standing() const {
  return static_cast<std::size_t>(std::count_if(bricks.begin(), bricks.end(),
                                                [](const BrickOutcome& b) { return !b.fell_at; }));
}

Status judgeInitialStructure(const Scene& scene, const BrickTypeLibrary& types,
                             const WorldOptions& world, StaticsLabel* label) {
  // Why "every brick frozen" is the LP of the whole structure. Bricks
  // placed at one instant are judged together (BrickWorld::addBricks). A
  // brick freezes alone when the COM rule holds it on what froze before it
  // (margin above stability/min_margin); one that cannot waits, and the
  // bricks waiting that touch are admitted as a group by the LP with the
  // frozen bricks under them held fixed (StackStabilityModel::
  // admitGroupAtRest, ComCriterion::admitsGroup), which is feasible
  // whenever the LP with those bricks free is (fixing a body only drops its
  // equations). Once all are in, settle() checks each component of the
  // support graph (bricks that touch, side contacts included, are linked):
  // where the COM rule finds a brick that cannot stay, mode equilibrium
  // solves the LP of the whole component, every brick free, and wakes the
  // collapse mechanism its dual names when it has no solution; where the
  // COM rule holds every brick, its vertical forces inside the patches are
  // a solution of that LP. So every brick stays frozen exactly when the LP
  // of the whole structure on the fixed table is feasible, up to a lone
  // brick within min_margin (1 micrometre) of its edge, which the COM rule
  // does not freeze and no group takes in, and to the contacts that
  // geometry finds (docs/design.md, "The stability layer").
  WorldOptions options = sceneWorldOptions(scene, world);
  options.stability.mode = "equilibrium";
  BrickTypeLibrary scene_types = types;
  if (Status merged = mergeSceneTypes(scene, &scene_types); !merged) return merged;
  std::unique_ptr<BrickWorld> judge;
  if (Status created = BrickWorld::create(options, scene_types, &judge); !created) return created;
  judge->addBricks(firstStructure(scene, scene_types));
  StaticsLabel result;
  result.stands = true;
  result.margin = std::numeric_limits<double>::infinity();
  for (const BrickSnapshot& brick : judge->snapshot()) {
    ++result.bricks;
    result.stands &= brick.state == BrickState::kStable || brick.state == BrickState::kLeaning;
    result.margin = std::min(result.margin, brick.margin);
  }
  // A woken brick reports no margin (0); one that never froze, its own.
  if (result.bricks == 0) result.margin = 0.0;
  if (!result.stands) result.margin = std::min(result.margin, 0.0);
  *label = result;
  return Status::success();
}

Status findBadSceneBricks(const Scene& scene, const BrickTypeLibrary& types,
                          const WorldOptions& world, std::vector<BadSceneBrick>* bad) {
  bad->clear();
  const WorldOptions options = sceneWorldOptions(scene, world);
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

std::vector<SetAsideBrick> setAsideBadBricks(const std::vector<BadSceneBrick>& bad, Scene* scene) {
  std::vector<SetAsideBrick> set_aside;
  std::vector<ScheduledBrick> kept;
  std::size_t next_bad = 0;
  for (std::size_t i = 0; i < scene->bricks.size(); ++i) {
    if (next_bad < bad.size() && bad[next_bad].index == i)
      set_aside.push_back(SetAsideBrick{std::move(scene->bricks[i]), bad[next_bad++].reason});
    else
      kept.push_back(std::move(scene->bricks[i]));
  }
  scene->bricks = std::move(kept);
  return set_aside;
}

Status runScene(const Scene& scene, const BrickTypeLibrary& types, const RunOptions& options,
                RunReport* report) {
  const double last_placement = scene.bricks.empty() ? 0.0 : scene.bricks.back().at;
  const double duration = options.duration.value_or(last_placement + kDefaultSettleTime);
  if (!std::isfinite(duration) || duration < 0.0)
    return Status::error("duration must be finite and >= 0 s");
  if (!std::isfinite(options.fall_distance) || options.fall_distance <= 0.0)
    return Status::error("fall distance must be finite and > 0 m");
  if (!std::isfinite(options.fall_angle) || options.fall_angle <= 0.0)
    return Status::error("fall angle must be finite and > 0 rad");
  RunReport result;
  if (options.statics) {
    StaticsLabel label;
    if (Status judged = judgeInitialStructure(scene, types, options.world, &label); !judged)
      return judged;
    result.statics = label;
  }
  std::unique_ptr<Simulation> simulation;
  if (Status created = Simulation::create(options.world, types, &simulation); !created)
    return created;
  const auto wall_start = std::chrono::steady_clock::now();
  if (Status reset = simulation->reset(scene); !reset) return reset;
  const BrickWorld& world = simulation->world();
  const double dt = world.options().time_step;
  const auto steps = static_cast<std::uint64_t>(std::llround(duration / dt));
  // Looks at most kFallCheckInterval apart (1e-9: ten 1 ms steps are 10 ms).
  const auto look_every = std::max<std::uint64_t>(
      1, static_cast<std::uint64_t>(std::floor(kFallCheckInterval / dt + 1e-9)));
  FallWatch watch(world, options.fall_distance, options.fall_angle);
  for (std::uint64_t i = 0; i < steps; ++i) {
    simulation->step();
    if (options.observer) options.observer(world);
    if ((i + 1) % look_every == 0) watch.look();
  }
  watch.look();
  result.scene = scene.name;
  result.world = world.options();
  result.wall_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  result.sim_time = world.time();
  result.cost = world.cost();
  result.refused = simulation->takeRefused();
  result.scheduled = scene.bricks.size() - simulation->player().pending();
  result.events = simulation->takeEvents();
  watch.lost(result.events);
  result.fall_distance = options.fall_distance;
  result.fall_angle = options.fall_angle;
  result.falls = watch.falls();
  for (const BrickSnapshot& brick : world.snapshot()) {
    result.bricks.push_back(outcomeOf(brick));
    result.bricks.back().fell_at = watch.fellAt(brick.id);
  }
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

/// Which bricks fell and which stand, and the statics label when asked for.
void writeFalls(const RunReport& r, JsonWriter& json) {
  json.key("fall_distance").value(r.fall_distance);
  json.key("fall_angle").value(r.fall_angle);
  json.key("fallen").value(static_cast<unsigned long long>(r.falls.size()));
  json.key("standing").value(static_cast<unsigned long long>(r.standing()));
  json.key("first_fall").value(r.falls.empty() ? std::string() : r.falls.front().id);
  json.key("first_fall_t");
  if (r.falls.empty()) {
    json.null();
  } else {
    json.value(r.falls.front().t);
  }
  if (!r.statics) return;
  json.key("statics").beginObject();
  json.key("stands").value(r.statics->stands);
  json.key("margin").value(r.statics->margin);
  json.key("bricks").value(static_cast<unsigned long long>(r.statics->bricks));
  json.endObject();
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
  // Bullet's own step by stage, also wall time: parts of stage_seconds'
  // bullet, so beside stage_seconds rather than in it, whose stages add up
  // to the step.
  const BulletStageSeconds& stages = r.cost.bullet_stages;
  json.key("bullet_stages").beginObject();
  json.key("broadphase").value(stages.broadphase);
  json.key("narrowphase").value(stages.narrowphase);
  json.key("islands").value(stages.islands);
  json.key("solver").value(stages.solver);
  json.key("integration").value(stages.integration);
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
    json.key("linear_velocity").numbers(b.linear_velocity.data(), 3);
    json.key("angular_velocity").numbers(b.angular_velocity.data(), 3);
    json.key("fell_off").value(b.fell_off);
    json.key("displacement").value(outcome.displacement);
    json.key("rotation").value(outcome.rotation);
    json.key("fell_at");
    if (outcome.fell_at) {
      json.value(*outcome.fell_at);
    } else {
      json.null();
    }
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
  writeFalls(r, json);
  writeRunCost(r, json);
  json.key("max_displacement").value(r.maxDisplacement());
  writeBrickOutcomes(r, json);
  writeEvents(r, json);
  writeRefused(r, json);
  json.endObject();
  return json.str() + "\n";
}

}  // namespace brick_stack_sim
