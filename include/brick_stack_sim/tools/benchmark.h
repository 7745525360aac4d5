#pragma once

#include <limits>
#include <map>
#include <string>
#include <vector>

#include "brick_stack_sim/core/types/brick.h"

#include "brick_stack_sim/core/status.h"
#include "brick_stack_sim/core/types/brick_type.h"
#include "brick_stack_sim/core/types/bullet_stage_seconds.h"
#include "brick_stack_sim/core/types/world_options.h"
#include "brick_stack_sim/tools/motion_cases.h"

namespace brick_stack_sim {

/// One way of simulating: a stability mode with Bullet's settings.
struct BenchSetting {
  /// none_nosleep, none_sleep, none_full (plain Bullet, sleeping, with
  /// full_warm_start), the mode's name, or com_full (com with
  /// full_warm_start).
  std::string mode_label;
  std::string mode = "none";  ///< A mode of the registry.
  bool sleeping = true;
  bool full_warm_start = false;  ///< WorldOptions::full_warm_start.
  double time_step = 1e-3;       ///< [s]
  int iterations = 20;
};

/// What error a case measures against ground truth.
enum class BenchMetric {
  kSettled,     ///< A structure at rest: drift [mm] over the duration, penetration.
  kDrop,        ///< Everything moves: penetration [mm]; cost is the point.
  kHarmonic,    ///< Harmonic stack: |measured threshold factor - 1| [% of f].
  kSlantTower,  ///< Slant tower: measured - statics collapse layer [layers].
  kMotion,      ///< A motion with an answer from mechanics: |measured / expected - 1| [%].
  /// A pile dropped and left to settle: penetration [mm] as kDrop, and when
  /// it comes to rest [s] and what it costs then [% of real time].
  kPile,
};

struct BenchCase {
  std::string label;  ///< Row label, e.g. "tower25".
  std::string scene;  ///< Scene name or path (for kHarmonic: the brick count is `bricks`).
  BenchMetric metric = BenchMetric::kSettled;
  double duration = 10.0;                  ///< Sim time per run [s].
  int bricks = 10;                         ///< kHarmonic: stack height.
  double offset = 0.011;                   ///< kSlantTower: layer shift [m].
  MotionCase motion = MotionCase::kSlide;  ///< kMotion: which.
  /// Runs of a short case; the fastest counts, as the least disturbed by the
  /// rest of a shared machine (kSettled and kDrop).
  int repeats = 1;
  std::vector<BenchSetting> settings;
};

struct BenchPlan {
  std::vector<BenchCase> cases;
  /// Also measure divergence from a reference run at dt = 1/4000 s with 100
  /// iterations (Erez, Tassa, Todorov 2015) over the first second.
  bool divergence = false;
};

/// One row of bench/results/*.csv.
struct BenchRow {
  std::string label, scene;
  BenchSetting setting;
  std::size_t bricks = 0;
  double sim_time = 0.0;   ///< [s], summed over the runs of the row.
  double wall_time = 0.0;  ///< Stepping wall time [s], setup excluded.
  double bullet_seconds = 0.0, contact_seconds = 0.0, stability_seconds = 0.0;
  BulletStageSeconds bullet_stages;  ///< Parts of bullet_seconds [s].
  unsigned long long bullet_steps = 0, awake_brick_steps = 0, steps = 0;
  double drift_mm = -1.0;  ///< -1: not measured by this case.
  double penetration_mm = -1.0;
  double collapse_layer_error = -1e9;  ///< -1e9: not measured.
  double threshold_error_pct = -1.0;
  double divergence_mm = -1.0;
  /// kMotion: the quantity measured and what mechanics (or, for the domino
  /// wave, plain Bullet at 1/4000 s and 100 iterations) says; NaN: absent.
  double motion_measured = std::numeric_limits<double>::quiet_NaN();
  double motion_expected = std::numeric_limits<double>::quiet_NaN();
  double motion_error_pct = -1.0;
  /// kPile: the earliest sim time from which at least PileRest::kSettledPct
  /// of the bricks stayed at rest to the end [s]; NaN: never.
  double settle_time = std::numeric_limits<double>::quiet_NaN();
  double at_rest_pct = -1.0;       ///< kPile: bricks at rest at the end [%]; -1: not measured.
  long fell_off = -1;              ///< kPile: bricks on the floor at the end; -1: not measured.
  double settled_cost_pct = -1.0;  ///< kPile: stepping wall time of the last sim second [% of it].
  unsigned long long nonfinite = 0;
  std::size_t lost = 0;     ///< Bricks placed but gone at the end, lost or missing (must be 0).
  std::size_t refused = 0;  ///< Scene placements the world refused.
};

/// When a pile comes to rest, from samples in time order of how many of its
/// bricks are at rest: frozen by a stability model, or asleep in plain Bullet.
class PileRest {
 public:
  /// The share of the bricks at rest from which a pile counts as settled [%]:
  /// not all, since a brick on the floor or at the pile's foot may rock on.
  static constexpr std::size_t kSettledPct = 98;

  /// `at_rest` of `bricks` were at rest at sim time `time` [s].
  void sample(double time, std::size_t at_rest, std::size_t bricks);
  /// The first sample from which every sample was settled [s]; NaN: the last was not.
  double settleTime() const { return settled_since_; }

 private:
  double settled_since_ = std::numeric_limits<double>::quiet_NaN();
};

/// The two-minute subset (`make bench-quick`) and the whole sweep (`make bench`).
BenchPlan quickBenchPlan();
BenchPlan fullBenchPlan();

/// Where the benchmark finds brick types and scenes.
struct BenchContext {
  BrickTypeLibrary types;
  std::vector<std::string> scene_dirs;
  /// Reference runs (1/4000 s, 100 iterations) are costly and the same for
  /// every setting of a case and mode: computed once, by "scene/mode".
  mutable std::map<std::string, std::vector<BrickSnapshot>> references;
  /// The same for the motions without a closed form, by case label.
  mutable std::map<std::string, double> motion_references;
};

/// Runs one case at one setting.
Status runBenchCase(const BenchCase& bench_case, const BenchSetting& setting,
                    const BenchContext& context, bool divergence, BenchRow* row);

std::string benchCsvHeader();
std::string toCsv(const BenchRow& row);

/// Statics of the slant tower: the first layer count n for which the COM of
/// bricks 2..n (at (j - 1) d) passes the right end of brick 1, n d > L.
int slantTowerCollapseLayer(double offset, double length);

}  // namespace brick_stack_sim
