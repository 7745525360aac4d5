#include "scene/generators/generator_support.h"

#include <cmath>

namespace brick_stack_sim {

using scene_yaml::readInt;
using scene_yaml::readNumber;

std::int64_t brickCount(const PyramidParams& params) {
  // Rows of base, base - 1, ..., 1 bricks.
  return clampedCount(0.5 * params.base * (params.base + 1.0));
}

Status generatePyramid(const PyramidParams& params, const BrickTypeLibrary& types,
                       std::vector<ScheduledBrick>* bricks) {
  if (params.base < 1 || params.base > 200)
    return Status::error("pyramid base = " + std::to_string(params.base) + ": must be in [1, 200]");
  if (!std::isfinite(params.gap) || params.gap < 0.0 || params.gap > 0.1)
    return Status::error("pyramid gap must be in [0, 0.1] m");
  const BrickType* type = nullptr;
  if (Status checked =
          checkStartAndType("pyramid", params.start, params.interval, params.type, types, &type);
      !checked)
    return checked;
  const double pitch = type->size.x() + params.gap;
  int placed = 0;
  for (int row = 0; row < params.base; ++row) {
    const int count = params.base - row;
    for (int i = 0; i < count; ++i) {
      appendBrick(
          *type,
          Eigen::Vector3d((i - 0.5 * (count - 1)) * pitch, 0.0, (row + 0.5) * type->size.z()),
          params.start + params.interval * placed++, bricks);
    }
  }
  return Status::success();
}

namespace {

PyramidParams readPyramidParams(const YAML::Node& node, const std::string& where) {
  requireGeneratorKeys(node, where, {"base", "gap"}, Placing::kOneByOne);
  PyramidParams params;
  params.base = readInt(node, "base", where, params.base);
  params.gap = readNumber(node, "gap", where, params.gap);
  readTypeAndTiming(node, where, &params);
  return params;
}

}  // namespace

void readPyramidGenerator(const YAML::Node& node, const std::string& where,
                          const GeneratorContext& context, std::vector<ScheduledBrick>* bricks) {
  const PyramidParams params = readPyramidParams(node, where);
  failUnless(generatePyramid(params, context.types, bricks), where);
}

std::int64_t countPyramidGenerator(const YAML::Node& node, const std::string& where) {
  return brickCount(readPyramidParams(node, where));
}

}  // namespace brick_stack_sim
