#pragma once
// Bullet stays behind this line: public core headers speak Eigen only.

#include <btBulletDynamicsCommon.h>
#include <Eigen/Geometry>

namespace brick_stack_sim {

inline btVector3 convertEigenToBt(const Eigen::Vector3d& v) {
  return btVector3(v.x(), v.y(), v.z());
}

inline Eigen::Vector3d convertBtToEigen(const btVector3& v) {
  return Eigen::Vector3d(v.x(), v.y(), v.z());
}

inline btTransform convertEigenToBt(const Eigen::Isometry3d& pose) {
  const Eigen::Matrix3d& r = pose.linear();
  const btMatrix3x3 basis(r(0, 0), r(0, 1), r(0, 2), r(1, 0), r(1, 1), r(1, 2), r(2, 0), r(2, 1),
                          r(2, 2));
  return btTransform(basis, convertEigenToBt(pose.translation()));
}

inline Eigen::Isometry3d convertBtToEigen(const btTransform& transform) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  const btMatrix3x3& b = transform.getBasis();
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col) pose.linear()(row, col) = b[row][col];
  pose.translation() = convertBtToEigen(transform.getOrigin());
  return pose;
}

}  // namespace brick_stack_sim
