#pragma once
// What the scene generators share: their YAML entry point, the checks every
// generator makes, and the brick type they place.

#include <cstdint>
#include <random>
#include <set>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>
#include <Eigen/Core>

#include "brick_stack_sim/core/scene/generators.h"
#include "brick_stack_sim/core/status.h"
#include "brick_stack_sim/core/types/brick_type.h"
#include "brick_stack_sim/core/types/world_options.h"
#include "scene/yaml_fields.h"

namespace brick_stack_sim {

/// What a generator may build on besides its own parameters.
struct GeneratorContext {
  const TableOptions& table;
  const BrickTypeLibrary& types;
  /// Where a generator that defines its own brick types (an arch's
  /// voussoir) puts them; the scene adds them to its types.
  std::vector<BrickType>* new_types;
};

/// Reads a generator's YAML map (`where` names it in messages) and appends its
/// bricks; throws scene_yaml::SceneError.
using GeneratorReader = void (*)(const YAML::Node& node, const std::string& where,
                                 const GeneratorContext& context,
                                 std::vector<ScheduledBrick>* bricks);
/// Reads a generator's YAML map and says how many bricks it would append,
/// building none; throws scene_yaml::SceneError.
using GeneratorCounter = std::int64_t (*)(const YAML::Node& node, const std::string& where);

void readTowerGenerator(const YAML::Node& node, const std::string& where,
                        const GeneratorContext& context, std::vector<ScheduledBrick>* bricks);
void readHarmonicGenerator(const YAML::Node& node, const std::string& where,
                           const GeneratorContext& context, std::vector<ScheduledBrick>* bricks);
void readSlantTowerGenerator(const YAML::Node& node, const std::string& where,
                             const GeneratorContext& context, std::vector<ScheduledBrick>* bricks);
void readPyramidGenerator(const YAML::Node& node, const std::string& where,
                          const GeneratorContext& context, std::vector<ScheduledBrick>* bricks);
void readAFrameGenerator(const YAML::Node& node, const std::string& where,
                         const GeneratorContext& context, std::vector<ScheduledBrick>* bricks);
void readCardHouseGenerator(const YAML::Node& node, const std::string& where,
                            const GeneratorContext& context, std::vector<ScheduledBrick>* bricks);
void readImpactGenerator(const YAML::Node& node, const std::string& where,
                         const GeneratorContext& context, std::vector<ScheduledBrick>* bricks);
void readKaplaRecordGenerator(const YAML::Node& node, const std::string& where,
                              const GeneratorContext& context, std::vector<ScheduledBrick>* bricks);
void readPileGenerator(const YAML::Node& node, const std::string& where,
                       const GeneratorContext& context, std::vector<ScheduledBrick>* bricks);
void readArchGenerator(const YAML::Node& node, const std::string& where,
                       const GeneratorContext& context, std::vector<ScheduledBrick>* bricks);
void readColumnGenerator(const YAML::Node& node, const std::string& where,
                         const GeneratorContext& context, std::vector<ScheduledBrick>* bricks);
void readBlockTowerGenerator(const YAML::Node& node, const std::string& where,
                             const GeneratorContext& context, std::vector<ScheduledBrick>* bricks);

std::int64_t countTowerGenerator(const YAML::Node& node, const std::string& where);
std::int64_t countHarmonicGenerator(const YAML::Node& node, const std::string& where);
std::int64_t countSlantTowerGenerator(const YAML::Node& node, const std::string& where);
std::int64_t countPyramidGenerator(const YAML::Node& node, const std::string& where);
std::int64_t countAFrameGenerator(const YAML::Node& node, const std::string& where);
std::int64_t countCardHouseGenerator(const YAML::Node& node, const std::string& where);
std::int64_t countImpactGenerator(const YAML::Node& node, const std::string& where);
std::int64_t countKaplaRecordGenerator(const YAML::Node& node, const std::string& where);
std::int64_t countPileGenerator(const YAML::Node& node, const std::string& where);
std::int64_t countArchGenerator(const YAML::Node& node, const std::string& where);
std::int64_t countColumnGenerator(const YAML::Node& node, const std::string& where);
std::int64_t countBlockTowerGenerator(const YAML::Node& node, const std::string& where);

/// A brick count computed in floating point, as brickCount() says it:
/// negative as 0, beyond kMaxCountedBricks as that.
std::int64_t clampedCount(double count);

/// What every generator checks before it places anything: its start and
/// interval (finite, >= 0 s) and the type it places (the requested one, or
/// the library's default), returned in `*type`. Messages name the generator.
Status checkStartAndType(const char* generator, double start, double interval,
                         const std::string& requested, const BrickTypeLibrary& types,
                         const BrickType** type);

/// Appends a brick of `type` at rest at `position` [m], placed at `at` [s],
/// named b<n> after its place in `bricks`; returns it for a rotation.
ScheduledBrick& appendBrick(const BrickType& type, const Eigen::Vector3d& position, double at,
                            std::vector<ScheduledBrick>* bricks);

/// A draw in [0, 1) from the generator's raw 64 bits, their top 53 as a
/// double's mantissa: std::uniform_real_distribution is not specified alike
/// in every standard library, and a scene must be the same scene on every
/// machine.
inline double unitDraw(std::mt19937_64& random) {
  return static_cast<double>(random() >> 11) * 0x1.0p-53;
}

/// ROS convention (REP 103): fixed-axis roll about x, then pitch about y, then yaw about z.
Eigen::Matrix3d rotationFromRpy(const Eigen::Vector3d& rpy);

/// Whether a generator places its bricks one by one, `interval` apart, or all
/// at its `start`.
enum class Placing { kOneByOne, kAtOnce };

/// Refuses a key of generator `node` that is neither its own nor one that
/// every generator takes (its name, the brick type, start and, placing one
/// by one, interval), so that the common keys are listed once.
inline void requireGeneratorKeys(const YAML::Node& node, const std::string& where,
                                 std::set<std::string> own, Placing placing) {
  own.insert({"name", "type", "start"});
  if (placing == Placing::kOneByOne) own.insert("interval");
  scene_yaml::requireKnownKeys(node, where, own);
}

/// The fields every generator that places bricks one by one shares.
template <typename Params>
void readTypeAndTiming(const YAML::Node& node, const std::string& where, Params* params) {
  params->type = scene_yaml::readString(node, "type", where);
  params->start = scene_yaml::readNumber(node, "start", where, params->start);
  params->interval = scene_yaml::readNumber(node, "interval", where, params->interval);
}

/// Turns a generator's refusal into the parser's error at `where`.
inline void failUnless(const Status& generated, const std::string& where) {
  if (!generated) scene_yaml::fail(where, generated.message);
}

}  // namespace brick_stack_sim
