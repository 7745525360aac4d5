// stack_sim_held_bench: what a held brick costs over a large frozen scene
// (docs/benchmarks.md, "A held brick over a frozen scene"). 25 frozen
// ten-layer towers (500 bricks) on the table, and a held brick swept back
// and forth 2 cm over their tops at the held speed
// limit, and one skimming their tops (touching them: every step checks what
// it presses on); the real-time factor (sim time over wall time) of those,
// of the same scene with nothing moving, and of the held brick alone on an
// empty table, measured side by side on one core, as CSV.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>

#include "brick_stack_sim/core/scene/generators.h"
#include "brick_stack_sim/core/simulation/simulation_config.h"
#include "brick_stack_sim/core/types/brick_type.h"
#include "brick_stack_sim/core/world/brick_world.h"
#include "brick_stack_sim/tools/package_data.h"

using namespace brick_stack_sim;

namespace {

constexpr int kTowersPerSide = 5;
constexpr int kLayers = 10;
constexpr double kTowerSpacing = 0.15;  ///< Between tower centres [m].
constexpr double kSimSeconds = 10.0;    ///< Of each run [s].
constexpr double kClearance = 0.02;     ///< Of the held brick over the tops [m].
constexpr int kRepeats = 3;             ///< Runs of each case; the fastest counts.

/// A KAPLA at rest at `position`, turned by `yaw` about z.
BrickPlacement brickAt(const std::string& id, const Eigen::Vector3d& position, double yaw) {
  BrickPlacement p;
  p.id = id;
  p.pose.translation() = position;
  p.pose.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return p;
}

/// The towers (the `tower` generator on a grid), all frozen when placed.
Status buildTowers(BrickWorld* world) {
  TowerParams params;
  params.layers = kLayers;
  params.grid_x = params.grid_y = kTowersPerSide;
  params.spacing = kTowerSpacing;
  params.origin = Eigen::Vector2d::Constant(-0.5 * (kTowersPerSide - 1) * kTowerSpacing);
  std::vector<ScheduledBrick> towers;
  if (Status generated = generateTower(params, world->types(), &towers); !generated)
    return generated;
  for (const ScheduledBrick& brick : towers)
    if (Status placed = world->addBrick(brick.placement); !placed) return placed;
  return Status::success();
}

struct Run {
  double real_time_factor = 0.0;
  std::uint64_t bullet_steps = 0;
  std::size_t woken = 0;  ///< Bricks not frozen at the end, the held one aside.
};

/// Runs `kSimSeconds`; with `sweep`, the held brick is sent from one side
/// of the scene to the other and back at every arrival.
Run timedRun(BrickWorld* world, bool sweep, double sweep_height) {
  const double reach = (kTowersPerSide / 2) * kTowerSpacing + 0.1;
  double side = 1.0;
  const long steps = std::lround(kSimSeconds / world->options().time_step);
  const std::uint64_t bullet_before = world->cost().bullet_steps;
  const auto start = std::chrono::steady_clock::now();
  for (long i = 0; i < steps; ++i) {
    if (sweep) {
      BrickSnapshot held;
      world->find(world->heldBrick(), &held);
      if (std::abs(held.pose.translation().x() - side * reach) < 1e-6 || i == 0) {
        side = -side;
        Eigen::Isometry3d target = Eigen::Isometry3d::Identity();
        // A slanted line, so the sweep crosses every row of towers.
        target.translation() = Eigen::Vector3d(side * reach, 0.5 * side * reach, sweep_height);
        world->setHeldTarget(target);
      }
    }
    world->step();
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::size_t woken = 0;
  for (const BrickSnapshot& brick : world->snapshot()) woken += brick.state == BrickState::kDynamic;
  return Run{kSimSeconds / wall, world->cost().bullet_steps - bullet_before, woken};
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: stack_sim_held_bench OUT.csv\n";
    return 2;
  }
  DataOptions data;
  fillPackageData(packageDataDir(BRICK_STACK_SIM_DATA_DIR), &data);
  BrickTypeLibrary types;
  if (Status loaded = BrickTypeLibrary::load(data.types_urdf, data.materials_yaml, &types);
      !loaded) {
    std::cerr << loaded.message << "\n";
    return 1;
  }
  const BrickType& kapla = *types.find(types.defaultType());
  const double top = kLayers * kapla.size.z() + kapla.size.z() / 2;  // of a brick on the tops
  std::ofstream csv(argv[1]);
  csv << "mode,case,frozen_bricks,sim_seconds,real_time_factor,bullet_steps,woken_at_end\n";
  for (const std::string mode : {"com", "equilibrium"}) {
    for (const std::string scene :
         {"frozen_still", "frozen_held_sweep", "frozen_held_skim", "empty_held_sweep"}) {
      Run best;
      std::size_t frozen = 0;
      for (int repeat = 0; repeat < kRepeats; ++repeat) {
        WorldOptions options;
        options.stability.mode = mode;
        std::unique_ptr<BrickWorld> world;
        if (Status created = BrickWorld::create(options, types, &world); !created) {
          std::cerr << created.message << "\n";
          return 1;
        }
        if (scene != "empty_held_sweep") {
          if (Status built = buildTowers(world.get()); !built) {
            std::cerr << built.message << "\n";
            return 1;
          }
        }
        frozen = world->brickCount();
        const bool sweep = scene != "frozen_still";
        if (sweep) {
          BrickPlacement hand = brickAt("hand", Eigen::Vector3d(-0.45, -0.35, 0.0039), 0.0);
          if (!world->addBrick(hand).ok || !world->graspBrick("hand").ok) {
            std::cerr << "could not place and grasp the held brick\n";
            return 1;
          }
        }
        const Run run =
            timedRun(world.get(), sweep, scene == "frozen_held_skim" ? top : top + kClearance);
        if (run.real_time_factor > best.real_time_factor) best = run;
      }
      csv << mode << "," << scene << "," << frozen << "," << kSimSeconds << ","
          << best.real_time_factor << "," << best.bullet_steps << "," << best.woken << "\n";
      std::printf("%-12s %-18s %4zu bricks: %8.1fx real time, %zu woken at the end\n", mode.c_str(),
                  scene.c_str(), frozen, best.real_time_factor, best.woken);
    }
  }
  return 0;
}
