#include <cmath>

#include "scene/generators/generator_support.h"
#include "util/text_format.h"

namespace brick_stack_sim {

using scene_yaml::readInt;
using scene_yaml::readNumber;
using scene_yaml::readString;

namespace {

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

/// A point of the arch's plane [m]: x along the springing line from its
/// middle, z up.
using ArchPoint = Eigen::Vector2d;

ArchPoint onRing(double centre_x, double r, double angle) {
  return ArchPoint(centre_x + r * std::cos(angle), r * std::sin(angle));
}

/// The frame of a voussoir whose middle radius, about a centre `centre_x`
/// on the springing line, is at `middle` [rad]: its origin on the ring's
/// centre line, x out along that radius, z along the ring, y across it.
Eigen::Isometry3d voussoirFrame(const ArchParams& p, double centre_x, double middle) {
  Eigen::Isometry3d frame = Eigen::Isometry3d::Identity();
  const ArchPoint at = onRing(centre_x, p.radius, middle);
  frame.translation() = Eigen::Vector3d(at.x(), 0.0, at.y());
  frame.linear() = Eigen::AngleAxisd(-middle, Eigen::Vector3d::UnitY()).toRotationMatrix();
  return frame;
}

/// The voussoir type `name` whose cross-section has `corners` (in order
/// around it), extruded over the depth, in `frame`.
Status voussoirType(const ArchParams& p, const std::string& name,
                    const std::vector<ArchPoint>& corners, const Eigen::Isometry3d& frame,
                    BrickType* type) {
  ShapePart part;
  part.kind = ShapeKind::kConvex;
  double twice_area = 0.0;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const ArchPoint& a = corners[i];
    const ArchPoint& b = corners[(i + 1) % corners.size()];
    twice_area += a.x() * b.y() - b.x() * a.y();
    for (double y : {-0.5 * p.depth, 0.5 * p.depth})
      part.vertices.push_back(frame.inverse() * Eigen::Vector3d(a.x(), y, a.y()));
  }
  type->name = name;
  type->shape.kind = ShapeKind::kConvex;
  type->shape.parts = {part};
  type->mass = p.density * p.depth * 0.5 * std::abs(twice_area);
  type->friction = p.friction;
  if (Status built = finishBrickType(type, false); !built)
    return Status::error("arch: " + built.message);
  return Status::success();
}

/// The corners of the ring between the radii at `from` and `to` [rad]
/// about a centre `centre_x`: its joints are radial, its faces chords.
std::vector<ArchPoint> ringSection(const ArchParams& p, double centre_x, double from, double to) {
  const double inner = p.radius - 0.5 * p.thickness, outer = p.radius + 0.5 * p.thickness;
  return {onRing(centre_x, inner, from), onRing(centre_x, inner, to), onRing(centre_x, outer, to),
          onRing(centre_x, outer, from)};
}

/// Places the ring's voussoirs from the right springing up: a semicircle
/// in one arc over to the left springing; a pointed arch's right half,
/// whose top voussoir meets the left half on the vertical crown joint, and
/// the left half as its mirror image (a voussoir turned half a turn about
/// the vertical is its mirror: it is the same across its depth).
Status placeRing(const ArchParams& p, std::vector<BrickType>* types,
                 std::vector<ScheduledBrick>* bricks) {
  const bool pointed = p.pointed > 0.0;
  const int count = pointed ? p.voussoirs / 2 : p.voussoirs;
  const double c = pointed ? -p.pointed * p.radius : 0.0;  // the right half's centre
  // A pointed half rises to where its arc crosses the middle: cos = c / R.
  const double top = pointed ? std::acos(p.pointed) : M_PI;
  const double step = top / count;
  BrickType regular, crown;
  if (Status built = voussoirType(p, p.type_name, ringSection(p, c, -0.5 * step, 0.5 * step),
                                  voussoirFrame(p, c, 0.0), &regular);
      !built)
    return built;
  const Eigen::Isometry3d crown_frame = voussoirFrame(p, c, top - 0.5 * step);
  if (pointed) {
    const double inner = p.radius - 0.5 * p.thickness, outer = p.radius + 0.5 * p.thickness;
    std::vector<ArchPoint> section = ringSection(p, c, top - step, top);
    section[1] = ArchPoint(0.0, std::sqrt(inner * inner - c * c));
    section[2] = ArchPoint(0.0, std::sqrt(outer * outer - c * c));
    if (Status built = voussoirType(p, p.type_name + "_crown", section, crown_frame, &crown);
        !built)
      return built;
  }
  const Eigen::Vector3d origin(p.origin.x(), p.origin.y(), 0.0);
  std::vector<std::pair<const BrickType*, Eigen::Isometry3d>> half;
  for (int i = 0; i < count; ++i) {
    const bool is_crown = pointed && i + 1 == count;
    half.emplace_back(is_crown ? &crown : &regular,
                      is_crown ? crown_frame : voussoirFrame(p, c, (i + 0.5) * step));
  }
  for (int side = 0; side < (pointed ? 2 : 1); ++side) {
    const Eigen::Isometry3d mirror(Eigen::AngleAxisd(side * M_PI, Eigen::Vector3d::UnitZ()));
    for (const auto& [type, frame] : half) {
      const Eigen::Isometry3d pose = Eigen::Translation3d(origin) * mirror * frame;
      ScheduledBrick& brick = appendBrick(*type, pose.translation(), p.start, bricks);
      brick.placement.pose.linear() = pose.linear();
    }
  }
  types->push_back(std::move(regular));
  if (pointed) types->push_back(std::move(crown));
  return Status::success();
}

}  // namespace

std::int64_t brickCount(const ArchParams& params) { return clampedCount(params.voussoirs); }

Status generateArch(const ArchParams& params, std::vector<BrickType>* types,
                    std::vector<ScheduledBrick>* bricks) {
  if (Status valid = checkArch(params); !valid) return valid;
  return placeRing(params, types, bricks);
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
  for (const std::string& name : {params.type_name, params.type_name + "_crown"})
    if (context.types.find(name))
      scene_yaml::fail(where + ".type_name",
                       "type " + quotedId(name) + " is already defined: give the arch another");
  failUnless(generateArch(params, context.new_types, bricks), where);
}

std::int64_t countArchGenerator(const YAML::Node& node, const std::string& where) {
  return brickCount(readArchParams(node, where));
}

}  // namespace brick_stack_sim
