#pragma once
// The interface between the world and a stability model (docs/design.md, "Stability models").

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "brick_stack_sim/core/geometry/polygon2d.h"
#include "brick_stack_sim/core/types/brick.h"
#include "brick_stack_sim/core/types/stability_options.h"
#include "physics/contact.h"

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
  double friction = 0.0;  ///< Coulomb coefficient of the pair [-].
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
  /// What bodies the stack does not hold (moving and held bricks) press on
  /// it with, measured (ContactLoads), in statics' g like every load passed
  /// between bricks [N] at their points [m], world.
  std::vector<PointForce> external_loads;
};

/// Why a brick left the stack.
enum class WakeCause {
  kOutsideSupport,    ///< Its load left its support (the criterion says how).
  kCarried,           ///< It rests (directly or not) on a brick that was woken.
  kSupporterRemoved,  ///< A brick under it was removed.
  kPushed,            ///< An impulse was applied to it.
  kStruck,            ///< A moving or held brick struck it hard enough to move it.
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
  /// The model woke it before, it froze again without having moved, and
  /// the model wakes it again: a wake/refreeze cycle (counted, reported).
  bool repeats = false;
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
  double dt = 0.0;  ///< Sim time since the last step [s]; 0 between steps.
  /// The world's gravity [m/s^2]: contact impulses become loads in the g
  /// statics weighs bricks in.
  double gravity = 9.81;
  std::vector<BodyMotion> movers;  ///< The bricks Bullet simulates, after this step.
  /// This step's touching pairs (frozen-frozen pairs never touch in Bullet);
  /// null when there are none to tell.
  const std::vector<PairContact>* contacts = nullptr;
  std::vector<RestingPlacement> placed;  ///< Bricks just placed at rest.
  /// More bricks are being placed at this instant: the structure is judged
  /// as a whole once the last is in, not half-built (an arch's half-ring
  /// cannot stand alone).
  bool more_to_come = false;
  std::vector<BodyHandle> removed;  ///< Bricks that left the world.
  /// Bricks taken into a hand (grasped): out of the stack, still in the world.
  std::vector<BodyHandle> grasped;
  std::vector<BodyHandle> pushed;  ///< Bricks pushed from outside.
  /// Frozen bricks an impact slid to a new pose, with their contacts there
  /// (from geometry): they rest anew, and what they carry rests on them anew.
  std::vector<RestingPlacement> slid;
};

/// A moving or held brick about to strike a frozen one within the coming
/// Bullet step: seen before Bullet's solver would bounce it off a static
/// collider.
struct Impact {
  BodyHandle striker = 0;
  /// [kg]; infinite for a held brick (a hand does not give way).
  double striker_mass = 0.0;
  BodyHandle struck = 0;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();    ///< Where they meet [m], world.
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();  ///< Unit, from struck towards striker.
  double closing_speed = 0.0;                         ///< Along the normal [m/s], > 0.
  double restitution = 0.0;                           ///< Of the pair [-].
  double gravity = 9.81;                              ///< [m/s^2]
};

/// What a model makes of an impact.
struct ImpactResponse {
  enum class Outcome : unsigned char {
    kAbsorbed,  ///< Nothing moves: the struck brick stays frozen where it is.
    kWoken,     ///< The struck brick (and what must move with it) is woken.
    kSlid,      ///< The struck brick slides under its load by `slide`, still frozen.
  };
  Impact impact;
  Outcome outcome = Outcome::kAbsorbed;
  Eigen::Vector3d impulse = Eigen::Vector3d::Zero();  ///< On the struck brick [N s].
  Eigen::Vector3d slide = Eigen::Vector3d::Zero();    ///< Of the struck brick [m], for kSlid.
  /// The sideways blow's energy in the struck brick [J]: 0 for a blow from
  /// above or below (a brick landing on the stack).
  double delivered_energy = 0.0;
  std::string reason;  ///< With the energies, for ~events.
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

  /// Whether judgeImpacts() wants the impacts; the world skips finding
  /// them for a model that does not.
  virtual bool judgesImpacts() const { return false; }
  /// Before Bullet advances the movers: what each impact on a frozen brick
  /// does (a response per impact, in order), with the wake decisions it
  /// takes. Everything absorbed by default.
  virtual void judgeImpacts(const std::vector<Impact>& impacts,
                            std::vector<ImpactResponse>* responses,
                            StabilityDecisions* /*decisions*/) {
    for (const Impact& impact : impacts) responses->push_back({impact, {}, {}, {}, {}, {}});
  }
  /// Frozen bricks resting on `brick` (empty when it is not frozen).
  virtual std::vector<BodyHandle> carriedBy(BodyHandle /*brick*/) const { return {}; }

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
  /// Frozen bricks whose describe() may say something else than at the
  /// last call (any order, maybe repeated): publishers skip the others.
  /// What it says of a mover may change at any step and is not listed.
  virtual std::vector<BodyHandle> takeRedescribed() = 0;

  /// A model in this one's exact state, every later decision the same,
  /// naming bodies with `name_of` (the copy's world).
  virtual std::unique_ptr<StabilityModel> clone(BodyNamer name_of) const = 0;
};

}  // namespace brick_stack_sim
