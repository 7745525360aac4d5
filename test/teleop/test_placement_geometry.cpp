// "Place here" puts the ghost at rest on what is under its footprint, with
// KAPLA's real size: the expected heights are sums of brick thicknesses.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "brick_stack_sim/teleop/placement_geometry.h"
#include "support/kapla.h"

namespace {

using namespace brick_stack_sim;
using namespace brick_stack_sim::teleop;
using test::kKaplaLength;
using test::kKaplaThickness;
using test::kKaplaWidth;

const Eigen::Vector3d kKaplaHalf =
    0.5 * Eigen::Vector3d(kKaplaLength, kKaplaWidth, kKaplaThickness);
const Eigen::Vector3d kCubeHalf = 0.5 * Eigen::Vector3d(kKaplaWidth, kKaplaWidth, kKaplaWidth);

OrientedBox box(const Eigen::Vector3d& half_extents, double x, double y, double z,
                double yaw = 0.0) {
  OrientedBox b;
  b.half_extents = half_extents;
  b.pose.translation() = Eigen::Vector3d(x, y, z);
  b.pose.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return b;
}

OrientedBox kapla(double x, double y, double z, double yaw = 0.0) {
  return box(kKaplaHalf, x, y, z, yaw);
}

TEST(RestingPose, OnTheEmptyTableKeepsXYAndOrientation) {
  const OrientedBox ghost = kapla(0.1, -0.2, 0.5, 0.7);
  const Eigen::Isometry3d rest = restingPose(ghost, {});
  EXPECT_NEAR(rest.translation().x(), 0.1, 1e-12);
  EXPECT_NEAR(rest.translation().y(), -0.2, 1e-12);
  EXPECT_NEAR(rest.translation().z(), 0.5 * kKaplaThickness, 1e-12);
  EXPECT_TRUE(rest.linear().isApprox(ghost.pose.linear(), 1e-12));
}

TEST(RestingPose, CrosswiseOnABrick) {
  const std::vector<OrientedBox> bricks = {kapla(0.0, 0.0, 0.5 * kKaplaThickness)};
  const Eigen::Isometry3d rest = restingPose(kapla(0.03, 0.0, 0.2, M_PI / 2), bricks);
  EXPECT_NEAR(rest.translation().z(), 1.5 * kKaplaThickness, 1e-12);
}

TEST(RestingPose, GhostSunkIntoTheTopBrickIsRaisedOntoIt) {
  const std::vector<OrientedBox> bricks = {kapla(0.0, 0.0, 0.5 * kKaplaThickness)};
  // Its bottom 2 mm inside the brick, its centre above the brick's top.
  const Eigen::Isometry3d rest = restingPose(kapla(0.0, 0.0, 0.0078 + 0.0019), bricks);
  EXPECT_NEAR(rest.translation().z(), 1.5 * kKaplaThickness, 1e-12);
}

TEST(RestingPose, OnTheHighestOfATowerUnderIt) {
  // Two layers of a KAPLA tower: along x, then along y across their ends.
  const double offset = test::kTowerOffset;
  const std::vector<OrientedBox> bricks = {kapla(0.0, -offset, 0.5 * kKaplaThickness),
                                           kapla(0.0, offset, 0.5 * kKaplaThickness),
                                           kapla(-offset, 0.0, 1.5 * kKaplaThickness, M_PI / 2),
                                           kapla(offset, 0.0, 1.5 * kKaplaThickness, M_PI / 2)};
  // Over the second layer's brick at +offset: on top of the tower.
  EXPECT_NEAR(restingPose(kapla(offset, 0.0, 0.3), bricks).translation().z(), 2.5 * kKaplaThickness,
              1e-12);
  // Over the middle of the tower, lying along x: it spans both second-layer bricks.
  EXPECT_NEAR(restingPose(kapla(0.0, 0.0, 0.3), bricks).translation().z(), 2.5 * kKaplaThickness,
              1e-12);
  // A cube in the hole between the second layer's bricks rests on the first layer.
  EXPECT_NEAR(restingPose(box(kCubeHalf, 0.0, offset, 0.3), bricks).translation().z(),
              kKaplaThickness + 0.5 * kKaplaWidth, 1e-12);
}

TEST(RestingPose, ABrickThatOnlyTouchesTheFootprintEdgeCarriesNothing) {
  const std::vector<OrientedBox> bricks = {kapla(0.0, 0.0, 0.5 * kKaplaThickness)};
  // Side by side, long edges touching: the ghost lands on the table beside it.
  EXPECT_NEAR(restingPose(kapla(0.0, kKaplaWidth, 0.2), bricks).translation().z(),
              0.5 * kKaplaThickness, 1e-12);
  // A tenth of a millimetre over its edge: on it.
  EXPECT_NEAR(restingPose(kapla(0.0, kKaplaWidth - 1e-4, 0.2), bricks).translation().z(),
              1.5 * kKaplaThickness, 1e-12);
}

TEST(RestingPose, FootprintIsTheTurnedOutlineNotItsBoundingBox) {
  // A plank turned 45 degrees; a cube off its long side but inside its
  // axis-aligned bounding box (half extent 0.0496 m) is over the table.
  const std::vector<OrientedBox> bricks = {kapla(0.0, 0.0, 0.5 * kKaplaThickness, M_PI / 4)};
  EXPECT_NEAR(restingPose(box(kCubeHalf, 0.04, -0.04, 0.2), bricks).translation().z(),
              0.5 * kKaplaWidth, 1e-12);
  // The same cube over the plank's long axis is on the plank.
  EXPECT_NEAR(restingPose(box(kCubeHalf, 0.04, 0.04, 0.2), bricks).translation().z(),
              kKaplaThickness + 0.5 * kKaplaWidth, 1e-12);
}

TEST(RestingPose, ABrickAboveTheGhostsCentreIsNotUnderIt) {
  // A plank held 10 cm up, the ghost below its top: the ghost is under the
  // plank, not on it, and lands on the table.
  const std::vector<OrientedBox> bricks = {kapla(0.0, 0.0, 0.1)};
  EXPECT_NEAR(restingPose(kapla(0.0, 0.0, 0.05), bricks).translation().z(), 0.5 * kKaplaThickness,
              1e-12);
}

TEST(RestingPose, TiltedGhostRestsOnItsLowestCorner) {
  // A KAPLA on its long edge (rolled 90 degrees about x) is a width tall.
  OrientedBox ghost = kapla(0.2, 0.0, 0.3);
  ghost.pose.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  EXPECT_NEAR(restingPose(ghost, {}).translation().z(), 0.5 * kKaplaWidth, 1e-12);
  // Standing on its end on a plank: a length tall, from the plank's top.
  ghost.pose.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  ghost.pose.translation() = Eigen::Vector3d(0.0, 0.0, 0.3);
  EXPECT_NEAR(restingPose(ghost, {kapla(0.0, 0.0, 0.5 * kKaplaThickness)}).translation().z(),
              kKaplaThickness + 0.5 * kKaplaLength, 1e-12);
}

TEST(RestingPose, NonFiniteBricksAreIgnored) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<OrientedBox> bricks = {kapla(0.0, 0.0, nan), kapla(nan, 0.0, 0.0039)};
  EXPECT_NEAR(restingPose(kapla(0.0, 0.0, 0.2), bricks).translation().z(), 0.5 * kKaplaThickness,
              1e-12);
}

