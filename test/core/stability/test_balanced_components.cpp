// A component judged again where only its loads changed: statics of the
// bricks the changed loads reach, the rest pushing with the kept forces.
// Whenever it says "balanced", the contact forces it leaves must balance
// every brick (checked here by summing forces and torques), and the LP of
// the whole component must agree; a load statics cannot bear is left to the
// whole component's LP.
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "stability/balanced_components.h"
#include "stability/statics_assembly.h"

namespace brick_stack_sim {
namespace {

constexpr double kGravity = 9.81;             ///< Statics' g [m/s^2] (StaticsOptions).
constexpr double kMass = 0.01;                ///< Each block [kg].
constexpr double kWeight = kMass * kGravity;  ///< [N]
constexpr double kHalf = 0.01;                ///< Half a block's side [m]: 20 mm cubes.
constexpr double kFriction = 0.5;

/// The four corners of a block's face at height `z`, centred on (x, y),
/// pressed from below (normals up), on `supporter`.
SupportPatch faceOn(BodyHandle supporter, double x, double y, double z) {
  SupportPatch patch;
  patch.supporter = supporter;
  patch.friction = kFriction;
  for (double dx : {-kHalf, kHalf})
    for (double dy : {-kHalf, kHalf}) {
      patch.points.emplace_back(x + dx, y + dy, z);
      patch.normals.push_back(Eigen::Vector3d::UnitZ());
    }
  patch.height = z;
  return patch;
}

/// Block 0 and block 1 side by side on the table, block 2 bridging them
/// (a half over each), block 3 on block 2 over block 0's edge: loads shared
/// by two supports.
SupportGraph bridge() {
  SupportGraph graph;
  const double h = 2 * kHalf;
  graph.add(0, {-kHalf, 0, kHalf}, kMass, {faceOn(kTableHandle, -kHalf, 0, 0)});
  graph.add(1, {3 * kHalf, 0, kHalf}, kMass, {faceOn(kTableHandle, 3 * kHalf, 0, 0)});
  SupportPatch left = faceOn(0, -kHalf, 0, h), right = faceOn(1, 3 * kHalf, 0, h);
  // Block 2 spans x in [-kHalf, 3 kHalf]: half of each face under it.
  for (SupportPatch* patch : {&left, &right})
    for (Eigen::Vector3d& point : patch->points)
      point.x() = std::min(std::max(point.x(), -kHalf + 1e-9), 3 * kHalf - 1e-9);
  graph.add(2, {kHalf, 0, 3 * kHalf}, kMass, {left, right});
  graph.add(3, {0, 0, 5 * kHalf}, kMass, {faceOn(2, 0, 0, 4 * kHalf)});
  graph.takeChangedComponents();
  return graph;
}

const std::vector<BodyHandle> kComponent = {0, 1, 2, 3};

StabilityOptions options() { return StabilityOptions(); }

/// Solves the whole component, leaves its forces on the bricks; whether it balanced.
bool solveWhole(SupportGraph* graph) {
  const StaticsAssembly assembly = assembleStatics(*graph, kComponent, options());
  const StaticsSolution solution = assembly.solve();
  EXPECT_TRUE(solution.solved) << solution.message;
  std::vector<std::vector<ContactForce>> forces = assembly.contactForces(solution);
  for (std::size_t i = 0; i < kComponent.size(); ++i)
    graph->find(kComponent[i])->stability.contact_forces = forces[i];
  return solution.feasible;
}

/// The force and torque (about its COM) left unbalanced on `brick` by its
/// weight, its loads and its contact forces, over its weight [-] and its
/// weight times a block's side [-].
std::pair<double, double> unbalanced(const SupportGraph& graph, BodyHandle brick) {
  const SupportGraph::Node& node = *graph.find(brick);
  Eigen::Vector3d force(0, 0, -node.mass * kGravity), torque = Eigen::Vector3d::Zero();
  const auto add = [&](const Eigen::Vector3d& f, const Eigen::Vector3d& at) {
    force += f;
    torque += (at - node.com).cross(f);
  };
  for (const PointForce& load : node.stability.external_loads) add(load.force, load.point);
  for (const ContactForce& contact : node.stability.contact_forces)
    add(contact.force, contact.point);
  return {force.norm() / kWeight, torque.norm() / (kWeight * 2 * kHalf)};
}

void expectEveryBrickBalanced(const SupportGraph& graph) {
  for (BodyHandle brick : kComponent) {
    const auto [force, torque] = unbalanced(graph, brick);
    EXPECT_LT(force, 1e-6) << "brick " << brick;
    EXPECT_LT(torque, 1e-6) << "brick " << brick;
  }
}

void load(SupportGraph* graph, BodyHandle brick, const Eigen::Vector3d& force,
          const Eigen::Vector3d& point) {
  graph->find(brick)->stability.external_loads = {PointForce{force, point}};
}

TEST(BalancedComponents, NothingKeptNothingSaid) {
  SupportGraph graph = bridge();
  BalancedComponents balanced;
  EXPECT_FALSE(balanced.stillBalanced(&graph, kComponent, options(), 1.0));
}

/// The bridge, solved whole and kept: what the model holds once its
/// component balanced.
class KeptBridge : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(solveWhole(&graph));
    balanced.keep(graph, kComponent);
  }

