// The `block_tower` generator: one box per level, each offset from the one
// below at random, the offsets scaled together so that the tower's most
// critical level has the criticality asked for (docs/design.md, "Simulation
// and scenes"). By statics it stands exactly when that is below 1: a label
// known before the run, for parameter sweeps.
#include "scene/generators/generator_support.h"

#include <cmath>
#include <limits>

#include "util/text_format.h"

namespace brick_stack_sim {

using scene_yaml::readInt;
using scene_yaml::readNumber;

namespace {

/// Most levels of a block tower: enough for any sweep of toppling, few
/// enough that the scale of its offsets stays well conditioned.
constexpr int kMaxLevels = 50;

/// The common factor of the offsets `levels` (each brick's centre from the
/// lowest one's, before scaling) that gives the most critical level exactly
/// `criticality`; 0 when none exists. Level k's criticality along an axis
/// is |s D + c| / h, with D the mean of the centres of bricks k..n-1 minus
/// brick k-1's, c the centre of mass off the box's centre and h the half
/// extent: convex in s and below `criticality` at s = 0 (checked by the
/// caller), so it first reaches `criticality` at s = (criticality h - sign(D)
/// c) / |D|, and the least of those over every level and axis is the factor.
double commonScale(const std::vector<Eigen::Vector2d>& levels, double criticality,
                   const Eigen::Vector2d& half, const Eigen::Vector2d& com_offset) {
  const int n = static_cast<int>(levels.size());
  double scale = std::numeric_limits<double>::infinity();
  Eigen::Vector2d above_sum = Eigen::Vector2d::Zero();
  for (int k = n - 1; k >= 1; --k) {
    above_sum += levels[k];
    const Eigen::Vector2d lever = above_sum / (n - k) - levels[k - 1];
    for (int axis = 0; axis < 2; ++axis) {
      if (lever[axis] == 0.0) continue;
      const double sign = lever[axis] > 0.0 ? 1.0 : -1.0;
      scale = std::min(
          scale, (criticality * half[axis] - sign * com_offset[axis]) / std::abs(lever[axis]));
    }
  }
  return std::isfinite(scale) ? scale : 0.0;
}

/// The unscaled centres: brick 0 at 0, each next one offset from the one
/// below by a draw in [-1, 1) of its half extent along x and along y, so
/// that the two axes compete evenly for the most critical level.
std::vector<Eigen::Vector2d> drawLevels(int bricks, std::uint64_t seed,
                                        const Eigen::Vector2d& half) {
  std::mt19937_64 random(seed);
  std::vector<Eigen::Vector2d> levels(bricks, Eigen::Vector2d::Zero());
  for (int i = 1; i < bricks; ++i) {
    const double dx = 2.0 * unitDraw(random) - 1.0;
    const double dy = 2.0 * unitDraw(random) - 1.0;
    levels[i] = levels[i - 1] + Eigen::Vector2d(dx * half.x(), dy * half.y());
  }
  return levels;
}

}  // namespace

std::int64_t brickCount(const BlockTowerParams& params) { return clampedCount(params.bricks); }

Status generateBlockTower(const BlockTowerParams& params, const BrickTypeLibrary& types,
                          std::vector<ScheduledBrick>* bricks) {
  if (params.bricks < 1 || params.bricks > kMaxLevels)
    return Status::error("block_tower bricks = " + std::to_string(params.bricks) +
                         ": must be in [1, " + std::to_string(kMaxLevels) + "]");
  if (!std::isfinite(params.criticality) || params.criticality <= 0.0)
    return Status::error("block_tower criticality must be finite and > 0");
  if (!params.origin.allFinite()) return Status::error("block_tower origin must be finite");
  const BrickType* type = nullptr;
  if (Status checked =
          checkStartAndType("block_tower", params.start, 0.0, params.type, types, &type);
      !checked)
    return checked;
  // A level's criticality is a box's: its support is the box's bottom face.
  if (!type->isBox()) return Status::error("block_tower type '" + type->name + "' is not a box");
  const Eigen::Vector2d half = type->halfExtents().head<2>();
  // Equal masses: the centre of mass of bricks k..n-1 is the mean of
  // theirs, each off its box's centre as the type's mass frame says.
  const Eigen::Vector2d com_offset = type->mass_frame.translation().head<2>();
  if (std::abs(com_offset.x()) >= params.criticality * half.x() ||
      std::abs(com_offset.y()) >= params.criticality * half.y())
    return Status::error("block_tower criticality " + formatNumber(params.criticality) +
                         ": the centre of mass of type '" + type->name +
                         "' alone is that far off its centre");
  std::vector<Eigen::Vector2d> levels = drawLevels(params.bricks, params.seed, half);
  double scale = 1.0;
  if (params.bricks > 1) {
    scale = commonScale(levels, params.criticality, half, com_offset);
    if (!(scale > 0.0))
      return Status::error("block_tower seed " + std::to_string(params.seed) +
                           " draws no offset at all; choose another seed");
  }
  for (int i = 0; i < params.bricks; ++i) {
    const Eigen::Vector2d centre = params.origin + scale * levels[i];
    appendBrick(*type, Eigen::Vector3d(centre.x(), centre.y(), (i + 0.5) * type->size.z()),
                params.start, bricks);
  }
  return Status::success();
}

namespace {

BlockTowerParams readBlockTowerParams(const YAML::Node& node, const std::string& where) {
  requireGeneratorKeys(node, where, {"bricks", "criticality", "seed", "origin"}, Placing::kAtOnce);
  BlockTowerParams params;
  params.bricks = readInt(node, "bricks", where, params.bricks);
  params.criticality = readNumber(node, "criticality", where, params.criticality);
  params.seed = scene_yaml::readSeed(node, "seed", where, params.seed);
  params.origin = scene_yaml::readVector<2>(node, "origin", where, params.origin);
  params.type = scene_yaml::readString(node, "type", where, params.type);
  params.start = readNumber(node, "start", where, params.start);
  return params;
}

}  // namespace

void readBlockTowerGenerator(const YAML::Node& node, const std::string& where,
                             const GeneratorContext& context, std::vector<ScheduledBrick>* bricks) {
  failUnless(generateBlockTower(readBlockTowerParams(node, where), context.types, bricks), where);
}

std::int64_t countBlockTowerGenerator(const YAML::Node& node, const std::string& where) {
  return brickCount(readBlockTowerParams(node, where));
}

}  // namespace brick_stack_sim
