#include "scene/generators/generator_support.h"

#include <cmath>
#include <random>

namespace brick_stack_sim {

using scene_yaml::readInt;
using scene_yaml::readNumber;
using scene_yaml::readVector;

std::int64_t brickCount(const PileParams& params) { return clampedCount(params.bricks); }

Status generatePile(const PileParams& params, const BrickTypeLibrary& types,
                    std::vector<ScheduledBrick>* bricks) {
  if (params.bricks < 1 || params.bricks > 100000)
    return Status::error("pile bricks = " + std::to_string(params.bricks) +
                         ": must be in [1, 100000]");
  if (params.columns < 1 || params.rows < 1)
    return Status::error("pile columns and rows must be >= 1");
  if (!params.origin.allFinite()) return Status::error("pile origin must be finite");
  if (!std::isfinite(params.cell) || !std::isfinite(params.layer_height) ||
      !std::isfinite(params.base_height) || !std::isfinite(params.max_tilt) || params.cell <= 0.0 ||
      params.layer_height <= 0.0 || params.base_height <= 0.0 || params.max_tilt < 0.0 ||
      params.max_tilt > 1.5)
    return Status::error(
        "pile cell, layer_height and base_height must be > 0 m, max_tilt in "
        "[0, 1.5] rad");
  const BrickType* type = nullptr;
  if (Status checked = checkStartAndType("pile", params.start, 0.0, params.type, types, &type);
      !checked)
    return checked;
  // Raw mt19937 output scaled by hand: std's distributions differ between
  // standard libraries, and a scene must be the same scene everywhere.
  std::mt19937 random(params.seed);
  auto uniform = [&random](double low, double high) {
    return low + (high - low) * (static_cast<double>(random()) / 4294967296.0);
  };
  const int per_layer = params.columns * params.rows;
  // Offsets stay within what keeps two neighbours apart whatever their yaw.
  const double footprint_radius = 0.5 * std::hypot(type->size.x(), type->size.y());
  const double slack = 0.5 * params.cell - footprint_radius;
  for (int i = 0; i < params.bricks; ++i) {
    const int layer = i / per_layer, column = i % params.columns,
              row = (i % per_layer) / params.columns;
    const double jitter = std::max(slack, 0.0);
    // One expression, as it always was: the order of the draws inside it
    // fixes the scene.
    ScheduledBrick& brick = appendBrick(
        *type,
        Eigen::Vector3d(params.origin.x() + (column - 0.5 * (params.columns - 1)) * params.cell +
                            uniform(-jitter, jitter),
                        params.origin.y() + (row - 0.5 * (params.rows - 1)) * params.cell +
                            uniform(-jitter, jitter),
                        params.base_height + layer * params.layer_height),
        params.start, bricks);
    const double yaw = uniform(-M_PI, M_PI), pitch = uniform(-params.max_tilt, params.max_tilt),
                 roll = uniform(-params.max_tilt, params.max_tilt);
    brick.placement.pose.linear() = rotationFromRpy(Eigen::Vector3d(roll, pitch, yaw));
  }
  return Status::success();
}

namespace {

PileParams readPileParams(const YAML::Node& node, const std::string& where) {
  requireGeneratorKeys(node, where,
                       {"bricks", "columns", "rows", "cell", "layer_height", "base_height",
                        "max_tilt", "seed", "origin"},
                       Placing::kAtOnce);
  PileParams params;
  params.origin = readVector<2>(node, "origin", where, params.origin);
  params.bricks = readInt(node, "bricks", where, params.bricks);
  params.columns = readInt(node, "columns", where, params.columns);
  params.rows = readInt(node, "rows", where, params.rows);
  params.cell = readNumber(node, "cell", where, params.cell);
  params.layer_height = readNumber(node, "layer_height", where, params.layer_height);
  params.base_height = readNumber(node, "base_height", where, params.base_height);
  params.max_tilt = readNumber(node, "max_tilt", where, params.max_tilt);
  params.seed = static_cast<unsigned>(readInt(node, "seed", where, static_cast<int>(params.seed)));
  params.type = scene_yaml::readString(node, "type", where);
  params.start = readNumber(node, "start", where, params.start);
  return params;
}

}  // namespace

void readPileGenerator(const YAML::Node& node, const std::string& where,
                       const GeneratorContext& context, std::vector<ScheduledBrick>* bricks) {
  const PileParams params = readPileParams(node, where);
  failUnless(generatePile(params, context.types, bricks), where);
}

std::int64_t countPileGenerator(const YAML::Node& node, const std::string& where) {
  return brickCount(readPileParams(node, where));
}

}  // namespace brick_stack_sim
