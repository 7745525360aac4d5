// Brick types of every shape from a URDF: the mass, centre of mass and
// inertia each reports are derived by hand in the comments.
#include <cmath>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/types/brick_type.h"
#include "support/kapla.h"

namespace brick_stack_sim {
namespace {

using test::dataPath;

std::string link(const std::string& name, const std::string& inertial,
                 const std::string& collisions) {
  return "<link name=\"" + name + "\"><inertial>" + inertial + "</inertial>" + collisions +
         "</link>";
}

std::string massOnly(double mass) {
  // All-zero inertia is a placeholder: the solid's, at uniform density.
  return "<mass value=\"" + std::to_string(mass) +
         "\"/><inertia ixx=\"0\" ixy=\"0\" ixz=\"0\" iyy=\"0\" iyz=\"0\" izz=\"0\"/>";
}

std::string robot(const std::string& links) { return "<robot name=\"t\">" + links + "</robot>"; }

/// The inertia tensor a type reports, back in its type frame's axes [kg m^2].
Eigen::Matrix3d tensorOf(const BrickType& type) {
  const Eigen::Matrix3d r = type.mass_frame.linear();
  return r * type.inertia.asDiagonal() * r.transpose();
}

const BrickType& loaded(const std::string& urdf, BrickTypeLibrary* types, const char* name) {
  const Status s = BrickTypeLibrary::parse(urdf, "", types, dataPath("test/fixtures/meshes"));
  EXPECT_TRUE(s.ok) << s.message;
  static const BrickType kNone;
  const BrickType* type = types->find(name);
  return type ? *type : kNone;
}

TEST(BrickShapes, UrdfCylinderHasTheSolidCylindersInertia) {
  BrickTypeLibrary types;
  const BrickType& can = loaded(
      robot(link("can", massOnly(0.1),
                 "<collision><geometry><cylinder radius=\"0.02\" length=\"0.05\"/></geometry>"
                 "</collision>")),
      &types, "can");
  EXPECT_EQ(can.shape.kind, ShapeKind::kCylinder);
  EXPECT_NEAR((can.size - Eigen::Vector3d(0.04, 0.04, 0.05)).norm(), 0.0, 1e-12);
  // A solid cylinder about its axis m r^2 / 2, across it m (3 r^2 + l^2) / 12.
  const double m = 0.1, r = 0.02, l = 0.05;
  EXPECT_NEAR(can.inertia.z(), m * r * r / 2, 1e-15);
  EXPECT_NEAR(can.inertia.x(), m * (3 * r * r + l * l) / 12, 1e-15);
  EXPECT_NEAR(can.inertia.y(), m * (3 * r * r + l * l) / 12, 1e-15);
  EXPECT_NEAR(can.mass_frame.translation().norm(), 0.0, 1e-15);
  ASSERT_TRUE(can.solid);
  // Judged as an inscribed prism no more than the facet sag inside it.
  const Eigen::AlignedBox3d extent = bounds(can.placed(Eigen::Isometry3d::Identity()));
  EXPECT_NEAR(extent.max().x(), r, 1e-12);
  EXPECT_GT(extent.max().y(), r - kCylinderFacetSag);
}

// A wedge: the right triangle (0, 0), (a, 0), (0, h) in x-z, extruded over
// y in [-d/2, d/2]. Its centroid lies at (a/3, 0, h/3). About the centroid
// a triangle's second moments per unit mass are h^2/18 (about x) and a^2/18
// (about z), the extrusion's d^2/12, and its product of inertia per unit
// mass is the integral of (x - a/3)(z - h/3) over the area, -a^2 h^2 / 72,
// over the area a h / 2: -a h / 36. The tensor's xz entry is minus that.
// Mesh files hold single-precision numbers: 1e-7 relative.
void expectWedge(const BrickType& wedge, double m) {
  const double a = 0.06, h = 0.03, d = 0.02;
  EXPECT_EQ(wedge.shape.kind, ShapeKind::kConvex);
  EXPECT_NEAR((wedge.mass_frame.translation() - Eigen::Vector3d(a / 3, 0, h / 3)).norm(), 0.0,
              1e-8);
  EXPECT_NEAR((wedge.size - Eigen::Vector3d(a, d, h)).norm(), 0.0, 1e-8);
  Eigen::Matrix3d expected;
  expected << m * (d * d / 12 + h * h / 18), 0, m * a * h / 36,  //
      0, m * (a * a + h * h) / 18, 0,                            //
      m * a * h / 36, 0, m * (d * d / 12 + a * a / 18);
  EXPECT_NEAR((tensorOf(wedge) - expected).norm(), 0.0, 1e-6 * expected.norm())
      << tensorOf(wedge) << "\nexpected\n"
      << expected;
  EXPECT_NEAR(wedge.mass_frame.linear().determinant(), 1.0, 1e-12);
}

TEST(BrickShapes, UrdfMeshIsReadAsItsHullWithTheWedgesCentroidAndInertia) {
  for (const char* file : {"wedge.stl", "wedge.obj"}) {
    const std::string scale = std::string(file) == "wedge.stl" ? "0.001 0.001 0.001" : "1 1 1";
    BrickTypeLibrary types;
    const BrickType& wedge =
        loaded(robot(link("wedge", massOnly(0.05),
                          "<collision><geometry><mesh filename=\"" + std::string(file) +
                              "\" scale=\"" + scale + "\"/></geometry></collision>")),
               &types, "wedge");
    SCOPED_TRACE(file);
    expectWedge(wedge, 0.05);
  }
}

TEST(BrickShapes, UrdfMeshIsFoundInItsPackage) {
  const std::string previous =
      std::getenv("ROS_PACKAGE_PATH") ? std::getenv("ROS_PACKAGE_PATH") : "";
  setenv("ROS_PACKAGE_PATH", BRICK_STACK_SIM_SOURCE_DIR, 1);
  BrickTypeLibrary types;
  const Status s = BrickTypeLibrary::parse(
      robot(link("wedge", massOnly(0.05),
                 "<collision><geometry><mesh filename=\"package://brick_stack_sim/test/fixtures/"
                 "meshes/wedge.stl\" scale=\"0.001 0.001 0.001\"/></geometry></collision>")),
      "", &types);
  setenv("ROS_PACKAGE_PATH", previous.c_str(), 1);
  ASSERT_TRUE(s.ok) << s.message;
  expectWedge(*types.find("wedge"), 0.05);
}

// An L of two boxes: A of 60 x 20 x 20 mm at the origin and B of 20 x 20 x
// 40 mm standing on A's right end, centred at (20, 0, 30) mm. At 1000
// kg/m^3 they weigh 24 g and 16 g: the centroid lies at x = 0.016 * 0.02 /
// 0.04 = 8 mm, z = 0.016 * 0.03 / 0.04 = 12 mm. About y: each box's own
// m (a^2 + c^2) / 12 plus its mass times its centre's squared x-z distance
// from the centroid (parallel axes).
TEST(BrickShapes, UrdfLinkWithTwoCollisionsIsACompound) {
  BrickTypeLibrary types;
  const BrickType& l_block =
      loaded(robot(link("l_block", massOnly(0.04),
                        "<collision><geometry><box size=\"0.06 0.02 0.02\"/></geometry></collision>"
                        "<collision><origin xyz=\"0.02 0 0.03\"/><geometry><box size=\"0.02 0.02 "
                        "0.04\"/></geometry></collision>")),
             &types, "l_block");
  EXPECT_EQ(l_block.shape.kind, ShapeKind::kCompound);
  ASSERT_EQ(l_block.solid->parts.size(), 2u);
  EXPECT_NEAR((l_block.mass_frame.translation() - Eigen::Vector3d(0.008, 0, 0.012)).norm(), 0.0,
              1e-12);
  EXPECT_NEAR((l_block.size - Eigen::Vector3d(0.06, 0.02, 0.06)).norm(), 0.0, 1e-12);
  const double m_a = 0.024, m_b = 0.016;
  const double own =
      m_a * (0.06 * 0.06 + 0.02 * 0.02) / 12 + m_b * (0.02 * 0.02 + 0.04 * 0.04) / 12;
  const double shifted =
      m_a * (0.008 * 0.008 + 0.012 * 0.012) + m_b * (0.012 * 0.012 + 0.018 * 0.018);
  EXPECT_NEAR(tensorOf(l_block)(1, 1), own + shifted, 1e-12);
}

TEST(BrickShapes, GivenInertiaAndItsOriginAreKept) {
  BrickTypeLibrary types;
  const BrickType& can = loaded(
      robot(link("can",
                 "<origin xyz=\"0 0 0.001\"/><mass value=\"0.1\"/><inertia ixx=\"3e-5\" ixy=\"0\" "
                 "ixz=\"0\" iyy=\"3e-5\" iyz=\"0\" izz=\"2e-5\"/>",
                 "<collision><geometry><cylinder radius=\"0.02\" length=\"0.05\"/></geometry>"
                 "</collision>")),
      &types, "can");
  EXPECT_EQ(can.inertia, Eigen::Vector3d(3e-5, 3e-5, 2e-5));
  EXPECT_EQ(can.mass_frame.translation(), Eigen::Vector3d(0, 0, 0.001));
}

TEST(BrickShapes, BadGeometryIsRefusedNamingTheType) {
  const std::string cylinder_zero =
      "<collision><geometry><cylinder radius=\"0\" length=\"0.05\"/></geometry></collision>";
  const std::string sphere =
      "<collision><geometry><sphere radius=\"0.02\"/></geometry></collision>";
  const std::string missing =
      "<collision><geometry><mesh filename=\"no_such.stl\"/></geometry></collision>";
  const std::string not_a_mesh =
      "<collision><geometry><mesh filename=\"../../core/types/test_brick_shapes.cpp\"/>"
      "</geometry></collision>";
  for (const auto& [collision, reason] :
       std::vector<std::pair<std::string, std::string>>{{cylinder_zero, "radius"},
                                                        {sphere, "sphere"},
                                                        {missing, "no_such.stl"},
                                                        {not_a_mesh, "does not load"}}) {
    BrickTypeLibrary types;
    const Status s = BrickTypeLibrary::parse(robot(link("odd", massOnly(0.1), collision)), "",
                                             &types, dataPath("test/fixtures/meshes"));
    EXPECT_FALSE(s.ok) << collision;
    EXPECT_NE(s.message.find("odd"), std::string::npos) << s.message;
    EXPECT_NE(s.message.find(reason), std::string::npos) << s.message;
  }
}

TEST(BrickShapes, PackageBoxesKeepTheirBits) {
  // A box type is the box it always was: its inertia is the closed form's
  // bits and its body frame is its type frame.
  BrickTypeLibrary types = test::packageTypes();
  const BrickType& kapla = *types.find("kapla");
  EXPECT_TRUE(kapla.isBox());
  EXPECT_TRUE(kapla.mass_frame.matrix().isIdentity(0.0));
  EXPECT_EQ(kapla.thinnestHalfWidth(), kapla.halfExtents().minCoeff());
  EXPECT_EQ(kapla.reachFromCentreOfMass(), kapla.halfExtents().norm());
}

}  // namespace
}  // namespace brick_stack_sim
