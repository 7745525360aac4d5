// Which contacts carry a brick, and how long it has been at rest: the parts
// of the stability layer that come before any criterion.
#include <cmath>

#include <gtest/gtest.h>

#include "stability/contact_classifier.h"
#include "stability/rest_tracker.h"
#include "stability/support_graph.h"
#include "support/kapla.h"

namespace brick_stack_sim {
namespace {

PairContact contact(BodyHandle a, BodyHandle b, const Eigen::Vector3d& normal, double z = 0.0) {
  PairContact c;
  c.a = a;
  c.b = b;
  c.normal = normal.normalized();
  c.points = {{-0.05, -0.01, z}, {0.05, -0.01, z}, {0.05, 0.01, z}, {-0.05, 0.01, z}};
  return c;
}

BodyMotion body(BodyHandle handle) {
  return BodyMotion{handle, Eigen::Vector3d(0, 0, 0.004), 0.0119, Eigen::Vector3d::Zero(),
                    Eigen::Vector3d::Zero()};
}

std::vector<SupportPatch> patchesOf(BodyHandle handle, const std::vector<PairContact>& contacts,
                                    const SupportGraph& graph) {
  const ContactIndex index(&contacts);
  return supportPatches(body(handle), index.of(handle), frozenOrGround(graph), StabilityOptions());
}

TEST(ContactClassifier, TheLowerBodyOfAnUpwardContactSupports) {
  SupportGraph graph;
  graph.add(1, Eigen::Vector3d::Zero(), 0.0119, {});
  // The normal points from b to a: a rests on b, whichever way round Bullet names them.
  const std::vector<PairContact> contacts = {contact(0, kTableHandle, Eigen::Vector3d::UnitZ()),
                                             contact(1, 0, -Eigen::Vector3d::UnitZ(), 0.0078)};
  const auto patches = patchesOf(0, contacts, graph);
  ASSERT_EQ(patches.size(), 2u);
  EXPECT_EQ(patches[0].supporter, 1u);  // in supporter order
  EXPECT_EQ(patches[1].supporter, kTableHandle);
  EXPECT_EQ(patches[1].points.size(), 4u);
  // For b1 the same contact has it underneath: nothing supports b1 there.
  EXPECT_TRUE(patchesOf(1, contacts, graph).empty());
}

TEST(ContactClassifier, SideContactsImpactsAndMovingSupportersCarryNothing) {
  SupportGraph graph;  // b1 is not frozen
  StabilityOptions options;
  const Eigen::Vector3d steep(std::sin(options.support_normal_tolerance + 0.05), 0.0,
                              std::cos(options.support_normal_tolerance + 0.05));
  PairContact impact = contact(0, kTableHandle, Eigen::Vector3d::UnitZ());
  impact.approach_speed = options.impact_speed * 2;
  EXPECT_TRUE(patchesOf(0, {contact(0, kTableHandle, steep)}, graph).empty());
  EXPECT_TRUE(patchesOf(0, {contact(0, kTableHandle, Eigen::Vector3d::UnitX())}, graph).empty());
  EXPECT_TRUE(patchesOf(0, {impact}, graph).empty());
  EXPECT_TRUE(patchesOf(0, {contact(0, 1, Eigen::Vector3d::UnitZ())}, graph).empty());
  // Just inside the tolerance still supports.
  const Eigen::Vector3d tilted(std::sin(options.support_normal_tolerance - 0.05), 0.0,
                               std::cos(options.support_normal_tolerance - 0.05));
  EXPECT_EQ(patchesOf(0, {contact(0, kTableHandle, tilted)}, graph).size(), 1u);
}

TEST(ContactClassifier, ContactsOnOneSupporterMakeOnePatch) {
  SupportGraph graph;
  PairContact second = contact(0, kTableHandle, Eigen::Vector3d::UnitZ());
  for (Eigen::Vector3d& point : second.points) point.x() += 0.2;
  const auto patches =
      patchesOf(0, {contact(0, kTableHandle, Eigen::Vector3d::UnitZ()), second}, graph);
  ASSERT_EQ(patches.size(), 1u);
  EXPECT_EQ(patches[0].points.size(), 8u);
}

TEST(ContactClassifier, FlushFacesGetTheirWholeOverlap) {
  // A KAPLA crosswise on another, tilted by a micro-radian: Bullet's clipper
  // would report only the penetrating half; the patch is the whole square.
  const OrientedBox lower{
      Eigen::Isometry3d::Identity(),
      Eigen::Vector3d(test::kKaplaLength, test::kKaplaWidth, test::kKaplaThickness) / 2};
  OrientedBox upper = lower;
  upper.pose.linear() = (Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()) *
                         Eigen::AngleAxisd(1e-6, Eigen::Vector3d::UnitX()))
                            .toRotationMatrix();
  upper.pose.translation().z() = test::kKaplaThickness;
  const ConvexSolid plank = boxSolid(lower.half_extents);
  const auto solid_of = [&](BodyHandle h) {
    return PlacedSolid{h == 0 ? lower.pose : upper.pose, &plank};
  };
  PairContact half = contact(1, 0, Eigen::Vector3d::UnitZ(), test::kKaplaThickness / 2);
  half.points.resize(2);
  std::vector<PairContact> contacts = {half};
  refineFlushPatches(solid_of, StabilityOptions(), &contacts);
  ASSERT_EQ(contacts[0].points.size(), 4u);
  Polygon2d square;
  for (const Eigen::Vector3d& p : contacts[0].points) square.push_back(p.head<2>());
  EXPECT_NEAR(area(convexHull(square)), test::kKaplaWidth * test::kKaplaWidth, 1e-9);
  // A side contact is left as Bullet reported it.
  std::vector<PairContact> side = {contact(1, 0, Eigen::Vector3d::UnitX())};
  refineFlushPatches(solid_of, StabilityOptions(), &side);
  EXPECT_EQ(side[0].points.size(), 4u);
  EXPECT_EQ(side[0].points[0], contact(1, 0, Eigen::Vector3d::UnitX()).points[0]);
  // A pair the caller does not want judged keeps Bullet's two points.
  std::vector<PairContact> unwanted = {half};
  refineFlushPatches(solid_of, StabilityOptions(), &unwanted,
                     [](const PairContact& pair) { return pair.a == 7 || pair.b == 7; });
  ASSERT_EQ(unwanted[0].points.size(), 2u);
  EXPECT_EQ(unwanted[0].points[1], half.points[1]);
}

TEST(ContactIndex, SkipsContactsWithoutPoints) {
  PairContact empty = contact(0, kTableHandle, Eigen::Vector3d::UnitZ());
  empty.points.clear();
  const std::vector<PairContact> contacts = {empty, contact(0, 1, Eigen::Vector3d::UnitZ())};
  const ContactIndex index(&contacts);
  ASSERT_EQ(index.of(0).size(), 1u);
  EXPECT_EQ(index.of(0)[0]->b, 1u);
  EXPECT_EQ(index.of(1).size(), 1u);
  EXPECT_TRUE(index.of(7).empty());
  EXPECT_TRUE(ContactIndex(nullptr).of(0).empty());
}

TEST(ContactIndex, KeepsEachBodysContactsInTheStepsOrder) {
  // Body 5 is a in some pairs and b in others, among pairs of other bodies:
  // its patches are built in this order, so the order is part of the bits.
  const std::vector<PairContact> contacts = {
      contact(5, 9, Eigen::Vector3d::UnitZ()), contact(2, 3, Eigen::Vector3d::UnitZ()),
      contact(4, 5, Eigen::Vector3d::UnitZ()), contact(5, kTableHandle, Eigen::Vector3d::UnitZ()),
      contact(1, 5, Eigen::Vector3d::UnitZ())};
  const ContactIndex index(&contacts);
  const ContactSpan of_five = index.of(5);
  ASSERT_EQ(of_five.size(), 4u);
  EXPECT_EQ(of_five[0], &contacts[0]);
  EXPECT_EQ(of_five[1], &contacts[2]);
  EXPECT_EQ(of_five[2], &contacts[3]);
  EXPECT_EQ(of_five[3], &contacts[4]);
  ASSERT_EQ(index.of(kTableHandle).size(), 1u);
  EXPECT_EQ(index.of(kTableHandle)[0], &contacts[3]);
  EXPECT_TRUE(index.of(6).empty());
}

TEST(RestTracker, RestTimeGrowsWhileAtRestAndStartsOverWhenNot) {
  StabilityOptions options;
  RestTracker tracker(options);
  BodyMotion still = body(3);
  BodyMotion moving = still;
  moving.linear_velocity.x() = 2 * options.rest_linear_speed;
  BodyMotion turning = still;
  turning.angular_velocity.z() = 2 * options.rest_angular_speed;
  EXPECT_DOUBLE_EQ(tracker.advance(still, 0.01).rest_time, 0.01);
  EXPECT_DOUBLE_EQ(tracker.advance(still, 0.01).rest_time, 0.02);
  EXPECT_DOUBLE_EQ(tracker.advance(moving, 0.01).rest_time, 0.0);
  EXPECT_DOUBLE_EQ(tracker.advance(still, 0.01).rest_time, 0.01);
  EXPECT_DOUBLE_EQ(tracker.advance(turning, 0.01).rest_time, 0.0);
  EXPECT_TRUE(tracker.atRest(still));
  EXPECT_FALSE(tracker.atRest(moving));
  tracker.erase(3);
  EXPECT_EQ(tracker.find(3), nullptr);
}

TEST(RestTracker, ABrickPushedOutOfAnOverlapWithoutVelocityIsNotAtRest) {
  // Bullet's split impulse moves a brick out of a deep overlap by its
  // position alone: its velocity stays below the rest speeds while its
  // centre rises, here at three times the rest speed. It is still moving.
  StabilityOptions options;
  RestTracker tracker(options);
  const double dt = 0.001;
  BodyMotion rising = body(4);
  EXPECT_DOUBLE_EQ(tracker.advance(rising, dt).rest_time, dt);  // nothing to compare yet
  for (int step = 0; step < 30; ++step) {
    rising.com.z() += 3 * options.rest_linear_speed * dt;
    EXPECT_DOUBLE_EQ(tracker.advance(rising, dt).rest_time, 0.0);
  }
  EXPECT_TRUE(tracker.atRest(rising));  // by its velocity alone
  // Once it stops rising it rests again; between steps (no time) it keeps
  // what it had.
  EXPECT_DOUBLE_EQ(tracker.advance(rising, dt).rest_time, dt);
  EXPECT_DOUBLE_EQ(tracker.advance(rising, 0.0).rest_time, dt);
  // Creeping slower than the rest speed is rest.
  rising.com.x() += 0.5 * options.rest_linear_speed * dt;
  EXPECT_DOUBLE_EQ(tracker.advance(rising, dt).rest_time, 2 * dt);
}

}  // namespace
}  // namespace brick_stack_sim
