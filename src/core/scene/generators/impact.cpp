#include "scene/generators/generator_support.h"

#include <algorithm>
#include <cmath>

namespace brick_stack_sim {

using scene_yaml::readInt;
using scene_yaml::readNumber;

std::int64_t brickCount(const ImpactParams& params) {
  const std::int64_t tower = brickCount(params.tower);
  return tower == 0 ? 0 : std::min(tower + 1, kMaxCountedBricks);
}

Status generateImpact(const ImpactParams& params, const BrickTypeLibrary& types,
                      std::vector<ScheduledBrick>* bricks) {
  const TowerParams& tower = params.tower;
  if (tower.grid_x != 1 || tower.grid_y != 1)
    return Status::error("impact strikes one tower: grid must be [1, 1]");
  if (params.layer < 1 || params.layer > tower.layers)
    return Status::error("impact layer = " + std::to_string(params.layer) + ": must be in [1, " +
                         std::to_string(tower.layers) + "] (1 is the lowest)");
  // A throw faster than the node's default speed limit would be refused.
  if (!std::isfinite(params.speed) || params.speed <= 0.0 || params.speed > 50.0)
    return Status::error("impact speed must be in (0, 50] m/s");
  if (!std::isfinite(params.delay) || params.delay < 0.0)
    return Status::error("impact delay must be finite and >= 0 s");
  if (!std::isfinite(params.gap) || params.gap < 0.0 || params.gap > 1.0)
    return Status::error("impact gap must be in [0, 1] m");

  std::vector<ScheduledBrick> generated = *bricks;
  const std::size_t first = generated.size();
  if (Status built = generateTower(tower, types, &generated); !built) return built;
  const BrickType& type = *types.find(generated.back().placement.type);

  const std::size_t struck_index = first + (params.layer - 1) * tower.bricks_per_layer;
  const Eigen::Isometry3d& struck = generated[struck_index].placement.pose;
  // Even layers (from 0) lie along x: their outer long face looks to -y.
  const bool along_x = (params.layer - 1) % 2 == 0;
  const Eigen::Vector3d inward = along_x ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitX();
  const double gap = std::min(params.gap, params.speed * kMaxImpactFlight);
  const double back = type.size.y() + gap;  // centre to centre, across the bricks' width
  const Eigen::Vector3d centre =
      struck.translation() - back * inward + Eigen::Vector3d(0.0, 0.0, kImpactAimAbove);

  ScheduledBrick& striker =
      appendBrick(type, centre, generated.back().at + params.delay, &generated);
  striker.placement.id = kStrikerId;
  striker.placement.pose.linear() = struck.linear();
  striker.placement.linear_velocity = params.speed * inward;
  *bricks = std::move(generated);
  return Status::success();
}

namespace {

ImpactParams readImpactParams(const YAML::Node& node, const std::string& where) {
  requireGeneratorKeys(node, where,
                       {"layers", "bricks_per_layer", "layer", "speed", "delay", "gap"},
                       Placing::kOneByOne);
  ImpactParams params;
  params.tower.layers = readInt(node, "layers", where, 13);
  params.tower.bricks_per_layer = readInt(node, "bricks_per_layer", where, 2);
  readTypeAndTiming(node, where, &params.tower);
  params.layer = readInt(node, "layer", where, params.tower.layers);
  params.speed = readNumber(node, "speed", where, params.speed);
  params.delay = readNumber(node, "delay", where, params.delay);
  params.gap = readNumber(node, "gap", where, params.gap);
  return params;
}

}  // namespace

void readImpactGenerator(const YAML::Node& node, const std::string& where,
                         const GeneratorContext& context, std::vector<ScheduledBrick>* bricks) {
  const ImpactParams params = readImpactParams(node, where);
  failUnless(generateImpact(params, context.types, bricks), where);
}

std::int64_t countImpactGenerator(const YAML::Node& node, const std::string& where) {
  return brickCount(readImpactParams(node, where));
}

}  // namespace brick_stack_sim
