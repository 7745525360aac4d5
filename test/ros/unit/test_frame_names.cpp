// The frames the node names on tf, with no master: a prefix gets its '/',
// and a brick id is refused exactly when tf2 would refuse its transform as
// a frame that is its own parent (TF_SELF_TRANSFORM); the fixed frame may
// not be one of the node's own frames (docs/ros_interface.md, "Frames and
// units"). The warnings of GraphChecks name what the user must change.
#include <string>

#include <gtest/gtest.h>
#include <tf2/buffer_core.h>

#include "brick_stack_sim/core/simulation/simulation_config.h"
#include "brick_stack_sim/ros/brick_transforms.h"
#include "brick_stack_sim/ros/graph_checks.h"

namespace brick_stack_sim {
namespace ros_adapter {
namespace {

/// Whether tf2 takes the transform parent -> child (an identity, now).
bool tf2Accepts(const std::string& parent, const std::string& child) {
  tf2::BufferCore buffer;
  geometry_msgs::TransformStamped transform;
  transform.header.stamp = ros::Time(1.0);
  transform.header.frame_id = parent;
  transform.child_frame_id = child;
  transform.transform.rotation.w = 1.0;
  return buffer.setTransform(transform, "test_frame_names");
}

TEST(FrameNames, PrefixGetsOneSeparator) {
  EXPECT_EQ(FrameNames("world", "sim1").brick("b0"), "sim1/b0");
  EXPECT_EQ(FrameNames("world", "sim1").table(), "sim1/table");
  // Given with its '/', it is not doubled.
  EXPECT_EQ(FrameNames("world", "sim1/").brick("b0"), "sim1/b0");
  EXPECT_EQ(FrameNames("world", "sim1/").table(), "sim1/table");
  EXPECT_EQ(FrameNames("world", "a/b").brick("b0"), "a/b/b0");
  // No prefix: bare ids.
  EXPECT_EQ(FrameNames("world", "").brick("b0"), "b0");
  EXPECT_EQ(FrameNames("world", "").table(), "table");
  EXPECT_EQ(FrameNames("map", "").fixed(), "map");
}

TEST(FrameNames, PrefixedFramesAreFramesTf2Takes) {
  for (const std::string prefix : {"", "sim1", "sim1/", "left/arm"}) {
    const FrameNames names("world", prefix);
    EXPECT_TRUE(tf2Accepts("world", names.brick("b0"))) << names.brick("b0");
    EXPECT_TRUE(tf2Accepts("world", names.table())) << names.table();
  }
}

TEST(FrameNames, RefusesExactlyTheBrickIdsTf2Refuses) {
  struct Case {
    std::string frame_id, prefix, id;
  };
  const Case cases[] = {
      {"b0", "", "b0"},           {"b0", "", "b1"},         {"sim1/b0", "sim1", "b0"},
      {"sim1/b0", "sim1/", "b0"}, {"sim1/b0", "", "b0"},    {"b0", "sim1", "b0"},
      {"map", "", "map"},         {"world", "", "world_b"}, {"left/world", "left/", "b0"},
  };
  for (const Case& c : cases) {
    const FrameNames names(c.frame_id, c.prefix);
    const Status status = names.checkBrickId(c.id);
    EXPECT_EQ(status.ok, tf2Accepts(c.frame_id, names.brick(c.id)))
        << "frame_id " << c.frame_id << ", prefix '" << c.prefix << "', id " << c.id << ": "
        << status.message;
    if (!status.ok) {
      EXPECT_NE(status.message.find("'" + c.id + "'"), std::string::npos) << status.message;
      EXPECT_NE(status.message.find("~frame_id"), std::string::npos) << status.message;
    }
  }
  // An empty id is the world's to name (brick_<n>, which the fixed frame may not be).
  EXPECT_TRUE(FrameNames("b0", "").checkBrickId("").ok);
}

/// validate(PublishOptions) of a frame_id under a frame_prefix.
Status validateFrames(const std::string& frame_id, const std::string& prefix) {
  PublishOptions options;
  options.frame_id = frame_id;
  options.frame_prefix = prefix;
  return validate(options);
}

TEST(FrameNames, FixedFrameMayNotBeOneOfTheNodesFrames) {
  // Each would make tf2 refuse the table (or an unnamed brick) as its own parent.
  for (const auto& [frame_id, prefix] :
       std::initializer_list<std::pair<std::string, std::string>>{{"table", ""},
                                                                  {"sim1/table", "sim1"},
                                                                  {"sim1/table", "sim1/"},
                                                                  {"floor", ""},
                                                                  {"Table", ""},
                                                                  {"brick_3", ""},
                                                                  {"sim1/brick_12", "sim1"}}) {
    const Status status = validateFrames(frame_id, prefix);
    EXPECT_FALSE(status.ok) << frame_id << " under '" << prefix << "'";
    EXPECT_NE(status.message.find("frame_id"), std::string::npos) << status.message;
    EXPECT_NE(status.message.find(frame_id), std::string::npos) << status.message;
  }
  EXPECT_FALSE(tf2Accepts("sim1/table", FrameNames("sim1/table", "sim1").table()));
  // Frames the node does not name.
  for (const auto& [frame_id, prefix] :
       std::initializer_list<std::pair<std::string, std::string>>{{"world", ""},
                                                                  {"left/world", "left/"},
                                                                  {"table", "sim1"},
                                                                  {"map", ""},
                                                                  {"brick_x", ""},
                                                                  {"brick_", ""},
                                                                  {"sim1/b0", "sim1"}}) {
    const Status status = validateFrames(frame_id, prefix);
    EXPECT_TRUE(status.ok) << frame_id << " under '" << prefix << "': " << status.message;
  }
}

// What docs/ros_interface.md, "Topics" tells a listener: a tf2 buffer keeps
// a static transform it received, through clear(), so a brick removed from
// the node's latched set lives on in a running listener; a new buffer starts
// without it.
TEST(FrameNames, Tf2KeepsStaticTransformsThroughClear) {
  tf2::BufferCore buffer;
  geometry_msgs::TransformStamped transform;
  transform.header.stamp = ros::Time(1.0);
  transform.header.frame_id = "world";
  transform.child_frame_id = "b5";
  transform.transform.rotation.w = 1.0;
  ASSERT_TRUE(buffer.setTransform(transform, "test_frame_names", true));
  buffer.clear();
  EXPECT_TRUE(buffer.canTransform("world", "b5", ros::Time(0)));
  EXPECT_FALSE(tf2::BufferCore().canTransform("world", "b5", ros::Time(0)));
}

TEST(GraphChecks, WarningsNameTheCauseAndTheFix) {
  const std::string clash = GraphChecks::clashWarning("table", "/tf_static", "/b/brick_sim");
  EXPECT_NE(clash.find("/b/brick_sim"), std::string::npos) << clash;
  EXPECT_NE(clash.find("'table'"), std::string::npos) << clash;
  EXPECT_NE(clash.find("~frame_prefix"), std::string::npos) << clash;
  const std::string clock = GraphChecks::clockWarning(1.0);
  EXPECT_NE(clock.find("/use_sim_time"), std::string::npos) << clock;
  EXPECT_NE(clock.find("publish_clock:=true"), std::string::npos) << clock;
  EXPECT_NE(clock.find("/clock"), std::string::npos) << clock;
}

}  // namespace
}  // namespace ros_adapter
}  // namespace brick_stack_sim
