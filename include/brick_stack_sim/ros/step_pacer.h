#pragma once

namespace brick_stack_sim {
namespace ros_adapter {

/// What paces the world on the node's wall timer, apart from ROS so that it
/// is tested without a master: how many steps a tick takes so that sim time
/// follows wall time times real_time_factor, when the world has fallen too
/// far behind to catch up, when ~bricks is due in sim time, and how fast the
/// timer ticks. Times are plain seconds: wall times from any fixed origin.
class StepPacer {
 public:
  struct Options {
    double time_step = 0.001;          ///< One world step [s].
    double real_time_factor = 1.0;     ///< Sim time per wall time [-]; 0: as fast as possible.
    double max_steps_per_tick = 2000;  ///< Upper bound of steps per timer tick.
    double publish_rate = 30.0;        ///< ~bricks per second of sim time [Hz].
    double step_timer_rate = 200.0;    ///< The timer's rate while the world moves [Hz].
  };

  /// Wall time [s] the world may fall behind real_time_factor before the
  /// pacing gives up catching up: longer than any scheduling hiccup, short
  /// enough that a user sees sim time slow down rather than jump.
  static constexpr double kMaxLag = 0.1;
  /// ~bricks (with tf and markers) follows sim time, but never comes more
  /// often than this many times publish_rate x max(1, real_time_factor) per
  /// second of wall time: with real_time_factor 0 or during a ~step sim time
  /// runs far ahead of wall time, and nobody can read thousands of messages
  /// a second.
  static constexpr double kMaxPublishRateRatio = 2.0;

  explicit StepPacer(const Options& options) : options_(options) {}

  /// Paces from here: sim time `sim` [s] at wall time `wall` [s] (after a
  /// pause, a reset, or when the world cannot keep up).
  void restart(double wall, double sim);
  /// Steps the tick at wall time `wall` owes the world at sim time `sim`: as
  /// many as bring sim time to the wall clock's target, or
  /// max_steps_per_tick with real_time_factor 0 [steps, whole].
  double stepsWanted(double wall, double sim) const;
  /// At most max_steps_per_tick of `wanted`.
  long stepLimit(double wanted) const;
  /// Whether a tick that did `done` of `wanted` steps left the world more
  /// than kMaxLag of wall time behind: then catching up would only come back
  /// as a burst, and the caller restarts the pacing.
  bool fellBehind(double wanted, long done) const;

  /// Whether ~bricks is due at sim time `sim`, given the wall time of the
  /// last one `last_publish_wall` and now `wall` [s]; left due when the
  /// wall-time cap holds it back, so the next step publishes it.
  bool publishDue(double sim, double wall, double last_publish_wall) const;
  /// ~bricks went out at sim time `sim`: the next is one period later, or one
  /// period from `sim` when the schedule fell behind.
  void published(double sim);
  /// The next ~bricks is due at sim time `sim` (after a reset).
  void schedulePublish(double sim) { next_publish_time_ = sim; }

  /// The timer's rate [Hz]: publish_rate while `idle` (paused, or settled
  /// with nothing left to place), else step_timer_rate.
  double timerRate(bool idle) const;

 private:
  Options options_;
  double wall_start_ = 0.0;         ///< [s]
  double sim_start_ = 0.0;          ///< [s]
  double next_publish_time_ = 0.0;  ///< Sim time of the next ~bricks [s].
};

}  // namespace ros_adapter
}  // namespace brick_stack_sim
