// The builder's label: what tells two builders' lines apart in one console
// (docs/ros_interface.md, "blueprint_builder").
#include <gtest/gtest.h>

#include "brick_stack_sim/planner/blueprint_builder.h"

namespace {

using brick_stack_sim::planner::BuilderOptions;
using brick_stack_sim::planner::linePrefix;

TEST(BuilderLabel, StartsEveryLineInBrackets) {
  BuilderOptions options;
  options.label = "left com";
  const std::string line = linePrefix(options) + "placed b0 (1/50)";
  // The label comes first, closed, and apart from the text.
  EXPECT_EQ(line.rfind("[left com]", 0), 0u);
  EXPECT_EQ(line.substr(std::string("[left com]").size(), 1), " ");
}

TEST(BuilderLabel, NoLabelNoTag) { EXPECT_TRUE(linePrefix(BuilderOptions()).empty()); }

}  // namespace
