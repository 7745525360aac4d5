#include "world/impacts.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "brick_stack_sim/core/geometry/box_geometry.h"
#include "brick_stack_sim/core/geometry/convex_solid.h"
#include "util/text_format.h"
#include "world/placement_check.h"
#include "world/world_state.h"

namespace brick_stack_sim {

namespace {

/// A push meets the struck face at least this squarely (cosine), or a
/// glancing hand would slide the brick unboundedly far out of its way.
constexpr double kLeastCrossing = 0.2;
/// Two boxes whose faces overlap less than this across the contact plane
/// only graze (a striker flush with a layer touches the layers above and
/// below along an edge): no blow passes there [m].
constexpr double kGrazeOverlap = 5e-4;
/// Halvings of a slide that would push the struck brick into a neighbour.
constexpr int kSlideHalvings = 8;

double restitutionOf(const WorldState& w, BodyHandle handle) {
  return isGround(handle) ? w.options.table.restitution : w.bricks.find(handle)->type.restitution;
}

/// How much two boxes overlap across the plane with `normal`, the less of
/// the two directions in it [m].
double overlapAcross(const PlacedSolid& a, const PlacedSolid& b, const Eigen::Vector3d& normal) {
  const Eigen::Vector3d first = normal.unitOrthogonal();
  double least = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& axis : {first, normal.cross(first)}) {
    const Eigen::Vector2d along_a = extentAlong(a, axis), along_b = extentAlong(b, axis);
    least =
        std::min(least, std::min(along_a.y(), along_b.y()) - std::max(along_a.x(), along_b.x()));
  }
  return least;
}

/// Whether `brick` at `box` would sink into any brick but itself and `except`.
bool overlapsOthers(const WorldState& w, BodyHandle brick, BodyHandle except,
                    const PlacedSolid& box) {
  const Eigen::AlignedBox3d extent = bounds(box);
  std::vector<BodyHandle> others = w.dormant.near(extent.min(), extent.max());
  for (const BrickRecord* mover : w.sets.movers()) others.push_back(mover->handle);
  for (const BrickRecord* held : w.sets.held()) others.push_back(held->handle);
  others.push_back(kTableHandle);
  for (BodyHandle other : others) {
    if (other == brick || other == except) continue;
    if (separation(box, w.solidOf(other)) < -w.options.overlap_tolerance) return true;
  }
  return false;
}

/// Moves the frozen `brick` by up to `slide` [m] (less when a neighbour is
/// in the way) and lets the model rest it anew; false when it could not
/// move visibly.
bool slideFrozen(WorldState* w, BrickRecord* brick, BodyHandle striker,
                 const Eigen::Vector3d& slide) {
  const Eigen::Isometry3d start = w->scene.pose(brick->handle);
  PlacedSolid box = brick->type.placed(start);
  Eigen::Vector3d offset = slide;
  for (int halving = 0;; ++halving) {
    box.pose.translation() = start.translation() + offset;
    if (!overlapsOthers(*w, brick->handle, striker, box)) break;
    if (halving == kSlideHalvings) return false;
    offset *= 0.5;
  }
  if (offset.norm() < w->options.stability.impact_min_slide) return false;
  w->scene.moveStatic(brick->handle, box.pose);
  w->dormant.refresh(brick->handle);
  brick->last_good_pose = box.pose;
  Eigen::Vector3d low, high;
  w->scene.bounds(brick->handle, &low, &high);
  StabilityInput input;
  input.slid.push_back({w->motionOf(*brick),
                        restingContacts(*w, brick->handle, brick->type.friction, box, low, high)});
  decide(w, input);
  return true;
}

/// GJK's distance of two boxes is trusted to this [m].
constexpr double kDistanceTolerance = 1e-6;

/// Whether the mover's box, carried from its origin `from` [m] by `shift`
/// [m] and turned by up to `turn` [rad] about that origin on the way, stays
/// further than `gap` [m] from the frozen brick all along: the boxes that
/// bound them (Bullet's, with its margins) are further apart. A point of
/// the box turned by `turn` moves by at most `turn` times its distance from
/// the origin.
bool apartAlongStep(const WorldState& w, BodyHandle mover, const Eigen::Vector3d& from,
                    const Eigen::Vector3d& shift, double turn, BodyHandle frozen, double gap) {
  Eigen::Vector3d low, high, frozen_low, frozen_high;
  w.scene.bounds(mover, &low, &high);
  w.scene.bounds(frozen, &frozen_low, &frozen_high);
  const double radius = (low - from).cwiseAbs().cwiseMax((high - from).cwiseAbs()).norm();
  const Eigen::Vector3d slack = Eigen::Vector3d::Constant(turn * radius + gap);
  const Eigen::Vector3d swept_low = low + shift.cwiseMin(0.0) - slack;
  const Eigen::Vector3d swept_high = high + shift.cwiseMax(0.0) + slack;
  return (swept_low.array() > frozen_high.array()).any() ||
         (swept_high.array() < frozen_low.array()).any();
}

}  // namespace

