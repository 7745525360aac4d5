// The teleop nodes' parameters: defaults stay when nothing is set; a bad
// value, a wrong type or an unknown name stops the node with a message
// naming the parameter, and leaves the options as they were.
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "brick_stack_sim/ros/interface_names.h"
#include "brick_stack_sim/teleop/teleop_options.h"

namespace {

using namespace brick_stack_sim;
using namespace brick_stack_sim::teleop;

ParameterValue numbers(double x, double y, double z) {
  return ParameterValue::makeList({ParameterValue::makeDouble(x), ParameterValue::makeDouble(y),
                                   ParameterValue::makeDouble(z)});
}

/// Loads a keyboard teleop's options from one parameter; expects a refusal
/// whose message starts with "parameter ~<name>".
void expectKeyboardRefused(const std::string& name, const ParameterValue& value) {
  ParameterValue tree;
  tree.set(name, value);
  KeyboardOptions options;
  const Status loaded = loadKeyboardOptions(tree, &options);
  EXPECT_FALSE(loaded.ok) << name << " = " << value.describe() << " was accepted";
  EXPECT_EQ(loaded.message.rfind("parameter ~" + name, 0), 0u) << loaded.message;
  // Nothing changed.
  EXPECT_EQ(options.steps.linear, CursorSteps().linear);
  EXPECT_EQ(options.teleop.sim, TeleopOptions().sim);
}

TEST(TeleopOptions, NoParametersKeepTheDefaults) {
  KeyboardOptions keyboard;
  ASSERT_TRUE(loadKeyboardOptions(ParameterValue(), &keyboard).ok);
  EXPECT_EQ(keyboard.teleop.sim, ros_adapter::kDefaultNamespace);
  EXPECT_EQ(keyboard.steps.linear, 0.005);
  PlacerOptions placer;
  ASSERT_TRUE(loadPlacerOptions(ParameterValue(), &placer).ok);
  EXPECT_TRUE(placer.type.empty());
  EXPECT_TRUE(placer.teleop.initial_position.isApprox(Eigen::Vector3d(0.0, 0.0, 0.1)));
}

TEST(TeleopOptions, ValuesAreRead) {
  ParameterValue tree;
  tree.set("sim", ParameterValue::makeString("/other_sim"));
  tree.set("initial_position", numbers(0.1, -0.2, 0.3));
  tree.set("initial_yaw", ParameterValue::makeInt(1));  // YAML writes 1 for 1.0
  tree.set("type", ParameterValue::makeString("cube"));
  PlacerOptions placer;
  const Status loaded = loadPlacerOptions(tree, &placer);
  ASSERT_TRUE(loaded.ok) << loaded.message;
  EXPECT_EQ(placer.teleop.sim, "/other_sim");
  EXPECT_TRUE(placer.teleop.initial_position.isApprox(Eigen::Vector3d(0.1, -0.2, 0.3)));
  EXPECT_EQ(placer.teleop.initial_yaw, 1.0);
  EXPECT_EQ(placer.type, "cube");
}

TEST(TeleopOptions, BadValuesAreRefusedByName) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expectKeyboardRefused("linear_step", ParameterValue::makeDouble(0.0));
  expectKeyboardRefused("linear_step", ParameterValue::makeDouble(5.0));  // mm typed as m
  expectKeyboardRefused("linear_step", ParameterValue::makeDouble(nan));
  expectKeyboardRefused("linear_step", ParameterValue::makeString("small"));
  expectKeyboardRefused("angular_step", ParameterValue::makeDouble(-0.1));
  expectKeyboardRefused("angular_step", ParameterValue::makeDouble(90.0));  // degrees, not rad
  expectKeyboardRefused("held_target_rate", ParameterValue::makeDouble(0.0));
  expectKeyboardRefused("initial_position", numbers(0.0, nan, 0.1));
  expectKeyboardRefused("initial_position", numbers(0.0, 0.0, -0.1));  // under the table
  expectKeyboardRefused("initial_position", ParameterValue::makeDouble(0.1));
  expectKeyboardRefused("initial_yaw", ParameterValue::makeDouble(nan));
  expectKeyboardRefused("wait_for_sim", ParameterValue::makeDouble(-1.0));
  expectKeyboardRefused("sim", ParameterValue::makeString(""));
  expectKeyboardRefused("sim", ParameterValue::makeString("brick sim"));
}

TEST(TeleopOptions, UnknownParametersAreRefused) {
  expectKeyboardRefused("linear_stepp", ParameterValue::makeDouble(0.01));
  // A placer parameter is not a keyboard one.
  expectKeyboardRefused("type", ParameterValue::makeString("kapla"));
  ParameterValue tree;
  tree.set("linear_step", ParameterValue::makeDouble(0.01));
  PlacerOptions placer;
  const Status loaded = loadPlacerOptions(tree, &placer);
  EXPECT_FALSE(loaded.ok);
  EXPECT_NE(loaded.message.find("linear_step is not a known parameter"), std::string::npos)
      << loaded.message;
}

}  // namespace
