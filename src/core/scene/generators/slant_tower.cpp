#include "scene/generators/generator_support.h"

#include <cmath>

namespace brick_stack_sim {

using scene_yaml::readInt;
using scene_yaml::readNumber;

std::int64_t brickCount(const SlantTowerParams& params) { return clampedCount(params.layers); }

Status generateSlantTower(const SlantTowerParams& params, const BrickTypeLibrary& types,
                          std::vector<ScheduledBrick>* bricks) {
  if (params.layers < 1 || params.layers > 10000)
    return Status::error("slant_tower layers = " + std::to_string(params.layers) +
                         ": must be in [1, 10000]");
  if (!std::isfinite(params.offset) || std::abs(params.offset) > 1.0)
    return Status::error("slant_tower offset must be finite and at most 1 m");
  const BrickType* type = nullptr;
  if (Status checked = checkStartAndType("slant_tower", params.start, params.interval, params.type,
                                         types, &type);
      !checked)
    return checked;
  for (int layer = 0; layer < params.layers; ++layer)
    appendBrick(*type, Eigen::Vector3d(layer * params.offset, 0.0, (layer + 0.5) * type->size.z()),
                params.start + params.interval * layer, bricks);
  return Status::success();
}

namespace {

SlantTowerParams readSlantTowerParams(const YAML::Node& node, const std::string& where) {
  requireGeneratorKeys(node, where, {"layers", "offset"}, Placing::kOneByOne);
  SlantTowerParams params;
  params.layers = readInt(node, "layers", where, params.layers);
  params.offset = readNumber(node, "offset", where, params.offset);
  readTypeAndTiming(node, where, &params);
  return params;
}

}  // namespace

void readSlantTowerGenerator(const YAML::Node& node, const std::string& where,
                             const GeneratorContext& context, std::vector<ScheduledBrick>* bricks) {
  const SlantTowerParams params = readSlantTowerParams(node, where);
  failUnless(generateSlantTower(params, context.types, bricks), where);
}

std::int64_t countSlantTowerGenerator(const YAML::Node& node, const std::string& where) {
  return brickCount(readSlantTowerParams(node, where));
}

}  // namespace brick_stack_sim
