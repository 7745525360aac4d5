#pragma once
// Everything a BrickWorld holds, shared by the files that implement it (the
// staged step, the placement check, the numerical guard), as Box2D's
// b2World is shared by its stages. Not part of the public interface.

#include <memory>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "brick_stack_sim/core/geometry/box_geometry.h"
#include "brick_stack_sim/core/geometry/convex_solid.h"
#include "brick_stack_sim/core/world/brick_world.h"
#include "bullet/bullet_scene.h"
#include "bullet/dormant_colliders.h"
#include "stability/stability_model.h"
#include "world/brick_record.h"
#include "world/brick_sets.h"

namespace brick_stack_sim {

/// The bricks by id and handle, in placement order.
class BrickRegistry {
 public:
  BrickRecord* add(std::unique_ptr<BrickRecord> brick);
  void erase(BrickRecord* brick);
  BrickRecord* find(const std::string& id) const;
  BrickRecord* find(BodyHandle handle) const;
  const std::vector<std::unique_ptr<BrickRecord>>& all() const { return bricks_; }
  std::vector<const BrickRecord*> records() const;
  std::size_t size() const { return bricks_.size(); }
  /// The first free id of the form brick_<n>, n from `serial` up.
  std::string freeId(unsigned serial) const;

 private:
  std::vector<std::unique_ptr<BrickRecord>> bricks_;
  std::unordered_map<std::string, BrickRecord*> by_id_;
  std::unordered_map<BodyHandle, BrickRecord*> by_handle_;
};

/// Where the centre of mass of a brick of `type` at `pose` lies [m].
Eigen::Vector3d centreOfMassAt(const BrickType& type, const Eigen::Isometry3d& pose);

struct WorldState {
  WorldState(const WorldOptions& world_options, const BrickTypeLibrary& brick_types, double start);

  WorldOptions options;
  BrickTypeLibrary types;
  double start_time = 0.0;  ///< Sim time of step 0 [s]: worlds that replace one go on from it.
  ConvexSolid table_solid;  ///< The table's box, centred on its own frame.
  ConvexSolid floor_solid;  ///< A slab far wider than anything that lands on it.
  BulletScene scene;
  DormantColliders dormant;
  BrickSets sets;
  BrickRegistry bricks;
  std::unique_ptr<StabilityModel> model;  ///< Null in mode none.
  std::vector<PairContact> contacts;      ///< Of the last Bullet step.
  /// What held bricks press on the frozen bricks that stop them this step,
  /// as contacts (world/held_bricks): Bullet has no contact between a
  /// kinematic and a static body.
  std::vector<PairContact> presses;
  /// The model has something new to look at without a Bullet step: a brick
  /// placed, removed, frozen or woken.
  bool model_changed = false;
  /// Bricks were placed at rest with more to come at the same instant: the
  /// model has not judged the structure as a whole yet (the next step or
  /// request does).
  bool judgement_pending = false;
  /// Movers placed at rest since the last step, in placement order: Bullet
  /// has not moved them, so a brick placed at rest against one is judged
  /// with it (a V).
  std::vector<BodyHandle> placed_at_rest;
  unsigned next_serial = 0;
  /// Grows at every step that moves or judges something and at every request
  /// that changes something (BrickWorld::revision).
  std::uint64_t revision = 0;
  /// Every stamp of a brick's changed_at after revision `stamps_from`, in
  /// revision order: a reader of snapshotChangedSince() finds the frozen
  /// bricks that changed here without walking every brick (whose records
  /// lie far apart in memory: 2000 frozen bricks cost a runner that looks
  /// every 10 ms more than ten moving ones).
  std::vector<std::pair<std::uint64_t, BodyHandle>> stamps;
  std::uint64_t stamps_from = 0;
  /// The first of `stamps` made after revision `revision`.
  std::vector<std::pair<std::uint64_t, BodyHandle>>::const_iterator firstStampAfter(
      std::uint64_t revision) const;
  CostCounters cost;
  /// Bricks the guard found outside the world box this step, with why; the
  /// world removes them (as lost) once the guard is done with its loop.
  std::vector<std::pair<std::string, std::string>> left_world;
  std::vector<SimEvent> events;

  /// What a request that passed its checks is about to change.
  enum class Change {
    kBricks,  ///< Poses, speeds or targets: a new revision stamps what changes.
    kModel,   ///< And the model has something new to look at in the next step.
    /// And bodies move in or out of Bullet's world: the last step's contacts
    /// name them wrongly, so they go.
    kBodies,
  };
  /// Every request records its change here after its checks and before it
  /// changes anything, so that a refused request leaves the world as it was,
  /// its revision included.
  void recordChange(Change change);
  /// `brick` changed in this revision (BrickRecord::changed_at), and the
  /// stamp is logged; the log keeps up to twice as many stamps as bricks
  /// (plus 64), then drops its older half.
  void stampChanged(BrickRecord* brick);

  double time() const { return start_time + static_cast<double>(cost.steps) * options.time_step; }
  void emit(SimEventKind kind, const std::string& id, std::string reason,
            std::vector<std::string> affected = {});
  /// A brick's id, "table", "floor", or "brick#<n>" for a handle no brick has.
  std::string nameOf(BodyHandle handle) const;
  /// The solid of a brick (at its pose in Bullet), of the table, or of the
  /// floor as a slab far wider than anything that can land on it; valid
  /// while the brick lives.
  PlacedSolid solidOf(BodyHandle handle) const;
  /// The Coulomb coefficient of a brick's material or the table's [-].
  double frictionOf(BodyHandle handle) const;
  /// What the model is told of a brick now.
  BodyMotion motionOf(const BrickRecord& brick) const;
  /// The speed of a brick's fastest point, at most: its centre of mass's
  /// speed plus its spin times its reach from there [m/s].
  double fastestPointSpeed(const BrickRecord& brick) const;
};

/// The decision path: every call of the model goes through decide(), and
/// every decision is applied by applyDecisions() (bricks change mode,
/// events are emitted). decide() returns the decisions (none without a model).
void applyDecisions(WorldState* world, const StabilityDecisions& decisions);
StabilityDecisions decide(WorldState* world, const StabilityInput& input);

}  // namespace brick_stack_sim
