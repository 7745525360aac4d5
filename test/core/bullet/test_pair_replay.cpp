// A pair of boxes that has barely moved relative to each other keeps its
// manifold from the step before, its points carried along with the two
// bodies, instead of being detected again. The replayed contact must be the
// one a detection would give at the new poses, wherever the pair has gone
// as a whole, and a pair that did move must be detected again: its contact
// then follows the motion, and a brick on a tilting plank slides where
// Coulomb says it does.
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bullet/bullet_scene.h"
#include "bullet/contact_reader.h"
#include "support/kapla.h"

namespace brick_stack_sim {
namespace {

using test::kKaplaThickness;
using test::kKaplaWidth;
using test::pose;

constexpr BodyHandle kLower = 0, kUpper = 1;

/// Two planks well above the table: the lower one kinematic (moved from
/// outside), the upper one dynamic, each at the pose given.
class PlankPair {
 public:
  PlankPair(const Eigen::Isometry3d& upper, const Eigen::Isometry3d& lower) : scene_(options()) {
    scene_.addBrick(kLower, kapla_, test::placement("lower", lower));
    scene_.makeKinematic(kLower);
    scene_.addBrick(kUpper, kapla_, test::placement("upper", upper));
  }

  /// Puts both planks at these poses and steps once: the contact read is
  /// the one Bullet's narrowphase gave at these poses.
  std::vector<ContactPoint> contactAt(const Eigen::Isometry3d& upper,
                                      const Eigen::Isometry3d& lower) {
    scene_.moveKinematic(kLower, lower);
    scene_.restoreAtRest(kUpper, upper);
    return step();
  }

  /// One step; the points of the pair's contact, its normal from the lower
  /// plank up.
  std::vector<ContactPoint> step() {
    scene_.step(options().time_step);
    std::vector<PairContact> pairs;
    readContacts(scene_, options().stability.contact_distance, &pairs);
    std::vector<ContactPoint> points;
    for (const PairContact& pair : pairs)
      for (ContactPoint point : pair.manifold) {
        if (pair.a == kLower) point.normal = -point.normal;
        points.push_back(point);
      }
    return points;
  }

  BulletScene& scene() { return scene_; }

 private:
  static WorldOptions options() {
    WorldOptions o;
    o.sleeping.enabled = false;
    return o;
  }

