#include "scene/generators/generator_support.h"

#include <cmath>

#include <Eigen/Geometry>

namespace brick_stack_sim {

Status checkStartAndType(const char* generator, double start, double interval,
                         const std::string& requested, const BrickTypeLibrary& types,
                         const BrickType** type) {
  if (!std::isfinite(start) || start < 0.0 || !std::isfinite(interval) || interval < 0.0)
    return Status::error(std::string(generator) + " start and interval must be finite and >= 0 s");
  *type = types.find(requested.empty() ? types.defaultType() : requested);
  if (!*type)
    return Status::error(std::string(generator) + " type '" + requested +
                         "' is not a known brick type");
  return Status::success();
}

ScheduledBrick& appendBrick(const BrickType& type, const Eigen::Vector3d& position, double at,
                            std::vector<ScheduledBrick>* bricks) {
  ScheduledBrick brick;
  brick.placement.id = "b" + std::to_string(bricks->size());
  brick.placement.type = type.name;
  brick.placement.pose.translation() = position;
  brick.at = at;
  bricks->push_back(std::move(brick));
  return bricks->back();
}

std::int64_t clampedCount(double count) {
  if (!(count > 0.0)) return 0;
  if (count >= static_cast<double>(kMaxCountedBricks)) return kMaxCountedBricks;
  return static_cast<std::int64_t>(count);
}

Eigen::Matrix3d rotationFromRpy(const Eigen::Vector3d& rpy) {
  return (Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

}  // namespace brick_stack_sim
