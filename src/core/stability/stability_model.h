#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include <Eigen/Core>

#include "brick_stack_sim/core/geometry/polygon2d.h"

namespace brick_stack_sim {

/// Names a body for the stability models: a brick's placement serial, or one
/// of the two static bodies. Models never see Bullet.
using BodyHandle = std::uint32_t;
constexpr BodyHandle kTableHandle = std::numeric_limits<BodyHandle>::max();
constexpr BodyHandle kFloorHandle = kTableHandle - 1;
inline bool isGround(BodyHandle handle) { return handle >= kFloorHandle; }

/// A brick as the stability model sees it in one step.
struct BodyMotion {
  BodyHandle handle = 0;
  Eigen::Vector3d com = Eigen::Vector3d::Zero();               ///< [m], world
  double mass = 0.0;                                           ///< [kg]
  Eigen::Vector3d linear_velocity = Eigen::Vector3d::Zero();   ///< [m/s]
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  ///< [rad/s]
};

/// The touching points of one pair of bodies in one step.
struct PairContact {
  BodyHandle a = 0, b = 0;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< Unit, from b towards a.
  std::vector<Eigen::Vector3d> points;                ///< World [m].
  double approach_speed = 0.0;  ///< Largest closing speed along the normal [m/s].
};

/// One support of a brick: the patch where it rests on `supporter`.
struct SupportPatch {
  BodyHandle supporter = 0;
  std::vector<Eigen::Vector3d> points;  ///< Contact points, world [m].
  Polygon2d hull;                       ///< Their hull, projected along gravity.
  double height = 0.0;                  ///< Mean z of the points [m].
};

/// What a stability model knows about one brick.
struct BrickStability {
  bool frozen = false;
  Eigen::Vector3d com_above = Eigen::Vector3d::Zero();  ///< [m]
  double mass_above = 0.0;                              ///< [kg]
  double margin = 0.0;  ///< Signed distance of the COM-above projection to the support hull [m].
  std::vector<SupportPatch> supports;
  Polygon2d combined_hull;      ///< Hull of all support patches.
  double support_height = 0.0;  ///< Mean height of the supports [m].
};

/// Why a brick left the stack.
enum class WakeCause {
  kOutsideSupport,    ///< Its COM-above left its support hull.
  kCarried,           ///< It rests (directly or not) on a brick that was woken.
  kSupporterRemoved,  ///< A brick under it was removed.
  kPushed,            ///< An impulse was applied to it.
  kSupportCycle,      ///< Contacts made a cycle in the support graph (no order of loads).
};

struct WakeDecision {
  BodyHandle brick = 0;
  WakeCause cause = WakeCause::kOutsideSupport;
  BodyHandle because_of = 0;  ///< The woken or removed brick for kCarried, kSupporterRemoved.
  double margin = 0.0;        ///< For kOutsideSupport [m].
};

struct FreezeDecision {
  BodyHandle brick = 0;
  double margin = 0.0;  ///< [m]
  std::vector<BodyHandle> supporters;
};

struct StabilityDecisions {
  std::vector<FreezeDecision> freeze;
  std::vector<WakeDecision> wake;
  bool empty() const { return freeze.empty() && wake.empty(); }
};

/// A stability model on top of the physics engine (DESIGN.md section 2). It
/// sees the moving bricks and their contacts each step and decides which bricks
/// leave the engine (freeze) and which return to it (wake).
class StabilityModel {
 public:
  virtual ~StabilityModel() = default;
  /// One step: `movers` are the bricks not frozen by this model, `contacts`
  /// this step's touching pairs (frozen-frozen pairs never touch in Bullet).
  virtual void update(double dt, const std::vector<BodyMotion>& movers,
                      const std::vector<PairContact>& contacts, StabilityDecisions* decisions) = 0;
  /// A brick was just placed at rest; `contacts` are its touching supports
  /// found from geometry (Bullet has not seen it yet). A stable placement
  /// joins the stack at once, before Bullet's first, unconverged steps can
  /// rock it.
  virtual void placedAtRest(const BodyMotion& brick, const std::vector<PairContact>& contacts,
                            StabilityDecisions* decisions) = 0;
  /// A brick leaves the world; decisions wake what it carried.
  virtual void remove(BodyHandle brick, StabilityDecisions* decisions) = 0;
  /// An outside push: the brick and what it carries must wake.
  virtual void wake(BodyHandle brick, WakeCause cause, StabilityDecisions* decisions) = 0;
  virtual void clear() = 0;
  /// What the model knows of `brick`; false when it knows nothing.
  virtual bool describe(BodyHandle brick, BrickStability* stability) const = 0;
};

}  // namespace brick_stack_sim
