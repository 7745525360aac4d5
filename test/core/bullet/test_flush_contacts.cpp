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
  double fastest_spin = 0.0;
  for (int i = 0; i < 1000; ++i) {
    scene.step(options.time_step);
    for (BodyHandle level = 0; level < 4; ++level)
      fastest_spin = std::max(fastest_spin, scene.angularSpeed(level));
  }
  // A tenth of the rest speed the stability layer asks for a whole window.
  EXPECT_LT(fastest_spin, 0.1 * StabilityOptions().rest_angular_speed);
}

}  // namespace
}  // namespace brick_stack_sim