  SupportGraph graph = bridge();
  BalancedComponents balanced;
};

TEST_F(KeptBridge, UnchangedLoadsNeedNoStatics) {
  for (BodyHandle brick : kComponent) graph.find(brick)->stability.contact_forces.clear();
  EXPECT_TRUE(balanced.stillBalanced(&graph, kComponent, options(), 1.0));
  EXPECT_EQ(balanced.localSolves(), 0u);
  expectEveryBrickBalanced(graph);
}

TEST_F(KeptBridge, ALoadOnABottomBlockIsSolvedForItAlone) {
  // Block 1 stands on the table: a push down on it reaches nothing else, so
  // the others keep their forces and block 1 alone is solved.
  const std::vector<ContactForce> kept_on_3 = graph.find(3)->stability.contact_forces;
  load(&graph, 1, {0, 0, -0.05}, {3 * kHalf + 0.005, 0, 2 * kHalf});
  ASSERT_TRUE(balanced.stillBalanced(&graph, kComponent, options(), 1.0));
  EXPECT_EQ(balanced.localSolves(), 1u);
  expectEveryBrickBalanced(graph);
  const std::vector<ContactForce>& on_3 = graph.find(3)->stability.contact_forces;
  ASSERT_EQ(on_3.size(), kept_on_3.size());
  for (std::size_t i = 0; i < on_3.size(); ++i) EXPECT_EQ(on_3[i].force, kept_on_3[i].force);
}

TEST_F(KeptBridge, ALoadOnTheTopReachesEveryBrickBelowIt) {
  // A push down on block 3, off its centre towards the bridge's middle:
  // through block 2 to both supports.
  load(&graph, 3, {0, 0, -0.08}, {0.004, 0, 6 * kHalf});
  ASSERT_TRUE(balanced.stillBalanced(&graph, kComponent, options(), 1.0));
  expectEveryBrickBalanced(graph);
  EXPECT_TRUE(solveWhole(&graph));
}

TEST_F(KeptBridge, ASidewaysPushBeyondFrictionIsLeftToTheWholeComponent) {
  // Block 3 pushed sideways with more than friction can hold under its
  // weight and the push's own vertical part: 0.6 of its weight against
  // 0.5 x (1 + 0.1). Statics of the whole cannot hold it either.
  load(&graph, 3, {0.6 * kWeight, 0, -0.1 * kWeight}, {0, 0, 5 * kHalf});
  EXPECT_FALSE(balanced.stillBalanced(&graph, kComponent, options(), 1.0));
  EXPECT_FALSE(solveWhole(&graph));
}

TEST_F(KeptBridge, AMovedBrickIsNotJudgedFromTheKeptForces) {
  graph.find(3)->com.x() += 1e-6;
  EXPECT_FALSE(balanced.stillBalanced(&graph, kComponent, options(), 1.0));
  EXPECT_EQ(balanced.localSolves(), 0u);
}

TEST_F(KeptBridge, ForgottenComponentsAreSolvedWhole) {
  balanced.forget(kComponent);
  EXPECT_FALSE(balanced.stillBalanced(&graph, kComponent, options(), 1.0));
}

TEST_F(KeptBridge, WhatItCallsBalancedTheWholeComponentsStaticsBalances) {
  // Random loads on random blocks, each judged from what the last balanced
  // judgement kept, as the model does; every "balanced" is checked against
  // the sums of forces and torques and against the whole component's LP.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> which(0, 3);
  int said_balanced = 0, left_to_whole = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const BodyHandle brick = static_cast<BodyHandle>(which(random));
    const Eigen::Vector3d com = graph.find(brick)->com;
    const Eigen::Vector3d force(0.4 * kWeight * unit(random), 0.4 * kWeight * unit(random),
                                -kWeight * (0.2 + unit(random)));
    load(&graph, brick, force,
         com + Eigen::Vector3d(kHalf * unit(random), kHalf * unit(random), kHalf));
    if (balanced.stillBalanced(&graph, kComponent, options(), 1.0)) {
      ++said_balanced;
      expectEveryBrickBalanced(graph);
      SupportGraph whole = graph;
      EXPECT_TRUE(solveWhole(&whole)) << "trial " << trial;
    } else {
      ++left_to_whole;
      if (solveWhole(&graph)) {
        balanced.keep(graph, kComponent);
      } else {
        // As the model: what did not balance wakes; these loads go again.
        balanced.forget(kComponent);
        graph.find(brick)->stability.external_loads.clear();
        ASSERT_TRUE(solveWhole(&graph));
        balanced.keep(graph, kComponent);
      }
    }
  }
  // Both answers were given: the check above was not vacuous.
  EXPECT_GT(said_balanced, 50);
  EXPECT_GT(left_to_whole, 10);
}

}  // namespace
}  // namespace brick_stack_sim
