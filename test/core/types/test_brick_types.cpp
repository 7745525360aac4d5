#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/types/brick_type.h"
#include "support/kapla.h"

namespace brick_stack_sim {
namespace {

using test::dataPath;

TEST(BrickTypes, PackageUrdfHasKaplaWithItsMeasuredSizeAndMass) {
  BrickTypeLibrary types = test::packageTypes();
  const BrickType* kapla = types.find("kapla");
  ASSERT_NE(kapla, nullptr);
  EXPECT_DOUBLE_EQ(kapla->size.x(), 0.117);
  EXPECT_DOUBLE_EQ(kapla->size.y(), 0.0234);
  EXPECT_DOUBLE_EQ(kapla->size.z(), 0.0078);
  EXPECT_DOUBLE_EQ(kapla->mass, 0.0119);
  EXPECT_DOUBLE_EQ(kapla->friction, 0.5);
  EXPECT_EQ(types.defaultType(), "kapla");
  // A uniform box: I_xx = m (b^2 + c^2) / 12, to the 7 digits the URDF keeps.
  const double m = 0.0119, a = 0.117, b = 0.0234, c = 0.0078;
  const Eigen::Vector3d expected(m * (b * b + c * c) / 12, m * (a * a + c * c) / 12,
                                 m * (a * a + b * b) / 12);
  for (int axis = 0; axis < 3; ++axis)
    EXPECT_NEAR(kapla->inertia[axis], expected[axis], 1e-6 * expected[axis]) << axis;
}

TEST(BrickTypes, PackageUrdfHasAtLeastTwoMoreTypes) {
  BrickTypeLibrary types = test::packageTypes();
  const BrickType* half = types.find("half_kapla");
  const BrickType* cube = types.find("cube");
  ASSERT_NE(half, nullptr);
  ASSERT_NE(cube, nullptr);
  EXPECT_DOUBLE_EQ(half->size.x(), 0.0585);
  EXPECT_DOUBLE_EQ(half->mass, 0.00595);
  EXPECT_DOUBLE_EQ(cube->size.x(), cube->size.z());
  // The root link that ties the URDF tree together is not a brick type.
  EXPECT_EQ(types.find("bricks_root"), nullptr);
  // The KAPLA family and the ten unit blocks (test_unit_blocks.cpp).
  EXPECT_EQ(types.names().size(), 13u);
}

const char* kOneBrickUrdf = R"(<robot name="t">
  <link name="slab">
    <inertial><mass value="0.1"/><inertia ixx="1e-4" ixy="0" ixz="0" iyy="1e-4" iyz="0" izz="1e-4"/></inertial>
    <collision><geometry><box size="0.1 0.1 0.01"/></geometry></collision>
  </link></robot>)";

TEST(BrickTypes, MaterialsOverrideFrictionPerType) {
  BrickTypeLibrary types;
  ASSERT_TRUE(BrickTypeLibrary::parse(kOneBrickUrdf,
                                      "default: {friction: 0.3}\ntypes: {slab: {restitution: 0.2}}",
                                      &types)
                  .ok);
  EXPECT_DOUBLE_EQ(types.find("slab")->friction, 0.3);
  EXPECT_DOUBLE_EQ(types.find("slab")->restitution, 0.2);
}

TEST(BrickTypes, BadDescriptionsAreRefusedWithAReason) {
  BrickTypeLibrary types;
  Status s = BrickTypeLibrary::parse("<robot", "", &types);
  EXPECT_FALSE(s.ok);
  s = BrickTypeLibrary::parse(kOneBrickUrdf, "types: {plank: {friction: 0.4}}", &types);
  EXPECT_FALSE(s.ok);
  EXPECT_NE(s.message.find("plank"), std::string::npos) << s.message;
  s = BrickTypeLibrary::parse(kOneBrickUrdf, "default: {friction: -1}", &types);
  EXPECT_FALSE(s.ok);
  EXPECT_NE(s.message.find("friction"), std::string::npos) << s.message;
  const std::string zero_mass =
      std::string(kOneBrickUrdf).replace(std::string(kOneBrickUrdf).find("0.1\"/>"), 3, "0.0");
  s = BrickTypeLibrary::parse(zero_mass, "", &types);
  EXPECT_FALSE(s.ok);
  EXPECT_NE(s.message.find("mass"), std::string::npos) << s.message;
  // A typo in the materials is named with its place, never silently ignored.
  for (const auto& [yaml, name] : std::vector<std::pair<std::string, std::string>>{
           {"default: {frction: 0.3}", "default/frction"},
           {"types: {slab: {restitusion: 0.1}}", "types/slab/restitusion"},
           {"defualt_type: slab", "defualt_type"},
           {"types: [slab]", "types"}}) {
    s = BrickTypeLibrary::parse(kOneBrickUrdf, yaml, &types);
    EXPECT_FALSE(s.ok) << yaml;
    EXPECT_NE(s.message.find(name), std::string::npos) << s.message;
  }
  s = BrickTypeLibrary::load("/nonexistent/bricks.urdf", "", &types);
  EXPECT_FALSE(s.ok);
  EXPECT_NE(s.message.find("/nonexistent/bricks.urdf"), std::string::npos) << s.message;
}

TEST(BrickTypes, ZeroSizeAndImpossibleInertiaAreRefused) {
  BrickType type;
  type.name = "flat";
  type.size = Eigen::Vector3d(0.1, 0.1, 0.0);
  type.mass = 0.1;
  type.inertia = Eigen::Vector3d(1e-4, 1e-4, 1e-4);
  EXPECT_FALSE(validateBrickType(type).ok);
  type.size.z() = 0.01;
  EXPECT_TRUE(validateBrickType(type).ok);
  type.inertia = Eigen::Vector3d(1e-4, 1e-4, 5e-4);  // I_z > I_x + I_y: no such body
  EXPECT_FALSE(validateBrickType(type).ok);
}

}  // namespace
}  // namespace brick_stack_sim
