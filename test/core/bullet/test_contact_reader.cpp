// The contact reader against statics: a brick resting on the table is held
// up by normal impulses that add up to its weight times the step, along a
// vertical normal, at a depth within the collision tolerance, with the
// geometric mean of the two friction coefficients.
#include <cmath>
#include <numeric>

#include <gtest/gtest.h>

#include "bullet/bullet_scene.h"
#include "bullet/contact_reader.h"
#include "support/kapla.h"

namespace brick_stack_sim {
namespace {

TEST(ContactReader, ARestingBrickCarriesItsWeightThroughTheTable) {
  WorldOptions options;
  options.table.friction = 0.8;
  BulletScene scene(options);
  const BrickType kapla = *test::packageTypes().find("kapla");
  scene.addBrick(0, kapla, test::placement("b0", {0.05, -0.02, test::kKaplaThickness / 2}));
  for (int i = 0; i < 1000; ++i) scene.step(options.time_step);
  std::vector<PairContact> contacts;
  readContacts(scene, options.stability.contact_distance, &contacts);
  ASSERT_EQ(contacts.size(), 1u);
  const PairContact& pair = contacts[0];
  const BodyHandle other = pair.a == 0 ? pair.b : pair.a;
  EXPECT_EQ(other, kTableHandle);
  // The normal points from b to a: up when the brick is a.
  const double up = pair.a == 0 ? 1.0 : -1.0;
  EXPECT_NEAR(pair.normal.z(), up, 1e-9);
  ASSERT_EQ(pair.manifold.size(), 4u);  // the box-box clipper: the face's corners
  ASSERT_EQ(pair.points.size(), pair.manifold.size());
  double impulse = 0.0;
  for (const ContactPoint& point : pair.manifold) {
    EXPECT_NEAR(point.normal.z(), up, 1e-9);
    EXPECT_LT(std::abs(point.depth), 1e-4);
    EXPECT_NEAR(point.position.z(), 0.0, 1e-4);
    impulse += point.impulse;
  }
  // Statics: the table pushes up with the brick's weight, m g, for one step.
  EXPECT_NEAR(impulse, kapla.mass * options.gravity * options.time_step,
              1e-4 * kapla.mass * options.gravity * options.time_step);
  EXPECT_NEAR(pair.friction, std::sqrt(kapla.friction * 0.8), 1e-12);
  EXPECT_LT(pair.approach_speed, 1e-3);
}

TEST(ContactReader, PlanksOverlappingInAHexagonAreOnePairWithSixPointsCarryingTheWeight) {
  // A plank on another at 20 degrees, its centre 46 mm along and 5 mm
  // across from the other's: their faces overlap in a hexagon, whose six
  // corners fill more than one manifold. It is still one pair, with every
  // corner, and statics: its points carry the upper plank's weight.
  WorldOptions options;
  BulletScene scene(options);
  const BrickType kapla = *test::packageTypes().find("kapla");
  const double t = test::kKaplaThickness;
  scene.addBrick(0, kapla, test::placement("lower", {0.39, 0.26, 0.5 * t}));
  scene.addBrick(1, kapla, test::placement("upper", {0.344, 0.255, 1.5 * t}, 20.0 * M_PI / 180.0));
  for (int i = 0; i < 500; ++i) scene.step(options.time_step);
  std::vector<PairContact> contacts;
  readContacts(scene, options.stability.contact_distance, &contacts);
  int planks = 0;
  for (const PairContact& pair : contacts) {
    if (pair.a == kTableHandle || pair.b == kTableHandle) continue;
    ++planks;
    ASSERT_EQ(pair.points.size(), 6u);
    double impulse = 0.0;
    for (const ContactPoint& point : pair.manifold) impulse += point.impulse;
    EXPECT_NEAR(impulse, kapla.mass * options.gravity * options.time_step,
                1e-3 * kapla.mass * options.gravity * options.time_step);
  }
  EXPECT_EQ(planks, 1);
}

TEST(ContactReader, ASlidingBrickIsHeldBackByKineticFrictionMuMg) {
  // Coulomb: a brick sliding on the table feels mu m g against its motion,
  // and the table still carries its weight.
  WorldOptions options;
  options.table.friction = 0.5;
  BulletScene scene(options);
  BrickType kapla = *test::packageTypes().find("kapla");
  kapla.friction = 0.5;
  BrickPlacement sliding = test::placement("b0", {0.0, 0.0, test::kKaplaThickness / 2});
  sliding.linear_velocity = Eigen::Vector3d(1.0, 0.0, 0.0);
  scene.addBrick(0, kapla, sliding);
  for (int i = 0; i < 20; ++i) scene.step(options.time_step);
  ASSERT_GT(scene.linearVelocity(0).x(), 0.5);  // still sliding
  std::vector<PairContact> contacts;
  readContacts(scene, options.stability.contact_distance, &contacts);
  ASSERT_EQ(contacts.size(), 1u);
  const PairContact& pair = contacts[0];
  const double on_brick = pair.a == 0 ? 1.0 : -1.0;  // impulses are on a
  Eigen::Vector3d impulse = Eigen::Vector3d::Zero();
  for (const ContactPoint& point : pair.manifold)
    impulse += on_brick * (point.impulse * point.normal + point.friction_impulse);
  const double weight_step = kapla.mass * options.gravity * options.time_step;
  EXPECT_NEAR(impulse.z(), weight_step, 0.02 * weight_step);
  EXPECT_NEAR(impulse.x(), -0.5 * weight_step, 0.02 * weight_step);
  EXPECT_NEAR(impulse.y(), 0.0, 0.01 * weight_step);
}

TEST(ContactReader, BodiesApartAreNoContact) {
  WorldOptions options;
  BulletScene scene(options);
  const BrickType kapla = *test::packageTypes().find("kapla");
  scene.addBrick(0, kapla, test::placement("b0", {0, 0, 0.1}));
  scene.step(options.time_step);
  std::vector<PairContact> contacts(3);
  readContacts(scene, options.stability.contact_distance, &contacts);
  EXPECT_TRUE(contacts.empty());
}

}  // namespace
}  // namespace brick_stack_sim
