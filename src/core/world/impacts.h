#pragma once
// Impacts on frozen bricks, seen before Bullet's step (docs/design.md,
// "Impacts and held bricks": an impact may carry more energy than the stack
// above can absorb). Bullet
// sees a frozen brick as a static collider and would bounce any striker off
// it; the model judges each blow first, and the world carries out what it
// decides: the struck brick is woken and kicked, slid in place under its
// load, or left where it is.

#include <vector>

#include <Eigen/Geometry>

#include "bullet/dormant_colliders.h"
#include "stability/stability_model.h"

namespace brick_stack_sim {

struct WorldState;

/// A brick that may strike frozen ones within the coming step.
struct Striker {
  BodyHandle handle = 0;
  double mass = 0.0;  ///< [kg]; infinite when held.
  /// Where it will be at the end of the coming step if nothing stops it [m]:
  /// a blow is one it would sink into the struck brick by then (a swept
  /// test along its motion: nearest points alone would call a striker that
  /// skims past a corner an impact).
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  ///< [m/s]
  Eigen::Vector3d spin = Eigen::Vector3d::Zero();      ///< [rad/s]
  double restitution = 0.0;                            ///< Of its material [-].
};

/// Where along its way from `from` to its end pose `striker` first touches
/// `struck` (the fraction of the way, 1 when it does not touch it on the
/// way). A striker that covers more than half its thickness in a step is
/// swept (it could end the step beyond a thin brick it passed);
/// a slower one is judged where it ends, as the discrete contact would.
double firstContactOnTheWay(const WorldState& world, const Striker& striker,
                            const Eigen::Isometry3d& from, BodyHandle struck);
/// The pose a fraction `fraction` of the way from `from` to `to`.
Eigen::Isometry3d partWay(const Eigen::Isometry3d& from, const Eigen::Isometry3d& to,
                          double fraction);

/// Where `striker` meets the frozen brick `struck` within the coming step:
/// false when it does not touch it at its end pose, closes slower than the
/// stability's impact speed, or only grazes it along an edge. `overlap`
/// (optional) receives how deep the striker would sit in it (>= 0) [m].
bool findImpact(const WorldState& world, const Striker& striker, BodyHandle struck, Impact* impact,
                double* overlap = nullptr);

/// The model judges `impacts` and the world carries out its responses: wake
/// decisions are applied, a woken struck brick gets the impulse (and a free
/// striker the opposite one), a slid one is moved and rests anew, a free
/// striker of a slid brick bounces off it. Every blow that moved something,
/// and every absorbed blow of a free striker, is an `impact` event. Returns
/// the responses, in the order of `impacts`. `overlaps` (optional, one per
/// impact) are how deep a held striker would sit in the struck brick: a
/// brick the hand keeps pushing slides at least out of its way.
std::vector<ImpactResponse> carryOutImpacts(WorldState* world, const std::vector<Impact>& impacts,
                                            const std::vector<double>* overlaps = nullptr);

/// Stage 1, before Bullet's step: every mover that will strike a frozen
/// brick of `near` (the pairs within reach of this step) faster than the
/// impact speed is judged.
void strikeFrozenBricks(WorldState* world, const std::vector<ColliderApproach>& near);

}  // namespace brick_stack_sim
