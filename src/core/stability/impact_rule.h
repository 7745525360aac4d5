#pragma once
// When does a blow move a frozen brick? The thesis (3.6) compared the
// striker's kinetic energy with the potential energy of the struck brick and
// its load, which ignores where the blow lands and what holds the brick: a
// hard hit low in a tower did nothing, and the threshold was a step function
// of speed. Here the blow is an impulse, and what it takes to move the brick
// is what friction and gravity can absorb: the energy the impulse gives a free
// brick, against the work friction does over a visible slide, and the
// rotational energy it gives about the support edge, against lifting the
// COM-above over that edge. Nothing here depends on the time step.

#include <string>

#include <Eigen/Geometry>

#include "brick_stack_sim/core/geometry/polygon2d.h"
#include "stability/stability_model.h"

namespace brick_stack_sim {

/// The struck brick as the stack holds it.
struct StruckBrick {
  double mass = 0.0;        ///< Its own [kg].
  double mass_above = 0.0;  ///< It and its share of what it carries [kg].
  Eigen::Vector3d com_above = Eigen::Vector3d::Zero();  ///< [m], world.
  Polygon2d support_hull;                               ///< Where it rests, from above [m].
  double support_height = 0.0;                          ///< [m]
  double friction = 0.0;  ///< Coulomb coefficient of its supports, the weakest [-].
};

/// What the blow does to the struck brick.
struct ImpactJudgement {
  Eigen::Vector3d impulse = Eigen::Vector3d::Zero();  ///< On the struck brick [N s].
  /// Sideways unit direction the impulse pushes it (zero for a blow from
  /// straight above or below).
  Eigen::Vector3d push_direction = Eigen::Vector3d::Zero();
  double striker_energy = 0.0;    ///< Kinetic energy of the closing motion [J] (inf when held).
  double delivered_energy = 0.0;  ///< The sideways impulse's energy in the free brick [J].
  double friction_force = 0.0;    ///< Friction against sliding, below and above it [N].
  double slide = 0.0;             ///< How far that friction lets it slide [m].
  double tip_energy = 0.0;        ///< Lifting the COM-above over the support edge [J].
  double tip_delivered = 0.0;     ///< Rotational energy the blow gives about that edge [J].
  bool slides = false;            ///< slide >= the visible minimum.
  bool tips = false;              ///< tip_delivered > tip_energy.
  bool moves() const { return slides || tips; }
};

/// Judges the blow of `impact` on `brick`. A slide shorter than
/// `min_slide` [m] is absorbed (a gentle touch moves nothing a person could
/// see).
ImpactJudgement judgeImpact(const StruckBrick& brick, const Impact& impact, double min_slide);

/// "delivered 1.49 mJ, slides 25.3 mm, tipping needs 0.98 mJ (gets 0.15 mJ)".
std::string describeImpact(const ImpactJudgement& judgement);

}  // namespace brick_stack_sim
