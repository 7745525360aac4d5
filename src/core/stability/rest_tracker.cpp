#include "stability/rest_tracker.h"

namespace brick_stack_sim {

bool slowerThanRestSpeeds(const BodyMotion& body, const StabilityOptions& options) {
  return body.linear_velocity.norm() < options.rest_linear_speed &&
         body.angular_velocity.norm() < options.rest_angular_speed;
}

bool RestTracker::atRest(const BodyMotion& body) const {
  return slowerThanRestSpeeds(body, options_);
}

RestTracker::Mover& RestTracker::advance(const BodyMotion& body, double dt) {
  Mover& mover = movers_[body.handle];
  const bool still =
      !mover.has_last_com || (body.com - mover.last_com).norm() <= options_.rest_linear_speed * dt;
  mover.last_com = body.com;
  mover.has_last_com = true;
  if (atRest(body) && still) {
    mover.rest_time += dt;
  } else {
    mover.rest_time = 0.0;
    mover.next_judgement = 0.0;
  }
  return mover;
}

RestTracker::Mover& RestTracker::restart(BodyHandle handle) {
  Mover& mover = movers_[handle];
  mover = Mover();
  return mover;
}

const RestTracker::Mover* RestTracker::find(BodyHandle handle) const {
  auto found = movers_.find(handle);
  return found == movers_.end() ? nullptr : &found->second;
}

}  // namespace brick_stack_sim
