#pragma once
// Shared fixtures of the core tests: the package's own brick types and a
// fingerprint of a world's state to prove that a refused request changed nothing.

#include <cmath>
#include <cstring>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/world/brick_world.h"

namespace brick_stack_sim {
namespace test {

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

/// Plain Bullet: the world the tests of the world itself run in.
inline WorldOptions plainBulletOptions() {
  WorldOptions options;
  options.stability.mode = "none";
  return options;
}

inline std::unique_ptr<BrickWorld> makeWorld(const WorldOptions& options = plainBulletOptions()) {
  std::unique_ptr<BrickWorld> world;
  const Status created = BrickWorld::create(options, packageTypes(), &world);
  EXPECT_TRUE(created.ok) << created.message;
  return world;
}

/// The exact bits of every brick's id, pose and velocity, plus the clock.
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
  const auto steps = static_cast<long>(std::lround(seconds / world->options().time_step));
  for (long i = 0; i < steps; ++i) world->step();
}

inline BrickPlacement placement(const std::string& id, const Eigen::Vector3d& position,
                                double yaw = 0.0, const std::string& type = "kapla") {
  BrickPlacement p;
  p.id = id;
  p.type = type;
  p.pose.translation() = position;
  p.pose.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return p;
}

constexpr double kKaplaLength = 0.117;      // [m]
constexpr double kKaplaWidth = 0.0234;      // [m]
constexpr double kKaplaThickness = 0.0078;  // [m]
constexpr double kKaplaMass = 0.0119;       // [kg]

}  // namespace test
}  // namespace brick_stack_sim