Eigen::Isometry3d partWay(const Eigen::Isometry3d& from, const Eigen::Isometry3d& to,
                          double fraction) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = from.translation() + fraction * (to.translation() - from.translation());
  pose.linear() = Eigen::Quaterniond(from.linear())
                      .slerp(fraction, Eigen::Quaterniond(to.linear()))
                      .normalized()
                      .toRotationMatrix();
  return pose;
}

double firstContactOnTheWay(const WorldState& w, const Striker& striker,
                            const Eigen::Isometry3d& from, BodyHandle struck) {
  const BrickRecord* record = w.bricks.find(striker.handle);
  if (!record) return 1.0;
  // As the engine's continuous collision (BrickDynamicsWorld): swept past
  // half its thickness a step, meeting what it closes on by half that.
  const double sweep = record->type.thinnestHalfWidth();
  const Eigen::Vector3d travel = striker.pose.translation() - from.translation();
  double fraction = 1.0;
  if (travel.norm() <= sweep ||
      !w.scene.firstContact(striker.handle, from, striker.pose, struck, &fraction))
    return 1.0;
  ClosestPoints met;
  if (!w.scene.closestPoints(striker.handle, partWay(from, striker.pose, fraction), struck, &met) ||
      -travel.dot(met.normal) <= 0.5 * sweep)
    return 1.0;
  // The cast stops short of touching by up to its tolerance: judged a
  // little further on, the striker touches what it meets.
  return std::min(1.0, fraction + 2.0 * w.options.stability.contact_distance / travel.norm());
}

bool findImpact(const WorldState& w, const Striker& striker, BodyHandle struck, Impact* impact,
                double* overlap) {
  const BrickType& striker_type = w.bricks.find(striker.handle)->type;
  const PlacedSolid struck_box = w.solidOf(struck);
  const PlacedSolid striker_box = striker_type.placed(striker.pose);
  // The separating axes bound the distance from below at a fraction of
  // GJK's cost: on a landing pile two in three pairs brought here are apart
  // beyond the contact distance, and no blow passes between those (with
  // GJK's tolerance, so that none it would have found is skipped).
  if (separation(striker_box, struck_box) >
      w.options.stability.contact_distance + kDistanceTolerance) {
    if (overlap) *overlap = 0.0;
    return false;
  }
  ClosestPoints nearest;
  if (!w.scene.closestPoints(striker.handle, striker.pose, struck, &nearest)) return false;
  // GJK's witness of two flush faces is any corner of their overlap; the
  // blow acts nearer the striker's centre, on the struck brick's surface.
  const Eigen::Vector3d centre = centreOfMassAt(striker_type, striker.pose);
  const Eigen::Vector3d on_plane =
      centre - (centre - nearest.on_b).dot(nearest.normal) * nearest.normal;
  const Eigen::Vector3d point = nearestPointIn(struck_box, on_plane);
  const Eigen::Vector3d velocity = striker.velocity + striker.spin.cross(point - centre);
  const double closing_speed = -velocity.dot(nearest.normal);
  if (overlap) *overlap = std::max(0.0, -nearest.distance);
  if (closing_speed <= w.options.stability.impact_speed) return false;
  if (nearest.distance > w.options.stability.contact_distance) return false;
  if (overlapAcross(striker_box, struck_box, nearest.normal) < kGrazeOverlap) return false;
  impact->striker = striker.handle;
  impact->striker_mass = striker.mass;
  impact->struck = struck;
  impact->point = point;
  impact->normal = nearest.normal;
  impact->closing_speed = closing_speed;
  impact->restitution = striker.restitution * restitutionOf(w, struck);
  impact->gravity = w.options.gravity;
  return true;
}

