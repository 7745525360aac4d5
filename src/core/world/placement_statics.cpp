#include "world/placement_statics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "stability/contact_classifier.h"
#include "stability/rigid_block_statics.h"
#include "stability/statics_assembly.h"
#include "stability/support_evaluation.h"
#include "util/text_format.h"
#include "world/placement_check.h"
#include "world/world_state.h"

namespace brick_stack_sim {

namespace {

// judgeAlone's parts: what the brick touches, and what its verdict says.

/// Every body the brick has a contact with, each once, in handle order.
std::vector<BodyHandle> touchedBodies(const std::vector<PairContact>& contacts) {
  std::vector<BodyHandle> touching;
  for (const PairContact& contact : contacts) touching.push_back(contact.b);
  std::sort(touching.begin(), touching.end());
  touching.erase(std::unique(touching.begin(), touching.end()), touching.end());
  return touching;
}

/// "a, b": the names of `bodies`, as the verdict's reason lists them.
std::string namesOf(const WorldState& w, const std::vector<BodyHandle>& bodies) {
  std::string names;
  for (BodyHandle other : bodies) names += (names.empty() ? "" : ", ") + w.nameOf(other);
  return names;
}

/// The most acceleration a verdict reports [m/s^2] (ten g: held beyond any shake).
constexpr double kAccelerationCap = 100.0;

/// How firmly statics holds a brick: the least sideways acceleration,
/// along +-x or +-y, that would move it [m/s^2].
double leastMovingAcceleration(const std::vector<StaticsBody>& bodies,
                               const std::vector<StaticsContact>& statics,
                               const StaticsOptions& options) {
  double least = std::numeric_limits<double>::infinity();
  const Eigen::Vector3d directions[] = {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(-1, 0, 0),
                                        Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, -1, 0)};
  for (const Eigen::Vector3d& direction : directions)
    least = std::min(
        least, horizontalAccelerationMargin(bodies, statics, direction, options, kAccelerationCap));
  return least;
}

/// The reason of a verdict that it stands: on what, and how firmly.
std::string standsReason(BrickState kind, const std::string& names, double acceleration_margin) {
  char text[64];
  std::snprintf(text, sizeof text, "%.3g m/s^2", acceleration_margin);
  return std::string(kind == BrickState::kStable ? "rests on " : "leans on ") + names +
         " (statics; a sideways acceleration of " + text + " would move it)";
}

/// Within this of its support's edge [m], a brick's verdict is left to the
/// LP, whose tolerance decides there.
constexpr double kClosedFormBand = 1e-6;

/// Level enough for the closed form: normals within this of vertical [rad]
/// and points within this of one height [m]. A brick Bullet has tilted by a
/// micro-radian is left to the LP; one placed level, as planners do, is not.
constexpr double kLevel = 1e-9;

/// How far `from` may move along `direction` (unit) before it leaves the
/// convex, counter-clockwise `hull` [m]; 0 when it is not inside.
double rayToEdge(const Polygon2d& hull, const Eigen::Vector2d& from,
                 const Eigen::Vector2d& direction) {
  double reach = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Eigen::Vector2d& a = hull[i];
    const Eigen::Vector2d edge = hull[(i + 1) % hull.size()] - a;
    const Eigen::Vector2d outward(edge.y(), -edge.x());
    const double closing = outward.dot(direction);
    if (closing > 0.0) reach = std::min(reach, outward.dot(a - from) / closing);
  }
  return std::isfinite(reach) ? std::max(reach, 0.0) : 0.0;
}

/// Rigid-block statics of a brick that rests only on level supports (every
/// contact normal straight up, every point at one height, one friction
/// coefficient) under its weight alone, in closed form: the LP's answer
/// without the LP. Vertical forces balance it exactly when its COM lies
/// over the hull of the contact points, friction unused. Accelerated
/// sideways by a along u, the resultant of weight and inertia meets the
/// support plane (h below the COM) at COM - (a / g) h u: it tips when that
/// point leaves the hull (t_u from the COM along -u), slides when a > mu g;
/// so the least acceleration that moves it is g min(mu, t_u / h), which the
/// LP reaches too (its friction pyramid has edges along x and y). False
/// when the brick is not so supported, or lies within kClosedFormBand of
/// its edge: the LP decides then.
bool levelSupportStatics(const BodyMotion& brick, const BrickStability& support, double gravity,
                         double cap, bool* stands, double* acceleration_margin) {
  if (!support.side_contacts.empty() || support.supports.empty() ||
      std::abs(support.margin) <= kClosedFormBand)
    return false;
  const double friction = support.supports.front().friction;
  const double height = support.supports.front().points.front().z();
  for (const SupportPatch& patch : support.supports) {
    if (patch.friction != friction) return false;
    for (const Eigen::Vector3d& normal : patch.normals)
      if (!(normal.z() > 0.0) || normal.head<2>().norm() > kLevel) return false;
    for (const Eigen::Vector3d& point : patch.points)
      if (std::abs(point.z() - height) > kLevel) return false;
  }
  *stands = support.margin > 0.0;
  if (!*stands) return true;
  const double lever = brick.com.z() - height;
  if (!(lever > 0.0)) return false;
  double least = std::min(friction, cap / gravity);
  const Eigen::Vector2d com = brick.com.head<2>();
  for (const Eigen::Vector2d& direction : {Eigen::Vector2d(1, 0), Eigen::Vector2d(-1, 0),
                                           Eigen::Vector2d(0, 1), Eigen::Vector2d(0, -1)})
    least = std::min(least, rayToEdge(support.combined_hull, com, -direction) / lever);
  *acceleration_margin = least * gravity;
  return true;
}

}  // namespace

