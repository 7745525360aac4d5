#include "stability/impact_rule.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "util/text_format.h"

namespace brick_stack_sim {

namespace {

/// Horizontal normals shorter than this make a blow from above or below.
constexpr double kVerticalBlow = 1e-6;

}  // namespace

ImpactJudgement judgeImpact(const StruckBrick& brick, const Impact& blow, double min_slide) {
  ImpactJudgement result;
  const bool held = !std::isfinite(blow.striker_mass);
  // A hand gives the struck brick the striker's whole closing speed; a free
  // striker shares it by the reduced mass.
  const double reduced_mass =
      held ? brick.mass : 1.0 / (1.0 / blow.striker_mass + 1.0 / brick.mass);
  const double impulse = (1.0 + blow.restitution) * reduced_mass * blow.closing_speed;
  result.impulse = -impulse * blow.normal;
  result.striker_energy = held ? std::numeric_limits<double>::infinity()
                               : 0.5 * blow.striker_mass * blow.closing_speed * blow.closing_speed;

  const Eigen::Vector3d sideways(result.impulse.x(), result.impulse.y(), 0.0);
  if (sideways.norm() <= kVerticalBlow * impulse || impulse <= 0.0) return result;
  result.push_direction = sideways.normalized();
  const double sideways_impulse = sideways.norm();
  result.delivered_energy = sideways_impulse * sideways_impulse / (2.0 * brick.mass);

  // It slides between its supports (carrying its own weight and its load)
  // and what it carries (pressing with the load): both faces rub.
  const double carried = std::max(0.0, brick.mass_above - brick.mass);
  result.friction_force = brick.friction * blow.gravity * (brick.mass + 2.0 * carried);
  result.slide = result.friction_force > 0.0 ? result.delivered_energy / result.friction_force
                                             : std::numeric_limits<double>::infinity();
  result.slides = result.slide >= min_slide;

  // Tipping: about the support edge ahead of the push, the COM-above must
  // rise over it; the blow gives the angular impulse of its line about it.
  const Eigen::Vector2d direction = result.push_direction.head<2>();
  const Eigen::Vector2d centre = brick.com_above.head<2>();
  double reach = 0.0;  // from the COM-above to the edge, along the push [m]
  for (const Eigen::Vector2d& corner : brick.support_hull)
    reach = std::max(reach, (corner - centre).dot(direction));
  const double height = std::max(0.0, brick.com_above.z() - brick.support_height);
  const double arm = std::hypot(reach, height);
  result.tip_energy = brick.mass_above * blow.gravity * (arm - height);
  const Eigen::Vector3d pivot(centre.x() + reach * direction.x(),
                              centre.y() + reach * direction.y(), brick.support_height);
  const Eigen::Vector3d axis = Eigen::Vector3d::UnitZ().cross(result.push_direction);
  const double angular_impulse = (blow.point - pivot).cross(result.impulse).dot(axis);
  const double inertia = brick.mass_above * arm * arm;
  if (angular_impulse > 0.0 && inertia > 0.0)
    result.tip_delivered = angular_impulse * angular_impulse / (2.0 * inertia);
  result.tips = result.tip_delivered > result.tip_energy;
  return result;
}

std::string describeImpact(const ImpactJudgement& j) {
  std::string text = "delivered " + millijoules(j.delivered_energy);
  if (std::isfinite(j.striker_energy)) text += " of " + millijoules(j.striker_energy);
  text += ", slides " + (std::isfinite(j.slide) ? millimetres(j.slide) : std::string("freely")) +
          " against " + newtons(j.friction_force) + " of friction, tipping needs " +
          millijoules(j.tip_energy) + " (gets " + millijoules(j.tip_delivered) + ")";
  return text;
}

}  // namespace brick_stack_sim
