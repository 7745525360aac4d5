#pragma once
// Rigid-block static equilibrium with Coulomb friction, as a linear program
// (Livesley 1978; Whiting, Ochsendorf and Durand 2009), solved with COIN-OR
// Clp. Clp's types stay in the .cpp.

#include <string>
#include <vector>

#include <Eigen/Geometry>

namespace brick_stack_sim {

/// A body of the problem: free (its forces must balance) or fixed (the
/// table, or a frozen brick taken as immovable for the question asked).
struct StaticsBody {
  double mass = 0.0;                              ///< [kg]
  Eigen::Vector3d com = Eigen::Vector3d::Zero();  ///< [m], world
  bool fixed = false;
  /// Loads from outside the problem besides its weight (bricks resting or
  /// leaning on it that are not bodies of the problem): force [N] and its
  /// torque about `com` [N m], world.
  Eigen::Vector3d applied_force = Eigen::Vector3d::Zero();
  Eigen::Vector3d applied_torque = Eigen::Vector3d::Zero();
};

/// Marks a contact's second body as the fixed world (table, floor).
constexpr int kStaticsGround = -1;

/// One contact point: body `a` touches body `b` (or the ground) at `point`;
/// the force on `a` is `normal` times a non-negative normal force plus a
/// friction force no larger than `friction` times it; `b` gets the opposite.
struct StaticsContact {
  int a = 0;
  int b = kStaticsGround;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();    ///< [m], world
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< Unit, from b towards a.
  double friction = 0.0;                              ///< Coulomb coefficient [-].
};

struct StaticsOptions {
  /// Faces of the pyramid inscribed in each friction cone (>= 4). Its edges
  /// lie along the world x and y axes projected on the contact plane, so
  /// friction along a brick's axes is exact; between them the cone is cut
  /// by at most 1 - cos(pi / faces) (7.6 % at 8 faces).
  int friction_faces = 8;
  double gravity = 9.81;  ///< [m/s^2], along -z.
  /// A uniform acceleration every free body must also resist [m/s^2], world
  /// (e.g. a horizontal shake); it adds to gravity's.
  Eigen::Vector3d extra_acceleration = Eigen::Vector3d::Zero();
  /// Feasible when the least total imbalance is below this fraction of the
  /// largest load on a free body (weight or applied force) [-].
  double tolerance = 1e-7;
};

/// The answer of the statics LP.
struct StaticsSolution {
  /// The LP solved (false: Clp failed, numbers are meaningless; `message` says why).
  bool solved = false;
  /// Contact forces exist that balance every free body.
  bool feasible = false;
  /// Per body: the force and torque no admissible contact force can supply,
  /// in the least-imbalance solution, as a fraction of the largest load
  /// on a free body (torques over the problem's size) [-]; 0 for bodies that
  /// are balanced, and for fixed ones. The bodies that must move.
  std::vector<double> imbalance;
  /// Per contact: the force on `a` in that solution [N], world.
  std::vector<Eigen::Vector3d> forces;
  std::string message;
};

/// Do non-negative normal forces inside the (linearised) friction cones
/// exist that balance gravity (and `extra_acceleration`) on every free body?
/// The LP minimises the total imbalance, so when they do not it also names
/// the bodies left unbalanced. Contacts between two fixed bodies are ignored.
StaticsSolution solveStatics(const std::vector<StaticsBody>& bodies,
                             const std::vector<StaticsContact>& contacts,
                             const StaticsOptions& options = StaticsOptions());

/// The largest horizontal acceleration [m/s^2] the set resists along
/// `direction` (a horizontal unit vector) on top of gravity: how hard it may
/// be shaken, or (over g) the tangent of the tilt it survives. 0 when it does
/// not stand at all; capped at `cap` [m/s^2].
double horizontalAccelerationMargin(const std::vector<StaticsBody>& bodies,
                                    const std::vector<StaticsContact>& contacts,
                                    const Eigen::Vector3d& direction,
                                    const StaticsOptions& options = StaticsOptions(),
                                    double cap = 100.0);

}  // namespace brick_stack_sim
