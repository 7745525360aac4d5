// Planks lying flat on planks, in Bullet alone: statics says each rests,
// so the engine must leave it at rest. Two planks crossing at an angle
// touch across an overlap with more corners than a manifold holds; the
// contact must keep the same points step after step (each with its warm
// start), or the plank is kicked whenever the engine swaps one.
#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "bullet/bullet_scene.h"
#include "support/kapla.h"

namespace brick_stack_sim {
namespace {

using test::kKaplaThickness;

WorldOptions stillWorld() {
  WorldOptions options;
  options.sleeping.enabled = false;  // what would hide a tremble
  return options;
}

/// The fastest any of the first `bricks` bodies turns over the next second [rad/s].
double fastestSpinOverASecond(const WorldOptions& options, BodyHandle bricks, BulletScene* scene) {
  double fastest = 0.0;
  for (int i = 0; i * options.time_step < 1.0; ++i) {
    scene->step(options.time_step);
    for (BodyHandle brick = 0; brick < bricks; ++brick)
      fastest = std::max(fastest, scene->angularSpeed(brick));
  }
  return fastest;
}

TEST(FlushContacts, AColumnOfPlanksCrossingAtAnglesStaysStill) {
  // Four planks of a dropped pile, each lying across the one below at 25 to
  // 125 degrees with its COM over it (the last within 0.6 mm of its
  // support's edge): they stand. With Bullet's clipper alone the manifolds
  // swapped a bearing corner every few steps and the column trembled at up
  // to 0.2 rad/s, never still for a rest window.
  const WorldOptions options = stillWorld();
  BulletScene scene(options);
  const BrickType kapla = *test::packageTypes().find("kapla");
  const struct {
    double x, y, yaw;
  } column[] = {{0.391217, 0.264563, -0.424293},
                {0.388548, 0.254561, 0.013401},
                {0.385025, 0.265573, 2.137943},
                {0.397175, 0.262374, 1.389164}};
  for (int level = 0; level < 4; ++level)
    scene.addBrick(
        level, kapla,
        test::placement("p" + std::to_string(level),
                        {column[level].x, column[level].y, (level + 0.5) * kKaplaThickness},
                        column[level].yaw));
  for (int i = 0; i < 2000; ++i) scene.step(options.time_step);
  // A tenth of the rest speed the stability layer asks for a whole window.
  EXPECT_LT(fastestSpinOverASecond(options, 4, &scene),
            0.1 * StabilityOptions().rest_angular_speed);
}

TEST(FlushContacts, APlankLoadedAnywhereOverItsOverlapWithAnotherStaysStill) {
  // A plank lies on another at 20 degrees, and a third lies on it 10 mm off
  // its axis. The two planks' overlap is a hexagon; their joint COM is 3.7
  // mm inside it, so statics holds them. It is also 3.7 mm outside the
  // quadrilateral of the hexagon's four corners that span the largest area:
  // with only those four in the contact, the pair tipped about the
  // quadrilateral's side and rocked in place for good.
  const WorldOptions options = stillWorld();
  BulletScene scene(options);
  const BrickType kapla = *test::packageTypes().find("kapla");
  const Eigen::Vector3d base(0.39, 0.26, 0.0);
  const double yaw = 20.0 * M_PI / 180.0;
  const Eigen::Vector3d upper = base + Eigen::Vector3d(-0.046, -0.005, 0.0);
  const Eigen::Vector3d top = upper + Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                                          Eigen::Vector3d(-0.015, 0.010, 0.0);
  scene.addBrick(
      0, kapla,
      test::placement("lower", base + 0.5 * kKaplaThickness * Eigen::Vector3d::UnitZ(), 0.0));
  scene.addBrick(
      1, kapla,
      test::placement("upper", upper + 1.5 * kKaplaThickness * Eigen::Vector3d::UnitZ(), yaw));
  scene.addBrick(
      2, kapla,
      test::placement("top", top + 2.5 * kKaplaThickness * Eigen::Vector3d::UnitZ(), yaw));
  for (int i = 0; i < 1000; ++i) scene.step(options.time_step);
  const Eigen::Vector3d settled_offset = scene.pose(1).translation() - scene.pose(0).translation();
  EXPECT_LT(fastestSpinOverASecond(options, 3, &scene),
            0.1 * StabilityOptions().rest_angular_speed);
  // Upright: the planks' faces stay parallel, as statics leaves them.
  const Eigen::Vector3d up = scene.pose(1).linear().col(2);
  EXPECT_GT(up.dot(scene.pose(0).linear().col(2)), std::cos(1e-3));
  // And where it lay on the lower one, to a twentieth of a millimetre.
  const Eigen::Vector3d offset = scene.pose(1).translation() - scene.pose(0).translation();
  EXPECT_LT((offset - settled_offset).norm(), 5e-5);
}

}  // namespace
}  // namespace brick_stack_sim
