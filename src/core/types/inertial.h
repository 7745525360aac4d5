#pragma once
// A URDF inertial as the brick type keeps it: principal moments, and the
// centre of mass with the principal axes as a frame in the type frame.

#include <Eigen/Geometry>

#include "brick_stack_sim/core/status.h"

namespace brick_stack_sim {

/// `tensor` [kg m^2] about the centre of mass, axes of `origin` (the
/// inertial's origin in the type frame), as principal `moments` and the
/// `mass_frame` they are about. A diagonal tensor keeps origin's axes.
Status inertialFrame(const Eigen::Isometry3d& origin, const Eigen::Matrix3d& tensor,
                     Eigen::Vector3d* moments, Eigen::Isometry3d* mass_frame);

}  // namespace brick_stack_sim
