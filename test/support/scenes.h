#pragma once
// Scenes written inline in a test, read with the package's brick types.

#include <string>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/scene/scene.h"
#include "support/kapla.h"

namespace brick_stack_sim {
namespace test {

/// The package's cube: full edge [m], a KAPLA's width (urdf/bricks.urdf).
constexpr double kCube = 0.0234;

/// The scene `yaml` describes, expecting it to be read without error.
inline Scene parsed(const std::string& yaml) {
  Scene scene;
  const Status s = parseScene(yaml, "sweep", packageTypes(), &scene);
  EXPECT_TRUE(s.ok) << s.message;
  return scene;
}

}  // namespace test
}  // namespace brick_stack_sim
