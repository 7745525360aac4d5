#include "brick_stack_sim/ros/conversions.h"

#include <cmath>
#include <limits>
#include <sstream>

namespace brick_stack_sim {
namespace ros_adapter {

Status notFinite(const std::string& field, double value) {
  std::ostringstream text;
  text << field << " is " << value << ": every number must be finite";
  return Status::error(text.str());
}

namespace {

/// Checks named components in order so the message points at the first bad one.
Status checkFinite(const std::string& field,
                   std::initializer_list<std::pair<const char*, double>> parts) {
  for (const auto& [name, value] : parts) {
    if (!std::isfinite(value)) return notFinite(field + "." + name, value);
  }
  return Status::success();
}

}  // namespace

Status fromMsg(const geometry_msgs::Point& msg, const std::string& field, Eigen::Vector3d* point) {
  if (Status s = checkFinite(field, {{"x", msg.x}, {"y", msg.y}, {"z", msg.z}}); !s) return s;
  *point = Eigen::Vector3d(msg.x, msg.y, msg.z);
  return Status::success();
}

Status fromMsg(const geometry_msgs::Vector3& msg, const std::string& field,
               Eigen::Vector3d* vector) {
  if (Status s = checkFinite(field, {{"x", msg.x}, {"y", msg.y}, {"z", msg.z}}); !s) return s;
  *vector = Eigen::Vector3d(msg.x, msg.y, msg.z);
  return Status::success();
}

Status fromMsg(const geometry_msgs::Pose& msg, const std::string& field, Eigen::Isometry3d* pose) {
  Eigen::Vector3d position;
  if (Status s = fromMsg(msg.position, field + ".position", &position); !s) return s;
  const geometry_msgs::Quaternion& q = msg.orientation;
  const std::string orientation = field + ".orientation";
  if (Status s = checkFinite(orientation, {{"x", q.x}, {"y", q.y}, {"z", q.z}, {"w", q.w}}); !s)
    return s;
  const double norm = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
  // A zero quaternion is the default of a message nobody filled in: say so.
  if (!(std::abs(norm - 1.0) <= kQuaternionNormTolerance)) {
    std::ostringstream text;
    text << orientation << " has norm " << norm << ": it must be a unit quaternion (within "
         << kQuaternionNormTolerance << ")"
         << (norm == 0.0 ? "; an all-zero orientation is not a rotation (identity is w = 1)" : "");
    return Status::error(text.str());
  }
  Eigen::Isometry3d result = Eigen::Isometry3d::Identity();
  result.translation() = position;
  result.linear() = Eigen::Quaterniond(q.w, q.x, q.y, q.z).normalized().toRotationMatrix();
  *pose = result;
  return Status::success();
}

Status fromMsg(const geometry_msgs::Twist& msg, const std::string& field, Eigen::Vector3d* linear,
               Eigen::Vector3d* angular) {
  Eigen::Vector3d linear_in, angular_in;
  if (Status s = fromMsg(msg.linear, field + ".linear", &linear_in); !s) return s;
  if (Status s = fromMsg(msg.angular, field + ".angular", &angular_in); !s) return s;
  *linear = linear_in;
  *angular = angular_in;
  return Status::success();
}

Status fromMsg(const PlaceBrick::Request& request, BrickPlacement* placement) {
  BrickPlacement result;
  result.id = request.id;
  result.type = request.type;
  if (Status s = fromMsg(request.pose, "pose", &result.pose); !s) return s;
  if (Status s = fromMsg(request.twist, "twist", &result.linear_velocity, &result.angular_velocity);
      !s)
    return s;
  *placement = std::move(result);
  return Status::success();
}

Status fromMsg(const PushBrick::Request& request, Eigen::Vector3d* impulse,
               Eigen::Vector3d* point) {
  Eigen::Vector3d impulse_in;
  Eigen::Vector3d point_in;
  if (Status s = fromMsg(request.impulse, "impulse", &impulse_in); !s) return s;
  if (Status s = fromMsg(request.point, "point", &point_in); !s) return s;
  *impulse = impulse_in;
  *point = point_in;
  return Status::success();
}

geometry_msgs::Point toPointMsg(const Eigen::Vector3d& point) {
  geometry_msgs::Point msg;
  msg.x = point.x();
  msg.y = point.y();
  msg.z = point.z();
  return msg;
}

geometry_msgs::Vector3 toVectorMsg(const Eigen::Vector3d& vector) {
  geometry_msgs::Vector3 msg;
  msg.x = vector.x();
  msg.y = vector.y();
  msg.z = vector.z();
  return msg;
}

geometry_msgs::Pose toPoseMsg(const Eigen::Isometry3d& pose) {
  geometry_msgs::Pose msg;
  msg.position = toPointMsg(pose.translation());
  // linear(), not rotation(): an isometry's linear part is already a rotation
  // and rotation() would run a needless polar decomposition.
  const Eigen::Quaterniond q(pose.linear());
  msg.orientation.x = q.x();
  msg.orientation.y = q.y();
  msg.orientation.z = q.z();
  msg.orientation.w = q.w();
  return msg;
}

geometry_msgs::Transform toTransformMsg(const Eigen::Isometry3d& pose) {
  const geometry_msgs::Pose p = toPoseMsg(pose);
  geometry_msgs::Transform msg;
  msg.translation.x = p.position.x;
  msg.translation.y = p.position.y;
  msg.translation.z = p.position.z;
  msg.rotation = p.orientation;
  return msg;
}

bool allFinite(const Eigen::Isometry3d& pose) { return pose.matrix().allFinite(); }

Status toMsg(const BrickSnapshot& brick, Brick* msg) {
  if (!allFinite(brick.pose)) return Status::error("brick " + brick.id + ": pose is not finite");
  if (!brick.linear_velocity.allFinite() || !brick.angular_velocity.allFinite())
    return Status::error("brick " + brick.id + ": twist is not finite");
  const double margin = brick.margin;
  if (!brick.com_above.allFinite() || !std::isfinite(brick.mass_above) || !std::isfinite(margin))
    return Status::error("brick " + brick.id + ": com_above, mass_above or margin is not finite");
  if (!brick.size.allFinite() || !std::isfinite(brick.mass) || !std::isfinite(brick.placed_at))
    return Status::error("brick " + brick.id + ": size, mass or placed_at is not finite");
  msg->id = brick.id;
  msg->type = brick.type;
  msg->pose = toPoseMsg(brick.pose);
  msg->twist.linear = toVectorMsg(brick.linear_velocity);
  msg->twist.angular = toVectorMsg(brick.angular_velocity);
  msg->size = toVectorMsg(brick.size);
  msg->mass = brick.mass;
  msg->state = static_cast<uint8_t>(brick.state);
  msg->com_above = toPointMsg(brick.com_above);
  msg->mass_above = brick.mass_above;
  msg->supported_by = brick.supported_by;
  msg->margin = margin;
  msg->asleep = brick.asleep;
  msg->fell_off = brick.fell_off;
  msg->placed_at = brick.placed_at;
  return Status::success();
}

StabilityEvent toMsg(const SimEvent& event) {
  StabilityEvent msg;
  msg.brick_id = event.brick_id;
  msg.kind = static_cast<uint8_t>(event.kind);
  msg.reason = event.reason;
  msg.affected = event.affected;
  return msg;
}

// The message constants are the enums' values; a change on either side must
// fail the build, not mislabel bricks.
static_assert(Brick::DYNAMIC == static_cast<int>(BrickState::kDynamic), "Brick.msg state");
static_assert(Brick::STABLE == static_cast<int>(BrickState::kStable), "Brick.msg state");
static_assert(Brick::LEANING == static_cast<int>(BrickState::kLeaning), "Brick.msg state");
static_assert(Brick::HELD == static_cast<int>(BrickState::kHeld), "Brick.msg state");
static_assert(StabilityEvent::SPAWNED == static_cast<int>(SimEventKind::kSpawned), "event kind");
static_assert(StabilityEvent::FROZEN == static_cast<int>(SimEventKind::kFrozen), "event kind");
static_assert(StabilityEvent::WOKEN == static_cast<int>(SimEventKind::kWoken), "event kind");
static_assert(StabilityEvent::IMPACT == static_cast<int>(SimEventKind::kImpact), "event kind");
static_assert(StabilityEvent::FELL_OFF == static_cast<int>(SimEventKind::kFellOff), "event kind");
static_assert(StabilityEvent::REMOVED == static_cast<int>(SimEventKind::kRemoved), "event kind");
static_assert(StabilityEvent::NONFINITE == static_cast<int>(SimEventKind::kNonFinite),
              "event kind");
static_assert(StabilityEvent::GRASPED == static_cast<int>(SimEventKind::kGrasped), "event kind");
static_assert(StabilityEvent::RELEASED == static_cast<int>(SimEventKind::kReleased), "event kind");
static_assert(StabilityEvent::LOST == static_cast<int>(SimEventKind::kLost), "event kind");

}  // namespace ros_adapter
}  // namespace brick_stack_sim