TEST(LowestCentreZ, TheBoxsHalfHeightAboveTheTableTop) {
  const Eigen::Matrix3d flat = Eigen::Matrix3d::Identity();
  EXPECT_NEAR(lowestCentreZ(kKaplaHalf, flat), kTableTop + 0.5 * kKaplaThickness, 1e-15);
  // Turning about z changes nothing; standing on its end, half its length.
  EXPECT_NEAR(lowestCentreZ(kKaplaHalf,
                            Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitZ()).toRotationMatrix()),
              0.5 * kKaplaThickness, 1e-15);
  EXPECT_NEAR(
      lowestCentreZ(kKaplaHalf,
                    Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY()).toRotationMatrix()),
      0.5 * kKaplaLength, 1e-15);
  // At that height, a tilted box's lowest corner is on the table top.
  const Eigen::Matrix3d tilted = (Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()) *
                                  Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitY()))
                                     .toRotationMatrix();
  OrientedBox b = kapla(0.0, 0.0, 0.0);
  b.pose.linear() = tilted;
  b.pose.translation().z() = lowestCentreZ(kKaplaHalf, tilted);
  EXPECT_NEAR(bounds(b).min().z(), kTableTop, 1e-15);
}

TEST(BesideBricks, OnTheTableClearOfTheStructure) {
  // A two-layer 4-stack around the origin.
  const double offset = 0.5 * (kKaplaLength - kKaplaWidth);
  const double z0 = 0.5 * kKaplaThickness;
  const std::vector<OrientedBox> tower = {kapla(0.0, -offset, z0), kapla(0.0, offset, z0),
                                          kapla(-offset, 0.0, z0 + kKaplaThickness, M_PI / 2),
                                          kapla(offset, 0.0, z0 + kKaplaThickness, M_PI / 2)};
  const Eigen::Vector3d fallback(0.0, 0.0, 0.1);
  const Eigen::Vector3d start = besideBricks(tower, kKaplaHalf, fallback);
  // Resting on the table top, centred on the tower in y.
  EXPECT_NEAR(start.z(), kTableTop + 0.5 * kKaplaThickness, 1e-12);
  EXPECT_NEAR(start.y(), 0.0, 1e-12);
  // Its box clears the tower's footprint along x, on the +x side, by half its
  // length: the handles' rings (as wide as its length) do not reach over it.
  const OrientedBox ghost = kapla(start.x(), start.y(), start.z());
  double tower_max_x = -1.0;
  for (const OrientedBox& brick : tower)
    tower_max_x = std::max(tower_max_x, bounds(brick).max().x());
  EXPECT_NEAR(bounds(ghost).min().x() - tower_max_x, 0.5 * kKaplaLength, 1e-12);
  // A tower off the centre moves the start with it.
  std::vector<OrientedBox> moved = tower;
  for (OrientedBox& brick : moved) brick.pose.translation() += Eigen::Vector3d(0.1, -0.2, 0.0);
  EXPECT_TRUE(besideBricks(moved, kKaplaHalf, fallback)
                  .isApprox(start + Eigen::Vector3d(0.1, -0.2, 0.0), 1e-12));
  // No bricks, or none finite: the fallback.
  EXPECT_EQ(besideBricks({}, kKaplaHalf, fallback), fallback);
  OrientedBox broken = kapla(0.0, 0.0, z0);
  broken.pose.translation().x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(besideBricks({broken}, kKaplaHalf, fallback), fallback);
}

TEST(NearestIndex, PicksTheNearestCentre) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(nearestIndex(Eigen::Vector3d::Zero(), {}), -1);
  const std::vector<Eigen::Vector3d> centres = {
      {0.1, 0.0, 0.0}, {nan, 0.0, 0.0}, {0.0, 0.0, 0.05}, {-0.06, 0.0, 0.0}};
  EXPECT_EQ(nearestIndex(Eigen::Vector3d(0.0, 0.0, 0.0), centres), 2);
  EXPECT_EQ(nearestIndex(Eigen::Vector3d(-0.05, 0.0, 0.0), centres), 3);
  EXPECT_EQ(nearestIndex(Eigen::Vector3d(0.2, 0.0, 0.0), centres), 0);
}

}  // namespace
