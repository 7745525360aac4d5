// The card house (thesis figure 10) and its element, the inverted V.
#include <algorithm>
#include <cmath>

#include "scene/generators/generator_support.h"
#include "util/text_format.h"

namespace brick_stack_sim {

using scene_yaml::readInt;
using scene_yaml::readNumber;
using scene_yaml::readString;
using scene_yaml::readVector;

namespace {

/// The shape of a V of `type` bricks tilted by `angle` from vertical, each
/// with its length up and its thickness along the tilt.
struct VShape {
  double angle;
  double length, thickness;
  /// From the apex to the outer corner of a foot, along x [m].
  double halfWidth() const { return length * std::sin(angle) + thickness * std::cos(angle); }
  /// Height of the outer top edges, the highest, above the base [m].
  double top() const { return length * std::cos(angle) + thickness * std::sin(angle); }
  /// The outer top edges lie this far from the apex along x [m].
  double topEdge() const { return thickness * std::cos(angle); }
};

Status checkAngle(const char* generator, double angle) {
  // Beyond 80 degrees a V is two bricks lying on each other's edge.
  if (!std::isfinite(angle) || angle <= 0.0 || angle > 80.0 * M_PI / 180.0)
    return Status::error(std::string(generator) + " angle = " + formatNumber(angle) +
                         ": must be in (0, 1.396] rad (0 to 80 degrees from vertical)");
  return Status::success();
}

Status checkOrigin(const char* generator, const Eigen::Vector2d& origin) {
  if (!origin.allFinite() || origin.cwiseAbs().maxCoeff() > 100.0)
    return Status::error(std::string(generator) + " origin must be finite, within 100 m");
  return Status::success();
}

/// Appends the two bricks of a V whose apex (where the upper inner edges
/// meet) is at (`apex_x`, `y`), standing on the plane z = `base`, at `at`.
void appendV(const BrickType& type, const VShape& v, double apex_x, double y, double base,
             double at, std::vector<ScheduledBrick>* bricks) {
  // Turned about y by angle - 90 degrees, the brick's length leans towards +x.
  const Eigen::Matrix3d leaning_right =
      Eigen::AngleAxisd(v.angle - M_PI / 2.0, Eigen::Vector3d::UnitY()).toRotationMatrix();
  const Eigen::Matrix3d flip_x = Eigen::Vector3d(-1.0, 1.0, 1.0).asDiagonal();
  // Its lowest edge, the inner one of its foot, rests on the base.
  const double dx = 0.5 * (v.thickness * std::cos(v.angle) + v.length * std::sin(v.angle));
  const double z = base + 0.5 * (v.thickness * std::sin(v.angle) + v.length * std::cos(v.angle));
  appendBrick(type, Eigen::Vector3d(apex_x - dx, y, z), at, bricks).placement.pose.linear() =
      leaning_right;
  // Its mirror image: the same box turned, a proper rotation.
  appendBrick(type, Eigen::Vector3d(apex_x + dx, y, z), at, bricks).placement.pose.linear() =
      flip_x * leaning_right * flip_x;
}

}  // namespace

std::int64_t brickCount(const AFrameParams& /*params*/) { return 2; }

std::int64_t brickCount(const CardHouseParams& params) {
  // Levels of n, n - 1, ..., 1 V's of two bricks, and a level brick across
  // each two neighbouring V's of every level but the top one.
  const double n = params.levels;
  if (n < 1.0) return 0;
  return clampedCount(n * (n + 1.0) + 0.5 * n * (n - 1.0));
}

Status generateAFrame(const AFrameParams& params, const BrickTypeLibrary& types,
                      std::vector<ScheduledBrick>* bricks) {
  if (Status checked = checkAngle("aframe", params.angle); !checked) return checked;
  if (Status checked = checkOrigin("aframe", params.origin); !checked) return checked;
  const BrickType* type = nullptr;
  if (Status checked = checkStartAndType("aframe", params.start, 0.0, params.type, types, &type);
      !checked)
    return checked;
  const VShape v{params.angle, type->size.x(), type->size.z()};
  appendV(*type, v, params.origin.x(), params.origin.y(), 0.0, params.start, bricks);
  return Status::success();
}

Status generateCardHouse(const CardHouseParams& params, const BrickTypeLibrary& types,
                         std::vector<ScheduledBrick>* bricks) {
  if (params.levels < 1 || params.levels > 30)
    return Status::error("card_house levels = " + std::to_string(params.levels) +
                         ": must be in [1, 30]");
  if (Status checked = checkAngle("card_house", params.angle); !checked) return checked;
  if (Status checked = checkOrigin("card_house", params.origin); !checked) return checked;
  const BrickType* type = nullptr;
  if (Status checked =
          checkStartAndType("card_house", params.start, params.interval, params.type, types, &type);
      !checked)
    return checked;
  const double length = type->size.x(), width = type->size.y(), thickness = type->size.z();
  const VShape v{params.angle, length, thickness};
  // A level brick must reach the outer top edges of both V's it spans, with
  // 2 % of its length to spare, and a V must stand on one with both feet.
  const double reach = 0.5 * length - v.topEdge() - 0.02 * length;
  if (params.levels > 1 && (reach <= 0.0 || v.halfWidth() > 0.5 * length - 0.02 * length))
    return Status::error("card_house angle = " + formatNumber(params.angle) +
                         " rad: a V that wide cannot stand on a level brick of type '" +
                         type->name + "'; use a smaller angle or levels: 1");
  // Neighbouring V's side by side, or closer where a level brick could not
  // span them (they are in different rows along y, so they may overlap in x).
  const double spacing = std::min(2.0 * v.halfWidth(), 2.0 * reach);
  // Each row along y a little more than half a width from the one below:
  // neighbouring level bricks, which share an apex, do not touch.
  const double row_pitch = 0.5 * (width + 0.02 * width);
  const double y0 = params.origin.y() - (params.levels - 1) * row_pitch;
  double at = params.start;
  for (int level = 0; level < params.levels; ++level) {
    const int count = params.levels - level;
    const double base = level * (v.top() + thickness);
    auto apex_x = [&](int i) { return params.origin.x() + (i - 0.5 * (count - 1)) * spacing; };
    // Rows alternate: V's at even pitches, level bricks at odd ones.
    for (int i = 0; i < count; ++i) {
      appendV(*type, v, apex_x(i), y0 + (2 * i + level) * row_pitch, base, at, bricks);
      at += params.interval;
    }
    if (level + 1 == params.levels) break;
    for (int i = 0; i + 1 < count; ++i) {
      appendBrick(
          *type,
          Eigen::Vector3d(0.5 * (apex_x(i) + apex_x(i + 1)), y0 + (2 * i + level + 1) * row_pitch,
                          base + v.top() + 0.5 * thickness),
          at, bricks);
      at += params.interval;
    }
  }
  return Status::success();
}

namespace {

AFrameParams readAFrameParams(const YAML::Node& node, const std::string& where) {
  requireGeneratorKeys(node, where, {"angle", "origin"}, Placing::kAtOnce);
  AFrameParams params;
  params.angle = readNumber(node, "angle", where, params.angle);
  params.type = readString(node, "type", where);
  params.start = readNumber(node, "start", where, params.start);
  params.origin = readVector<2>(node, "origin", where, params.origin);
  return params;
}

}  // namespace

void readAFrameGenerator(const YAML::Node& node, const std::string& where,
                         const GeneratorContext& context, std::vector<ScheduledBrick>* bricks) {
  const AFrameParams params = readAFrameParams(node, where);
  failUnless(generateAFrame(params, context.types, bricks), where);
}

std::int64_t countAFrameGenerator(const YAML::Node& node, const std::string& where) {
  return brickCount(readAFrameParams(node, where));
}

namespace {

CardHouseParams readCardHouseParams(const YAML::Node& node, const std::string& where) {
  requireGeneratorKeys(node, where, {"levels", "angle", "origin"}, Placing::kOneByOne);
  CardHouseParams params;
  params.levels = readInt(node, "levels", where, params.levels);
  params.angle = readNumber(node, "angle", where, params.angle);
  readTypeAndTiming(node, where, &params);
  params.origin = readVector<2>(node, "origin", where, params.origin);
  return params;
}

}  // namespace

void readCardHouseGenerator(const YAML::Node& node, const std::string& where,
                            const GeneratorContext& context, std::vector<ScheduledBrick>* bricks) {
  const CardHouseParams params = readCardHouseParams(node, where);
  failUnless(generateCardHouse(params, context.types, bricks), where);
}

std::int64_t countCardHouseGenerator(const YAML::Node& node, const std::string& where) {
  return brickCount(readCardHouseParams(node, where));
}

}  // namespace brick_stack_sim
