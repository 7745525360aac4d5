#include <cmath>

#include "scene/generators/generator_support.h"

namespace brick_stack_sim {

using scene_yaml::readInt;

std::int64_t brickCount(const ColumnParams& params) { return clampedCount(params.count); }

Status generateColumn(const ColumnParams& params, const BrickTypeLibrary& types,
                      std::vector<ScheduledBrick>* bricks) {
  if (params.count < 1 || params.count > 10000)
    return Status::error("column count = " + std::to_string(params.count) +
                         ": must be in [1, 10000]");
  if (!params.origin.allFinite()) return Status::error("column origin must be finite");
  const BrickType* type = nullptr;
  if (Status checked =
          checkStartAndType("column", params.start, params.interval, params.type, types, &type);
      !checked)
    return checked;
  // Each brick's bounds rest on the top of the one below; a type whose
  // bounds are not centred on its frame keeps that offset.
  const double lowest = bounds(type->placed(Eigen::Isometry3d::Identity())).min().z();
  for (int i = 0; i < params.count; ++i)
    appendBrick(*type,
                Eigen::Vector3d(params.origin.x(), params.origin.y(), i * type->size.z() - lowest),
                params.start + params.interval * i, bricks);
  return Status::success();
}

namespace {

ColumnParams readColumnParams(const YAML::Node& node, const std::string& where) {
  requireGeneratorKeys(node, where, {"count", "origin"}, Placing::kOneByOne);
  ColumnParams params;
  params.count = readInt(node, "count", where, params.count);
  params.origin = scene_yaml::readVector<2>(node, "origin", where, params.origin);
  readTypeAndTiming(node, where, &params);
  return params;
}

}  // namespace

void readColumnGenerator(const YAML::Node& node, const std::string& where,
                         const GeneratorContext& context, std::vector<ScheduledBrick>* bricks) {
  failUnless(generateColumn(readColumnParams(node, where), context.types, bricks), where);
}

std::int64_t countColumnGenerator(const YAML::Node& node, const std::string& where) {
  return brickCount(readColumnParams(node, where));
}

}  // namespace brick_stack_sim
