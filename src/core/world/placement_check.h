#pragma once

#include <vector>

#include "brick_stack_sim/core/geometry/convex_solid.h"
#include "brick_stack_sim/core/status.h"
#include "brick_stack_sim/core/types/brick.h"
#include "brick_stack_sim/core/types/brick_type.h"
#include "physics/contact.h"

namespace brick_stack_sim {

struct WorldState;

/// A brick of `type` at `pose`: a finite position, a proper rotation, no
/// point of it below the table top. Messages start with `prefix`
/// ("target "): "target position is not finite: ...".
Status checkPose(const WorldState& world, const Eigen::Isometry3d& pose, const BrickType& type,
                 const std::string& prefix = "");

/// Velocities [m/s], [rad/s]: finite and within the world's speed limits.
/// Messages start with `prefix` ("release ").
Status checkVelocity(const WorldState& world, const Eigen::Vector3d& linear,
                     const Eigen::Vector3d& angular, const std::string& prefix = "");

/// Whether `id` names one of the scene's fixed bodies (table, floor, world,
/// in any case), which supported_by and tf use: never a brick's id.
bool isReservedId(const std::string& id);

/// Would the world accept this placement? The id (valid, not reserved, not
/// in use), the type, finite numbers, a proper rotation, speeds within the
/// limits, not below the table top and not inside another brick. The
/// message names what is wrong and its value.
Status checkPlacement(const WorldState& world, const BrickPlacement& placement);

/// The contacts of a brick at `box` (handle `brick`, of a material with
/// `friction`) with `other`, found from geometry and appended to `contacts`:
/// the flush patch where it rests flat on `other`, or, when `any_face`, the
/// contact across every touching face (touchingContacts). Nothing when they
/// do not touch within the stability's contact distance.
void appendContacts(const WorldState& world, BodyHandle brick, double friction,
                    const PlacedSolid& box, BodyHandle other, bool any_face,
                    std::vector<PairContact>* contacts);

/// The contacts of a brick resting at `box` (handle `brick`, of a material
/// with `friction`, whose bounds are `low`..`high` [m]) with the table and
/// the frozen bricks, found from geometry: a brick placed at rest is judged
/// before Bullet's first, unconverged steps can rock it. Flush supports
/// always; for a model that judges leaning, every touching face too, and the
/// bricks placed at rest since the last step.
std::vector<PairContact> restingContacts(const WorldState& world, BodyHandle brick, double friction,
                                         const PlacedSolid& box, const Eigen::Vector3d& low,
                                         const Eigen::Vector3d& high);

}  // namespace brick_stack_sim
