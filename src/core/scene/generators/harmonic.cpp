#include "scene/generators/generator_support.h"

#include <cmath>

namespace brick_stack_sim {

using scene_yaml::readInt;
using scene_yaml::readNumber;
using scene_yaml::readVector;
using scene_yaml::requireKnownKeys;

Status generateHarmonic(const HarmonicParams& params, const TableOptions& table,
                        const BrickTypeLibrary& types, std::vector<ScheduledBrick>* bricks) {
  if (params.bricks < 1 || params.bricks > 1000)
    return Status::error("harmonic bricks = " + std::to_string(params.bricks) +
                         ": must be in [1, 1000]");
  if (!std::isfinite(params.factor) || params.factor < 0.0 || params.factor > 2.0)
    return Status::error("harmonic factor must be in [0, 2]");
  if (Status timing = checkTiming("harmonic", params.start, params.interval); !timing)
    return timing;
  const BrickType* type = generatorType(params.type, types);
  if (!type) return Status::error("harmonic type '" + params.type + "' is not a known brick type");
  const double length = type->size.x(), height = type->size.z();
  const int n = params.bricks;
  // Right ends from the bottom up: the table edge, then one overhang per brick.
  double right_end = 0.5 * table.size.x();
  int index = static_cast<int>(bricks->size());
  for (int from_top = n; from_top >= 1; --from_top) {
    right_end += params.factor * length / (2.0 * from_top);
    const int layer = n - from_top;
    ScheduledBrick brick;
    brick.placement.id = "b" + std::to_string(index++);
    brick.placement.type = type->name;
    brick.placement.pose.translation() =
        Eigen::Vector3d(right_end - 0.5 * length, 0.0, (layer + 0.5) * height);
    brick.at = params.start + params.interval * layer;
    bricks->push_back(brick);
  }
  return Status::success();
}

void readHarmonicGenerator(const YAML::Node& node, const std::string& where,
                           const GeneratorContext& context, std::vector<ScheduledBrick>* bricks) {
  requireKnownKeys(node, where, {"name", "bricks", "factor", "type", "start", "interval"});
  HarmonicParams params;
  params.bricks = readInt(node, "bricks", where, params.bricks);
  params.factor = readNumber(node, "factor", where, params.factor);
  readTypeAndTiming(node, where, &params);
  failUnless(generateHarmonic(params, context.table, context.types, bricks), where);
}

}  // namespace brick_stack_sim
