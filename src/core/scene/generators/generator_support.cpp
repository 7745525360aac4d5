#include "scene/generators/generator_support.h"

#include <cmath>

#include <Eigen/Geometry>

namespace brick_stack_sim {

Status checkTiming(const char* generator, double start, double interval) {
  if (!std::isfinite(start) || start < 0.0 || !std::isfinite(interval) || interval < 0.0)
    return Status::error(std::string(generator) + " start and interval must be finite and >= 0 s");
  return Status::success();
}

const BrickType* generatorType(const std::string& requested, const BrickTypeLibrary& types) {
  return types.find(requested.empty() ? types.defaultType() : requested);
}

Eigen::Matrix3d rotationFromRpy(const Eigen::Vector3d& rpy) {
  return (Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

}  // namespace brick_stack_sim
