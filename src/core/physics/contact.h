#pragma once
// What the stability models see of the physics: bodies in motion and their
// contacts, in Eigen types, named by handle.

#include <vector>

#include <Eigen/Core>

#include "physics/body_handle.h"

namespace brick_stack_sim {

/// A brick as the stability model sees it in one step.
struct BodyMotion {
  BodyHandle handle = 0;
  Eigen::Vector3d com = Eigen::Vector3d::Zero();               ///< [m], world
  double mass = 0.0;                                           ///< [kg]
  Eigen::Vector3d linear_velocity = Eigen::Vector3d::Zero();   ///< [m/s]
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  ///< [rad/s]
};

/// A force applied at a point, world: a load one brick passes to another.
struct PointForce {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();  ///< [N]
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  ///< [m]
};

/// One point of a contact manifold as the physics engine solved it.
struct ContactPoint {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< Midway between the surfaces, world [m].
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();   ///< Unit, from b towards a.
  double depth = 0.0;    ///< Signed distance of the surfaces [m], < 0: penetrating.
  double impulse = 0.0;  ///< Normal impulse applied in the last step [N s].
  /// Friction impulse on a in the last step [N s], world (in the contact plane).
  Eigen::Vector3d friction_impulse = Eigen::Vector3d::Zero();
};

/// The touching points of one pair of bodies in one step.
struct PairContact {
  BodyHandle a = 0, b = 0;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< Unit, from b towards a.
  /// The contact patch [m], world: the manifold points' positions or, where
  /// two faces rest flush, the corners of their exact overlap.
  std::vector<Eigen::Vector3d> points;
  /// The engine's points with their forces; empty for contacts found from
  /// geometry (a brick placed at rest has not been simulated yet).
  std::vector<ContactPoint> manifold;
  double approach_speed = 0.0;  ///< Largest closing speed along the normal [m/s].
  double friction = 0.0;        ///< Combined Coulomb coefficient of the pair [-].
};

}  // namespace brick_stack_sim
