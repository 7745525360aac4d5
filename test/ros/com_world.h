#pragma once
// A real BrickWorld in mode com with the package's brick types, for the
// adapter's unit tests: what they convert and draw comes from the stability
// layer itself, not from hand-made snapshots that could drift from it. The
// tower geometry here is also what the node tests place through ~place_brick.

#include <cmath>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/world/brick_world.h"

namespace brick_stack_sim {
namespace ros_adapter {
namespace test {

constexpr double kKaplaLength = 0.117;      ///< [m]
constexpr double kKaplaWidth = 0.0234;      ///< [m]
constexpr double kKaplaThickness = 0.0078;  ///< [m]
/// Offset of the two bricks of a layer from the tower axis [m] (DESIGN.md
/// tower: the outer bricks rest across the ends of the layer below).
constexpr double kTowerOffset = 0.5 * (kKaplaLength - kKaplaWidth);

inline std::unique_ptr<BrickWorld> makeComWorld() {
  BrickTypeLibrary types;
  const std::string dir = BRICK_STACK_SIM_SOURCE_DIR;
  const Status loaded =
      BrickTypeLibrary::load(dir + "/urdf/bricks.urdf", dir + "/config/bricks.yaml", &types);
  EXPECT_TRUE(loaded.ok) << loaded.message;
  WorldOptions options;
  options.stability.mode = "com";
  std::unique_ptr<BrickWorld> world;
  const Status created = BrickWorld::create(options, types, &world);
  EXPECT_TRUE(created.ok) << created.message;
  return world;
}

/// Centre and yaw of a brick of a two-per-layer tower.
struct TowerSlot {
  double x, y, z;  ///< [m]
  double yaw;      ///< About z [rad].
};

/// Brick `slot` (0 or 1) of `layer` of a two-per-layer tower, as the core's
/// tower generator lays it: even layers along x at y = -/+ kTowerOffset, odd
/// layers turned by pi/2 at x = -/+ kTowerOffset.
inline TowerSlot towerSlot(int layer, int slot) {
  const double across = slot == 0 ? -kTowerOffset : kTowerOffset;
  const bool along_x = layer % 2 == 0;
  return {along_x ? 0.0 : across, along_x ? across : 0.0,
          kKaplaThickness / 2 + layer * kKaplaThickness, along_x ? 0.0 : M_PI / 2};
}

/// Brick `index` of a two-per-layer tower: towerSlot(index / 2, index % 2).
inline BrickPlacement towerBrick(int index) {
  const TowerSlot slot = towerSlot(index / 2, index % 2);
  BrickPlacement p;
  p.id = "t" + std::to_string(index);
  p.type = "kapla";
  p.pose.translation() = Eigen::Vector3d(slot.x, slot.y, slot.z);
  p.pose.linear() = Eigen::AngleAxisd(slot.yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return p;
}

inline void runFor(BrickWorld* world, double seconds) {
  const long steps = std::lround(seconds / world->options().time_step);
  for (long i = 0; i < steps; ++i) world->step();
}

}  // namespace test
}  // namespace ros_adapter
}  // namespace brick_stack_sim
