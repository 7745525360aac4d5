#pragma once
// Rigid-block static equilibrium with Coulomb friction, as a linear program
// (Livesley 1978; Whiting, Ochsendorf and Durand 2009), solved with COIN-OR
// Clp. Clp's types stay in the .cpp.

#include <cstdint>
#include <string>
#include <unordered_map>
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
  /// Faces of the pyramid inscribed in each friction cone (>= 4). On a
  /// tilted contact an edge lies along the plane's steepest slope, so the
  /// friction that holds a weight on it is exact; on a flat one the edges
  /// lie along the world x and y axes projected on it, so friction along a
  /// brick's axes is exact. Between edges the cone is cut by at most
  /// 1 - cos(pi / faces) (7.6 % at 8 faces).
  int friction_faces = 8;
  double gravity = 9.81;  ///< [m/s^2], along -z.
  /// A uniform acceleration every free body must also resist [m/s^2], world
  /// (e.g. a horizontal shake); it adds to gravity's.
  Eigen::Vector3d extra_acceleration = Eigen::Vector3d::Zero();
  /// Feasible when the least total imbalance is below this fraction of the
  /// largest load on a free body (weight or applied force) [-].
  double tolerance = 1e-7;
};

/// Where LPs ended (Clp's basis), under names that outlive one problem, so
/// that the next problem over mostly the same bodies and contacts starts
/// from there instead of from scratch: a component that grows by a brick
/// is re-solved in a few pivots. Each solve updates the names it has and
/// keeps the others: problems that take turns (the groups of a pile, each
/// asked every tick) each start from where they last ended. Opaque to
/// callers; kept by them between solves.
struct StaticsBasis {
  /// Per key (a contact's or a body's), the status (ClpSimplex::Status) of
  /// each of its columns or rows, by index there; kUnknown where no LP has
  /// left one. One lookup per contact or body: a pile's LPs name tens of
  /// thousands of columns, and a lookup per column was most of their set-up.
  using Statuses = std::unordered_map<std::uint64_t, std::vector<unsigned char>>;
  static constexpr unsigned char kUnknown = 0xff;
  /// Contact key -> one status per cone edge; body key -> its rows (0..5);
  /// body key -> its imbalance columns (0..11).
  Statuses columns, rows, imbalance;
  /// Statuses kept, over all three.
  std::size_t names = 0;
};

/// Names for one problem's bodies and contacts (parallel to them), and the
/// basis to start from and to leave the answer's basis in. Keys that
/// collide cost pivots, never correctness: any basis is a valid start.
struct StaticsWarmStart {
  std::vector<std::uint64_t> body_keys;
  std::vector<std::uint64_t> contact_keys;
  StaticsBasis* basis = nullptr;
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
  /// Per body, when not feasible: whether it moves in the collapse
  /// mechanism the LP's dual names, a virtual motion of the free bodies that
  /// every contact admits (touching faces part or slide within friction)
  /// and in which the loads do work. Those bodies cannot stay, together:
  /// with every other body held fixed they still cannot stand. False for
  /// fixed bodies and in a feasible solution.
  std::vector<bool> moves;
  /// Per contact: the force on `a` in that solution [N], world.
  std::vector<Eigen::Vector3d> forces;
  int iterations = 0;  ///< Simplex pivots Clp took.
  std::string message;
};

/// Do non-negative normal forces inside the (linearised) friction cones
/// exist that balance gravity (and `extra_acceleration`) on every free body?
/// The LP minimises the total imbalance, so when they do not it also names
/// the bodies left unbalanced. Contacts between two fixed bodies are ignored.
/// With `warm`, the LP starts from `warm->basis` and leaves its own there.
StaticsSolution solveStatics(const std::vector<StaticsBody>& bodies,
                             const std::vector<StaticsContact>& contacts,
                             const StaticsOptions& options = StaticsOptions(),
                             StaticsWarmStart* warm = nullptr);

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
