#pragma once
// What a planner knows of the structure it builds: which bricks it placed,
// where each came to rest, and which have fallen since. No ROS: the builder
// feeds it what ~get_bricks returns, a test feeds it by hand.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "brick_stack_sim/core/scene/scene.h"

namespace brick_stack_sim {
namespace planner {

/// What the ledger needs of a brick as the simulator reports it.
struct ObservedBrick {
  std::string id;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();      ///< Centre, frame world [m].
  Eigen::Vector3d linear_velocity = Eigen::Vector3d::Zero();   ///< [m/s]
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  ///< [rad/s]
  bool frozen = false;    ///< STABLE or LEANING: the stability layer holds it.
  bool leaning = false;   ///< LEANING: frozen, held by friction and side contacts.
  bool asleep = false;    ///< Bullet has deactivated it.
  bool fell_off = false;  ///< Dropped off the table.
};

/// When the ledger calls a brick settled and when fallen.
struct LedgerOptions {
  /// A brick that is neither frozen nor asleep settles once it is slower than
  /// these [m/s], [rad/s] (sim.yaml's sleeping thresholds) and has moved less
  /// than `settle_step` since the previous observation [m].
  double settle_linear_speed = 0.005;
  double settle_angular_speed = 0.05;
  double settle_step = 0.0005;
  /// A settled brick has fallen once its centre is this far from where it
  /// settled [m] (most of a KAPLA's thickness: no rest jitter comes near it)
  double fall_distance = 0.005;
  /// ... or it has turned this much from how it settled [rad]: 3 degrees, a
  /// tilt anyone sees, which a plank that tips off an edge onto the table
  /// (6 degrees for a KAPLA) exceeds while its centre barely moves.
  double fall_angle = 0.05;
};

/// How a placed brick stands at the last observation.
///
/// After a brick has been thrown, a brick of the structure that moves more
/// than `fall_distance` (or turns more than `fall_angle`) from where it had
/// come to rest has been knocked (kFallen with `fell_after_throw`) only when
/// it left the structure: it fell off the table, was removed, or its centre
/// is more than `fall_distance` lower than where it had come to rest (it no
/// longer rests on what it was placed on). One that moved without dropping,
/// such as a plank slid 11 mm along its layer by the blow, still stands in
/// the structure: kStanding with `shifted` (docs/ros_interface.md,
/// "blueprint_builder"). Before any throw, such a move is a fall.
enum class BrickFate { kUnsettled, kStanding, kFallen, kThrown };

/// One brick the builder placed (a thrown brick is not part of the structure).
struct LedgerEntry {
  std::string id;
  int placement = 0;       ///< 1-based order of placement among all bricks placed.
  double placed_at = 0.0;  ///< Sim time [s].
  Eigen::Isometry3d placed_pose = Eigen::Isometry3d::Identity();
  bool thrown = false;
  std::optional<Eigen::Isometry3d> settled_pose;  ///< Where it first came to rest.
  std::optional<Eigen::Isometry3d> last_pose;     ///< At the previous observation.
  bool frozen = false;                            ///< At the last observation.
  bool leaning = false;                           ///< Frozen and LEANING, at the last one.
  bool shifted = false;  ///< Standing, but moved in place by a throw (see BrickFate).
  BrickFate fate = BrickFate::kUnsettled;
  double fell_at = 0.0;           ///< Sim time it was first seen fallen [s].
  int placed_when_fell = 0;       ///< Bricks placed by then (all, thrown included).
  bool fell_after_throw = false;  ///< Knocked: a brick had been thrown before it fell.
  std::string how;                ///< Why it counts as fallen or shifted, in words.
};

/// The ledger's account, counted over every brick placed.
struct BuildSummary {
  int placed = 0, standing = 0, fallen = 0, knocked = 0, unsettled = 0, thrown = 0;
  int refused = 0;
  int frozen = 0;   ///< Standing bricks the stability layer holds (0 in mode none).
  int leaning = 0;  ///< Of those frozen, the LEANING ones; the rest are STABLE.
  int shifted = 0;  ///< Of those standing, the ones a throw moved in place.
};

class BuildLedger {
 public:
  explicit BuildLedger(const LedgerOptions& options = LedgerOptions()) : options_(options) {}

  /// A placement the simulator accepted at sim time `t` [s], at `pose`. A
  /// brick of the structure must come to rest within `fall_distance` of it
  /// seen from above and turned less than `fall_angle` (it may drop onto what
  /// is below), or it counts as fallen.
  void recordPlaced(const std::string& id, const Eigen::Isometry3d& pose, double t, bool thrown);
  /// A placement it refused, with its reason.
  void recordRefused(const std::string& id, const std::string& reason);

  /// Takes in every brick the simulator reports at sim time `t` [s]; a placed
  /// brick missing from `bricks` has been removed, which counts as fallen.
  /// Returns the entries that fell, or were shifted in place by a throw, at
  /// this observation, in placement order (see BrickFate).
  std::vector<const LedgerEntry*> observe(double t, const std::vector<ObservedBrick>& bricks);

  const LedgerEntry* find(const std::string& id) const;
  const std::vector<LedgerEntry>& entries() const { return entries_; }
  /// The first brick of the structure seen fallen (earliest, then first placed).
  const LedgerEntry* firstFallen() const;
  const std::vector<std::string>& refusals() const { return refusals_; }
  BuildSummary summary() const;

  /// Whether the build did what the scene expects, and why not in words
  /// naming the brick: a scene that should stand fails on any brick of the
  /// structure that fell before a throw, never settled or was refused; one
  /// that should collapse fails when nothing fell.
  bool met(ExpectedOutcome expect, std::string* verdict) const;

 private:
  LedgerEntry* findMutable(const std::string& id);
  /// Whether a brick not yet at rest has come to rest where it was placed
  /// (then standing); returns why it counts as fallen, or "".
  std::string judgeResting(LedgerEntry* entry, const ObservedBrick& brick) const;
  /// Whether a brick that had come to rest has fallen since, returning why
  /// in words, or ""; after a throw a move in place sets `shifted` instead
  /// (and `*shifted_now` the first time).
  std::string judgeSettled(LedgerEntry* entry, const Eigen::Isometry3d& pose,
                           bool* shifted_now) const;

  LedgerOptions options_;
  std::vector<LedgerEntry> entries_;
  std::vector<std::string> refusals_;  ///< "id: reason", in order.
  int placed_ = 0;
  bool thrown_yet_ = false;
};

/// The one-line summary a demo prints last: "demo summary: scene <name>,
/// placed N, standing N, fallen N, knocked N, unsettled N, refused N,
/// thrown N, frozen N (stable N, leaning N), t=T s", with " (N shifted)"
/// after standing's count when a throw shifted bricks in place.
std::string formatSummary(const std::string& scene, const BuildSummary& summary, double t);

}  // namespace planner
}  // namespace brick_stack_sim
