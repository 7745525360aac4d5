// Brick types of shapes other than boxes for tests, finished as a scene's
// types are (solid built, inertia from the solid at uniform density).
#pragma once

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/types/brick_type.h"

namespace brick_stack_sim {
namespace test {

inline BrickType finishedType(BrickType type) {
  EXPECT_TRUE(finishBrickType(&type, false).ok) << type.name;
  return type;
}

/// A solid cylinder [m], [kg], axis along its frame's z; `rolling_friction` [m].
inline BrickType cylinderType(const std::string& name, double radius, double length, double mass,
                              double rolling_friction = 0.0) {
  BrickType type;
  type.name = name;
  type.shape = cylinderShape(radius, length);
  type.mass = mass;
  type.rolling_friction = rolling_friction;
  return finishedType(type);
}

/// The convex hull of `vertices` [m], of `mass` [kg].
inline BrickType convexType(const std::string& name, std::vector<Eigen::Vector3d> vertices,
                            double mass) {
  BrickType type;
  type.name = name;
  type.shape.kind = ShapeKind::kConvex;
  ShapePart part;
  part.kind = ShapeKind::kConvex;
  part.vertices = std::move(vertices);
  type.shape.parts = {part};
  type.mass = mass;
  return finishedType(type);
}

/// A ramp over x in [-half_x, half_x], y in [-half_y, half_y], rising from
/// 0 to `height` [m] towards y = -half_y, its bottom at z = 0 of its frame.
inline BrickType rampType(const std::string& name, double half_x, double half_y, double height,
                          double mass) {
  std::vector<Eigen::Vector3d> vertices;
  for (double x : {-half_x, half_x}) {
    vertices.emplace_back(x, -half_y, 0.0);
    vertices.emplace_back(x, half_y, 0.0);
    vertices.emplace_back(x, -half_y, height);
  }
  return convexType(name, vertices, mass);
}

}  // namespace test
}  // namespace brick_stack_sim
