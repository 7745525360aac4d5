#include "brick_stack_sim/ros/step_pacer.h"

#include <algorithm>
#include <cmath>

namespace brick_stack_sim {
namespace ros_adapter {

void StepPacer::restart(double wall, double sim) {
  wall_start_ = wall;
  sim_start_ = sim;
}

double StepPacer::stepsWanted(double wall, double sim) const {
  if (options_.real_time_factor <= 0.0) return options_.max_steps_per_tick;
  const double target = sim_start_ + (wall - wall_start_) * options_.real_time_factor;
  // The small epsilon keeps a step that is due "exactly now" from slipping
  // to the next tick through rounding.
  return std::max(0.0, std::floor((target - sim) / options_.time_step + 1e-6));
}

long StepPacer::stepLimit(double wanted) const {
  return static_cast<long>(std::min<double>(wanted, options_.max_steps_per_tick));
}

bool StepPacer::fellBehind(double wanted, long done) const {
  if (options_.real_time_factor <= 0.0) return false;
  const double lag =
      (wanted - done) * options_.time_step / std::max(options_.real_time_factor, 1e-9);
  return lag > kMaxLag;
}

bool StepPacer::publishDue(double sim, double wall, double last_publish_wall) const {
  if (sim + 1e-9 < next_publish_time_) return false;
  const double fastest =
      kMaxPublishRateRatio * options_.publish_rate * std::max(1.0, options_.real_time_factor);
  return wall >= last_publish_wall + 1.0 / fastest;
}

void StepPacer::published(double sim) {
  const double period = 1.0 / options_.publish_rate;
  next_publish_time_ += period;
  if (next_publish_time_ <= sim) next_publish_time_ = sim + period;
}

double StepPacer::timerRate(bool idle) const {
  return idle ? std::min(options_.publish_rate, options_.step_timer_rate)
              : options_.step_timer_rate;
}

}  // namespace ros_adapter
}  // namespace brick_stack_sim
