#pragma once
// What the core and the ROS tests share: KAPLA's measured size and mass
// (docs/ros_interface.md, "Parameters"), the package's brick types, worlds in a given mode,
// towers laid out by hand (independently of the core's generator, which the
// scene tests check against them), and a fingerprint of a world's state to
// prove that a refused request changed nothing.

#include <cmath>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/world/brick_world.h"

namespace brick_stack_sim {
namespace test {

constexpr double kKaplaLength = 0.117;      ///< [m]
constexpr double kKaplaWidth = 0.0234;      ///< [m]
constexpr double kKaplaThickness = 0.0078;  ///< [m]
constexpr double kKaplaMass = 0.0119;       ///< [kg]
/// Offset of the two bricks of a tower's layer from its axis [m]: the outer
/// bricks rest across the ends of the layer below.
constexpr double kTowerOffset = 0.5 * (kKaplaLength - kKaplaWidth);

/// A file of the package's source tree (urdf/, config/, scenes/).
inline std::string dataPath(const std::string& relative) {
  return std::string(BRICK_STACK_SIM_SOURCE_DIR) + "/" + relative;
}

inline BrickTypeLibrary packageTypes() {
  BrickTypeLibrary types;
  const Status loaded =
      BrickTypeLibrary::load(dataPath("urdf/bricks.urdf"), dataPath("config/bricks.yaml"), &types);
  EXPECT_TRUE(loaded.ok) << loaded.message;
  return types;
}

/// The default world options in stability mode `mode`.
inline WorldOptions optionsFor(const std::string& mode) {
  WorldOptions options;
  options.stability.mode = mode;
  return options;
}

/// Plain Bullet: the world the tests of the world itself run in.
inline WorldOptions plainBulletOptions() { return optionsFor("none"); }

inline std::unique_ptr<BrickWorld> makeWorld(const WorldOptions& options = plainBulletOptions()) {
  std::unique_ptr<BrickWorld> world;
  const Status created = BrickWorld::create(options, packageTypes(), &world);
  EXPECT_TRUE(created.ok) << created.message;
  return world;
}

/// The exact bits of every brick's id, type, state, pose and velocity, plus the clock.
inline std::string fingerprint(const BrickWorld& world) {
  std::string bytes;
  auto append = [&bytes](const void* data, std::size_t size) {
    bytes.append(static_cast<const char*>(data), size);
  };
  const double time = world.time();
  append(&time, sizeof time);
  for (const BrickSnapshot& b : world.snapshot()) {
    bytes += b.id + '\0' + b.type + '\0' + static_cast<char>(b.state);
    append(b.pose.matrix().data(), sizeof(double) * 16);
    append(b.linear_velocity.data(), sizeof(double) * 3);
    append(b.angular_velocity.data(), sizeof(double) * 3);
  }
  return bytes;
}

/// Steps the world for `seconds` of sim time.
inline void runFor(BrickWorld* world, double seconds) {
  const long steps = std::lround(seconds / world->options().time_step);
  for (long i = 0; i < steps; ++i) world->step();
}

/// A brick at rest at `position` [m], turned by `yaw` [rad] about z.
inline BrickPlacement placement(const std::string& id, const Eigen::Vector3d& position,
                                double yaw = 0.0, const std::string& type = "kapla") {
  BrickPlacement p;
  p.id = id;
  p.type = type;
  p.pose.translation() = position;
  p.pose.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return p;
}

/// The pose at `position` [m] turned by `rotation`.
inline Eigen::Isometry3d pose(const Eigen::Vector3d& position, const Eigen::AngleAxisd& rotation) {
  Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
  p.translation() = position;
  p.linear() = rotation.toRotationMatrix();
  return p;
}

/// A KAPLA at rest at `at`.
inline BrickPlacement placement(const std::string& id, const Eigen::Isometry3d& at) {
  BrickPlacement p = placement(id, Eigen::Vector3d::Zero());
  p.pose = at;
  return p;
}

/// Centre and yaw of a brick of a two-per-layer tower.
struct TowerSlot {
  double x, y, z;  ///< [m]
  double yaw;      ///< About z [rad].
};

/// Brick `slot` (0 or 1) of `layer` of a two-per-layer KAPLA tower on the
/// table centre: even layers along x at y = -/+ kTowerOffset, odd layers
/// turned by pi/2 at x = -/+ kTowerOffset.
inline TowerSlot towerSlot(int layer, int slot) {
  const double across = slot == 0 ? -kTowerOffset : kTowerOffset;
  const bool along_x = layer % 2 == 0;
  return {along_x ? 0.0 : across, along_x ? across : 0.0,
          kKaplaThickness / 2 + layer * kKaplaThickness, along_x ? 0.0 : M_PI / 2};
}

/// Brick `index` of that tower (id "t<index>"): towerSlot(index / 2, index % 2).
inline BrickPlacement towerBrick(int index) {
  const TowerSlot slot = towerSlot(index / 2, index % 2);
  return placement("t" + std::to_string(index), Eigen::Vector3d(slot.x, slot.y, slot.z), slot.yaw);
}

}  // namespace test
}  // namespace brick_stack_sim
