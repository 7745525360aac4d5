#pragma once

namespace brick_stack_sim {

/// Wall time of the stages of Bullet's step [s], for a profile of where a
/// large pile spends it. Their sum is less than the whole step: applying
/// gravity, updating activation (sleeping) and the motion states are in
/// none of them.
struct BulletStageSeconds {
  /// Updating the bodies' broadphase boxes and finding the overlapping
  /// pairs [s].
  double broadphase = 0.0;
  /// Box-box (and other shape) tests of the overlapping pairs, which fill
  /// the contact manifolds [s].
  double narrowphase = 0.0;
  /// Merging bodies that touch into simulation islands (union-find) and
  /// storing each body's island [s].
  double islands = 0.0;
  /// The constraint solver, including Bullet's sorting of the manifolds
  /// into islands and the island processing that feeds them to it [s].
  double solver = 0.0;
  /// Predicting the motion, the continuous collision (sweeps and predictive
  /// contacts) and integrating the poses [s].
  double integration = 0.0;

  /// The five stages together [s].
  double total() const { return broadphase + narrowphase + islands + solver + integration; }

  BulletStageSeconds& operator+=(const BulletStageSeconds& other) {
    broadphase += other.broadphase;
    narrowphase += other.narrowphase;
    islands += other.islands;
    solver += other.solver;
    integration += other.integration;
    return *this;
  }
};

}  // namespace brick_stack_sim
