#include "brick_stack_sim/core/types/stability_options.h"

#include "brick_stack_sim/core/options/options_reader.h"
#include "brick_stack_sim/core/types/stability_modes.h"
#include "util/text_format.h"
#include "util/validation.h"

namespace brick_stack_sim {

Status validate(const StabilityOptions& s) {
  if (!checkStabilityMode(s.mode))
    return bad(
        "mode", "'" + s.mode + "'",
        "not available in this build (available: " + joinNames(availableStabilityModes()) + ")");
  if (!positive(s.rest_linear_speed))
    return bad("rest_linear_speed", s.rest_linear_speed, "must be > 0 m/s");
  if (!positive(s.rest_angular_speed))
    return bad("rest_angular_speed", s.rest_angular_speed, "must be > 0 rad/s");
  if (!nonNegative(s.rest_time)) return bad("rest_time", s.rest_time, "must be >= 0 s");
  if (!positive(s.impact_speed)) return bad("impact_speed", s.impact_speed, "must be > 0 m/s");
  if (!positive(s.impact_min_slide) || s.impact_min_slide > 0.1)
    return bad("impact_min_slide", s.impact_min_slide, "must be in (0, 0.1] m");
  if (!positive(s.support_normal_tolerance) || s.support_normal_tolerance >= M_PI / 2)
    return bad("support_normal_tolerance", s.support_normal_tolerance, "must be in (0, pi/2) rad");
  if (!nonNegative(s.flush_angle) || s.flush_angle > 0.1)
    return bad("flush_angle", s.flush_angle, "must be in [0, 0.1] rad");
  if (!positive(s.contact_distance) || s.contact_distance > 0.01)
    return bad("contact_distance", s.contact_distance, "must be in (0, 0.01] m");
  if (!nonNegative(s.min_margin) || s.min_margin > 0.01)
    return bad("min_margin", s.min_margin, "must be in [0, 0.01] m");
  return Status::success();
}

Status readStabilityOptions(OptionsReader& reader, StabilityOptions* options) {
  return readAndValidate(reader, true, options, [&reader](StabilityOptions& stability) {
    reader.read("mode", &stability.mode);
    reader.read("rest_linear_speed", &stability.rest_linear_speed);
    reader.read("rest_angular_speed", &stability.rest_angular_speed);
    reader.read("rest_time", &stability.rest_time);
    reader.read("impact_speed", &stability.impact_speed);
    reader.read("impact_min_slide", &stability.impact_min_slide);
    reader.read("support_normal_tolerance", &stability.support_normal_tolerance);
    reader.read("flush_angle", &stability.flush_angle);
    reader.read("contact_distance", &stability.contact_distance);
    reader.read("min_margin", &stability.min_margin);
  });
}

}  // namespace brick_stack_sim
