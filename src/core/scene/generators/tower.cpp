#include "scene/generators/generator_support.h"

#include <cmath>

namespace brick_stack_sim {

using scene_yaml::readInt;
using scene_yaml::readNumber;
using scene_yaml::readVector;

std::int64_t brickCount(const TowerParams& params) {
  return clampedCount(static_cast<double>(params.layers) * params.bricks_per_layer * params.grid_x *
                      params.grid_y);
}

Status generateTower(const TowerParams& params, const BrickTypeLibrary& types,
                     std::vector<ScheduledBrick>* bricks) {
  if (params.layers < 1 || params.layers > 10000)
    return Status::error("tower layers = " + std::to_string(params.layers) +
                         ": must be in [1, 10000]");
  if (params.bricks_per_layer != 2 && params.bricks_per_layer != 3)
    return Status::error("tower bricks_per_layer = " + std::to_string(params.bricks_per_layer) +
                         ": must be 2 or 3");
  if (!std::isfinite(params.gap) || params.gap < 0.0)
    return Status::error("tower gap must be finite and >= 0 m");
  const BrickType* type = nullptr;
  if (Status checked =
          checkStartAndType("tower", params.start, params.interval, params.type, types, &type);
      !checked)
    return checked;

  const double length = type->size.x(), width = type->size.y(), height = type->size.z();
  // Bricks of a layer lie under the ends of the crosswise layer above.
  const double offset = 0.5 * (length - width);
  std::vector<double> lanes = {-offset, offset};
  if (params.bricks_per_layer == 3) lanes.insert(lanes.begin() + 1, 0.0);

  if (params.grid_x < 1 || params.grid_y < 1 || params.grid_x * params.grid_y > 10000)
    return Status::error("tower grid must have 1 to 10000 copies");
  // The same bound as a pile: more bricks than any table holds is a typo.
  const std::int64_t total = brickCount(params);
  if (total > 100000)
    return Status::error("tower of " + std::to_string(total) +
                         " bricks: at most 100000 (layers x bricks_per_layer x grid)");
  if (!params.origin.allFinite() || !std::isfinite(params.spacing) || params.spacing < 0.0)
    return Status::error("tower origin and spacing must be finite, spacing >= 0 m");

  int placed = 0;
  for (int gx = 0; gx < params.grid_x; ++gx) {
    for (int gy = 0; gy < params.grid_y; ++gy) {
      const Eigen::Vector2d centre = params.origin + params.spacing * Eigen::Vector2d(gx, gy);
      for (int layer = 0; layer < params.layers; ++layer) {
        const bool along_y = layer % 2 == 1;
        const double z = 0.5 * height + layer * (height + params.gap);
        for (double lane : lanes) {
          ScheduledBrick& brick =
              appendBrick(*type,
                          along_y ? Eigen::Vector3d(centre.x() + lane, centre.y(), z)
                                  : Eigen::Vector3d(centre.x(), centre.y() + lane, z),
                          params.start + params.interval * placed++, bricks);
          if (along_y)
            brick.placement.pose.linear() =
                Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
        }
      }
    }
  }
  return Status::success();
}

namespace {

TowerParams readTowerParams(const YAML::Node& node, const std::string& where) {
  requireGeneratorKeys(node, where,
                       {"layers", "bricks_per_layer", "gap", "origin", "grid", "spacing"},
                       Placing::kOneByOne);
  TowerParams params;
  params.origin = readVector<2>(node, "origin", where, params.origin);
  const Eigen::Vector2d grid =
      readVector<2>(node, "grid", where, Eigen::Vector2d(params.grid_x, params.grid_y));
  params.grid_x = static_cast<int>(grid.x());
  params.grid_y = static_cast<int>(grid.y());
  if (params.grid_x != grid.x() || params.grid_y != grid.y())
    scene_yaml::fail(where + ".grid", "expected two integers");
  params.spacing = readNumber(node, "spacing", where, params.spacing);
  params.layers = readInt(node, "layers", where, params.layers);
  params.bricks_per_layer = readInt(node, "bricks_per_layer", where, params.bricks_per_layer);
  readTypeAndTiming(node, where, &params);
  params.gap = readNumber(node, "gap", where, params.gap);
  return params;
}

}  // namespace

void readTowerGenerator(const YAML::Node& node, const std::string& where,
                        const GeneratorContext& context, std::vector<ScheduledBrick>* bricks) {
  const TowerParams params = readTowerParams(node, where);
  failUnless(generateTower(params, context.types, bricks), where);
}

std::int64_t countTowerGenerator(const YAML::Node& node, const std::string& where) {
  return brickCount(readTowerParams(node, where));
}

}  // namespace brick_stack_sim
