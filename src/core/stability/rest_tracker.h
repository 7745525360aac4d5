#pragma once

#include <unordered_map>

#include "stability/stability_model.h"

namespace brick_stack_sim {

/// Whether `body` is slower than both rest speeds of `options` (thesis
/// 3.3.2): the one test of rest, for the model and for what the world reads
/// on its behalf.
bool slowerThanRestSpeeds(const BodyMotion& body, const StabilityOptions& options);

/// How long each moving brick has been at rest (thesis 3.3.2), and what the
/// model last found about its supports while it moves.
class RestTracker {
 public:
  struct Mover {
    double rest_time = 0.0;  ///< [s] below both rest speeds, without a break.
    /// The rest time at which the criterion is next asked [s]: a brick it
    /// did not admit is asked again a rest window later, not every step
    /// (a leaning brick's statics is an LP).
    double next_judgement = 0.0;
    BrickStability stability;
    /// Woken by the model, and where its centre of mass was then [m]: until
    /// it has moved away from there, it may freeze again only when statics
    /// holds with a margin (else it would freeze and wake for ever).
    bool woken = false;
    Eigen::Vector3d woken_at = Eigen::Vector3d::Zero();
    /// Its centre of mass at the last step [m], and whether that is known.
    Eigen::Vector3d last_com = Eigen::Vector3d::Zero();
    bool has_last_com = false;
  };

  explicit RestTracker(const StabilityOptions& options) : options_(options) {}

  /// Whether `body` is slower than both rest speeds.
  bool atRest(const BodyMotion& body) const;
  /// One step of `dt` [s] for `body`: its rest time grows while it is at
  /// rest and starts over when it is not. Here at rest also asks that its
  /// centre of mass moved slower than the rest speed over the step: Bullet
  /// pushes a brick out of an overlap deeper than the split-impulse
  /// threshold without giving it any velocity, and a brick frozen during
  /// that push stays sunk (a plank knocked 7.7 mm into the floor froze 0.7
  /// mm deep, its velocity below the rest speeds while it rose at 15 mm/s).
  Mover& advance(const BodyMotion& body, double dt);
  /// The record of `handle`, a fresh one when it has none.
  Mover& record(BodyHandle handle) { return movers_[handle]; }
  /// Starts `handle` over, carrying only itself (a brick just woken).
  Mover& restart(BodyHandle handle);
  const Mover* find(BodyHandle handle) const;
  void erase(BodyHandle handle) { movers_.erase(handle); }

 private:
  StabilityOptions options_;
  /// Looked up for every mover every step; never walked in order.
  std::unordered_map<BodyHandle, Mover> movers_;
};

}  // namespace brick_stack_sim
