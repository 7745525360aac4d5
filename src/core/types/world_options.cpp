#include "brick_stack_sim/core/types/world_options.h"

#include <cmath>
#include <sstream>

#include "brick_stack_sim/core/options/options_reader.h"
#include "util/text_format.h"
#include "util/validation.h"

namespace brick_stack_sim {

Status validate(const TableOptions& t) {
  if (!positive(t.size.x()) || !positive(t.size.y()))
    return bad("size", positive(t.size.x()) ? t.size.y() : t.size.x(), "must be > 0 m");
  if (!positive(t.thickness)) return bad("thickness", t.thickness, "must be > 0 m");
  if (!positive(t.height) || t.height < t.thickness)
    return bad("height", t.height, "must be > 0 m and at least table/thickness");
  if (!nonNegative(t.friction)) return bad("friction", t.friction, "must be >= 0");
  if (!nonNegative(t.restitution) || t.restitution > 1.0)
    return bad("restitution", t.restitution, "must be in [0, 1]");
  return Status::success();
}

Status validate(const SleepingOptions& s) {
  if (!nonNegative(s.linear_threshold))
    return bad("linear_threshold", s.linear_threshold, "must be >= 0 m/s");
  if (!nonNegative(s.angular_threshold))
    return bad("angular_threshold", s.angular_threshold, "must be >= 0 rad/s");
  if (!positive(s.time)) return bad("time", s.time, "must be > 0 s");
  return Status::success();
}

Status validate(const HeldOptions& h) {
  if (!positive(h.max_linear_speed) || h.max_linear_speed > 10.0)
    return bad("max_linear_speed", h.max_linear_speed, "must be in (0, 10] m/s");
  if (!positive(h.max_angular_speed) || h.max_angular_speed > 100.0)
    return bad("max_angular_speed", h.max_angular_speed, "must be in (0, 100] rad/s");
  if (!nonNegative(h.stiffness) || h.stiffness > 1e4)
    return bad("stiffness", h.stiffness, "must be in [0, 10000] N/m");
  if (!nonNegative(h.max_force) || h.max_force > 1e3)
    return bad("max_force", h.max_force, "must be in [0, 1000] N");
  return Status::success();
}

Status validate(const BoundsOptions& b) {
  // Beyond 10 km double precision still holds a brick, but nothing a table
  // scene does goes there, and a typo of a few zeros is caught.
  if (!positive(b.horizontal) || b.horizontal > 1e4)
    return bad("horizontal", b.horizontal, "must be in (0, 1e4] m");
  if (!positive(b.height) || b.height > 1e4)
    return bad("height", b.height, "must be in (0, 1e4] m");
  return Status::success();
}

bool insideWorld(const WorldOptions& o, const Eigen::Vector3d& c) {
  // Written so that NaN is outside.
  return std::abs(c.x()) <= o.bounds.horizontal && std::abs(c.y()) <= o.bounds.horizontal &&
         c.z() <= o.bounds.height && c.z() >= -o.table.height - BoundsOptions::kBelowFloor;
}

std::string describeWorldBox(const WorldOptions& o) {
  std::ostringstream text;
  text << "|x|, |y| <= " << o.bounds.horizontal << " m, "
       << -o.table.height - BoundsOptions::kBelowFloor << " m <= z <= " << o.bounds.height
       << " m (parameters bounds/horizontal, bounds/height)";
  return text.str();
}

Status validate(const WorldOptions& o) {
  // Below 10 us a step resolves nothing Bullet needs; at 0.1 s a brick that
  // has fallen a few centimetres crosses several of its own thicknesses in one
  // step, which no contact can catch.
  if (!positive(o.time_step) || o.time_step < 1e-5 || o.time_step > 0.1)
    return bad("time_step", o.time_step, "must be in [1e-5, 0.1] s");
  if (o.solver_iterations < 1 || o.solver_iterations > 10000)
    return bad("solver_iterations", o.solver_iterations, "must be in [1, 10000]");
  if (!nonNegative(o.gravity) || o.gravity > 1000.0)
    return bad("gravity", o.gravity, "must be in [0, 1000] m/s^2");
  if (Status sleeping = validate(o.sleeping); !sleeping) return prefixed("sleeping/", sleeping);
  if (!std::isfinite(o.split_impulse_penetration_threshold) ||
      o.split_impulse_penetration_threshold > 0.0)
    return bad("split_impulse_penetration_threshold", o.split_impulse_penetration_threshold,
               "must be <= 0 m");
  if (!positive(o.erp) || o.erp > 1.0) return bad("erp", o.erp, "must be in (0, 1]");
  // Bullet's friction turns its direction with the slip: what one step's
  // friction was carried into the next would push the wrong way.
  if (o.full_warm_start && !o.friction_cone)
    return bad("full_warm_start", "true", "needs friction_cone = true");
  if (!nonNegative(o.collision_margin) || o.collision_margin > 0.01)
    return bad("collision_margin", o.collision_margin, "must be in [0, 0.01] m");
  if (!nonNegative(o.overlap_tolerance) || o.overlap_tolerance > 0.01)
    return bad("overlap_tolerance", o.overlap_tolerance, "must be in [0, 0.01] m");
  if (!positive(o.fall_off_depth)) return bad("fall_off_depth", o.fall_off_depth, "must be > 0 m");
  if (!positive(o.max_linear_speed))
    return bad("max_linear_speed", o.max_linear_speed, "must be > 0 m/s");
  if (!positive(o.max_angular_speed))
    return bad("max_angular_speed", o.max_angular_speed, "must be > 0 rad/s");
  if (Status held = validate(o.held); !held) return prefixed("held/", held);
  if (Status table = validate(o.table); !table) return prefixed("table/", table);
  if (Status bounds = validate(o.bounds); !bounds) return prefixed("bounds/", bounds);
  if (o.bounds.horizontal < 0.5 * o.table.size.maxCoeff())
    return bad("bounds/horizontal", o.bounds.horizontal,
               "must reach the table's edges (table/size / 2 = " +
                   formatNumber(0.5 * o.table.size.maxCoeff()) + " m)");
  if (Status stability = validate(o.stability); !stability)
    return prefixed("stability/", stability);
  return Status::success();
}

Status readTableOptions(OptionsReader& reader, TableOptions* options) {
  return readAndValidate(reader, true, options, [&reader](TableOptions& table) {
    reader.read("size", &table.size);
    reader.read("thickness", &table.thickness);
    reader.read("height", &table.height);
    reader.read("friction", &table.friction);
    reader.read("restitution", &table.restitution);
  });
}

Status readSleepingOptions(OptionsReader& reader, SleepingOptions* options) {
  return readAndValidate(reader, true, options, [&reader](SleepingOptions& sleeping) {
    reader.read("enabled", &sleeping.enabled);
    reader.read("linear_threshold", &sleeping.linear_threshold);
    reader.read("angular_threshold", &sleeping.angular_threshold);
    reader.read("time", &sleeping.time);
  });
}

Status readHeldOptions(OptionsReader& reader, HeldOptions* options) {
  return readAndValidate(reader, true, options, [&reader](HeldOptions& held) {
    reader.read("max_linear_speed", &held.max_linear_speed);
    reader.read("max_angular_speed", &held.max_angular_speed);
    reader.read("stiffness", &held.stiffness);
    reader.read("max_force", &held.max_force);
  });
}

Status readBoundsOptions(OptionsReader& reader, BoundsOptions* options) {
  return readAndValidate(reader, true, options, [&reader](BoundsOptions& bounds) {
    reader.read("horizontal", &bounds.horizontal);
    reader.read("height", &bounds.height);
  });
}

Status readWorldOptions(OptionsReader& reader, WorldOptions* options) {
  return readAndValidate(reader, false, options, [&reader](WorldOptions& world) {
    reader.read("time_step", &world.time_step);
    reader.read("solver_iterations", &world.solver_iterations);
    reader.read("gravity", &world.gravity);
    reader.section("sleeping", &readSleepingOptions, &world.sleeping);
    reader.read("split_impulse_penetration_threshold", &world.split_impulse_penetration_threshold);
    reader.read("erp", &world.erp);
    reader.read("friction_cone", &world.friction_cone);
    reader.read("full_warm_start", &world.full_warm_start);
    reader.read("collision_margin", &world.collision_margin);
    reader.read("overlap_tolerance", &world.overlap_tolerance);
    reader.read("fall_off_depth", &world.fall_off_depth);
    reader.read("max_linear_speed", &world.max_linear_speed);
    reader.read("max_angular_speed", &world.max_angular_speed);
    reader.section("held", &readHeldOptions, &world.held);
    reader.section("table", &readTableOptions, &world.table);
    reader.section("bounds", &readBoundsOptions, &world.bounds);
    reader.section("stability", &readStabilityOptions, &world.stability);
  });
}

}  // namespace brick_stack_sim