  const BrickType kapla_ = *test::packageTypes().find("kapla");
  BulletScene scene_;
};

/// Every point of `expected` has a point in `actual` at the same place, with
/// the same normal and depth, and no point is left over.
void expectSameContact(const std::vector<ContactPoint>& expected,
                       const std::vector<ContactPoint>& actual) {
  // Both lists, shown only when a check below fails.
  std::ostringstream listing;
  for (auto& p : expected)
    listing << "want " << p.position.transpose() << " n " << p.normal.transpose() << " d "
            << p.depth << "\n";
  for (auto& p : actual)
    listing << "have " << p.position.transpose() << " n " << p.normal.transpose() << " d "
            << p.depth << "\n";
  SCOPED_TRACE(listing.str());
  ASSERT_EQ(expected.size(), actual.size());
  ASSERT_FALSE(expected.empty());
  for (const ContactPoint& want : expected) {
    const ContactPoint* match = &actual.front();
    for (const ContactPoint& have : actual)
      if ((have.position - want.position).norm() < (match->position - want.position).norm())
        match = &have;
    EXPECT_LT((match->position - want.position).norm(), 1e-9);
    EXPECT_LT((match->normal - want.normal).norm(), 1e-9);
    EXPECT_NEAR(match->depth, want.depth, 1e-9);
  }
}

/// An upper plank 0.02 mm into the one below it, lying across it flat at
/// 40 degrees (the flush corners), or tilted onto its long edge (Bullet's
/// clipper).
struct Resting {
  const char* name;
  Eigen::Isometry3d upper, lower;
};

std::vector<Resting> restingPairs() {
  // Well above the table.
  const Eigen::Isometry3d lower = pose({0, 0, 0.1}, Eigen::AngleAxisd::Identity());
  const double depth = 2e-5;
  const Eigen::Isometry3d flat = lower * pose({0.01, 0.005, kKaplaThickness - depth},
                                              Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()));
  // Tilted by 0.1 rad about its length, its lower long edge into the face.
  const double tilt = 0.1;
  const double rise = 0.5 * kKaplaWidth * std::sin(tilt) + 0.5 * kKaplaThickness * std::cos(tilt);
  const Eigen::Isometry3d edge = lower * pose({0.0, 0.0, 0.5 * kKaplaThickness + rise - depth},
                                              Eigen::AngleAxisd(tilt, Eigen::Vector3d::UnitX()));
  return {{"flat across", flat, lower}, {"on its edge", edge, lower}};
}

TEST(PairReplay, APairMovedAsAWholeKeepsTheContactADetectionGives) {
  // Both planks carried 0.3 m and turned 0.8 rad together, with the upper
  // one 3 um further in: far less than the replay's drift, so the manifold
  // is replayed, and it must be what a detection at the new poses gives.
  // They turn about the vertical: the flush corners are found seen from
  // above, which moves them by a fraction of the gap when the pair tilts as
  // a whole (the tilting plank below turns the normal).
  const Eigen::Isometry3d carried =
      pose({0.3, -0.2, 0.1}, Eigen::AngleAxisd(0.8, Eigen::Vector3d::UnitZ()));
  for (const Resting& pair : restingPairs()) {
    SCOPED_TRACE(pair.name);
    PlankPair replayed(pair.upper, pair.lower);
    ASSERT_FALSE(replayed.step().empty());
    // 3 um down along the lower plank's normal, in its frame.
    const Eigen::Isometry3d sunk = pair.lower * pose({0, 0, -3e-6}, Eigen::AngleAxisd::Identity()) *
                                   pair.lower.inverse() * pair.upper;
    const std::vector<ContactPoint> replay =
        replayed.contactAt(carried * sunk, carried * pair.lower);
    PlankPair fresh(carried * sunk, carried * pair.lower);
    expectSameContact(fresh.step(), replay);
  }
}

TEST(PairReplay, APairThatMovedIsDetectedAgain) {
  // The upper plank slid 2 mm along the lower one and turned 0.01 rad about
  // the vertical: the corners of the overlap move on the lower plank, where
  // points carried with the upper one would not be.
  for (const Resting& pair : restingPairs()) {
    SCOPED_TRACE(pair.name);
    PlankPair moved(pair.upper, pair.lower);
    ASSERT_FALSE(moved.step().empty());
    const Eigen::Isometry3d slid =
        pair.lower * pose({0.002, 0, 0}, Eigen::AngleAxisd(0.01, Eigen::Vector3d::UnitZ())) *
        pair.lower.inverse() * pair.upper;
    const std::vector<ContactPoint> detected = moved.contactAt(slid, pair.lower);
    PlankPair fresh(slid, pair.lower);
    expectSameContact(fresh.step(), detected);
  }
}

TEST(PairReplay, APlankOnATiltingPlankSlidesAtTheAngleOfFriction) {
  // A plank lies on another that tilts slowly about its length. While it
  // sticks the pair does not move relative to itself and its manifold is
  // replayed, so its normal must turn with the tilt: it slides once the
  // slope's tangent passes mu (Coulomb), not before and not never.
  WorldOptions options;
  options.sleeping.enabled = false;
  BulletScene scene(options);
  const BrickType kapla = *test::packageTypes().find("kapla");
  const Eigen::Vector3d centre(0.0, 0.0, 0.1);  // well above the table
  scene.addBrick(0, kapla, test::placement("support", centre));
  scene.makeKinematic(0);
  scene.addBrick(1, kapla,
                 test::placement("rider", centre + Eigen::Vector3d(0, 0, kKaplaThickness)));
  const double rate = 0.1;  // [rad/s]
  const double slip_angle = std::atan(kapla.friction);
  double slid_at = std::numeric_limits<double>::quiet_NaN();
  for (int i = 1; i <= 6000 && std::isnan(slid_at); ++i) {
    const double angle = rate * i * options.time_step;
    const Eigen::Isometry3d support =
        pose(centre, Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitX()));
    scene.moveKinematic(0, support);
    scene.step(options.time_step);
    const Eigen::Vector3d on_support = support.inverse() * scene.pose(1).translation();
    if (std::abs(on_support.y()) > 1e-4) slid_at = angle;
  }
  ASSERT_FALSE(std::isnan(slid_at)) << "the rider never slid";
  // From rest, the rider takes about 0.008 rad more of tilt to slide its
  // first 0.1 mm (g (sin - mu cos) grows from zero); it may not go earlier.
  EXPECT_GT(slid_at, slip_angle - 0.005) << "slid at " << slid_at << " rad";
  EXPECT_LT(slid_at, slip_angle + 0.015) << "slid at " << slid_at << " rad";
}

}  // namespace
}  // namespace brick_stack_sim
