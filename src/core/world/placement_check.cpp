#include "world/placement_check.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "brick_stack_sim/core/geometry/box_contact.h"

#include "util/text_format.h"
#include "world/world_state.h"

namespace brick_stack_sim {

namespace {

constexpr std::size_t kMaxIdLength = 128;
/// A moving brick within this of a placement's bounds is checked for overlap [m].
constexpr double kNearby = 1e-3;

bool validId(const std::string& id) {
  if (id.empty() || id.size() > kMaxIdLength) return false;
  if (!std::isalpha(static_cast<unsigned char>(id[0]))) return false;
  return std::all_of(id.begin(), id.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
  });
}

}  // namespace

bool isReservedId(const std::string& id) {
  std::string lower(id);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return lower == "table" || lower == "floor" || lower == "world";
}

Status checkPose(const WorldState& w, const Eigen::Isometry3d& pose, const BrickType& type,
                 const std::string& prefix) {
  if (!pose.translation().allFinite())
    return Status::error(prefix + "position is not finite: " + formatVector(pose.translation()));
  if (!insideWorld(w.options, pose.translation()))
    return Status::error(prefix + "position " + formatVector(pose.translation()) +
                         " lies outside the world box: " + describeWorldBox(w.options));
  if (!isRotation(pose.linear()))
    return Status::error(prefix +
                         "orientation is not a proper rotation (NaN, Inf or not orthonormal)");
  const double lowest = bounds(type.placed(pose)).min().z();
  if (lowest < -w.options.overlap_tolerance)
    return Status::error(prefix + "pose puts the brick " + millimetres(-lowest) +
                         " below the table top (z = 0)");
  return Status::success();
}

Status checkVelocity(const WorldState& w, const Eigen::Vector3d& linear,
                     const Eigen::Vector3d& angular, const std::string& prefix) {
  if (!linear.allFinite() || !angular.allFinite())
    return Status::error(prefix + "velocity is not finite");
  if (linear.norm() > w.options.max_linear_speed)
    return Status::error(prefix + "linear speed " + formatNumber(linear.norm()) +
                         " m/s, over the limit of " + formatNumber(w.options.max_linear_speed) +
                         " m/s");
  if (angular.norm() > w.options.max_angular_speed)
    return Status::error(prefix + "angular speed " + formatNumber(angular.norm()) +
                         " rad/s, over the limit of " + formatNumber(w.options.max_angular_speed) +
                         " rad/s");
  return Status::success();
}

Status checkPlacement(const WorldState& w, const BrickPlacement& p) {
  if (!p.id.empty()) {
    if (!validId(p.id))
      return Status::error("id " + quotedId(p.id) +
                           " is not valid: use a letter then letters, digits, '_' or '-' "
                           "(at most 128 characters)");
    if (isReservedId(p.id))
      return Status::error("id " + quotedId(p.id) +
                           " is reserved: table, floor and world (in any case) name the "
                           "scene's fixed bodies in supported_by and on tf");
    if (w.bricks.find(p.id)) return Status::error("id " + quotedId(p.id) + " is already in use");
  }
  const std::string type_name = p.type.empty() ? w.types.defaultType() : p.type;
  const BrickType* type = w.types.find(type_name);
  if (!type)
    return Status::error("unknown brick type '" + type_name +
                         "' (known: " + joinNames(w.types.names()) + ")");
  if (Status pose = checkPose(w, p.pose, *type); !pose) return pose;
  if (Status velocity = checkVelocity(w, p.linear_velocity, p.angular_velocity); !velocity)
    return velocity;

  const PlacedSolid solid = type->placed(p.pose);
  const Eigen::AlignedBox3d extent = bounds(solid);
  const Eigen::Vector3d low = extent.min(), high = extent.max();
  // Candidates: the bricks whose boxes come near, from Bullet's tree (what
  // moves or is held) and the dormant colliders' (what is frozen), in
  // placement order. Every brick in turn would make placing n bricks cost n^2.
  const Eigen::Vector3d nearby = Eigen::Vector3d::Constant(kNearby);
  std::vector<BodyHandle> candidates = w.scene.inWorldNear(low - nearby, high + nearby);
  for (BodyHandle frozen : w.dormant.near(low - nearby, high + nearby))
    candidates.push_back(frozen);
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  for (BodyHandle other : candidates) {
    const double gap = separation(solid, w.solidOf(other));
    if (gap < -w.options.overlap_tolerance)
      return Status::error("pose overlaps brick '" + w.nameOf(other) + "' by " + millimetres(-gap));
  }
  return Status::success();
}

void appendContacts(const WorldState& w, BodyHandle brick, double friction, const PlacedSolid& box,
                    BodyHandle other, bool any_face, std::vector<PairContact>* contacts) {
  const double touching = w.options.stability.contact_distance;
  const PlacedSolid other_box = w.solidOf(other);
  // Touching, not sunk in: an overlap the placement check let through is
  // Bullet's to resolve before the brick can rest.
  if (std::abs(separation(other_box, box)) > touching) return;
  PairContact contact;
  contact.a = brick;
  contact.b = other;
  // Bullet's combination (bullet_scene.cpp): the geometric mean.
  contact.friction = std::sqrt(w.frictionOf(other) * friction);
  if (flushContactPatch(other_box, box, w.options.stability.flush_angle, touching, &contact.points,
                        &contact.normal)) {
    contacts->push_back(std::move(contact));
    return;
  }
  if (!any_face) return;
  for (BoxContactFace& face : touchingContacts(box, other_box, touching)) {
    PairContact across = contact;
    across.normal = face.normal;
    across.points = std::move(face.points);
    contacts->push_back(std::move(across));
  }
}

std::vector<PairContact> restingContacts(const WorldState& w, BodyHandle brick, double friction,
                                         const PlacedSolid& box, const Eigen::Vector3d& low,
                                         const Eigen::Vector3d& high) {
  const bool leaning = w.model && w.model->judgesLeaning();
  std::vector<PairContact> contacts;
  appendContacts(w, brick, friction, box, kTableHandle, leaning, &contacts);
  const Eigen::Vector3d reach = Eigen::Vector3d::Constant(w.options.stability.contact_distance);
  for (BodyHandle frozen : w.dormant.near(low - reach, high + reach))
    appendContacts(w, brick, friction, box, frozen, leaning, &contacts);
  if (leaning) {
    // Of the movers placed at rest (in placement order), those near.
    for (BodyHandle placed : w.scene.inWorldNear(low - reach, high + reach)) {
      if (placed == brick ||
          !std::binary_search(w.placed_at_rest.begin(), w.placed_at_rest.end(), placed))
        continue;
      const BrickRecord* record = w.bricks.find(placed);
      if (record && record->mode == BrickMode::kDynamic)
        appendContacts(w, brick, friction, box, placed, true, &contacts);
    }
  }
  return contacts;
}

}  // namespace brick_stack_sim
