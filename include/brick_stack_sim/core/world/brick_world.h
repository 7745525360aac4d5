#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "brick_stack_sim/core/status.h"
#include "brick_stack_sim/core/types/brick.h"
#include "brick_stack_sim/core/types/brick_type.h"
#include "brick_stack_sim/core/types/bullet_stage_seconds.h"
#include "brick_stack_sim/core/types/sim_event.h"
#include "brick_stack_sim/core/types/world_options.h"

namespace brick_stack_sim {

/// What the simulation has spent, for benchmarks.
struct CostCounters {
  std::uint64_t steps = 0;              ///< Calls to step().
  std::uint64_t bullet_steps = 0;       ///< Steps that advanced Bullet.
  std::uint64_t awake_brick_steps = 0;  ///< Sum over Bullet steps of bricks awake in it.
  std::uint64_t nonfinite = 0;          ///< NaN/Inf values caught and repaired.
  std::uint64_t blowups = 0;            ///< Runaway speeds (diverged solver) caught and repaired.
  /// Bricks the model woke again after they froze where it had woken them,
  /// without moving: a wake/refreeze cycle (must be 0).
  std::uint64_t wake_cycles = 0;
  std::uint64_t lost = 0;               ///< Bricks that left the world box and were removed.
  std::uint64_t stability_updates = 0;  ///< Steps in which the stability model ran.
  // Wall time per stage of step() [s], for the benchmark's cost shares.
  double bullet_seconds = 0.0;     ///< Advancing Bullet, with its colliders and the guard.
  double contact_seconds = 0.0;    ///< Reading contacts from Bullet's manifolds.
  double stability_seconds = 0.0;  ///< The stability model and freeze / wake.
  /// Bullet's own step, by stage [s]: part of bullet_seconds, which also
  /// holds the colliders' preparation, the guard and Bullet's bookkeeping.
  BulletStageSeconds bullet_stages;
};

/// The answer to "would a brick at rest here be stable?" (evaluatePlacement).
struct PlacementReport {
  /// Statics holds it where it is (contact forces within friction balance
  /// it on what it touches), and the stability model, if any, finds that
  /// nothing under it would fall.
  bool stable = false;
  BrickState state = BrickState::kDynamic;  ///< kStable or kLeaning when stable.
  /// Of the brick itself, as Brick.msg's margin [m]: its COM against the
  /// hull of what carries it from below (0 when nothing does).
  double margin = 0.0;
  /// The least horizontal acceleration, along +-x and +-y, that would move
  /// it on what it touches (statics; 0 when it does not stand) [m/s^2].
  /// Over g it is the tangent of the tilt it survives.
  double acceleration_margin = 0.0;
  std::vector<std::string> supported_by;  ///< Brick ids, "table" or "floor".
  std::vector<std::string> would_fall;    ///< Frozen bricks its load would tip.
  std::string reason;
};

struct BrickRecord;
struct WorldState;

/// Bricks on a table, simulated by Bullet in double precision with a fixed
/// time step, with a stability model on top (WorldOptions::stability.mode)
/// that freezes bricks resting stably and wakes them when their load leaves
/// their support. Every request is validated first: a refused request returns
/// an error Status and leaves the world exactly as it was. Bricks are kept in
/// placement order, so the same calls in the same order give bit-identical
/// results.
class BrickWorld {
 public:
  /// Fails (and leaves `world` empty) when the options or types are invalid.
  /// The world's clock starts at `start_time` [s] (a world that replaces
  /// another goes on from its time).
  static Status create(const WorldOptions& options, const BrickTypeLibrary& types,
                       std::unique_ptr<BrickWorld>* world, double start_time = 0.0);
  ~BrickWorld();
  BrickWorld(const BrickWorld&) = delete;
  BrickWorld& operator=(const BrickWorld&) = delete;

  /// Would addBrick() accept this placement? Nothing changes.
  Status checkPlacement(const BrickPlacement& placement) const;
  /// Adds a brick; `assigned_id` (optional) receives its id. A brick placed
  /// at rest is judged by the model at once, alone or with the bricks placed
  /// at rest with it; `more_to_come`: more bricks follow at this instant,
  /// and the structure is judged as a whole only when the last is in, at
  /// the next step, or by judgePlacements() (a paused node places so).
  Status addBrick(const BrickPlacement& placement, std::string* assigned_id = nullptr,
                  bool more_to_come = false);
  /// Judges the structure placed with `more_to_come` now; a no-op when none is pending.
  void judgePlacements();
  /// Adds bricks at one instant, each checked and placed as by addBrick()
  /// in order (one refused leaves the others placed); those placed at rest
  /// are judged together once all are in, as one structure: an arch whose
  /// half-rings could not stand alone stands when its ring closes. One
  /// status per placement; `assigned_ids` (optional) receives the ids,
  /// empty for a refused one.
  std::vector<Status> addBricks(const std::vector<BrickPlacement>& placements,
                                std::vector<std::string>* assigned_ids = nullptr);
  /// Removes a brick; what rested on it is woken.
  Status removeBrick(const std::string& id);
  /// Applies an impulse [N s] at a world point [m] on or in the brick
  /// (within kPushPointTolerance of its surface) to a brick, waking it and
  /// what it carries.
  Status applyImpulse(const std::string& id, const Eigen::Vector3d& impulse,
                      const Eigen::Vector3d& point);
  /// How far outside its surface a push may be applied to a brick [m].
  static constexpr double kPushPointTolerance = 1e-3;

