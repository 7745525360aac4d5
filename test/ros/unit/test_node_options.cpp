// Parameters -> NodeOptions with no master: XML-RPC values, as the parameter
// server holds them, go through the same conversion (fromXmlRpc) and the same
// core readers the node uses.
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/types/stability_modes.h"
#include "brick_stack_sim/ros/node_options.h"
#include "brick_stack_sim/ros/xmlrpc_parameters.h"
#include "support/xmlrpc_list.h"

namespace brick_stack_sim {
namespace ros_adapter {
namespace {

using XmlRpc::XmlRpcValue;

/// The private namespace as the parameter server returns it: "table/size"
/// is member "size" of the struct "table".
class PrivateParameters {
 public:
  void set(const std::string& path, const XmlRpcValue& value) {
    XmlRpcValue* node = &root_;
    std::size_t start = 0;
    for (std::size_t slash; (slash = path.find('/', start)) != std::string::npos; start = slash + 1)
      node = &(*node)[path.substr(start, slash - start)];
    (*node)[path.substr(start)] = value;
  }
  Status load(NodeOptions* options) const {
    ParameterValue tree;
    if (root_.getType() == XmlRpcValue::TypeStruct) {
      if (Status converted = fromXmlRpc(root_, "~", &tree); !converted) return converted;
    }
    return loadNodeOptions(tree, options);
  }

