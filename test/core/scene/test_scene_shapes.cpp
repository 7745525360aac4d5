// A scene's own types of every shape, and the geometry it refuses.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/scene/scene.h"
#include "support/kapla.h"

namespace brick_stack_sim {
namespace {

const BrickType* sceneType(const Scene& scene, const std::string& name) {
  for (const BrickType& type : scene.types)
    if (type.name == name) return &type;
  return nullptr;
}

TEST(SceneShapes, EveryShapeReadsWithItsGeometryAndMass) {
  Scene scene;
  const Status s = parseScene(R"(
types:
  plank: {size: [0.1, 0.02, 0.01], mass: 0.01}
  block: {shape: box, size: [0.04, 0.04, 0.04], mass: 0.05}
  can: {shape: cylinder, radius: 0.02, length: 0.06, mass: 0.08, rolling_friction: 0.0001}
  roof: {shape: convex, mass: 0.03,
         vertices: [[-0.03, -0.01, 0], [0.03, -0.01, 0], [0, -0.01, 0.02],
                    [-0.03, 0.01, 0], [0.03, 0.01, 0], [0, 0.01, 0.02]]}
  tee: {shape: compound, mass: 0.02, parts: [
          {shape: box, size: [0.06, 0.02, 0.01], position: [0, 0, 0.035]},
          {shape: cylinder, radius: 0.01, length: 0.03, position: [0, 0, 0.015]}]}
bricks: []
)",
                              "shapes", test::packageTypes(), &scene);
  ASSERT_TRUE(s.ok) << s.message;
  ASSERT_NE(sceneType(scene, "plank"), nullptr);
  EXPECT_TRUE(sceneType(scene, "plank")->isBox());
  EXPECT_TRUE(sceneType(scene, "block")->isBox());
  const BrickType& can = *sceneType(scene, "can");
  EXPECT_EQ(can.shape.kind, ShapeKind::kCylinder);
  EXPECT_DOUBLE_EQ(can.rolling_friction, 0.0001);
  EXPECT_NEAR(can.inertia.z(), 0.08 * 0.02 * 0.02 / 2, 1e-15);  // m r^2 / 2
  // The roof's ridge triangle (base 60 mm, height 20 mm) has its centroid
  // a third of the way up: z = 20 / 3 mm.
  const BrickType& roof = *sceneType(scene, "roof");
  EXPECT_EQ(roof.shape.kind, ShapeKind::kConvex);
  EXPECT_NEAR((roof.mass_frame.translation() - Eigen::Vector3d(0, 0, 0.02 / 3)).norm(), 0.0, 1e-12);
  // The tee: a 60 x 20 x 10 mm bar (12 cm^3) on a post of radius 10 mm and
  // 30 mm (pi 3 cm^3): centroid z = (12 * 35 + 3 pi * 15) / (12 + 3 pi) mm.
  const BrickType& tee = *sceneType(scene, "tee");
  EXPECT_EQ(tee.shape.kind, ShapeKind::kCompound);
  const double bar = 12.0, post = 3.0 * M_PI;
  EXPECT_NEAR(tee.mass_frame.translation().z(), 1e-3 * (bar * 35 + post * 15) / (bar + post),
              1e-12);
  EXPECT_NEAR((tee.size - Eigen::Vector3d(0.06, 0.02, 0.04)).norm(), 0.0, 1e-12);
}

TEST(SceneShapes, BadGeometryIsRefusedWithTheTypesPlace) {
  for (const auto& [entry, reason] : std::vector<std::pair<std::string, std::string>>{
           {"{shape: cylinder, radius: 0.02, mass: 0.1}", "radius' and 'length"},
           {"{shape: cylinder, radius: -0.02, length: 0.1, mass: 0.1}", "positive"},
           {"{shape: box, size: [0.1, 0, 0.1], mass: 0.1}", "positive"},
           {"{shape: ball, radius: 0.02, mass: 0.1}", "no shape"},
           {"{shape: convex, vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]], mass: 0.1}",
            "fewer than 4"},
           {"{shape: convex, vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]], mass: 0.1}",
            "coplanar"},
           {"{shape: convex, vertices: [[0, 0, 0], [1, 0, 0], [0, 1, .nan], [1, 1, 1]], mass: 0.1}",
            "finite"},
           {"{shape: compound, parts: [], mass: 0.1}", "parts"},
           {"{shape: compound, parts: [{shape: box, size: [0.1, 0.1, 0]}], mass: 0.1}", "parts[0]"},
           {"{shape: compound, parts: [{shape: compound}], mass: 0.1}", "compound"},
           {"{shape: cylinder, radius: 0.02, length: 0.1}", "mass"},
           {"{shape: cylinder, radius: 0.02, length: 0.1, size: [1, 1, 1], mass: 0.1, colour: red}",
            "colour"}}) {
    Scene scene;
    const Status s = parseScene("types:\n  odd: " + entry + "\nbricks: []\n", "bad",
                                test::packageTypes(), &scene);
    EXPECT_FALSE(s.ok) << entry;
    EXPECT_NE(s.message.find("types.odd"), std::string::npos) << s.message;
    EXPECT_NE(s.message.find(reason), std::string::npos) << entry << ": " << s.message;
  }
}

TEST(SceneShapes, TypesWrittenAsASceneReadBackTheSame) {
  Scene scene;
  ASSERT_TRUE(parseScene(R"(
types:
  plank: {size: [0.1, 0.02, 0.01], mass: 0.01, friction: 0.7}
  can: {shape: cylinder, radius: 0.02, length: 0.06, mass: 0.08, rolling_friction: 0.0001}
  tee: {shape: compound, mass: 0.02, restitution: 0.1, parts: [
          {shape: box, size: [0.06, 0.02, 0.01], position: [0, 0, 0.035], rpy: [0.1, 0.2, 0.3]},
          {shape: cylinder, radius: 0.01, length: 0.03, position: [0, 0, 0.015]}]}
generator: {name: arch, voussoirs: 9, radius: 0.1, thickness: 0.02}
bricks: []
)",
                         "written", test::packageTypes(), &scene)
                  .ok);
  Scene read;
  const Status s = parseScene(typesAsScene(scene.types), "read", test::packageTypes(), &read);
  ASSERT_TRUE(s.ok) << s.message << "\n" << typesAsScene(scene.types);
  ASSERT_EQ(read.types.size(), scene.types.size());
  for (const BrickType& original : scene.types) {
    const BrickType* copy = sceneType(read, original.name);
    ASSERT_NE(copy, nullptr) << original.name;
    EXPECT_EQ(copy->shape.kind, original.shape.kind) << original.name;
    EXPECT_EQ(copy->mass, original.mass) << original.name;
    EXPECT_EQ(copy->friction, original.friction) << original.name;
    EXPECT_EQ(copy->restitution, original.restitution) << original.name;
    EXPECT_EQ(copy->rolling_friction, original.rolling_friction) << original.name;
    EXPECT_NEAR((copy->size - original.size).norm(), 0.0, 1e-12) << original.name;
    EXPECT_NEAR((copy->inertia - original.inertia).norm(), 0.0, 1e-9 * original.inertia.norm());
    EXPECT_NEAR((copy->mass_frame.translation() - original.mass_frame.translation()).norm(), 0.0,
                1e-12)
        << original.name;
  }
}

}  // namespace
}  // namespace brick_stack_sim
