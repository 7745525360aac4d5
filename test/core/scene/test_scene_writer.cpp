#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/scene/scene.h"
#include "support/kapla.h"

namespace brick_stack_sim {
namespace {

Scene parsed(const std::string& yaml) {
  Scene scene;
  const Status s = parseScene(yaml, "unnamed", test::packageTypes(), &scene);
  EXPECT_TRUE(s.ok) << s.message << "\n" << yaml;
  return scene;
}

TEST(SceneAsYaml, ReadsBackAsTheSameScene) {
  const Scene scene = parsed(R"(
name: written
expect: collapses
table: {size: [0.5, 0.4], thickness: 0.02, height: 0.7, friction: 0.7, restitution: 0.1}
friction: 0.6
types: {slab: {size: [0.1, 0.1, 0.01], mass: 0.06}}
bricks:
  - {id: a, type: slab, at: 0.25, position: [0.01, -0.02, 0.005], rpy: [0, 0, 0.3]}
  - {id: b, position: [0.1, 0.1, 0.2], rpy: [0.1, 1.5707963, -2.9],
     linear_velocity: [0.1, -0.2, 0.3], angular_velocity: [1e-9, 2, -3]}
)");
  const std::string yaml = sceneAsYaml(scene);
  const Scene read = parsed(yaml);
  SCOPED_TRACE(yaml);
  EXPECT_EQ(read.name, "written");
  EXPECT_EQ(read.expect, ExpectedOutcome::kCollapses);
  ASSERT_TRUE(read.table.has_value());
  EXPECT_EQ(read.table->size, scene.table->size);
  EXPECT_EQ(read.table->thickness, 0.02);
  EXPECT_EQ(read.table->height, 0.7);
  EXPECT_EQ(read.table->friction, 0.7);
  EXPECT_EQ(read.table->restitution, 0.1);
  ASSERT_TRUE(read.friction.has_value());
  EXPECT_EQ(*read.friction, 0.6);
  ASSERT_EQ(read.types.size(), 1u);
  EXPECT_EQ(read.types[0].name, "slab");
  EXPECT_EQ(read.types[0].mass, 0.06);
  ASSERT_EQ(read.bricks.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const ScheduledBrick& before = scene.bricks[i];
    const ScheduledBrick& after = read.bricks[i];
    EXPECT_EQ(after.placement.id, before.placement.id);
    EXPECT_EQ(after.placement.type, before.placement.type);
    EXPECT_EQ(after.at, before.at);
    // Seventeen digits give a double back to its last bit.
    EXPECT_EQ(after.placement.pose.translation(), before.placement.pose.translation());
    EXPECT_EQ(after.placement.linear_velocity, before.placement.linear_velocity);
    EXPECT_EQ(after.placement.angular_velocity, before.placement.angular_velocity);
    // Brick b is turned 1e-7 rad short of roll-pitch-yaw's pole, where
    // angles lose bits; the quaternion keeps its rotation.
    EXPECT_LT(
        (after.placement.pose.linear() - before.placement.pose.linear()).cwiseAbs().maxCoeff(),
        1e-15);
  }
}

TEST(SceneAsYaml, AnEmptySceneHasEmptyBricksAndNoMore) {
  const Scene read = parsed(sceneAsYaml(Scene{}));
  EXPECT_TRUE(read.bricks.empty());
  EXPECT_TRUE(read.types.empty());
  EXPECT_FALSE(read.table.has_value());
  EXPECT_FALSE(read.friction.has_value());
  EXPECT_EQ(read.expect, ExpectedOutcome::kStands);
}

}  // namespace
}  // namespace brick_stack_sim
