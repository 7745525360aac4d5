// Friction across a contact against Coulomb's law, with Bullet's own
// friction (one direction, along the slip), with the friction cone (two
// directions held to the cone together), and with the cone's friction
// carried over from step to step (full_warm_start). A plank sliding on the table at
// any angle to its axes stops after v^2 / (2 mu g), along the way it was
// sent: friction clamped one direction at a time, a square of half-width
// mu N, would stop it at 45 degrees after 1 / sqrt(2) of that, and bend
// its path where the two directions clamp apart.

#include <cmath>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/world/brick_world.h"
#include "support/kapla.h"

namespace brick_stack_sim {
namespace {

using test::kKaplaThickness;
using test::placement;
using test::runFor;

enum class Friction { kAlongTheSlip, kCone, kConeCarriedOver };

WorldOptions optionsWith(Friction friction) {
  WorldOptions options = test::plainBulletOptions();
  options.friction_cone = friction != Friction::kAlongTheSlip;
  options.full_warm_start = friction == Friction::kConeCarriedOver;
  return options;
}

class FrictionModel : public ::testing::TestWithParam<Friction> {};

TEST_P(FrictionModel, APlankSlidingAtAnyAngleStopsWhereCoulombSays) {
  const WorldOptions options = optionsWith(GetParam());
  const double mu = 0.5, speed = 1.0;  // pine on the pine table
  const double stopping_distance = speed * speed / (2.0 * mu * options.gravity);
  for (double angle_deg : {0.0, 30.0, 45.0, 80.0}) {
    SCOPED_TRACE(std::to_string(angle_deg) + " degrees from the plank's long axis");
    auto world = test::makeWorld(options);
    const double yaw = 0.3;  // neither axis along the world's
    BrickPlacement plank = placement("p", {0.0, 0.0, 0.5 * kKaplaThickness}, yaw);
    const double heading = yaw + angle_deg * M_PI / 180.0;
    plank.linear_velocity = speed * Eigen::Vector3d(std::cos(heading), std::sin(heading), 0.0);
    ASSERT_TRUE(world->addBrick(plank).ok);
    runFor(world.get(), 0.5);  // it stops after v / (mu g) = 0.2 s
    BrickSnapshot after;
    ASSERT_TRUE(world->find("p", &after));
    const Eigen::Vector2d moved = after.pose.translation().head<2>();
    EXPECT_NEAR(moved.norm() / stopping_distance, 1.0, 0.02);
    EXPECT_NEAR(std::atan2(moved.y(), moved.x()), heading, 0.01);  // [rad]
    EXPECT_LT(after.linear_velocity.norm(), 1e-3);
  }
}

INSTANTIATE_TEST_SUITE_P(BulletsAndTheCone, FrictionModel,
                         ::testing::Values(Friction::kAlongTheSlip, Friction::kCone,
                                           Friction::kConeCarriedOver),
                         [](const ::testing::TestParamInfo<Friction>& info) {
                           switch (info.param) {
                             case Friction::kAlongTheSlip:
                               return std::string("along_the_slip");
                             case Friction::kCone:
                               return std::string("cone");
                             case Friction::kConeCarriedOver:
                               break;
                           }
                           return std::string("cone_carried_over");
                         });

}  // namespace
}  // namespace brick_stack_sim
