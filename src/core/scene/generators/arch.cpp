#include <cmath>

#include "scene/generators/generator_support.h"
#include "util/text_format.h"

namespace brick_stack_sim {

using scene_yaml::readInt;
using scene_yaml::readNumber;
using scene_yaml::readString;

namespace {

/// One arc of the ring: its centre on the springing line and the angles
/// its voussoirs span [rad], from `from` in steps of `step`.
struct Arc {
  double centre_x = 0.0;  ///< [m]
  double from = 0.0;
  double step = 0.0;
  int count = 0;
};

std::vector<Arc> arcsOf(const ArchParams& p) {
  if (p.pointed == 0.0) return {Arc{0.0, 0.0, M_PI / p.voussoirs, p.voussoirs}};
  // Each half rises from its springing (angle 0 about a centre beyond the
  // middle) to the crown, where the arc crosses the middle: cos = c / R.
  const double crown = std::acos(p.pointed);
  const int half = p.voussoirs / 2;
  const double c = p.pointed * p.radius;
  return {Arc{-c, 0.0, crown / half, half}, Arc{c, M_PI - crown, crown / half, half}};
}

Status checkArch(const ArchParams& p) {
  const auto positive = [](double v, double most) {
    return std::isfinite(v) && v > 0 && v <= most;
  };
  if (p.voussoirs < 2 || p.voussoirs > 1000)
    return Status::error("arch voussoirs = " + std::to_string(p.voussoirs) +
                         ": must be in [2, 1000]");
  if (!positive(p.radius, 10.0)) return Status::error("arch radius must be in (0, 10] m");
  if (!positive(p.thickness, 1.9 * p.radius))
    return Status::error("arch thickness must be in (0, 1.9 radius] m");
  if (!positive(p.depth, 10.0)) return Status::error("arch depth must be in (0, 10] m");
  if (!std::isfinite(p.pointed) || p.pointed < 0.0 || p.pointed > 0.9)
    return Status::error("arch pointed must be in [0, 0.9]");
  if (p.pointed > 0.0 && p.voussoirs % 2 != 0)
    return Status::error("a pointed arch needs an even number of voussoirs (a joint at its crown)");
  if (!positive(p.density, 1e5)) return Status::error("arch density must be in (0, 1e5] kg/m^3");
  if (!std::isfinite(p.friction) || p.friction < 0.0)
    return Status::error("arch friction must be >= 0");
  if (!std::isfinite(p.start) || p.start < 0.0) return Status::error("arch start must be >= 0 s");
  if (!p.origin.allFinite()) return Status::error("arch origin must be finite");
  return Status::success();
}

/// The voussoir spanning `step` [rad] of a ring of centre-line `radius`:
/// its frame's origin on the centre line, x outward along the middle
/// radius, z along the ring, y across it.
Status voussoirType(const ArchParams& p, double step, BrickType* type) {
  const double inner = p.radius - 0.5 * p.thickness, outer = p.radius + 0.5 * p.thickness;
  ShapePart part;
  part.kind = ShapeKind::kConvex;
  for (double r : {inner, outer})
    for (double side : {-0.5, 0.5})
      for (double y : {-0.5 * p.depth, 0.5 * p.depth})
        part.vertices.emplace_back(r * std::cos(side * step) - p.radius, y,
                                   r * std::sin(side * step));
  type->name = p.type_name;
  type->shape.kind = ShapeKind::kConvex;
  type->shape.parts = {part};
  // The cross-section is the ring's sector less its inner one, cut by chords.
  type->mass = p.density * p.depth * 0.5 * (outer * outer - inner * inner) * std::sin(step);
  type->friction = p.friction;
  return finishBrickType(type, false);
}

}  // namespace

std::int64_t brickCount(const ArchParams& params) { return clampedCount(params.voussoirs); }

Status generateArch(const ArchParams& params, std::vector<BrickType>* types,
                    std::vector<ScheduledBrick>* bricks) {
  if (Status valid = checkArch(params); !valid) return valid;
  const std::vector<Arc> arcs = arcsOf(params);
  BrickType type;
  if (Status built = voussoirType(params, arcs[0].step, &type); !built)
    return Status::error("arch: " + built.message);
  for (const Arc& arc : arcs) {
    for (int i = 0; i < arc.count; ++i) {
      const double middle = arc.from + (i + 0.5) * arc.step;
      const Eigen::Vector3d centre(params.origin.x() + arc.centre_x, params.origin.y(), 0.0);
      ScheduledBrick& brick = appendBrick(
          type, centre + params.radius * Eigen::Vector3d(std::cos(middle), 0.0, std::sin(middle)),
          params.start, bricks);
      // x out along the middle radius, z along the ring: turned by -middle about y.
      brick.placement.pose.linear() =
          Eigen::AngleAxisd(-middle, Eigen::Vector3d::UnitY()).toRotationMatrix();
    }
  }
  types->push_back(std::move(type));
  return Status::success();
}

namespace {

ArchParams readArchParams(const YAML::Node& node, const std::string& where) {
  requireGeneratorKeys(node, where,
                       {"voussoirs", "radius", "thickness", "depth", "pointed", "density",
                        "friction", "type_name", "origin"},
                       Placing::kAtOnce);
  if (node["type"])
    scene_yaml::fail(where + ".type", "an arch defines its own type: name it with type_name");
  ArchParams params;
  params.voussoirs = readInt(node, "voussoirs", where, params.voussoirs);
  params.radius = readNumber(node, "radius", where, params.radius);
  params.thickness = readNumber(node, "thickness", where, params.thickness);
  params.depth = readNumber(node, "depth", where, params.depth);
  params.pointed = readNumber(node, "pointed", where, params.pointed);
  params.density = readNumber(node, "density", where, params.density);
  params.friction = readNumber(node, "friction", where, params.friction);
  params.type_name = readString(node, "type_name", where, params.type_name);
  params.start = readNumber(node, "start", where, params.start);
  params.origin = scene_yaml::readVector<2>(node, "origin", where, params.origin);
  return params;
}

}  // namespace

void readArchGenerator(const YAML::Node& node, const std::string& where,
                       const GeneratorContext& context, std::vector<ScheduledBrick>* bricks) {
  const ArchParams params = readArchParams(node, where);
  if (context.types.find(params.type_name))
    scene_yaml::fail(where + ".type_name", "type " + quotedId(params.type_name) +
                                               " is already defined: give the arch another");
  failUnless(generateArch(params, context.new_types, bricks), where);
}

std::int64_t countArchGenerator(const YAML::Node& node, const std::string& where) {
  return brickCount(readArchParams(node, where));
}

}  // namespace brick_stack_sim
