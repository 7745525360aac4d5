#include <gtest/gtest.h>

#include "brick_stack_sim/core/geometry/box_contact.h"
#include "support/leaning.h"

namespace brick_stack_sim {
namespace {

OrientedBox kapla(const Eigen::Isometry3d& pose) { return OrientedBox{pose, test::kaplaHalfExtents()}; }

TEST(BoxContact, FlatBrickOnTheTableTouchesWithItsWholeFace) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation().z() = 0.5 * test::kKaplaThickness;
  const std::vector<BoxContactFace> faces = touchingContacts(kapla(pose), test::tableBox(), 1e-7);
  ASSERT_EQ(faces.size(), 1u);
  EXPECT_TRUE(faces[0].normal.isApprox(Eigen::Vector3d::UnitZ()));
  ASSERT_EQ(faces[0].points.size(), 4u);
  for (const Eigen::Vector3d& p : faces[0].points) {
    EXPECT_NEAR(p.z(), 0.0, 1e-12);
    EXPECT_NEAR(std::abs(p.x()), 0.5 * test::kKaplaLength, 1e-12);
  }
}

TEST(BoxContact, LeaningPlankTouchesTheTableAlongOneEdge) {
  const Eigen::Isometry3d pose = test::plankLeaningTowardsX(0.4, 0.0);
  const std::vector<BoxContactFace> faces = touchingContacts(kapla(pose), test::tableBox(), 1e-7);
  ASSERT_EQ(faces.size(), 1u);
  ASSERT_EQ(faces[0].points.size(), 2u);
  // The lower inner edge, under the plank's upper inner edge (x = 0) by L sin.
  for (const Eigen::Vector3d& p : faces[0].points) {
    EXPECT_NEAR(p.x(), -test::kKaplaLength * std::sin(0.4), 1e-12);
    EXPECT_NEAR(std::abs(p.y()), 0.5 * test::kKaplaWidth, 1e-12);
  }
}

TEST(BoxContact, PlanksOfAVMeetAtTheApexAcrossBothFaces) {
  for (double theta : {0.3, 0.7, 0.9}) {
    const auto [left, right] = test::vPlanks(theta);
    const std::vector<BoxContactFace> faces = touchingContacts(kapla(left), kapla(right), 1e-7);
    ASSERT_EQ(faces.size(), 2u) << theta;
    for (const BoxContactFace& face : faces) {
      // From the right plank towards the left one, mirror images of each other.
      EXPECT_LT(face.normal.x(), 0.0);
      ASSERT_EQ(face.points.size(), 2u);
      for (const Eigen::Vector3d& p : face.points) {
        // At the apex, within the ten gaps where clipping merges points.
        EXPECT_NEAR(p.x(), 0.0, 1e-6);
        EXPECT_NEAR(p.z(), test::kKaplaLength * std::cos(theta), 1e-6);
      }
    }
    EXPECT_NEAR(faces[0].normal.z(), -faces[1].normal.z(), 1e-12);
  }
}

TEST(BoxContact, BoxesApartOrSunkInDoNotTouch) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation().z() = 0.5 * test::kKaplaThickness + 1e-4;
  EXPECT_TRUE(touchingContacts(kapla(pose), test::tableBox(), 1e-7).empty());
  pose.translation().z() = 0.5 * test::kKaplaThickness - 1e-4;
  EXPECT_TRUE(touchingContacts(kapla(pose), test::tableBox(), 1e-7).empty());
}

}  // namespace
}  // namespace brick_stack_sim
