// What the benchmark runs: its plans (cases and settings, quick and full)
// and the CSV it writes; benchmark.cpp runs them.
#include "brick_stack_sim/tools/benchmark.h"

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "brick_stack_sim/core/types/stability_modes.h"
#include "brick_stack_sim/tools/motion_cases.h"

namespace brick_stack_sim {

namespace {

std::vector<BenchSetting> settingsFor(const std::vector<std::string>& modes,
                                      const std::vector<std::pair<double, int>>& steps) {
  std::vector<BenchSetting> settings;
  for (const std::string& mode : modes) {
    for (const auto& [time_step, iterations] : steps) {
      BenchSetting s;
      s.mode_label = mode;
      // Plain Bullet runs with and without its own sleeping, and on the
      // piles plain Bullet and com once more with full_warm_start.
      const std::string full_suffix = "_full";
      s.full_warm_start =
          mode.size() > full_suffix.size() &&
          mode.compare(mode.size() - full_suffix.size(), full_suffix.size(), full_suffix) == 0;
      const std::string base =
          s.full_warm_start ? mode.substr(0, mode.size() - full_suffix.size()) : mode;
      s.mode = base.rfind("none", 0) == 0 ? "none" : base;
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

/// Structures built brick by brick as a user would, every mode side by
/// side: the thesis's 25-layer tower (one brick a second) and its card
/// house (a V every half second), each until 5 s after the last placement;
/// and shapes other than boxes: an arch of 25 voussoirs placed at once and
/// a building of 100 unit blocks, layer by layer.
void addBuiltStructures(const std::vector<BenchSetting>& settings, BenchPlan* plan) {
  plan->cases.push_back(
      makeCase("tower25_built", "tower25_built", BenchMetric::kSettled, 54.0, settings));
  plan->cases.push_back(
      makeCase("card_house", "card_house", BenchMetric::kSettled, 10.0, settings));
  plan->cases.push_back(makeCase("arch25", "arch", BenchMetric::kSettled, 5.0, settings));
  plan->cases.push_back(
      makeCase("unit_blocks", "unit_blocks", BenchMetric::kSettled, 10.0, settings));
}

/// How long each motion runs: until it is over, or measured [s].
double motionDuration(MotionCase motion) {
  switch (motion) {
    case MotionCase::kSlide:
      return 1.0;
    case MotionCase::kIncline:
      return 0.3;
    case MotionCase::kTopple:
      return 0.8;
    case MotionCase::kFreeFlight:
      return 0.35;
    case MotionCase::kDomino:
      return 2.0;
  }
  return 1.0;
}

/// 200 bricks falling through the air, in the modes that sleep. Its run
/// is a few tens of milliseconds, where one hiccup of a shared machine
/// moved a mode by half: the fastest of five runs counts.
void addFreeFall(BenchPlan* plan) {
  plan->cases.push_back(makeCase("freefall200", "freefall200", BenchMetric::kDrop, 0.4,
                                 settingsFor(sleepingModes(), {{1.0 / 1000, 20}})));
  plan->cases.back().repeats = 5;
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

/// Piles dropped and left to settle for 10 s, the modes that sleep side by
/// side: long enough to see a pile land (about 1 s), settle, and cost what a
/// settled pile costs in its last second. Plain Bullet without sleeping has
/// no rest to measure; plain Bullet and com with full_warm_start are the
/// pile's other points of wall time against error (with it, com freezes
/// pile1000 whole; without, the pile creeps and most of it stays dynamic).
void addPiles(const std::vector<std::string>& scenes, BenchPlan* plan) {
  std::vector<std::string> modes = sleepingModes();
  modes.insert(modes.begin() + 1, "none_full");
  const auto com = std::find(modes.begin(), modes.end(), "com");
  if (com != modes.end()) modes.insert(com + 1, "com_full");
  for (const std::string& scene : scenes)
    plan->cases.push_back(
        makeCase(scene, scene, BenchMetric::kPile, 10.0, settingsFor(modes, {{1.0 / 1000, 20}})));
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
  addPiles({"pile200"}, &plan);
  addFreeFall(&plan);
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
  addFreeFall(&plan);
  plan.cases.push_back(makeCase("tower100", "tower100", BenchMetric::kSettled, 30.0, steps));
  plan.cases.push_back(makeCase("pyramid210", "pyramid210", BenchMetric::kSettled, 30.0, defaults));
  addPiles({"pile200", "pile1000"}, &plan);
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

std::string benchCsvHeader() {
  return "case,scene,bricks,mode,sleeping,time_step,iterations,sim_time,wall_time,"
         "wall_ms_per_sim_s,real_time_factor,steps,bullet_steps,awake_brick_steps,"
         "bullet_share,contact_share,stability_share,broadphase_share,narrowphase_share,"
         "islands_share,solver_share,integration_share,drift_mm,penetration_mm,"
         "collapse_layer_error,threshold_error_pct,divergence_mm,nonfinite,lost,refused,"
         "motion_measured,motion_expected,motion_error_pct,settle_time,at_rest_pct,fell_off,"
         "settled_cost_pct\n";
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
      "%s,%s,%zu,%s,%d,%.6g,%d,%.6g,%.6g,%.6g,%.6g,%llu,%llu,%llu,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,"
      "%.4f,%.4f,%s,%s,%s,%s,%s,%llu,%zu,%zu,%s,%s,%s,%s,%s,%s,%s\n",
      r.label.c_str(), r.scene.c_str(), r.bricks, r.setting.mode_label.c_str(),
      r.setting.sleeping ? 1 : 0, r.setting.time_step, r.setting.iterations, r.sim_time,
      r.wall_time, r.sim_time > 0.0 ? 1000.0 * r.wall_time / r.sim_time : 0.0,
      r.wall_time > 0.0 ? r.sim_time / r.wall_time : 0.0, r.steps, r.bullet_steps,
      r.awake_brick_steps, share(r.bullet_seconds), share(r.contact_seconds),
      share(r.stability_seconds), share(r.bullet_stages.broadphase),
      share(r.bullet_stages.narrowphase), share(r.bullet_stages.islands),
      share(r.bullet_stages.solver), share(r.bullet_stages.integration),
      optional(r.drift_mm, -1.0).c_str(), optional(r.penetration_mm, -1.0).c_str(),
      optional(r.collapse_layer_error, -1e9).c_str(), optional(r.threshold_error_pct, -1.0).c_str(),
      optional(r.divergence_mm, -1.0).c_str(), r.nonfinite, r.lost, r.refused,
      optional(r.motion_measured, -1.0).c_str(), optional(r.motion_expected, -1.0).c_str(),
      optional(r.motion_error_pct, -1.0).c_str(), optional(r.settle_time, -1.0).c_str(),
      optional(r.at_rest_pct, -1.0).c_str(),
      optional(static_cast<double>(r.fell_off), -1.0).c_str(),
      optional(r.settled_cost_pct, -1.0).c_str());
  return line;
}

}  // namespace brick_stack_sim