std::vector<PairContact> touchingBricks(const WorldState& w, BodyHandle brick, double friction,
                                        const PlacedSolid& box, const Eigen::Vector3d& low,
                                        const Eigen::Vector3d& high) {
  std::vector<PairContact> contacts;
  appendContacts(w, brick, friction, box, kTableHandle, true, &contacts);
  const Eigen::AlignedBox3d reach(low.array() - w.options.stability.contact_distance,
                                  high.array() + w.options.stability.contact_distance);
  std::vector<BodyHandle> near = w.dormant.near(reach.min(), reach.max());
  for (BodyHandle body : w.scene.inWorldNear(reach.min(), reach.max())) near.push_back(body);
  std::sort(near.begin(), near.end());
  near.erase(std::unique(near.begin(), near.end()), near.end());
  for (BodyHandle other : near)
    if (other != brick) appendContacts(w, brick, friction, box, other, true, &contacts);
  return contacts;
}

StaticsVerdict judgeAlone(const BodyMotion& brick, const std::vector<PairContact>& contacts,
                          const WorldState& w) {
  StaticsVerdict verdict;
  std::vector<const PairContact*> pointers;
  for (const PairContact& contact : contacts) pointers.push_back(&contact);
  verdict.touching = touchedBodies(contacts);
  // The COM margin of Brick.msg, on what carries it from below.
  BrickStability support;
  support.supports = supportPatches(
      brick, ContactSpan(pointers), [](BodyHandle) { return true; }, w.options.stability,
      &support.side_contacts);
  evaluateSupport(brick.com, &support);
  verdict.margin = support.margin;
  // What it touches is held fixed; a brick resting on it from above is
  // left out, as in the running models: held fixed, it could press it down
  // with any force, where in truth it presses with its own weight at most.
  StaticsAssembly assembly(w.options.stability);
  assembly.addFree(brick.handle, brick.mass, brick.com);
  assembly.addPatches(0, support.supports);
  assembly.addPatches(0, support.side_contacts);
  const std::vector<StaticsBody>& bodies = assembly.bodies();
  const std::vector<StaticsContact>& statics = assembly.contacts();

  const std::string names = namesOf(w, verdict.touching);
  if (verdict.touching.empty()) {
    verdict.reason = "it would touch nothing: it would fall";
    return verdict;
  }
  bool stands = false;
  if (levelSupportStatics(brick, support, w.options.gravity, kAccelerationCap, &stands,
                          &verdict.acceleration_margin)) {
    if (!stands) {
      verdict.reason = "no contact forces within friction hold it on " + names;
      return verdict;
    }
    verdict.stands = true;
    verdict.kind = support.margin > w.options.stability.min_margin ? BrickState::kStable
                                                                   : BrickState::kLeaning;
    verdict.reason = standsReason(verdict.kind, names, verdict.acceleration_margin);
    return verdict;
  }
  StaticsOptions options;
  options.gravity = w.options.gravity;
  const StaticsSolution solution = solveStatics(bodies, statics, options);
  if (!solution.solved) {
    verdict.reason = "statics could not be solved: " + solution.message;
    return verdict;
  }
  if (!solution.feasible) {
    verdict.reason = "no contact forces within friction hold it on " + names;
    return verdict;
  }
  verdict.stands = true;
  verdict.kind = !support.supports.empty() && support.margin > w.options.stability.min_margin
                     ? BrickState::kStable
                     : BrickState::kLeaning;
  verdict.acceleration_margin = leastMovingAcceleration(bodies, statics, options);
  verdict.reason = standsReason(verdict.kind, names, verdict.acceleration_margin);
  return verdict;
}

}  // namespace brick_stack_sim
