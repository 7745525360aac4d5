#pragma once
// Worlds with one friction for every pair, bricks placed at any pose, and
// what the statics tests read back: a brick's snapshot, how far it moved,
// how often bricks were woken.

#include <algorithm>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "support/kapla.h"

namespace brick_stack_sim {
namespace test {

/// A world in `mode` whose KAPLA and table both have friction `mu`, so
/// every pair has it.
inline std::unique_ptr<BrickWorld> worldWithFriction(const std::string& mode, double mu) {
  BrickTypeLibrary types;
  BrickType kapla = *packageTypes().find("kapla");
  kapla.friction = mu;
  EXPECT_TRUE(types.add(kapla).ok);
  EXPECT_TRUE(types.setDefaultType("kapla").ok);
  WorldOptions options = optionsFor(mode);
  options.table.friction = mu;
  std::unique_ptr<BrickWorld> world;
  const Status created = BrickWorld::create(options, types, &world);
  EXPECT_TRUE(created.ok) << created.message;
  return world;
}

/// A KAPLA at rest at `pose`.
inline BrickPlacement at(const std::string& id, const Eigen::Isometry3d& pose) {
  BrickPlacement p;
  p.id = id;
  p.pose = pose;
  return p;
}

inline BrickSnapshot snapshotOf(const BrickWorld& world, const std::string& id) {
  BrickSnapshot snapshot;
  EXPECT_TRUE(world.find(id, &snapshot)) << id;
  return snapshot;
}

/// How far a brick's centre is from where it was placed [m].
inline double displacement(const BrickWorld& world, const std::string& id) {
  const BrickSnapshot b = snapshotOf(world, id);
  return (b.pose.translation() - b.placed_pose.translation()).norm();
}

/// How far a brick has turned from its placed orientation [rad].
inline double turn(const BrickWorld& world, const std::string& id) {
  const BrickSnapshot b = snapshotOf(world, id);
  const Eigen::AngleAxisd rotation(b.placed_pose.linear().transpose() * b.pose.linear());
  return std::abs(rotation.angle());
}

/// The `woken` events among the world's events since the last call.
inline int countWakes(BrickWorld* world) {
  const std::vector<SimEvent> events = world->takeEvents();
  return static_cast<int>(std::count_if(events.begin(), events.end(), [](const SimEvent& e) {
    return e.kind == SimEventKind::kWoken;
  }));
}

}  // namespace test
}  // namespace brick_stack_sim
