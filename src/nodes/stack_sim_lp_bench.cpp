// stack_sim_lp_bench: the statics LP's time per solve against component
// size, cold and warm-started (the basis of the same structure one brick
// smaller, as when a structure grows by a brick), on one core, as CSV.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <vector>

#include "stability/rigid_block_statics.h"

using namespace brick_stack_sim;

namespace {

// A KAPLA [m], [kg]; friction of every pair.
constexpr double kLength = 0.117, kWidth = 0.0234, kThickness = 0.0078, kMass = 0.0119;
constexpr double kFriction = 0.5;
/// Each layer this much further along x [m]: at 500 layers the COM of
/// layers 1..499 sits 50 mm past the bottom brick's centre, inside its
/// edge at 58.5 mm, so every tower here stands and the LP is feasible.
constexpr double kOffset = 0.0002;

struct Problem {
  std::vector<StaticsBody> bodies;
  std::vector<StaticsContact> contacts;
  StaticsWarmStart keys;
};

/// A straight tower of `layers` KAPLAs, each kOffset further along x: four
/// corner contacts per interface, the first on the table.
Problem tower(int layers) {
  Problem p;
  for (int i = 0; i < layers; ++i) {
    p.bodies.push_back(
        StaticsBody{kMass, Eigen::Vector3d(i * kOffset, 0.0, (i + 0.5) * kThickness)});
    p.keys.body_keys.push_back(static_cast<std::uint64_t>(i));
    // The overlap with the brick below (the table under the first).
    const double low = i * kOffset - 0.5 * kLength;
    const double high = (i > 0 ? (i - 1) * kOffset : 0.0) + 0.5 * kLength;
    const double corners[4][2] = {
        {low, -0.5 * kWidth}, {high, -0.5 * kWidth}, {high, 0.5 * kWidth}, {low, 0.5 * kWidth}};
    for (int k = 0; k < 4; ++k) {
      p.contacts.push_back(
          StaticsContact{i, i > 0 ? i - 1 : kStaticsGround,
                         Eigen::Vector3d(corners[k][0], corners[k][1], i * kThickness),
                         Eigen::Vector3d::UnitZ(), kFriction});
      p.keys.contact_keys.push_back((static_cast<std::uint64_t>(i) << 8) | k);
    }
  }
  return p;
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: stack_sim_lp_bench OUTPUT.csv\n";
    return 2;
  }
  std::ofstream csv(argv[1]);
  if (!csv) {
    std::cerr << "stack_sim_lp_bench: cannot write " << argv[1] << "\n";
    return 1;
  }
  csv << "bricks,contacts,cold_ms,warm_ms,cold_pivots,warm_pivots,feasible\n";
  using Clock = std::chrono::steady_clock;
  for (const int bricks : {10, 50, 100, 250, 500}) {
    Problem grown = tower(bricks);
    Problem smaller = tower(bricks - 1);
    StaticsBasis start;
    smaller.keys.basis = &start;
    solveStatics(smaller.bodies, smaller.contacts, StaticsOptions(), &smaller.keys);
    const int repeats = bricks <= 100 ? 9 : 3;
    std::vector<double> cold_ms, warm_ms;
    StaticsSolution cold, warm;
    for (int r = 0; r < repeats; ++r) {
      auto t0 = Clock::now();
      cold = solveStatics(grown.bodies, grown.contacts);
      auto t1 = Clock::now();
      StaticsBasis basis = start;  // every repeat from the same start
      grown.keys.basis = &basis;
      warm = solveStatics(grown.bodies, grown.contacts, StaticsOptions(), &grown.keys);
      auto t2 = Clock::now();
      cold_ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
      warm_ms.push_back(std::chrono::duration<double, std::milli>(t2 - t1).count());
    }
    if (!cold.solved || !warm.solved || cold.feasible != warm.feasible) {
      std::cerr << "stack_sim_lp_bench: " << bricks << " bricks: cold and warm disagree\n";
      return 1;
    }
    char line[160];
    std::snprintf(line, sizeof line, "%d,%zu,%.3f,%.3f,%d,%d,%d\n", bricks, grown.contacts.size(),
                  median(cold_ms), median(warm_ms), cold.iterations, warm.iterations,
                  cold.feasible ? 1 : 0);
    csv << line << std::flush;
    std::cerr << line;
  }
  return 0;
}
