#include "scene/generators/generator_support.h"

#include <cmath>

namespace brick_stack_sim {

using scene_yaml::readInt;
using scene_yaml::readNumber;

std::int64_t brickCount(const HarmonicParams& params) { return clampedCount(params.bricks); }

Status generateHarmonic(const HarmonicParams& params, const TableOptions& table,
                        const BrickTypeLibrary& types, std::vector<ScheduledBrick>* bricks) {
  if (params.bricks < 1 || params.bricks > 1000)
    return Status::error("harmonic bricks = " + std::to_string(params.bricks) +
                         ": must be in [1, 1000]");
  if (!std::isfinite(params.factor) || params.factor < 0.0 || params.factor > 2.0)
    return Status::error("harmonic factor must be in [0, 2]");
  const BrickType* type = nullptr;
  if (Status checked =
          checkStartAndType("harmonic", params.start, params.interval, params.type, types, &type);
      !checked)
    return checked;
  const double length = type->size.x(), height = type->size.z();
  const int n = params.bricks;
  // Right ends from the bottom up: the table edge, then one overhang per brick.
  double right_end = 0.5 * table.size.x();
  for (int from_top = n; from_top >= 1; --from_top) {
    right_end += params.factor * length / (2.0 * from_top);
    const int layer = n - from_top;
    appendBrick(*type, Eigen::Vector3d(right_end - 0.5 * length, 0.0, (layer + 0.5) * height),
                params.start + params.interval * layer, bricks);
  }
  return Status::success();
}

namespace {

HarmonicParams readHarmonicParams(const YAML::Node& node, const std::string& where) {
  requireGeneratorKeys(node, where, {"bricks", "factor"}, Placing::kOneByOne);
  HarmonicParams params;
  params.bricks = readInt(node, "bricks", where, params.bricks);
  params.factor = readNumber(node, "factor", where, params.factor);
  readTypeAndTiming(node, where, &params);
  return params;
}

}  // namespace

void readHarmonicGenerator(const YAML::Node& node, const std::string& where,
                           const GeneratorContext& context, std::vector<ScheduledBrick>* bricks) {
  const HarmonicParams params = readHarmonicParams(node, where);
  failUnless(generateHarmonic(params, context.table, context.types, bricks), where);
}

std::int64_t countHarmonicGenerator(const YAML::Node& node, const std::string& where) {
  return brickCount(readHarmonicParams(node, where));
}

}  // namespace brick_stack_sim
