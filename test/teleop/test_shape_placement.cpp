// "Place here" and the table floor for bricks of any shape: a cylinder
// carries what lands on its cap and nothing beside it, a lying one what
// lands on its side, a compound with each part on its own, and bricks of a
// type the teleop does not know count as the box of their size.
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/types/brick_type.h"
#include "brick_stack_sim/teleop/keyboard_command.h"
#include "brick_stack_sim/teleop/placement_geometry.h"
#include "support/shapes.h"

namespace brick_stack_sim {
namespace teleop {
namespace {

constexpr double kRadius = 0.02;  // [m]
constexpr double kLength = 0.05;  // [m]
const Eigen::Vector3d kCubeSize(0.01, 0.01, 0.01);

BrickType finished(BrickType type) { return test::finishedType(std::move(type)); }

BrickType cylinderType(double radius = kRadius, double length = kLength) {
  return test::cylinderType("peg", radius, length, 0.1);
}

BrickType boxType(const Eigen::Vector3d& size) {
  BrickType t;
  t.name = "box";
  t.size = size;
  t.mass = 0.01;
  return finished(t);
}

/// A ramp over x in [-0.03, 0.03], y in [-0.02, 0.02], 0.015 m high over
/// y = -0.02, its bottom at z = 0 of its frame.
BrickType wedgeType() { return test::rampType("wedge", 0.03, 0.02, 0.015, 0.05); }

Eigen::Isometry3d at(double x, double y, double z,
                     const Eigen::Matrix3d& rotation = Eigen::Matrix3d::Identity()) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(x, y, z);
  pose.linear() = rotation;
  return pose;
}

const Eigen::Matrix3d kLying =
    Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();

TEST(ShapePlacement, AGhostOverAStandingCylinderRestsOnItsCap) {
  const BrickType peg = cylinderType(), cube = boxType(kCubeSize);
  // Standing on the table at the origin: its cap at z = 0.05.
  const std::vector<PlacedSolid> bricks = {peg.placed(at(0.0, 0.0, 0.5 * kLength))};
  EXPECT_NEAR(restingPose(peg.placed(at(0.0, 0.0, 0.3)), bricks).translation().z(),
              kLength + 0.5 * kLength, 1e-12);
  EXPECT_NEAR(restingPose(cube.placed(at(0.005, -0.01, 0.3)), bricks).translation().z(),
              kLength + 0.005, 1e-12);
  // Sunk into it, its centre above the cap: raised onto it.
  EXPECT_NEAR(restingPose(cube.placed(at(0.0, 0.0, kLength + 0.001)), bricks).translation().z(),
              kLength + 0.005, 1e-12);
}

TEST(ShapePlacement, AGhostBesideACylinderFallsToTheTable) {
  const BrickType peg = cylinderType(), cube = boxType(kCubeSize);
  const std::vector<PlacedSolid> bricks = {peg.placed(at(0.0, 0.0, 0.5 * kLength))};
  EXPECT_NEAR(restingPose(peg.placed(at(0.05, 0.0, 0.3)), bricks).translation().z(), 0.5 * kLength,
              1e-12);
  // Inside the cylinder's bounding square but off its circle: the
  // footprint is the circle's, not its bounds'.
  EXPECT_NEAR(restingPose(cube.placed(at(0.02, 0.02, 0.3)), bricks).translation().z(), 0.005,
              1e-12);
  // A millimetre over the rim: on the cap.
  EXPECT_NEAR(restingPose(cube.placed(at(kRadius + 0.004, 0.0, 0.3)), bricks).translation().z(),
              kLength + 0.005, 1e-12);
}

TEST(ShapePlacement, ALyingCylinderCarriesOnItsSideAndKeepsOffTheTable) {
  const BrickType peg = cylinderType(), cube = boxType(kCubeSize);
  // Lying along y: its exact top, not its prism's, at 2 r.
  const std::vector<PlacedSolid> bricks = {peg.placed(at(0.0, 0.0, kRadius, kLying))};
  EXPECT_NEAR(restingPose(cube.placed(at(0.0, 0.02, 0.3)), bricks).translation().z(),
              2.0 * kRadius + 0.005, 1e-12);
  EXPECT_NEAR(lowestCentreZ(*peg.solid, kLying), kTableTop + kRadius, 1e-12);
  EXPECT_NEAR(lowestCentreZ(*peg.solid, Eigen::Matrix3d::Identity()), 0.5 * kLength, 1e-12);
  // A lying cylinder ghost lands on its side.
  EXPECT_NEAR(restingPose(peg.placed(at(0.3, 0.0, 0.2, kLying)), bricks).translation().z(), kRadius,
              1e-12);
  // The keyboard teleop's cursor floor, holding it lying or upright.
  Cursor cursor;
  cursor.position = Eigen::Vector3d(0.0, 0.0, 0.1);
  cursor.orientation = Eigen::Quaterniond(kLying);
  EXPECT_NEAR(cursorFloor(cursor, *peg.solid), kRadius, 1e-12);
  cursor.orientation = Eigen::Quaterniond::Identity();
  EXPECT_NEAR(cursorFloor(cursor, *peg.solid), 0.5 * kLength, 1e-12);
}

TEST(ShapePlacement, AHullRestsOnItsLowestVertexAndCarriesOnItsSlope) {
  const BrickType wedge = wedgeType(), cube = boxType(kCubeSize);
  // Its frame's origin is on its bottom face: it rests with z = 0.
  EXPECT_NEAR(restingPose(wedge.placed(at(0.0, 0.0, 0.3)), {}).translation().z(), 0.0, 1e-12);
  EXPECT_NEAR(lowestCentreZ(*wedge.solid, Eigen::Matrix3d::Identity()), 0.0, 1e-12);
  // Upside down: its top edge at 0.015 below its frame.
  const Eigen::Matrix3d flipped =
      Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX()).toRotationMatrix();
  EXPECT_NEAR(lowestCentreZ(*wedge.solid, flipped), 0.015, 1e-12);
  // A cube over it rests on its top (a tool's guess: the top of what is under it).
  const std::vector<PlacedSolid> bricks = {wedge.placed(at(0.0, 0.0, 0.0))};
  EXPECT_NEAR(restingPose(cube.placed(at(0.0, 0.0, 0.3)), bricks).translation().z(), 0.015 + 0.005,
              1e-12);
}

TEST(ShapePlacement, ACompoundCarriesWithEachPart) {
  // An L: a long low plank and a post standing at its +x end.
  BrickType l_shape;
  l_shape.name = "ell";
  l_shape.shape.kind = ShapeKind::kCompound;
  ShapePart plank, post;
  plank.size = Eigen::Vector3d(0.1, 0.02, 0.01);
  post.size = Eigen::Vector3d(0.02, 0.02, 0.04);
  post.pose.translation() = Eigen::Vector3d(0.04, 0.0, 0.025);
  l_shape.shape.parts = {plank, post};
  l_shape.mass = 0.05;
  l_shape = finished(l_shape);
  const BrickType cube = boxType(kCubeSize);
  const std::vector<PlacedSolid> bricks = {l_shape.placed(at(0.0, 0.0, 0.005))};
  // Over the plank: on its top at 0.01; over the post: on its top at 0.05.
  EXPECT_NEAR(restingPose(cube.placed(at(-0.03, 0.0, 0.3)), bricks).translation().z(), 0.015,
              1e-12);
  EXPECT_NEAR(restingPose(cube.placed(at(0.04, 0.0, 0.3)), bricks).translation().z(), 0.055, 1e-12);
}

TEST(ShapePlacement, BricksOfUnknownTypesAreBoxesOfTheirSize) {
  BrickTypeLibrary types;
  ASSERT_TRUE(types.add(cylinderType()).ok);
  const BrickType& peg = *types.find("peg");
  const Eigen::Vector3d size(2.0 * kRadius, 2.0 * kRadius, kLength);
  // Known, of its size: the type's own solid.
  EXPECT_EQ(brickSolid(types, "peg", peg.size), peg.solid);
  // Unknown, or of another size than the teleop's type: a box of the size.
  for (const std::shared_ptr<const ConvexSolid>& box :
       {brickSolid(types, "crate", size), brickSolid(types, "peg", 2.0 * size)}) {
    ASSERT_TRUE(box);
    ASSERT_EQ(box->parts.size(), 1u);
    EXPECT_TRUE(box->parts[0].isBox());
  }
  EXPECT_TRUE(brickSolid(types, "crate", size)->parts[0].box_half_extents.isApprox(0.5 * size));
  // No solid for a size that is not finite or not positive.
  EXPECT_FALSE(brickSolid(types, "crate", Eigen::Vector3d(std::nan(""), 0.01, 0.01)));
  EXPECT_FALSE(brickSolid(types, "crate", Eigen::Vector3d(0.0, 0.01, 0.01)));
  // A box stand-in carries at its box's top: a ghost over a corner of an
  // unknown 0.04 m crate lands on it.
  SolidBricks bricks;
  bricks.add(at(0.0, 0.0, 0.5 * kLength), brickSolid(types, "crate", size));
  const BrickType cube = boxType(kCubeSize);
  EXPECT_NEAR(restingPose(cube.placed(at(0.02, 0.02, 0.3)), bricks.placed).translation().z(),
              kLength + 0.005, 1e-12);
}

TEST(ShapePlacement, NonFiniteSolidsCarryNothingAndTheGhostStartsBesideTheRest) {
  const BrickType peg = cylinderType(), cube = boxType(kCubeSize);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<PlacedSolid> bricks = {peg.placed(at(0.0, 0.0, nan)),
                                           peg.placed(at(nan, 0.0, 0.025)),
                                           PlacedSolid{at(0.0, 0.0, 0.025), nullptr}};
  EXPECT_NEAR(restingPose(cube.placed(at(0.0, 0.0, 0.3)), bricks).translation().z(), 0.005, 1e-12);
  const Eigen::Vector3d fallback(0.0, 0.0, 0.1);
  EXPECT_EQ(besideBricks(bricks, *cube.solid, Eigen::Matrix3d::Identity(), fallback), fallback);
  // Beside a standing cylinder: on the table, its own longest half side
  // clear of the cylinder's +x side, centred on it in y.
  const std::vector<PlacedSolid> one = {peg.placed(at(0.1, -0.05, 0.025))};
  const Eigen::Vector3d start =
      besideBricks(one, *peg.solid, Eigen::Matrix3d::Identity(), fallback);
  EXPECT_NEAR(start.x(), 0.1 + kRadius + kRadius + 0.5 * kLength, 1e-12);
  EXPECT_NEAR(start.y(), -0.05, 1e-12);
  EXPECT_NEAR(start.z(), 0.5 * kLength, 1e-12);
}

}  // namespace
}  // namespace teleop
}  // namespace brick_stack_sim
