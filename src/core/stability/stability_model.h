#pragma once
// The interface between the world and a stability model (DESIGN.md section 2).

#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "brick_stack_sim/core/brick.h"
#include "brick_stack_sim/core/geometry/polygon2d.h"
#include "brick_stack_sim/core/stability/stability_options.h"
#include "stability/contact.h"

namespace brick_stack_sim {

/// One support of a brick: the patch where it rests on `supporter`, or
/// (among a brick's side contacts) where it leans on or touches it.
struct SupportPatch {
  BodyHandle supporter = 0;
  std::vector<Eigen::Vector3d> points;  ///< Contact points, world [m].
  /// Per point: unit, from the supporter towards the brick.
  std::vector<Eigen::Vector3d> normals;
  double friction = 0.0;  ///< Coulomb coefficient of the pair [-].
  Polygon2d hull;         ///< The points' hull, projected along gravity.
  double height = 0.0;    ///< Mean z of the points [m].
};

/// A force a brick receives at one contact point, as the statics LP found
/// it: one admissible set of contact forces that balances the brick (the LP
/// picks one where statics leaves them undetermined).
struct ContactForce {
  BodyHandle other = 0;                               ///< The body pushing: a brick or the ground.
  Eigen::Vector3d point = Eigen::Vector3d::Zero();    ///< [m], world
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< Unit, from `other` into the brick.
  /// On the brick [N], world, with weights in statics' g (StaticsOptions::gravity).
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  double friction = 0.0;                              ///< Coulomb coefficient of the pair [-].
};

/// What a stability model knows about one brick.
struct BrickStability {
  bool frozen = false;
  Eigen::Vector3d com_above = Eigen::Vector3d::Zero();  ///< [m]
  double mass_above = 0.0;                              ///< [kg]
  double margin = 0.0;  ///< Signed distance of the COM-above projection to the support hull [m].
  std::vector<SupportPatch> supports;
  /// Contacts with frozen bricks or the ground that do not carry it from
  /// below (it leans on them, or touches them beside it or above it), for
  /// the models that judge them (criteria with usesSideContacts()).
  std::vector<SupportPatch> side_contacts;
  Polygon2d combined_hull;      ///< Hull of all support patches.
  double support_height = 0.0;  ///< Mean height of the supports [m].
  /// Its contact forces where the last check solved statics for it (a
  /// leaning group; any brick of a component whose LP ran); else empty.
  std::vector<ContactForce> contact_forces;
};

/// Why a brick left the stack.
enum class WakeCause {
  kOutsideSupport,    ///< Its load left its support (the criterion says how).
  kCarried,           ///< It rests (directly or not) on a brick that was woken.
  kSupporterRemoved,  ///< A brick under it was removed.
  kPushed,            ///< An impulse was applied to it.
  kSupportCycle,      ///< Contacts made a cycle in the support graph (no order of loads).
};

/// A brick leaves Bullet: frozen as `kind` (kStable or kLeaning).
struct FreezeDecision {
  BodyHandle brick = 0;
  BrickState kind = BrickState::kStable;
  double margin = 0.0;  ///< [m]
  std::vector<BodyHandle> supporters;
  std::string reason;  ///< Worded by the model, for ~events.
};

/// A frozen brick returns to Bullet.
struct WakeDecision {
  BodyHandle brick = 0;
  WakeCause cause = WakeCause::kOutsideSupport;
  BodyHandle because_of = 0;  ///< The woken or removed brick for kCarried, kSupporterRemoved.
  double margin = 0.0;        ///< For kOutsideSupport [m].
  std::string reason;         ///< Worded by the model, for ~events.
};

struct StabilityDecisions {
  std::vector<FreezeDecision> freeze;
  std::vector<WakeDecision> wake;
  bool empty() const { return freeze.empty() && wake.empty(); }
};

/// A brick placed at rest, with its supports found from geometry: Bullet has
/// not simulated it yet.
struct RestingPlacement {
  BodyMotion brick;
  std::vector<PairContact> contacts;
};

/// What the model is told in one pass of the decision path: a step, or a
/// request between steps (a placement, a removal, a push). Everything goes
/// through StabilityModel::decide, so a model has one place where it reacts.
struct StabilityInput {
  double dt = 0.0;                 ///< Sim time since the last step [s]; 0 between steps.
  std::vector<BodyMotion> movers;  ///< The bricks Bullet simulates, after this step.
  /// This step's touching pairs (frozen-frozen pairs never touch in Bullet);
  /// null when there are none to tell.
  const std::vector<PairContact>* contacts = nullptr;
  std::vector<RestingPlacement> placed;  ///< Bricks just placed at rest.
  std::vector<BodyHandle> removed;       ///< Bricks that left the world.
  std::vector<BodyHandle> pushed;        ///< Bricks pushed from outside.
};

/// A moving brick that may reach a frozen one within the coming Bullet step.
struct Approach {
  BodyMotion mover;
  BodyHandle frozen = 0;
};

/// Would a brick at rest here join the stack, and would the stack under it
/// bear its load? The answer of a what-if query: nothing changes.
struct PlacementEvaluation {
  bool stable = false;  ///< It would freeze at once and nothing under it would fall.
  BrickState kind = BrickState::kDynamic;  ///< kStable or kLeaning when stable.
  double margin = 0.0;                     ///< Of the brick itself [m].
  std::vector<BodyHandle> supporters;      ///< What it would rest on.
  std::vector<BodyHandle> would_fall;      ///< Frozen bricks its load would tip.
  std::string reason;
};

/// Names bodies in the reasons a model words ("b3", "table").
using BodyNamer = std::function<std::string(BodyHandle)>;

/// A stability model on top of the physics engine. It sees the moving bricks
/// and their contacts each step, and every change made from outside, and
/// decides which bricks leave the engine (freeze) and which return (wake).
class StabilityModel {
 public:
  virtual ~StabilityModel() = default;

  /// Whether beforeBulletStep() wants the approaches; the world skips
  /// gathering them for a model that does not.
  virtual bool watchesApproaches() const { return false; }
  /// Before Bullet advances the movers: the pairs of a mover and a frozen
  /// brick it may reach within this step, seen before Bullet's solver would
  /// bounce the mover off a static collider (impacts). Nothing by default.
  virtual void beforeBulletStep(double /*dt*/, const std::vector<Approach>& /*approaches*/,
                                StabilityDecisions* /*decisions*/) {}

  /// Whether the model judges bricks that lean (contacts away from
  /// vertical); the world finds such contacts from geometry for a brick
  /// placed at rest only when it does.
  virtual bool judgesLeaning() const { return false; }

  /// The decision path: one step, or one change between steps.
  virtual void decide(const StabilityInput& input, StabilityDecisions* decisions) = 0;

  /// What-if: would `brick`, at rest with these `contacts` (from geometry),
  /// join the stack? Nothing changes.
  virtual PlacementEvaluation evaluatePlacement(const BodyMotion& brick,
                                                const std::vector<PairContact>& contacts) const = 0;

  /// What the model knows of `brick`; false when it knows nothing.
  virtual bool describe(BodyHandle brick, BrickStability* stability) const = 0;
};

}  // namespace brick_stack_sim