std::vector<ImpactResponse> carryOutImpacts(WorldState* w, const std::vector<Impact>& impacts,
                                            const std::vector<double>* overlaps) {
  std::vector<ImpactResponse> responses;
  if (impacts.empty()) return responses;
  StabilityDecisions decisions;
  w->model->judgeImpacts(impacts, &responses, &decisions);
  applyDecisions(w, decisions);
  // Who woke with whom: each struck brick's decision comes first, then
  // what it carried.
  std::unordered_map<BodyHandle, std::vector<std::string>> woken_with;
  BodyHandle first = 0;
  for (const WakeDecision& woken : decisions.wake) {
    if (woken.cause == WakeCause::kStruck) first = woken.brick;
    woken_with[first].push_back(w->nameOf(woken.brick));
  }
  std::vector<BodyHandle> slid;
  for (std::size_t i = 0; i < responses.size(); ++i) {
    const ImpactResponse& response = responses[i];
    const Impact& impact = response.impact;
    const bool held = !std::isfinite(impact.striker_mass);
    BrickRecord* struck = w->bricks.find(impact.struck);
    std::vector<std::string> affected;
    switch (response.outcome) {
      case ImpactResponse::Outcome::kAbsorbed:
        // The hand stops at it (no event per step of pressing); a brick
        // landing on the stack is no news either.
        if (held || response.delivered_energy <= 0.0) continue;
        break;
      case ImpactResponse::Outcome::kWoken:
        w->scene.applyImpulse(impact.struck, response.impulse, impact.point);
        if (!held) w->scene.applyImpulse(impact.striker, -response.impulse, impact.point);
        affected = woken_with[impact.struck];
        break;
      case ImpactResponse::Outcome::kSlid:
        if (std::find(slid.begin(), slid.end(), impact.struck) != slid.end()) continue;
        Eigen::Vector3d slide = response.slide;
        if (overlaps && slide.norm() > 0.0) {
          // Out of the way of the hand: along the push, the overlap across
          // the normal, plus the contact distance.
          const double across = std::max(kLeastCrossing, slide.normalized().dot(-impact.normal));
          const double clear = (*overlaps)[i] / across + w->options.stability.contact_distance;
          if (slide.norm() < clear) slide *= clear / slide.norm();
        }
        if (!struck || !isFrozen(struck->mode) || !slideFrozen(w, struck, impact.striker, slide))
          continue;
        slid.push_back(impact.struck);
        affected.push_back(struck->id);
        if (!held) {
          // It bounces off as off a wall: the struck brick took the blow in place.
          const double mass = impact.striker_mass;
          w->scene.applyImpulse(
              impact.striker,
              (1.0 + impact.restitution) * mass * impact.closing_speed * impact.normal,
              w->scene.centreOfMass(impact.striker));
        }
        break;
    }
    w->emit(SimEventKind::kImpact, w->nameOf(impact.struck), response.reason, std::move(affected));
  }
  return responses;
}

void strikeFrozenBricks(WorldState* w, const std::vector<ColliderApproach>& near) {
  if (near.empty() || !w->model || !w->model->judgesImpacts()) return;
  std::vector<Impact> impacts;
  for (const ColliderApproach& pair : near) {
    const BrickRecord* mover = w->bricks.find(pair.mover);
    const BrickRecord* struck = w->bricks.find(pair.frozen);
    if (!mover || !struck || mover->mode != BrickMode::kDynamic || !isFrozen(struck->mode))
      continue;
    // A brick slower than the impact speed everywhere cannot strike: most
    // movers near frozen bricks are settling on them.
    const double fastest = w->fastestPointSpeed(*mover);
    if (fastest <= w->options.stability.impact_speed) continue;
    const double dt = w->options.time_step;
    Striker striker{mover->handle,
                    mover->type.mass,
                    w->scene.pose(mover->handle),
                    w->scene.linearVelocity(mover->handle),
                    w->scene.angularVelocity(mover->handle),
                    mover->type.restitution};
    // Where it would be after the step, turning about its centre.
    const double turn = striker.spin.norm() * dt;
    if (turn > 0.0)
      striker.pose.linear() =
          Eigen::AngleAxisd(turn, striker.spin.normalized()).toRotationMatrix() *
          striker.pose.linear();
    striker.pose.translation() += striker.velocity * dt;
    const Eigen::Isometry3d from = w->scene.pose(mover->handle);
    // Most pairs brought near are not within the contact distance anywhere
    // on the step, where findImpact() finds no blow: the boxes that bound
    // them tell without GJK.
    if (apartAlongStep(*w, mover->handle, from.translation(),
                       striker.pose.translation() - from.translation(), turn, pair.frozen,
                       w->options.stability.contact_distance + kDistanceTolerance))
      continue;
    // A fast striker is judged where it first meets the brick, not beyond it.
    striker.pose =
        partWay(from, striker.pose, firstContactOnTheWay(*w, striker, from, pair.frozen));
    Impact impact;
    if (findImpact(*w, striker, pair.frozen, &impact)) impacts.push_back(impact);
  }
  carryOutImpacts(w, impacts);
}

}  // namespace brick_stack_sim