 private:
  XmlRpcValue root_;
};

/// Loads `name` = `value` on top of the defaults and expects a refusal that
/// names the parameter; returns the message for further checks.
std::string expectRefused(const std::string& name, const XmlRpcValue& value) {
  PrivateParameters params;
  params.set(name, value);
  NodeOptions options;
  options.config.publish.rate = 12.5;  // a marker: a refusal must leave the options alone
  const Status status = params.load(&options);
  EXPECT_FALSE(status.ok) << name << " was accepted";
  EXPECT_NE(status.message.find("~" + name), std::string::npos)
      << "message does not name ~" << name << ": " << status.message;
  EXPECT_EQ(options.config.publish.rate, 12.5) << "options changed by a refused load";
  return status.message;
}

TEST(NodeOptions, DefaultsAreValidAndMatchWorldOptions) {
  PrivateParameters params;
  NodeOptions options;
  const Status status = params.load(&options);
  ASSERT_TRUE(status.ok) << status.message;
  const WorldOptions defaults;
  EXPECT_EQ(options.config.world.time_step, defaults.time_step);
  EXPECT_EQ(options.config.world.solver_iterations, defaults.solver_iterations);
  // The node runs the stack stability layer unless told otherwise.
  EXPECT_EQ(options.config.world.stability.mode, "com");
  const StabilityOptions& stability = options.config.world.stability;
  EXPECT_EQ(stability.rest_linear_speed, defaults.stability.rest_linear_speed);
  EXPECT_EQ(stability.rest_angular_speed, defaults.stability.rest_angular_speed);
  EXPECT_EQ(stability.rest_time, defaults.stability.rest_time);
  EXPECT_EQ(stability.impact_speed, defaults.stability.impact_speed);
  EXPECT_EQ(stability.support_normal_tolerance, defaults.stability.support_normal_tolerance);
  EXPECT_EQ(stability.flush_angle, defaults.stability.flush_angle);
  EXPECT_EQ(stability.contact_distance, defaults.stability.contact_distance);
  EXPECT_EQ(stability.min_margin, defaults.stability.min_margin);
  EXPECT_EQ(options.config.world.table.size, defaults.table.size);
  EXPECT_EQ(options.config.world.friction_cone, defaults.friction_cone);
  EXPECT_EQ(options.config.world.full_warm_start, defaults.full_warm_start);
  EXPECT_FALSE(defaults.full_warm_start);  // Bullet's own unless asked
  EXPECT_EQ(options.config.publish.frame_id, "world");
  EXPECT_EQ(options.config.publish.frame_prefix, "");
  EXPECT_TRUE(options.config.data.scene_dirs.empty());
  EXPECT_TRUE(validate(options.config.world).ok);
  EXPECT_TRUE(validate(options.config.publish).ok);
}

TEST(NodeOptions, ReadsEveryParameter) {
  PrivateParameters params;
  params.set("time_step", 0.002);
  params.set("solver_iterations", 30);
  params.set("gravity", 10);  // an int where a double is expected: YAML writes 10
  params.set("publish_rate", 50.0);
  params.set("publish_clock", true);
  params.set("real_time_factor", 0.0);
  params.set("frame_id", std::string("map"));
  params.set("stability/mode", std::string("none"));
  params.set("stability/rest_linear_speed", 0.004);
  params.set("stability/rest_angular_speed", 0.04);
  params.set("stability/rest_time", 0.05);
  params.set("stability/impact_speed", 0.1);
  params.set("stability/support_normal_tolerance", 0.3);
  params.set("stability/flush_angle", 0.003);
  params.set("stability/contact_distance", 0.0002);
  params.set("stability/min_margin", 0);  // an int where a double is expected
  params.set("sleeping/enabled", false);
  params.set("sleeping/linear_threshold", 0.01);
  params.set("sleeping/angular_threshold", 0.1);
  params.set("sleeping/time", 1.5);
  params.set("table/size", test::xmlRpcList({XmlRpcValue(2.0), XmlRpcValue(1)}));
  params.set("table/thickness", 0.05);
  params.set("table/height", 0.7);
  params.set("table/friction", 0.6);
  params.set("table/restitution", 0.1);
  params.set("overlap_tolerance", 0.0002);
  params.set("fall_off_depth", 0.05);
  params.set("full_warm_start", true);
  params.set("types_urdf", std::string("/x/bricks.urdf"));
  params.set("materials_yaml", std::string("/x/bricks.yaml"));
  params.set("scene_dirs",
             test::xmlRpcList({XmlRpcValue(std::string("/a")), XmlRpcValue(std::string("/b"))}));
  params.set("scene", std::string("tower10"));
  NodeOptions options;
  const Status status = params.load(&options);
  ASSERT_TRUE(status.ok) << status.message;
  EXPECT_EQ(options.config.world.time_step, 0.002);
  EXPECT_EQ(options.config.world.solver_iterations, 30);
  EXPECT_EQ(options.config.world.gravity, 10.0);
  EXPECT_EQ(options.config.publish.rate, 50.0);
  EXPECT_TRUE(options.config.publish.clock);
  EXPECT_EQ(options.config.publish.real_time_factor, 0.0);
  EXPECT_EQ(options.config.publish.frame_id, "map");
  EXPECT_EQ(options.config.world.stability.mode, "none");
  const StabilityOptions& stability = options.config.world.stability;
  EXPECT_EQ(stability.rest_linear_speed, 0.004);
  EXPECT_EQ(stability.rest_angular_speed, 0.04);
  EXPECT_EQ(stability.rest_time, 0.05);
  EXPECT_EQ(stability.impact_speed, 0.1);
  EXPECT_EQ(stability.support_normal_tolerance, 0.3);
  EXPECT_EQ(stability.flush_angle, 0.003);
  EXPECT_EQ(stability.contact_distance, 0.0002);
  EXPECT_EQ(stability.min_margin, 0.0);
  EXPECT_FALSE(options.config.world.sleeping.enabled);
  EXPECT_EQ(options.config.world.sleeping.linear_threshold, 0.01);
  EXPECT_EQ(options.config.world.sleeping.angular_threshold, 0.1);
  EXPECT_EQ(options.config.world.sleeping.time, 1.5);
  EXPECT_EQ(options.config.world.table.size, Eigen::Vector2d(2.0, 1.0));
  EXPECT_EQ(options.config.world.table.thickness, 0.05);
  EXPECT_EQ(options.config.world.table.height, 0.7);
  EXPECT_EQ(options.config.world.table.friction, 0.6);
  EXPECT_EQ(options.config.world.table.restitution, 0.1);
  EXPECT_EQ(options.config.world.overlap_tolerance, 0.0002);
  EXPECT_EQ(options.config.world.fall_off_depth, 0.05);
  EXPECT_TRUE(options.config.world.full_warm_start);
  EXPECT_EQ(options.config.data.types_urdf, "/x/bricks.urdf");
  EXPECT_EQ(options.config.data.materials_yaml, "/x/bricks.yaml");
  ASSERT_EQ(options.config.data.scene_dirs.size(), 2u);
  EXPECT_EQ(options.config.data.scene_dirs[1], "/b");
  EXPECT_EQ(options.config.data.scene, "tower10");
}

TEST(NodeOptions, RefusesBadTimeStep) {
  const std::string message = expectRefused("time_step", -0.001);
  EXPECT_NE(message.find("-0.001"), std::string::npos) << message;  // the value is named too
  expectRefused("time_step", 0.0);
  expectRefused("time_step", std::numeric_limits<double>::quiet_NaN());
  expectRefused("time_step", std::numeric_limits<double>::infinity());
  expectRefused("time_step", 5.0);  // tunnels through the table
}

TEST(NodeOptions, RefusesBadNumbers) {
  expectRefused("solver_iterations", 0);
  expectRefused("solver_iterations", -3);
  expectRefused("gravity", -9.81);
  expectRefused("gravity", std::numeric_limits<double>::quiet_NaN());
  expectRefused("publish_rate", -1.0);
  expectRefused("publish_rate", 0.0);
  expectRefused("publish_rate", std::numeric_limits<double>::infinity());
  expectRefused("real_time_factor", -0.5);
  expectRefused("real_time_factor", std::numeric_limits<double>::quiet_NaN());
  expectRefused("sleeping/linear_threshold", -0.1);
  expectRefused("sleeping/angular_threshold", std::numeric_limits<double>::quiet_NaN());
  expectRefused("sleeping/time", 0.0);
  expectRefused("table/thickness", 0.0);
  expectRefused("table/height", -0.75);
  expectRefused("table/friction", -0.1);
  expectRefused("table/restitution", 1.5);
  expectRefused("overlap_tolerance", -1e-4);
  expectRefused("fall_off_depth", 0.0);
}

TEST(NodeOptions, RefusesFullWarmStartWithBulletsOwnFriction) {
  // Bullet's friction turns with the slip: last step's friction, carried
  // into this one, would push the wrong way.
  PrivateParameters params;
  params.set("friction_cone", false);
  params.set("full_warm_start", true);
  NodeOptions options;
  const Status status = params.load(&options);
  EXPECT_FALSE(status.ok);
  EXPECT_NE(status.message.find("full_warm_start"), std::string::npos) << status.message;
  EXPECT_NE(status.message.find("friction_cone = true"), std::string::npos) << status.message;
  expectRefused("full_warm_start", std::string("yes"));  // a bool, not a word
}

TEST(NodeOptions, RefusesBadStabilityThresholds) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  constexpr double kInf = std::numeric_limits<double>::infinity();
  // The value is named along with the parameter.
  const std::string message = expectRefused("stability/rest_linear_speed", -0.005);
  EXPECT_NE(message.find("-0.005"), std::string::npos) << message;
  expectRefused("stability/rest_linear_speed", 0.0);  // nothing would ever be at rest
  expectRefused("stability/rest_linear_speed", kNaN);
  expectRefused("stability/rest_angular_speed", 0.0);
  expectRefused("stability/rest_angular_speed", kInf);
  expectRefused("stability/rest_time", -0.01);
  expectRefused("stability/rest_time", kNaN);
  expectRefused("stability/impact_speed", 0.0);
  expectRefused("stability/impact_speed", -1.0);
  expectRefused("stability/support_normal_tolerance", 0.0);
  expectRefused("stability/support_normal_tolerance", M_PI / 2);  // walls would support
  expectRefused("stability/support_normal_tolerance", kNaN);
  expectRefused("stability/flush_angle", -0.001);
  expectRefused("stability/flush_angle", 0.2);
  expectRefused("stability/contact_distance", 0.0);
  expectRefused("stability/contact_distance", 0.05);  // half a brick away is not touching
  expectRefused("stability/min_margin", -0.001);
  expectRefused("stability/min_margin", 0.02);
  expectRefused("stability/min_margin", kInf);
  // Wrong types, too.
  expectRefused("stability/rest_time", std::string("short"));
  expectRefused("stability/flush_angle", true);
}

TEST(NodeOptions, StabilityThresholdsAreCheckedInModeNone) {
  // A typo must not wait until someone switches the layer on.
  PrivateParameters params;
  params.set("stability/mode", std::string("none"));
  params.set("stability/rest_time", -1.0);
  NodeOptions options;
  const Status status = params.load(&options);
  EXPECT_FALSE(status.ok);
  EXPECT_NE(status.message.find("~stability/rest_time"), std::string::npos) << status.message;
}

TEST(NodeOptions, AcceptsBoundaryStabilityThresholds) {
  PrivateParameters params;
  params.set("stability/rest_time", 0.0);    // at rest as soon as it is slow
  params.set("stability/flush_angle", 0.0);  // only exactly parallel faces are flush
  params.set("stability/min_margin", 0.01);
  NodeOptions options;
  const Status status = params.load(&options);
  ASSERT_TRUE(status.ok) << status.message;
  EXPECT_EQ(options.config.world.stability.rest_time, 0.0);
  EXPECT_EQ(options.config.world.stability.min_margin, 0.01);
}

TEST(NodeOptions, RefusesBadStrings) {
  expectRefused("frame_id", std::string(""));
  expectRefused("frame_id", std::string("/world"));
  expectRefused("frame_id", std::string("table"));  // the node's own table frame
  expectRefused("frame_prefix", std::string("/sim1/"));
  expectRefused("frame_prefix", std::string("sim 1/"));
}

TEST(NodeOptions, RefusesUnknownAndUnavailableModes) {
  const std::string unknown = expectRefused("stability/mode", std::string("magic"));
  EXPECT_NE(unknown.find("magic"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("not available"), std::string::npos) << unknown;
  // Every mode of the registry is accepted, and nothing else.
  for (const std::string& mode : availableStabilityModes()) {
    PrivateParameters params;
    params.set("stability/mode", mode);
    NodeOptions options;
    const Status status = params.load(&options);
    EXPECT_TRUE(status.ok) << mode << ": " << status.message;
    EXPECT_EQ(options.config.world.stability.mode, mode);
  }
  EXPECT_TRUE(checkStabilityMode("none").ok);
  EXPECT_TRUE(checkStabilityMode("com").ok);
}

TEST(NodeOptions, RefusesUnknownParametersByTheirName) {
  // A typo must stop the node, not silently become a default.
  const std::string top = expectRefused("time_stepp", 0.002);
  EXPECT_NE(top.find("not a known parameter"), std::string::npos) << top;
  EXPECT_NE(top.find("did you mean time_step?"), std::string::npos) << top;
  const std::string nested = expectRefused("stability/rest_tme", 0.1);
  EXPECT_NE(nested.find("did you mean stability/rest_time?"), std::string::npos) << nested;
  // Nothing close: no guess, the known keys only.
  const std::string far = expectRefused("colour_of_the_bricks", std::string("red"));
  EXPECT_EQ(far.find("did you mean"), std::string::npos) << far;
  EXPECT_NE(far.find("known here: "), std::string::npos) << far;
  expectRefused("table/colour", std::string("oak"));
  expectRefused("sleeping/enable", true);
  // A section given as a plain value is named as well.
  expectRefused("sleeping", 3.0);
}

TEST(NodeOptions, RefusesWrongTypes) {
  const std::string message = expectRefused("time_step", std::string("fast"));
  EXPECT_NE(message.find("fast"), std::string::npos) << message;
  expectRefused("solver_iterations", 20.0);  // a double is not silently truncated
  expectRefused("solver_iterations", std::string("20"));
  expectRefused("publish_clock", 1);
  expectRefused("publish_clock", std::string("true"));
  expectRefused("frame_id", 3);
  expectRefused("stability/mode", true);
  expectRefused("table/size", 1.2);
  expectRefused("table/size",
                test::xmlRpcList({XmlRpcValue(1.2), XmlRpcValue(std::string("wide"))}));
  expectRefused("scene_dirs", std::string("/one/dir"));
  expectRefused("scene_dirs", test::xmlRpcList({XmlRpcValue(4)}));
  expectRefused("scene", 7);
  expectRefused("types_urdf", false);
}

TEST(NodeOptions, RefusesTableSizeOfWrongLength) {
  expectRefused("table/size", test::xmlRpcList({XmlRpcValue(1.2)}));
  expectRefused("table/size",
                test::xmlRpcList({XmlRpcValue(1.2), XmlRpcValue(0.8), XmlRpcValue(0.1)}));
  expectRefused("table/size", test::xmlRpcList({XmlRpcValue(1.2), XmlRpcValue(-0.8)}));
  expectRefused("table/size", test::xmlRpcList({}));
}

TEST(NodeOptions, ResolvesDataPathsFromThePackage) {
  NodeOptions options;
  ASSERT_TRUE(resolveDataPaths("/pkg", &options).ok);
  EXPECT_EQ(options.config.data.types_urdf, "/pkg/urdf/bricks.urdf");
  EXPECT_EQ(options.config.data.materials_yaml, "/pkg/config/bricks.yaml");
  ASSERT_EQ(options.config.data.scene_dirs.size(), 1u);
  EXPECT_EQ(options.config.data.scene_dirs[0], "/pkg/scenes");

  NodeOptions given;
  given.config.data.types_urdf = "/mine.urdf";
  given.config.data.scene_dirs = {"/s"};
  ASSERT_TRUE(resolveDataPaths("/pkg", &given).ok);
  EXPECT_EQ(given.config.data.types_urdf, "/mine.urdf");
  EXPECT_EQ(given.config.data.scene_dirs, std::vector<std::string>{"/s"});

  NodeOptions nowhere;
  const Status status = resolveDataPaths("", &nowhere);
  EXPECT_FALSE(status.ok);
  EXPECT_NE(status.message.find("~types_urdf"), std::string::npos) << status.message;
}

}  // namespace
}  // namespace ros_adapter
}  // namespace brick_stack_sim
