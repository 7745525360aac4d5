#include "brick_stack_sim/core/world/world_options.h"

#include <cmath>
#include <sstream>

namespace brick_stack_sim {

namespace {

Status bad(const char* name, double value, const char* requirement) {
  std::ostringstream text;
  text << name << " = " << value << ": " << requirement;
  return Status::error(text.str());
}

bool positive(double value) { return std::isfinite(value) && value > 0.0; }
bool nonNegative(double value) { return std::isfinite(value) && value >= 0.0; }

}  // namespace

Status validate(const WorldOptions& o) {
  if (Status available = checkStabilityModeAvailable(o.mode); !available) return available;
  // Below 10 us a step resolves nothing Bullet needs; at 0.1 s a brick that
  // has fallen a few centimetres crosses several of its own thicknesses in one
  // step, which no contact can catch.
  if (!positive(o.time_step) || o.time_step < 1e-5 || o.time_step > 0.1)
    return bad("time_step", o.time_step, "must be in [1e-5, 0.1] s");
  if (o.solver_iterations < 1 || o.solver_iterations > 10000)
    return bad("solver_iterations", o.solver_iterations, "must be in [1, 10000]");
  if (!nonNegative(o.gravity) || o.gravity > 1000.0)
    return bad("gravity", o.gravity, "must be in [0, 1000] m/s^2");
  if (!nonNegative(o.linear_sleep_threshold))
    return bad("sleeping/linear_threshold", o.linear_sleep_threshold, "must be >= 0 m/s");
  if (!nonNegative(o.angular_sleep_threshold))
    return bad("sleeping/angular_threshold", o.angular_sleep_threshold, "must be >= 0 rad/s");
  if (!positive(o.deactivation_time))
    return bad("sleeping/time", o.deactivation_time, "must be > 0 s");
  if (!std::isfinite(o.split_impulse_penetration_threshold) ||
      o.split_impulse_penetration_threshold > 0.0)
    return bad("split_impulse_penetration_threshold", o.split_impulse_penetration_threshold,
               "must be <= 0 m");
  if (!positive(o.erp) || o.erp > 1.0) return bad("erp", o.erp, "must be in (0, 1]");
  if (!nonNegative(o.collision_margin) || o.collision_margin > 0.01)
    return bad("collision_margin", o.collision_margin, "must be in [0, 0.01] m");
  if (!nonNegative(o.overlap_tolerance) || o.overlap_tolerance > 0.01)
    return bad("overlap_tolerance", o.overlap_tolerance, "must be in [0, 0.01] m");
  if (!positive(o.fall_off_depth)) return bad("fall_off_depth", o.fall_off_depth, "must be > 0 m");
  if (!positive(o.max_linear_speed))
    return bad("max_linear_speed", o.max_linear_speed, "must be > 0 m/s");
  if (!positive(o.max_angular_speed))
    return bad("max_angular_speed", o.max_angular_speed, "must be > 0 rad/s");
  const TableOptions& t = o.table;
  if (!positive(t.size.x()) || !positive(t.size.y()))
    return bad("table/size", positive(t.size.x()) ? t.size.y() : t.size.x(), "must be > 0 m");
  if (!positive(t.thickness)) return bad("table/thickness", t.thickness, "must be > 0 m");
  if (!positive(t.height) || t.height < t.thickness)
    return bad("table/height", t.height, "must be > 0 m and at least table/thickness");
  if (!nonNegative(t.friction)) return bad("table/friction", t.friction, "must be >= 0");
  if (!nonNegative(t.restitution) || t.restitution > 1.0)
    return bad("table/restitution", t.restitution, "must be in [0, 1]");
  const StabilityOptions& s = o.stability;
  if (!positive(s.rest_linear_speed))
    return bad("stability/rest_linear_speed", s.rest_linear_speed, "must be > 0 m/s");
  if (!positive(s.rest_angular_speed))
    return bad("stability/rest_angular_speed", s.rest_angular_speed, "must be > 0 rad/s");
  if (!nonNegative(s.rest_time)) return bad("stability/rest_time", s.rest_time, "must be >= 0 s");
  if (!positive(s.impact_speed))
    return bad("stability/impact_speed", s.impact_speed, "must be > 0 m/s");
  if (!positive(s.support_normal_tolerance) || s.support_normal_tolerance >= M_PI / 2)
    return bad("stability/support_normal_tolerance", s.support_normal_tolerance,
               "must be in (0, pi/2) rad");
  if (!nonNegative(s.flush_angle) || s.flush_angle > 0.1)
    return bad("stability/flush_angle", s.flush_angle, "must be in [0, 0.1] rad");
  if (!positive(s.contact_distance) || s.contact_distance > 0.01)
    return bad("stability/contact_distance", s.contact_distance, "must be in (0, 0.01] m");
  if (!nonNegative(s.min_margin) || s.min_margin > 0.01)
    return bad("stability/min_margin", s.min_margin, "must be in [0, 0.01] m");
  return Status::success();
}

}  // namespace brick_stack_sim
