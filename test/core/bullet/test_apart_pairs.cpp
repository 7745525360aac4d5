// The narrowphase passes over a pair whose boxes are still too far apart to
// touch, until the two bodies could have closed the gap. Whatever moves them
// (a step, a teleport, a kinematic brick carried), no contact may be lost:
// a heap that tumbles gives the same bits with and without passing over, and
// a plank put into contact with one that was being passed over touches it
// at once.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bullet/bullet_scene.h"
#include "bullet/contact_reader.h"
#include "support/kapla.h"

namespace brick_stack_sim {
namespace {

using test::kKaplaThickness;

WorldOptions options() {
  WorldOptions o;
  o.sleeping.enabled = false;
  return o;
}

using test::pose;

std::uint64_t passedOver(const BulletScene& scene) { return scene.apartPairsPassedOver(); }

/// Planks in three loose layers over the table, each turned and tilted its
/// own way, dropped: they land on each other and tumble.
void addHeap(BulletScene* scene, const BrickType& kapla, int count) {
  for (int i = 0; i < count; ++i) {
    const double x = 0.05 * (i % 4) - 0.075, y = 0.03 * ((i / 4) % 4) - 0.045;
    const double z = 0.03 + 0.025 * (i / 16);
    const Eigen::Matrix3d turn =
        (Eigen::AngleAxisd(0.9 * i, Eigen::Vector3d::UnitZ()) *
         Eigen::AngleAxisd(0.25 * std::sin(1.7 * i), Eigen::Vector3d::UnitX()))
            .toRotationMatrix();
    Eigen::Isometry3d at = Eigen::Isometry3d::Identity();
    at.translation() = Eigen::Vector3d(x, y, z);
    at.linear() = turn;
    scene->addBrick(static_cast<BodyHandle>(i), kapla,
                    test::placement("b" + std::to_string(i), at));
  }
}

TEST(ApartPairs, PassingOverChangesNoBitOfATumblingHeap) {
  const BrickType kapla = *test::packageTypes().find("kapla");
  constexpr int kPlanks = 48;
  BulletScene passing(options()), testing_all(options());
  testing_all.passOverApartPairs(false);
  addHeap(&passing, kapla, kPlanks);
  addHeap(&testing_all, kapla, kPlanks);
  for (int step = 1; step <= 1200; ++step) {
    passing.step(options().time_step);
    testing_all.step(options().time_step);
    if (step % 100 != 0) continue;
    for (int i = 0; i < kPlanks; ++i) {
      const BodyHandle handle = static_cast<BodyHandle>(i);
      ASSERT_EQ(passing.pose(handle).matrix(), testing_all.pose(handle).matrix())
          << "plank " << i << " at step " << step;
    }
  }
  // The heap did tumble, and pairs were passed over while it did.
  double lowest = 1.0;
  for (int i = 0; i < kPlanks; ++i)
    lowest = std::min(lowest, passing.pose(static_cast<BodyHandle>(i)).translation().z());
  EXPECT_LT(lowest, 0.01);
  EXPECT_GT(passedOver(passing), 10000u);
  EXPECT_EQ(passedOver(testing_all), 0u);
}

/// A kinematic plank and a dynamic one held where it is put, well above the
/// table, apart: a pair that is passed over.
class HeldApart : public ::testing::Test {
 protected:
  static constexpr BodyHandle kLower = 0, kUpper = 1;
  void SetUp() override {
    scene_.addBrick(kLower, kapla_, test::placement("lower", lower_));
    scene_.makeKinematic(kLower);
    scene_.addBrick(kUpper, kapla_, test::placement("upper", apart()));
    for (int i = 0; i < 5; ++i) hold(apart());
    ASSERT_GT(passedOver(scene_), 0u);
  }
  /// Puts the upper plank at `at`, at rest, and steps: the contact points
  /// of the pair.
  std::vector<ContactPoint> hold(const Eigen::Isometry3d& at) {
    scene_.restoreAtRest(kUpper, at);
    scene_.step(options().time_step);
    std::vector<PairContact> pairs;
    readContacts(scene_, options().stability.contact_distance, &pairs);
    std::vector<ContactPoint> points;
    for (const PairContact& pair : pairs)
      if ((pair.a == kLower && pair.b == kUpper) || (pair.a == kUpper && pair.b == kLower))
        points.insert(points.end(), pair.manifold.begin(), pair.manifold.end());
    return points;
  }
  /// Lying across the lower plank, `gap` [m] above it (negative: into it).
  Eigen::Isometry3d across(double gap) const {
    return lower_ * pose({0.01, 0.0, kKaplaThickness + gap},
                         Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()));
  }
  /// Leaning at 45 degrees beyond the lower plank's end, its foot 20 mm past
  /// it and 3 mm above its top, some 12 mm from it: the broadphase boxes of
  /// the two overlap, the planks do not.
  Eigen::Isometry3d apart() const {
    const double reach = 0.5 * test::kKaplaLength * std::sqrt(0.5);
    return lower_ *
           pose({0.5 * test::kKaplaLength + 0.02 - reach, 0, 0.5 * kKaplaThickness + 0.003 + reach},
                Eigen::AngleAxisd(0.25 * M_PI, Eigen::Vector3d::UnitY()));
  }

  const BrickType kapla_ = *test::packageTypes().find("kapla");
  const Eigen::Isometry3d lower_ = pose({0, 0, 0.3}, Eigen::AngleAxisd::Identity());
  BulletScene scene_{options()};
};

TEST_F(HeldApart, APlankPutOntoTheOtherTouchesItAtOnce) {
  const std::uint64_t before = passedOver(scene_);
  const std::vector<ContactPoint> points = hold(across(-2e-5));
  EXPECT_EQ(passedOver(scene_), before);  // the pair was tested
  ASSERT_EQ(points.size(), 4u);           // the corners of the crossing
  for (const ContactPoint& point : points) EXPECT_NEAR(point.depth, -2e-5, 1e-9);
}

TEST_F(HeldApart, APlankCarriedOntoTheOtherTouchesItAtOnce) {
  // The kinematic plank is carried to lie under the held one.
  scene_.moveKinematic(kLower, apart() * (lower_.inverse() * across(-2e-5)).inverse());
  const std::vector<ContactPoint> points = hold(apart());
  ASSERT_EQ(points.size(), 4u);
  for (const ContactPoint& point : points) EXPECT_NEAR(point.depth, -2e-5, 1e-9);
}

TEST_F(HeldApart, APlankTurnedOntoTheOtherTouchesItAtOnce) {
  // Turned steeper about its centre, which does not move, its foot swings
  // in over the lower plank's end and into it: only the turn closed the gap.
  const Eigen::Isometry3d turned =
      apart() * pose({0, 0, 0}, Eigen::AngleAxisd(0.45, Eigen::Vector3d::UnitY()));
  const std::vector<ContactPoint> points = hold(turned);
  ASSERT_FALSE(points.empty());
  for (const ContactPoint& point : points) EXPECT_LT(point.depth, -5e-4);
}

}  // namespace
}  // namespace brick_stack_sim
