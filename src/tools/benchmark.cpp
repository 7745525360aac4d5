#include "brick_stack_sim/tools/benchmark.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "brick_stack_sim/core/geometry/box_geometry.h"
#include "brick_stack_sim/core/io/batch_runner.h"
#include "brick_stack_sim/core/scene/generators.h"
#include "brick_stack_sim/core/stability/stability_modes.h"

namespace brick_stack_sim {

namespace {

/// A brick that moved this far, or turned this much, has fallen [m], [rad].
constexpr double kFallenDistance = 0.005;
constexpr double kFallenAngle = 0.1;

std::vector<BenchSetting> settingsFor(const std::vector<std::string>& modes,
                                      const std::vector<std::pair<double, int>>& steps) {
  std::vector<BenchSetting> settings;
  for (const std::string& mode : modes) {
    for (const auto& [time_step, iterations] : steps) {
      BenchSetting s;
      s.mode_label = mode;
      // Plain Bullet runs twice, with and without its own sleeping.
      s.mode = mode.rfind("none", 0) == 0 ? "none" : mode;
      s.sleeping = mode != "none_nosleep";
      s.time_step = time_step;
      s.iterations = iterations;
      settings.push_back(s);
    }
  }
  return settings;
}

/// The modes of the registry as benchmark labels: every model, after plain
/// Bullet without (when `nosleep`) and with its own sleeping. A mode added to
/// the registry is benchmarked without a change here.
std::vector<std::string> modeLabels(bool plain_bullet, bool nosleep) {
  std::vector<std::string> labels;
  if (plain_bullet && nosleep) labels.push_back("none_nosleep");
  if (plain_bullet) labels.push_back("none_sleep");
  for (const std::string& mode : availableStabilityModes())
    if (mode != "none") labels.push_back(mode);
  return labels;
}

std::vector<std::string> allModes() { return modeLabels(true, true); }
/// Drops: plain Bullet without sleeping would only add minutes.
std::vector<std::string> sleepingModes() { return modeLabels(true, false); }
/// Cases that measure what a model skips: plain Bullet has nothing to skip.
std::vector<std::string> modelModes() { return modeLabels(false, false); }

BenchCase makeCase(const std::string& label, const std::string& scene, BenchMetric metric,
                   double duration, std::vector<BenchSetting> settings) {
  BenchCase c;
  c.label = label;
  c.scene = scene;
  c.metric = metric;
  c.duration = duration;
  c.settings = std::move(settings);
  return c;
}

/// Deepest overlap of two bricks, or of a brick into the table, at the end [m].
double deepestPenetration(const std::vector<BrickSnapshot>& bricks, const TableOptions& table) {
  double deepest = 0.0;
  std::vector<OrientedBox> boxes;
  std::vector<Eigen::AlignedBox3d> extents;
  for (const BrickSnapshot& b : bricks) {
    boxes.push_back(OrientedBox{b.pose, 0.5 * b.size});
    const Eigen::AlignedBox3d box = bounds(boxes.back());
    extents.push_back(box);
    // Into the table: only bricks on it (one that fell off may lie on the
    // floor under the table top).
    const Eigen::Vector3d& centre = b.pose.translation();
    if (!b.fell_off && std::abs(centre.x()) < table.size.x() / 2 &&
        std::abs(centre.y()) < table.size.y() / 2)
      deepest = std::max(deepest, -box.min().z());
  }
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (std::size_t j = i + 1; j < boxes.size(); ++j)
      if (extents[i].intersects(extents[j]))
        deepest = std::max(deepest, -separation(boxes[i], boxes[j]));
  return deepest;
}

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
  options.world.time_step = setting.time_step;
  options.world.solver_iterations = setting.iterations;
  options.duration = duration;
  return options;
}

/// A run with the stepping wall time measured apart from the setup.
struct TimedRun {
  RunReport report;
  double step_wall_time = 0.0;           ///< [s]
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
  options.observer = [&](const BrickWorld& world) {
    const Clock::time_point now = Clock::now();
    if (started) stepping += std::chrono::duration<double>(now - last_step).count();
    started = true;
    if (!sampled && window > 0.0 && world.time() >= window - 0.5 * world.options().time_step) {
      run->at_window = world.snapshot();
      sampled = true;
    }
    if (watch) watch(world);
    last_step = Clock::now();
  };
  const Status status = runScene(scene, context.types, options, &run->report);
  run->step_wall_time = stepping;
  return status;
}

void accumulate(const TimedRun& run, BenchRow* row) {
  const RunReport& r = run.report;
  row->sim_time += r.sim_time;
  row->wall_time += run.step_wall_time;
  row->bullet_seconds += r.cost.bullet_seconds;
  row->contact_seconds += r.cost.contact_seconds;
  row->stability_seconds += r.cost.stability_seconds;
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

/// Structures built brick by brick as a user would, every mode side by
/// side: the thesis's 25-layer tower (one brick a second) and its card
/// house (a V every half second), each until 5 s after the last placement.
void addBuiltStructures(const std::vector<BenchSetting>& settings, BenchPlan* plan) {
  plan->cases.push_back(
      makeCase("tower25_built", "tower25_built", BenchMetric::kSettled, 54.0, settings));
  plan->cases.push_back(
      makeCase("card_house", "card_house", BenchMetric::kSettled, 10.0, settings));
}

Status loadCaseScene(const std::string& name, const BenchContext& context, Scene* scene) {
  return loadScene(name, context.scene_dirs, context.types, scene);
}

/// How long each motion runs: until it is over, or measured [s].
double motionDuration(MotionCase motion) {
  switch (motion) {
    case MotionCase::kSlide: return 1.0;
    case MotionCase::kIncline: return 0.3;
    case MotionCase::kTopple: return 0.8;
    case MotionCase::kFreeFlight: return 0.35;
    case MotionCase::kDomino: return 2.0;
  }
  return 1.0;
}

/// The motions with answers from mechanics, each at `settings`.
void addMotions(const std::vector<BenchSetting>& settings, BenchPlan* plan) {
  for (MotionCase motion : kMotionCases) {
    plan->cases.push_back(makeCase(motionCaseName(motion), "", BenchMetric::kMotion,
                                   motionDuration(motion), settings));
    plan->cases.back().motion = motion;
    plan->cases.back().repeats = 3;
  }
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

int slantTowerCollapseLayer(double offset, double length) {
  return static_cast<int>(std::floor(length / offset)) + 1;
}

BenchPlan quickBenchPlan() {
  const auto settings =
      settingsFor(allModes(), {{1.0 / 240, 20}, {1.0 / 1000, 20}, {1.0 / 1000, 10}});
  BenchPlan plan;
  plan.cases.push_back(makeCase("tower25", "tower25", BenchMetric::kSettled, 10.0, settings));
  BenchCase harmonic = makeCase("harmonic10", "", BenchMetric::kHarmonic, 3.0, settings);
  plan.cases.push_back(harmonic);
  BenchCase slant = makeCase("slant_tower", "", BenchMetric::kSlantTower, 0.0, settings);
  plan.cases.push_back(slant);
  plan.cases.push_back(makeCase("pile200", "pile200", BenchMetric::kDrop, 1.0,
                                settingsFor(sleepingModes(), {{1.0 / 1000, 20}})));
  plan.cases.push_back(makeCase("freefall200", "freefall200", BenchMetric::kDrop, 0.4,
                                settingsFor(sleepingModes(), {{1.0 / 1000, 20}})));
  addBuiltStructures(settingsFor(allModes(), {{1.0 / 1000, 20}}), &plan);
  const auto model_only = settingsFor(modelModes(), {{1.0 / 1000, 20}});
  for (const char* scene : {"moving10", "settled2000_moving10"}) {
    plan.cases.push_back(makeCase(scene, scene, BenchMetric::kDrop, 0.3, model_only));
    plan.cases.back().repeats = 5;
  }
  addMotions(settingsFor(allModes(), {{1.0 / 1000, 20}}), &plan);
  return plan;
}

BenchPlan fullBenchPlan() {
  // Every setting where a run is cheap; the large plain-Bullet scenes, which
  // cost minutes per run, at the default setting and the step sweep only.
  const auto sweep = settingsFor(allModes(), {{1.0 / 60, 20},
                                              {1.0 / 240, 20},
                                              {1.0 / 1000, 20},
                                              {1.0 / 2000, 20},
                                              {1.0 / 1000, 5},
                                              {1.0 / 1000, 10},
                                              {1.0 / 1000, 50},
                                              {1.0 / 1000, 100}});
  const auto steps = settingsFor(allModes(), {{1.0 / 240, 20}, {1.0 / 1000, 20}});
  const auto defaults = settingsFor(allModes(), {{1.0 / 1000, 20}});
  BenchPlan plan;
  plan.divergence = true;
  plan.cases.push_back(makeCase("tower25", "tower25", BenchMetric::kSettled, 30.0, sweep));
  plan.cases.push_back(makeCase("harmonic10", "", BenchMetric::kHarmonic, 5.0, sweep));
  plan.cases.push_back(makeCase("slant_tower", "", BenchMetric::kSlantTower, 0.0, sweep));
  plan.cases.push_back(makeCase("pile200", "pile200", BenchMetric::kDrop, 3.0, steps));
  plan.cases.push_back(makeCase("freefall200", "freefall200", BenchMetric::kDrop, 0.4,
                                settingsFor(sleepingModes(), {{1.0 / 1000, 20}})));
  plan.cases.push_back(makeCase("tower100", "tower100", BenchMetric::kSettled, 30.0, steps));
  plan.cases.push_back(makeCase("pyramid210", "pyramid210", BenchMetric::kSettled, 30.0, defaults));
  plan.cases.push_back(makeCase("pile1000", "pile1000", BenchMetric::kDrop, 3.0,
                                settingsFor(sleepingModes(), {{1.0 / 1000, 20}})));
  for (const char* tower : {"tower10", "tower50"})
    plan.cases.push_back(makeCase(tower, tower, BenchMetric::kSettled, 30.0, defaults));
  addBuiltStructures(defaults, &plan);
  const auto model_only = settingsFor(modelModes(), {{1.0 / 1000, 20}});
  for (const char* scene : {"moving10", "settled2000_moving10"}) {
    plan.cases.push_back(makeCase(scene, scene, BenchMetric::kDrop, 0.3, model_only));
    plan.cases.back().repeats = 5;
  }
  addMotions(sweep, &plan);
  return plan;
}

Status runBenchCase(const BenchCase& c, const BenchSetting& setting, const BenchContext& context,
                    bool divergence, BenchRow* row) {
  *row = BenchRow();
  row->label = c.label;
  row->setting = setting;
  Scene scene;
  switch (c.metric) {
    case BenchMetric::kSettled:
    case BenchMetric::kDrop: {
      if (Status loaded = loadCaseScene(c.scene, context, &scene); !loaded) return loaded;
      row->scene = scene.name;
      const double window = std::min(1.0, c.duration);
      TimedRun run;
      for (int repeat = 0; repeat < std::max(c.repeats, 1); ++repeat) {
        TimedRun attempt;
        if (Status ran =
                timedRun(scene, context, optionsFor(setting, c.duration), window, &attempt);
            !ran)
          return ran;
        if (repeat == 0 || attempt.step_wall_time < run.step_wall_time) run = std::move(attempt);
      }
      accumulate(run, row);
      double drift = 0.0;
      for (const BrickOutcome& b : run.report.bricks) drift = std::max(drift, b.displacement);
      if (c.metric == BenchMetric::kSettled) row->drift_mm = 1000.0 * drift;
      std::vector<BrickSnapshot> final_bricks;
      for (const BrickOutcome& b : run.report.bricks) final_bricks.push_back(b.brick);
      row->penetration_mm =
          1000.0 * deepestPenetration(final_bricks, scene.table.value_or(TableOptions()));
      row->lost = run.report.lost() + run.report.missing();
      if (divergence && scene.bricks.size() <= 250) {
        std::vector<BrickSnapshot>& truth = context.references[c.label + "/" + setting.mode_label];
        if (truth.empty()) {
          BenchSetting reference = setting;
          reference.time_step = 1.0 / 4000;
          reference.iterations = 100;
          TimedRun reference_run;
          if (Status ran =
                  timedRun(scene, context, optionsFor(reference, window), window, &reference_run);
              !ran)
            return ran;
          truth = reference_run.at_window;
        }
        row->divergence_mm = 1000.0 * rmsDistance(run.at_window, truth);
      }
      return Status::success();
    }
    case BenchMetric::kHarmonic: {
      // Bisection on the overhang factor: statics puts the threshold at 1.
      double stands = 0.8, falls = 1.2;
      row->scene = "harmonic" + std::to_string(c.bricks);
      for (int round = 0; round < 6; ++round) {
        const double factor = 0.5 * (stands + falls);
        HarmonicParams params;
        params.bricks = c.bricks;
        params.factor = factor;
        scene = Scene();
        scene.name = row->scene;
        scene.table = TableOptions();
        if (Status made = generateHarmonic(params, *scene.table, context.types, &scene.bricks);
            !made)
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
    case BenchMetric::kSlantTower: {
      const BrickType& type = *context.types.find(context.types.defaultType());
      const int statics = slantTowerCollapseLayer(c.offset, type.size.x());
      SlantTowerParams params;
      params.layers = statics + 2;
      params.offset = c.offset;
      params.interval = 1.0;
      scene.name = "slant_tower";
      row->scene = scene.name;
      if (Status made = generateSlantTower(params, context.types, &scene.bricks); !made)
        return made;
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
    case BenchMetric::kMotion: {
      TimedRun run;
      double measured = 0.0;
      if (Status ran = measureMotion(c, setting, context, &measured, &run); !ran) return ran;
      row->scene = motionCaseName(c.motion);
      accumulate(run, row);
      row->lost = run.report.lost() + run.report.missing();
      double expected = motionExpected(c.motion, context.types, TableOptions(), WorldOptions().gravity);
      if (std::isnan(expected)) {
        // No closed form: plain Bullet at 1/4000 s and 100 iterations, once.
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
        expected = known->second;
      }
      row->motion_measured = measured;
      row->motion_expected = expected;
      // A motion that never happened is all error.
      row->motion_error_pct =
          std::isnan(measured) || !(expected != 0.0) ? 100.0
                                                     : 100.0 * std::abs(measured / expected - 1.0);
      return Status::success();
    }
  }
  return Status::error("unknown benchmark metric");
}

std::string benchCsvHeader() {
  return "case,scene,bricks,mode,sleeping,time_step,iterations,sim_time,wall_time,"
         "wall_ms_per_sim_s,real_time_factor,steps,bullet_steps,awake_brick_steps,"
         "bullet_share,contact_share,stability_share,drift_mm,penetration_mm,"
         "collapse_layer_error,threshold_error_pct,divergence_mm,nonfinite,lost,refused,"
         "motion_measured,motion_expected,motion_error_pct\n";
}

std::string toCsv(const BenchRow& r) {
  const double staged = r.bullet_seconds + r.contact_seconds + r.stability_seconds;
  auto share = [&](double part) { return staged > 0.0 ? part / staged : 0.0; };
  // Empty where the row does not measure it: `absent`, or NaN.
  auto optional = [](double value, double absent) {
    if (value == absent || std::isnan(value)) return std::string();
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return std::string(text);
  };
  char line[1024];
  std::snprintf(
      line, sizeof line,
      "%s,%s,%zu,%s,%d,%.6g,%d,%.6g,%.6g,%.6g,%.6g,%llu,%llu,%llu,%.4f,%.4f,%.4f,%s,%s,%s,%s,"
      "%s,%llu,%zu,%zu,%s,%s,%s\n",
      r.label.c_str(), r.scene.c_str(), r.bricks, r.setting.mode_label.c_str(),
      r.setting.sleeping ? 1 : 0, r.setting.time_step, r.setting.iterations, r.sim_time,
      r.wall_time, r.sim_time > 0.0 ? 1000.0 * r.wall_time / r.sim_time : 0.0,
      r.wall_time > 0.0 ? r.sim_time / r.wall_time : 0.0, r.steps, r.bullet_steps,
      r.awake_brick_steps, share(r.bullet_seconds), share(r.contact_seconds),
      share(r.stability_seconds), optional(r.drift_mm, -1.0).c_str(),
      optional(r.penetration_mm, -1.0).c_str(), optional(r.collapse_layer_error, -1e9).c_str(),
      optional(r.threshold_error_pct, -1.0).c_str(), optional(r.divergence_mm, -1.0).c_str(),
      r.nonfinite, r.lost, r.refused, optional(r.motion_measured, -1.0).c_str(),
      optional(r.motion_expected, -1.0).c_str(), optional(r.motion_error_pct, -1.0).c_str());
  return line;
}

}  // namespace brick_stack_sim
