#include "brick_stack_sim/tools/benchmark.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <map>

#include "brick_stack_sim/core/io/batch_runner.h"
#include "brick_stack_sim/core/scene/generators.h"
#include "brick_stack_sim/tools/penetration.h"

namespace brick_stack_sim {

namespace {

/// A brick that moved this far, or turned this much, has fallen [m], [rad].
constexpr double kFallenDistance = 0.005;
constexpr double kFallenAngle = 0.1;

bool fallen(const BrickSnapshot& b) {
  const double moved = (b.pose.translation() - b.placed_pose.translation()).norm();
  const double turned =
      Eigen::AngleAxisd(b.placed_pose.linear().transpose() * b.pose.linear()).angle();
  return b.fell_off || moved > kFallenDistance || turned > kFallenAngle;
}

RunOptions optionsFor(const BenchSetting& setting, double duration) {
  RunOptions options;
  options.world.stability.mode = setting.mode;
  options.world.sleeping.enabled = setting.sleeping;
  options.world.full_warm_start = setting.full_warm_start;
  options.world.time_step = setting.time_step;
  options.world.solver_iterations = setting.iterations;
  options.duration = duration;
  return options;
}

/// A run with the stepping wall time measured apart from the setup.
struct TimedRun {
  RunReport report;
  double step_wall_time = 0.0;  ///< [s]
  /// The part of step_wall_time spent on the last simulated second (on all
  /// of a shorter run) [s]: a settled scene's cost, after what settled it.
  double last_second_wall = 0.0;
  std::vector<BrickSnapshot> at_window;  ///< Bricks when sim time reached the window.
};

Status timedRun(const Scene& scene, const BenchContext& context, RunOptions options, double window,
                TimedRun* run, const std::function<void(const BrickWorld&)>& watch = nullptr) {
  using Clock = std::chrono::steady_clock;
  // Stepping time only: from the first step to the last, without the setup
  // (placing a large scene), the report, or the samples taken here.
  Clock::time_point last_step;
  bool started = false;
  bool sampled = false;
  double stepping = 0.0;
  // The stepping time before the last simulated second began: -1 until then.
  const double last_second_from = options.duration.value_or(0.0) - 1.0;
  double before_last_second = -1.0;
  options.observer = [&](const BrickWorld& world) {
    const Clock::time_point now = Clock::now();
    if (started) stepping += std::chrono::duration<double>(now - last_step).count();
    started = true;
    if (before_last_second < 0.0 &&
        world.time() >= last_second_from - 0.5 * world.options().time_step)
      before_last_second = stepping;
    if (!sampled && window > 0.0 && world.time() >= window - 0.5 * world.options().time_step) {
      run->at_window = world.snapshot();
      sampled = true;
    }
    if (watch) watch(world);
    last_step = Clock::now();
  };
  const Status status = runScene(scene, context.types, options, &run->report);
  run->step_wall_time = stepping;
  run->last_second_wall = stepping - std::max(before_last_second, 0.0);
  return status;
}

void accumulate(const TimedRun& run, BenchRow* row) {
  const RunReport& r = run.report;
  row->sim_time += r.sim_time;
  row->wall_time += run.step_wall_time;
  row->bullet_seconds += r.cost.bullet_seconds;
  row->contact_seconds += r.cost.contact_seconds;
  row->stability_seconds += r.cost.stability_seconds;
  row->bullet_stages += r.cost.bullet_stages;
  row->bullet_steps += r.cost.bullet_steps;
  row->awake_brick_steps += r.cost.awake_brick_steps;
  row->steps += r.cost.steps;
  row->nonfinite += r.cost.nonfinite;
  row->refused += r.refused.size();
  row->bricks = std::max(row->bricks, r.bricks.size());
}

double rmsDistance(const std::vector<BrickSnapshot>& a, const std::vector<BrickSnapshot>& b) {
  std::map<std::string, Eigen::Vector3d> reference;
  for (const BrickSnapshot& brick : b) reference[brick.id] = brick.pose.translation();
  double sum = 0.0;
  std::size_t count = 0;
  for (const BrickSnapshot& brick : a) {
    auto found = reference.find(brick.id);
    if (found == reference.end()) continue;
    sum += (brick.pose.translation() - found->second).squaredNorm();
    ++count;
  }
  return count ? std::sqrt(sum / count) : 0.0;
}

Status loadCaseScene(const std::string& name, const BenchContext& context, Scene* scene) {
  return loadScene(name, context.scene_dirs, context.types, scene);
}

/// The motion `c` measured in a run at `setting`; `run` receives the run
/// (the fastest of the case's repeats).
Status measureMotion(const BenchCase& c, const BenchSetting& setting, const BenchContext& context,
                     double* measured, TimedRun* run) {
  Scene scene;
  if (Status made = motionScene(c.motion, context.types, &scene); !made) return made;
  for (int repeat = 0; repeat < std::max(c.repeats, 1); ++repeat) {
    MotionProbe probe(c.motion);
    TimedRun attempt;
    if (Status ran = timedRun(scene, context, optionsFor(setting, c.duration), 0.0, &attempt,
                              [&probe](const BrickWorld& world) { probe.observe(world); });
        !ran)
      return ran;
    if (repeat == 0 || attempt.step_wall_time < run->step_wall_time) *run = std::move(attempt);
    *measured = probe.measured();
  }
  return Status::success();
}

}  // namespace

namespace {

// runBenchCase's metrics, one function each; each fills in `row` beyond the
// case's label and setting.

/// Where a small scene's bricks are at `window` in a run at 1/4000 s and 100
/// iterations: what the divergence of `setting`'s run is measured against.
Status referenceBricks(const Scene& scene, const BenchSetting& setting, const BenchContext& context,
                       double window, std::vector<BrickSnapshot>* truth) {
  BenchSetting reference = setting;
  reference.time_step = 1.0 / 4000;
  reference.iterations = 100;
  TimedRun reference_run;
  if (Status ran = timedRun(scene, context, optionsFor(reference, window), window, &reference_run);
      !ran)
    return ran;
  *truth = reference_run.at_window;
  return Status::success();
}

/// Sim time between two looks at how much of a pile rests [s]: a settle
/// time to within it, for a snapshot per 10 steps at 1 ms, not per step.
constexpr double kPileSamplePeriod = 0.01;

/// A brick that costs nothing more: frozen by a model, or asleep in Bullet.
bool atRest(const BrickSnapshot& b) {
  return b.state == BrickState::kStable || b.state == BrickState::kLeaning || b.asleep;
}

/// The fastest of the repeats of case `c` on `scene`; for kPile, `rest`
/// receives when that run's pile came to rest. The looks at the pile are
/// outside the stepping wall time (timedRun).
Status fastestRun(const Scene& scene, const BenchCase& c, const BenchSetting& setting,
                  const BenchContext& context, double window, TimedRun* run, PileRest* rest) {
  for (int repeat = 0; repeat < std::max(c.repeats, 1); ++repeat) {
    TimedRun attempt;
    PileRest attempt_rest;
    double next_look = 0.0;
    std::function<void(const BrickWorld&)> watch;
    if (c.metric == BenchMetric::kPile) {
      watch = [&](const BrickWorld& world) {
        if (world.time() < next_look - 0.5 * world.options().time_step) return;
        next_look = world.time() + kPileSamplePeriod;
        const std::vector<BrickSnapshot> bricks = world.snapshot();
        attempt_rest.sample(
            world.time(),
            static_cast<std::size_t>(std::count_if(bricks.begin(), bricks.end(), atRest)),
            bricks.size());
      };
    }
    if (Status ran =
            timedRun(scene, context, optionsFor(setting, c.duration), window, &attempt, watch);
        !ran)
      return ran;
    if (repeat == 0 || attempt.step_wall_time < run->step_wall_time) {
      *run = std::move(attempt);
      *rest = attempt_rest;
    }
  }
  return Status::success();
}

/// kPile: when the pile of `run` settled, how much of it rests and lies on
/// the floor at the end, and what its last simulated second cost.
void measurePile(const TimedRun& run, double duration, PileRest rest, BenchRow* row) {
  std::size_t at_rest = 0, fell_off = 0;
  for (const BrickOutcome& b : run.report.bricks) {
    at_rest += atRest(b.brick) ? 1 : 0;
    fell_off += b.brick.fell_off ? 1 : 0;
  }
  const std::size_t bricks = run.report.bricks.size();
  // The end as the last look: a pile that stirred after it counts as unsettled.
  rest.sample(run.report.sim_time, at_rest, bricks);
  row->settle_time = rest.settleTime();
  row->at_rest_pct = bricks > 0 ? 100.0 * at_rest / bricks : 0.0;
  row->fell_off = static_cast<long>(fell_off);
  row->settled_cost_pct = 100.0 * run.last_second_wall / std::min(1.0, duration);
}

/// kSettled, kDrop and kPile: the fastest of the repeats of a stored scene,
/// its drift (kSettled), the overlap left at the end, how it came to rest
/// (kPile) and, with `divergence`, how far its bricks are at the window from
/// a reference run's.
Status runStoredScene(const BenchCase& c, const BenchSetting& setting, const BenchContext& context,
                      bool divergence, BenchRow* row) {
  Scene scene;
  if (Status loaded = loadCaseScene(c.scene, context, &scene); !loaded) return loaded;
  row->scene = scene.name;
  const double window = std::min(1.0, c.duration);
  TimedRun run;
  PileRest rest;
  if (Status ran = fastestRun(scene, c, setting, context, window, &run, &rest); !ran) return ran;
  accumulate(run, row);
  if (c.metric == BenchMetric::kPile) measurePile(run, c.duration, rest, row);
  double drift = 0.0;
  for (const BrickOutcome& b : run.report.bricks) drift = std::max(drift, b.displacement);
  if (c.metric == BenchMetric::kSettled) row->drift_mm = 1000.0 * drift;
  std::vector<BrickSnapshot> final_bricks;
  for (const BrickOutcome& b : run.report.bricks) final_bricks.push_back(b.brick);
  row->penetration_mm =
      1000.0 * deepestPenetration(final_bricks, scene.table.value_or(TableOptions()));
  row->lost = run.report.lost() + run.report.missing();
  if (divergence && scene.bricks.size() <= 250) {
    // One reference run per case and mode, shared by every setting.
    std::vector<BrickSnapshot>& truth = context.references[c.label + "/" + setting.mode_label];
    if (truth.empty()) {
      if (Status ran = referenceBricks(scene, setting, context, window, &truth); !ran) return ran;
    }
    row->divergence_mm = 1000.0 * rmsDistance(run.at_window, truth);
  }
  return Status::success();
}

/// kHarmonic: how far the overhang factor at which the harmonic stack
/// falls is from the 1 statics puts it at.
Status runHarmonic(const BenchCase& c, const BenchSetting& setting, const BenchContext& context,
                   BenchRow* row) {
  // Bisection on the overhang factor: statics puts the threshold at 1.
  double stands = 0.8, falls = 1.2;
  row->scene = "harmonic" + std::to_string(c.bricks);
  for (int round = 0; round < 6; ++round) {
    const double factor = 0.5 * (stands + falls);
    HarmonicParams params;
    params.bricks = c.bricks;
    params.factor = factor;
    Scene scene;
    scene.name = row->scene;
    scene.table = TableOptions();
    if (Status made = generateHarmonic(params, *scene.table, context.types, &scene.bricks); !made)
      return made;
    TimedRun run;
    if (Status ran = timedRun(scene, context, optionsFor(setting, c.duration), 0.0, &run); !ran)
      return ran;
    accumulate(run, row);
    bool any_fell = false;
    for (const BrickOutcome& b : run.report.bricks) any_fell = any_fell || fallen(b.brick);
    (any_fell ? falls : stands) = factor;
  }
  row->threshold_error_pct = 100.0 * std::abs(0.5 * (stands + falls) - 1.0);
  return Status::success();
}

/// kSlantTower: how many layers from the statics answer the slanted tower,
/// built a layer a second, first lost a brick.
Status runSlantTower(const BenchCase& c, const BenchSetting& setting, const BenchContext& context,
                     BenchRow* row) {
  const BrickType& type = *context.types.find(context.types.defaultType());
  const int statics = slantTowerCollapseLayer(c.offset, type.size.x());
  SlantTowerParams params;
  params.layers = statics + 2;
  params.offset = c.offset;
  params.interval = 1.0;
  Scene scene;
  scene.name = "slant_tower";
  row->scene = scene.name;
  if (Status made = generateSlantTower(params, context.types, &scene.bricks); !made) return made;
  // The collapse layer: how many bricks were placed when one first fell.
  int collapse_layer = 0;
  auto watch = [&](const BrickWorld& world) {
    if (collapse_layer > 0 || world.cost().steps % 10 != 0) return;
    const std::vector<BrickSnapshot> bricks = world.snapshot();
    for (const BrickSnapshot& b : bricks)
      if (fallen(b)) collapse_layer = static_cast<int>(bricks.size());
  };
  TimedRun run;
  if (Status ran =
          timedRun(scene, context, optionsFor(setting, params.layers + 2.0), 0.0, &run, watch);
      !ran)
    return ran;
  accumulate(run, row);
  // A tower that never fell is off by at least the layers it was given.
  row->collapse_layer_error =
      collapse_layer > 0 ? collapse_layer - statics : params.layers + 1 - statics;
  return Status::success();
}

/// What a motion without a closed form should measure: plain Bullet at
/// 1/4000 s and 100 iterations, run once per case and kept in `context`.
Status motionReference(const BenchCase& c, const BenchContext& context, double* expected) {
  auto known = context.motion_references.find(c.label);
  if (known == context.motion_references.end()) {
    BenchSetting reference;
    reference.mode_label = "none_nosleep";
    reference.mode = "none";
    reference.sleeping = false;
    reference.time_step = 1.0 / 4000;
    reference.iterations = 100;
    BenchCase once = c;
    once.repeats = 1;
    double truth = 0.0;
    TimedRun reference_run;
    if (Status ran = measureMotion(once, reference, context, &truth, &reference_run); !ran)
      return ran;
    known = context.motion_references.emplace(c.label, truth).first;
  }
  *expected = known->second;
  return Status::success();
}

/// kMotion: the motion measured against mechanics' answer, or a reference
/// run's where mechanics has none.
Status runMotion(const BenchCase& c, const BenchSetting& setting, const BenchContext& context,
                 BenchRow* row) {
  TimedRun run;
  double measured = 0.0;
  if (Status ran = measureMotion(c, setting, context, &measured, &run); !ran) return ran;
  row->scene = motionCaseName(c.motion);
  accumulate(run, row);
  row->lost = run.report.lost() + run.report.missing();
  double expected = motionExpected(c.motion, context.types, TableOptions(), WorldOptions().gravity);
  if (std::isnan(expected)) {
    if (Status known = motionReference(c, context, &expected); !known) return known;
  }
  row->motion_measured = measured;
  row->motion_expected = expected;
  // A motion that never happened is all error.
  row->motion_error_pct = std::isnan(measured) || !(expected != 0.0)
                              ? 100.0
                              : 100.0 * std::abs(measured / expected - 1.0);
  return Status::success();
}

}  // namespace

void PileRest::sample(double time, std::size_t at_rest, std::size_t bricks) {
  // In whole bricks, with no rounding: 196 of 200 is settled, 195 is not.
  const bool settled = bricks > 0 && 100 * at_rest >= kSettledPct * bricks;
  if (!settled)
    settled_since_ = std::numeric_limits<double>::quiet_NaN();
  else if (std::isnan(settled_since_))
    settled_since_ = time;
}

Status runBenchCase(const BenchCase& c, const BenchSetting& setting, const BenchContext& context,
                    bool divergence, BenchRow* row) {
  *row = BenchRow();
  row->label = c.label;
  row->setting = setting;
  switch (c.metric) {
    case BenchMetric::kSettled:
    case BenchMetric::kDrop:
    case BenchMetric::kPile:
      return runStoredScene(c, setting, context, divergence, row);
    case BenchMetric::kHarmonic:
      return runHarmonic(c, setting, context, row);
    case BenchMetric::kSlantTower:
      return runSlantTower(c, setting, context, row);
    case BenchMetric::kMotion:
      return runMotion(c, setting, context, row);
  }
  return Status::error("unknown benchmark metric");
}

}  // namespace brick_stack_sim
