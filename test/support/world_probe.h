#pragma once
// Worlds with one friction for every pair, bricks placed at any pose, and
// what the statics tests read back: a brick's snapshot, how far it moved,
// how often bricks were woken.

#include <algorithm>
#include <map>
#include <memory>
#include <string>
#include <vector>

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

/// How far the contact forces the world reports for `ids` are from holding
/// each of them in equilibrium (Newton's laws, not the solver's word):
/// per brick with reported forces, its weight plus its forces plus the
/// reactions of the forces other bricks of `ids` report on it (where it
/// does not report that contact itself, as across two statics problems).
struct ForceBalance {
  int bricks_with_forces = 0;
  double worst_force = 0.0;     ///< Net force over the brick's weight [-].
  double worst_torque = 0.0;    ///< Net torque about its COM over weight x length [-].
  double worst_friction = 0.0;  ///< Largest |tangential| - mu normal, over the weight [-].
  double worst_pull = 0.0;      ///< Largest tension (negative normal force), over the weight [-].
};

inline ForceBalance contactForceBalance(const BrickWorld& world,
                                        const std::vector<std::string>& ids) {
  constexpr double kGravity = 9.81;    // the g of statics (StaticsOptions)
  constexpr double kSamePoint = 1e-6;  // [m]
  std::map<std::string, SupportGeometry> geometry;
  for (const std::string& id : ids) EXPECT_TRUE(world.supportGeometry(id, &geometry[id])) << id;
  // Whether `id` names the contact with `other` at `at` itself (then its
  // forces there already include what the other's naming stands for).
  auto reports = [&](const std::string& id, const std::string& other, const Eigen::Vector3d& at) {
    for (const SupportGeometry::ContactForce& f : geometry[id].contact_forces)
      if (f.other == other && (f.point - at).norm() < kSamePoint) return true;
    return false;
  };
  ForceBalance result;
  for (const std::string& id : ids) {
    const SupportGeometry& own = geometry[id];
    if (own.contact_forces.empty()) continue;
    ++result.bricks_with_forces;
    const BrickSnapshot brick = snapshotOf(world, id);
    const double weight = brick.mass * kGravity;
    const Eigen::Vector3d com = brick.pose.translation();
    Eigen::Vector3d force(0.0, 0.0, -weight);
    Eigen::Vector3d torque = Eigen::Vector3d::Zero();
    auto add = [&](const Eigen::Vector3d& f, const Eigen::Vector3d& at) {
      force += f;
      torque += (at - com).cross(f);
    };
    for (const SupportGeometry::ContactForce& f : own.contact_forces) {
      add(f.force, f.point);
      const double normal = f.force.dot(f.normal);
      const double tangential = (f.force - normal * f.normal).norm();
      result.worst_pull = std::max(result.worst_pull, -normal / weight);
      result.worst_friction =
          std::max(result.worst_friction, (tangential - f.friction * normal) / weight);
    }
    for (const std::string& other : ids) {
      if (other == id) continue;
      for (const SupportGeometry::ContactForce& f : geometry[other].contact_forces)
        if (f.other == id && !reports(id, other, f.point)) add(-f.force, f.point);
    }
    result.worst_force = std::max(result.worst_force, force.norm() / weight);
    result.worst_torque =
        std::max(result.worst_torque, torque.norm() / (weight * brick.size.maxCoeff()));
  }
  return result;
}

}  // namespace test
}  // namespace brick_stack_sim
