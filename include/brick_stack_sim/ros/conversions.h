#pragma once

#include <string>

#include <geometry_msgs/Point.h>
#include <geometry_msgs/Pose.h>
#include <geometry_msgs/Transform.h>
#include <geometry_msgs/Twist.h>
#include <geometry_msgs/Vector3.h>
#include <Eigen/Geometry>

#include "brick_stack_sim/Brick.h"
#include "brick_stack_sim/PlaceBrick.h"
#include "brick_stack_sim/PushBrick.h"
#include "brick_stack_sim/StabilityEvent.h"
#include "brick_stack_sim/core/status.h"
#include "brick_stack_sim/core/types/brick.h"
#include "brick_stack_sim/core/types/sim_event.h"

namespace brick_stack_sim {
namespace ros_adapter {

/// How far a quaternion's norm may be from 1 before a request is refused [-].
/// Wider than float rounding so hand-typed quaternions (0.7071) pass; narrower
/// than any real mistake (a forgotten normalisation of an axis-angle sum).
constexpr double kQuaternionNormTolerance = 1e-3;

// --- messages in: every value is checked before it reaches the core --------
// `field` names the message field in the error ("pose.position.x is nan").

/// The refusal of a number that is not finite, naming its field ("steps[2].at").
Status notFinite(const std::string& field, double value);

/// Position [m] and orientation of a pose. Refused: NaN/Inf anywhere, a
/// quaternion whose norm differs from 1 by more than kQuaternionNormTolerance
/// (or is zero). A quaternion within tolerance is normalised.
Status fromMsg(const geometry_msgs::Pose& msg, const std::string& field, Eigen::Isometry3d* pose);
/// A point [m]; refused when any coordinate is NaN or Inf.
Status fromMsg(const geometry_msgs::Point& msg, const std::string& field, Eigen::Vector3d* point);
/// A vector (velocity [m/s], [rad/s] or impulse [N s]); refused when not finite.
Status fromMsg(const geometry_msgs::Vector3& msg, const std::string& field,
               Eigen::Vector3d* vector);

/// A twist's linear [m/s] and angular [rad/s] velocity, refused when not
/// finite (the message names `field`.linear or `field`.angular).
Status fromMsg(const geometry_msgs::Twist& msg, const std::string& field, Eigen::Vector3d* linear,
               Eigen::Vector3d* angular);

/// A PlaceBrick request as a placement: pose [m], linear [m/s] and angular
/// [rad/s] velocity in the world frame. Empty id and type are passed on empty
/// (the world picks brick_<n> and the default type).
Status fromMsg(const PlaceBrick::Request& request, BrickPlacement* placement);

/// A PushBrick request: impulse [N s] and its point of application [m], world frame.
Status fromMsg(const PushBrick::Request& request, Eigen::Vector3d* impulse, Eigen::Vector3d* point);

// --- messages out ------------------------------------------------------------

geometry_msgs::Pose toPoseMsg(const Eigen::Isometry3d& pose);
/// The same transform for tf (translation [m], rotation).
geometry_msgs::Transform toTransformMsg(const Eigen::Isometry3d& pose);
geometry_msgs::Point toPointMsg(const Eigen::Vector3d& point);
geometry_msgs::Vector3 toVectorMsg(const Eigen::Vector3d& vector);

/// Every field of a snapshot as Brick.msg. Refused (msg unspecified) when any
/// number of the snapshot is NaN or Inf: nothing non-finite is ever published.
Status toMsg(const BrickSnapshot& brick, Brick* msg);

/// An event of the core as StabilityEvent.msg; the header is left to the caller
/// (the stamp depends on whether the node publishes sim time).
StabilityEvent toMsg(const SimEvent& event);

/// Whether every number of the pose (translation and rotation) is finite.
bool allFinite(const Eigen::Isometry3d& pose);

}  // namespace ros_adapter
}  // namespace brick_stack_sim