  /// Takes a brick into the hand where it is: kinematic (state kHeld), it
  /// follows the held target (setHeldTarget), which starts at its pose, and
  /// pushes what it meets. One brick at a time; a brick that carries frozen
  /// bricks is refused (what rests on it would be left in the air).
  Status graspBrick(const std::string& id);
  /// Where the held brick is to go [m], frame world; it moves there no
  /// faster than WorldOptions::held allows. Refused when nothing is held, or
  /// the pose is not finite, not a rotation, or below the table top.
  Status setHeldTarget(const Eigen::Isometry3d& target);
  /// The id of the held brick; empty when none is.
  std::string heldBrick() const;
  /// Lets the held brick `id` go with these velocities [m/s], [rad/s]
  /// (frame world): simulated again, it may settle and join the stack.
  Status releaseBrick(const std::string& id, const Eigen::Vector3d& linear_velocity,
                      const Eigen::Vector3d& angular_velocity);
  /// Would a brick placed at rest here stand, and would the stack bear it?
  /// Answered by rigid-block statics in every mode (what it touches held
  /// fixed), and by the stability model, when there is one, for the load on
  /// the stack below. Refused like addBrick() when the placement is invalid.
  /// Nothing changes.
  Status evaluatePlacement(const BrickPlacement& placement, PlacementReport* report) const;

  /// Advances the world by one fixed time step.
  void step();
  /// A step would only advance the clock: a stability model runs, no brick
  /// is awake in Bullet or held, and the model has nothing new to look at.
  /// Until a request changes the world, a caller may step it in batches.
  bool settled() const;

  double time() const;  ///< Sim time [s].
  const WorldOptions& options() const;
  const BrickTypeLibrary& types() const;
  const CostCounters& cost() const;

  std::size_t brickCount() const;
  /// Every brick, in placement order.
  std::vector<BrickSnapshot> snapshot() const;
  /// Every brick's id, in placement order: what snapshot() says at a
  /// fraction of its cost when only the names are wanted.
  std::vector<std::string> brickIds() const;
  /// A count that grows with every step and every request that may change
  /// a brick (a step of a settled() world changes none): a publisher keeps
  /// the value it last saw, and asks snapshotChangedSince() for what
  /// changed after it.
  std::uint64_t revision() const;
  /// The bricks whose snapshot() or supportGeometry() may differ from what
  /// they were when revision() was `revision`, in placement order: every
  /// brick that is not frozen (when anything happened since), and the
  /// frozen bricks that froze or that the model described anew since. A
  /// frozen brick nothing has touched costs no stability query. `serials`
  /// (optional) receives every brick's serial in placement order, so that a
  /// caller can tell which bricks were removed; that walks every brick.
  /// Without it, and for a `revision` not long past, the cost follows the
  /// bricks reported, not the bricks in the world. A world that replaces
  /// another (a reset) counts from 0 again.
  std::vector<BrickSnapshot> snapshotChangedSince(std::uint64_t revision,
                                                  std::vector<unsigned>* serials = nullptr) const;
  /// One brick; false when the id is unknown.
  bool find(const std::string& id, BrickSnapshot* brick) const;
  /// The support patches of a brick as the stability model sees them; false
  /// when the id is unknown or the model knows nothing of it (mode none).
  bool supportGeometry(const std::string& id, SupportGeometry* geometry) const;
  /// Events since the last call, oldest first.
  std::vector<SimEvent> takeEvents();

  /// A second world in this one's state (bricks, Bullet bodies bit for
  /// bit, the model's support graph and rest tracking, clock, counters;
  /// not the events not yet taken), independent of it from then on. The
  /// same requests and steps on both give the same bits when
  /// copiesExactly(); otherwise the copy starts without Bullet's contact
  /// caches between moving bricks and its motion may differ in the last
  /// bits, growing as bricks collide.
  std::unique_ptr<BrickWorld> copy() const;
  /// No brick moves in Bullet or is held: every brick is frozen (a settled
  /// structure), so copy() is exact.
  bool copiesExactly() const;
  /// A world like this one in stability mode `mode` (its other options,
  /// types and clock this one's), with every brick placed where it is now
  /// at its velocities, all at one instant: bricks at rest are judged anew
  /// by that mode's model as one structure, a held brick is let go. Fails,
  /// leaving `copy` alone, on an unknown mode or a brick the new world
  /// refuses (two bricks pressed into each other beyond the overlap
  /// tolerance).
  Status copyInMode(const std::string& mode, std::unique_ptr<BrickWorld>* copy) const;

  /// Every brick is where its mode says (Bullet's world, the movers, the
  /// frozen colliders); checked after each step in debug builds.
  Status checkInvariants() const;

 private:
  explicit BrickWorld(std::unique_ptr<WorldState> state);
  /// removeBrick, announced by an event of `kind` (removed or lost).
  Status remove(const std::string& id, SimEventKind kind, const std::string& reason);
  /// A checked placement's record and Bullet body, in the world's sets.
  BrickRecord* placeBody(const BrickPlacement& placement);
  /// Has the model judge a brick just placed at rest (see addBrick()).
  void judgeAtRest(BrickRecord* brick, const BrickPlacement& placement, bool more_to_come);
  std::unique_ptr<WorldState> state_;
};

}  // namespace brick_stack_sim
