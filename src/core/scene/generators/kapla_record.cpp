#include "scene/generators/generator_support.h"

namespace brick_stack_sim {

using scene_yaml::readInt;
using scene_yaml::readVector;

std::int64_t brickCount(const KaplaRecordParams& params) {
  // Two layers of two planks per floor.
  return clampedCount(4.0 * params.floors);
}

Status generateKaplaRecord(const KaplaRecordParams& params, const BrickTypeLibrary& types,
                           std::vector<ScheduledBrick>* bricks) {
  if (params.floors < 1 || params.floors > 5000)
    return Status::error("kapla_record floors = " + std::to_string(params.floors) +
                         ": must be in [1, 5000]");
  // A floor is a square frame: two planks along x, two across them along y.
  TowerParams tower;
  tower.layers = 2 * params.floors;
  tower.bricks_per_layer = 2;
  tower.type = params.type;
  tower.start = params.start;
  tower.interval = params.interval;
  tower.origin = params.origin;
  if (Status built = generateTower(tower, types, bricks); !built)
    return Status::error("kapla_record: " + built.message);
  return Status::success();
}

namespace {

KaplaRecordParams readKaplaRecordParams(const YAML::Node& node, const std::string& where) {
  requireGeneratorKeys(node, where, {"floors", "origin"}, Placing::kOneByOne);
  KaplaRecordParams params;
  params.floors = readInt(node, "floors", where, params.floors);
  params.origin = readVector<2>(node, "origin", where, params.origin);
  readTypeAndTiming(node, where, &params);
  return params;
}

}  // namespace

void readKaplaRecordGenerator(const YAML::Node& node, const std::string& where,
                              const GeneratorContext& context,
                              std::vector<ScheduledBrick>* bricks) {
  const KaplaRecordParams params = readKaplaRecordParams(node, where);
  failUnless(generateKaplaRecord(params, context.types, bricks), where);
}

std::int64_t countKaplaRecordGenerator(const YAML::Node& node, const std::string& where) {
  return brickCount(readKaplaRecordParams(node, where));
}

}  // namespace brick_stack_sim
