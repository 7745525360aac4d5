#include "brick_stack_sim/core/scene/scene.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <set>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "scene/generators/generator_support.h"
#include "scene/type_yaml.h"
#include "scene/yaml_fields.h"
#include "util/text_format.h"

namespace brick_stack_sim {

namespace {

using scene_yaml::fail;
using scene_yaml::readNumber;
using scene_yaml::readString;
using scene_yaml::readVector;
using scene_yaml::requireKnownKeys;
using scene_yaml::SceneError;

TableOptions readTable(const YAML::Node& node) {
  const std::string where = "table";
  requireKnownKeys(node, where, {"size", "thickness", "height", "friction", "restitution"});
  TableOptions table;
  table.size = readVector<2>(node, "size", where, table.size);
  table.thickness = readNumber(node, "thickness", where, table.thickness);
  table.height = readNumber(node, "height", where, table.height);
  table.friction = readNumber(node, "friction", where, table.friction);
  table.restitution = readNumber(node, "restitution", where, table.restitution);
  return table;
}

ScheduledBrick readBrick(const YAML::Node& node, std::size_t index) {
  const std::string where = "bricks[" + std::to_string(index) + "]";
  requireKnownKeys(node, where,
                   {"id", "type", "at", "position", "rpy", "orientation", "linear_velocity",
                    "angular_velocity"});
  if (!node["position"]) fail(where, "needs a 'position' [m]");
  if (node["rpy"] && node["orientation"])
    fail(where, "give either 'rpy' or 'orientation', not both");
  ScheduledBrick brick;
  brick.placement.id = readString(node, "id", where);
  brick.placement.type = readString(node, "type", where);
  brick.at = readNumber(node, "at", where, 0.0);
  if (brick.at < 0.0 || brick.at > kMaxSceneTime)
    fail(where + ".at",
         "must be in [0, " + std::to_string(static_cast<long>(kMaxSceneTime)) + "] s");
  brick.placement.pose.translation() =
      readVector<3>(node, "position", where, Eigen::Vector3d::Zero());
  if (node["orientation"]) {
    const Eigen::Vector4d xyzw = readVector<4>(node, "orientation", where, Eigen::Vector4d::Zero());
    if (std::abs(xyzw.norm() - 1.0) > 1e-3)
      fail(where + ".orientation", "must be a unit quaternion [x, y, z, w]");
    brick.placement.pose.linear() =
        Eigen::Quaterniond(xyzw[3], xyzw[0], xyzw[1], xyzw[2]).normalized().toRotationMatrix();
  } else {
    brick.placement.pose.linear() =
        rotationFromRpy(readVector<3>(node, "rpy", where, Eigen::Vector3d::Zero()));
  }
  brick.placement.linear_velocity =
      readVector<3>(node, "linear_velocity", where, Eigen::Vector3d::Zero());
  brick.placement.angular_velocity =
      readVector<3>(node, "angular_velocity", where, Eigen::Vector3d::Zero());
  return brick;
}

/// The scene's `friction` (docs/design.md, "Simulation and scenes").
double readFriction(const YAML::Node& root) {
  const double friction = readNumber(root["friction"], "friction");
  if (friction < 0.0)
    fail("friction", formatNumber(friction) + ": must be >= 0 (a Coulomb coefficient)");
  return friction;
}

PoseNoise readPoseNoise(const YAML::Node& node) {
  const std::string where = "pose_noise";
  requireKnownKeys(node, where, {"position", "yaw", "seed"});
  PoseNoise noise;
  noise.position = readNumber(node, "position", where, noise.position);
  if (noise.position < 0.0 || noise.position > kMaxPoseNoise)
    fail(where + ".position",
         formatNumber(noise.position) + ": must be in [0, " + formatNumber(kMaxPoseNoise) + "] m");
  // Beyond pi the draws would cover some turns twice.
  noise.yaw = readNumber(node, "yaw", where, noise.yaw);
  if (noise.yaw < 0.0 || noise.yaw > M_PI)
    fail(where + ".yaw", formatNumber(noise.yaw) + ": must be in [0, pi] rad");
  noise.seed = scene_yaml::readSeed(node, "seed", where, noise.seed);
  return noise;
}

/// Offsets and turns every brick, in order; three draws per brick (x, y,
/// yaw) whatever the bounds, so that a bound of 0 changes nothing else and
/// leaves the poses' bits as they were.
void applyPoseNoise(const PoseNoise& noise, std::vector<ScheduledBrick>* bricks) {
  std::mt19937_64 random(noise.seed);
  auto within = [&random](double bound) { return bound * (2.0 * unitDraw(random) - 1.0); };
  for (ScheduledBrick& brick : *bricks) {
    const double dx = within(noise.position), dy = within(noise.position), yaw = within(noise.yaw);
    Eigen::Isometry3d& pose = brick.placement.pose;
    if (noise.position > 0.0) pose.translation().head<2>() += Eigen::Vector2d(dx, dy);
    if (noise.yaw > 0.0)
      pose.linear() =
          Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix() * pose.linear();
  }
}

/// What a scene says besides its types and bricks: `expect`, `table`,
/// `friction` and `pose_noise`.
void readSceneSettings(const YAML::Node& root, Scene* scene) {
  const std::string expect = readString(root, "expect", "scene", "stands");
  if (expect == "collapses") {
    scene->expect = ExpectedOutcome::kCollapses;
  } else if (expect != "stands") {
    fail("expect", "'" + expect + "': expected 'stands' or 'collapses'");
  }
  if (root["table"]) scene->table = readTable(root["table"]);
  if (root["friction"]) scene->friction = readFriction(root);
  if (root["pose_noise"]) scene->pose_noise = readPoseNoise(root["pose_noise"]);
}

struct GeneratorEntry {
  const char* name;
  GeneratorReader read;
  GeneratorCounter count;
};

/// Every generator a scene may name, one file each under generators/.
constexpr GeneratorEntry kGenerators[] = {
    {"tower", &readTowerGenerator, &countTowerGenerator},
    {"harmonic", &readHarmonicGenerator, &countHarmonicGenerator},
    {"slant_tower", &readSlantTowerGenerator, &countSlantTowerGenerator},
    {"pyramid", &readPyramidGenerator, &countPyramidGenerator},
    {"pile", &readPileGenerator, &countPileGenerator},
    {"aframe", &readAFrameGenerator, &countAFrameGenerator},
    {"card_house", &readCardHouseGenerator, &countCardHouseGenerator},
    {"impact", &readImpactGenerator, &countImpactGenerator},
    {"kapla_record", &readKaplaRecordGenerator, &countKaplaRecordGenerator},
    {"arch", &readArchGenerator, &countArchGenerator},
    {"column", &readColumnGenerator, &countColumnGenerator},
    {"block_tower", &readBlockTowerGenerator, &countBlockTowerGenerator},
};

/// The generator `node` names; fails on a node without a known name.
const GeneratorEntry& findGenerator(const YAML::Node& node, const std::string& where) {
  if (!node.IsMap() || !node["name"]) fail(where, "needs a 'name'");
  const std::string name = readString(node, "name", where);
  std::string available;
  for (const GeneratorEntry& generator : kGenerators) {
    if (name == generator.name) return generator;
    available += (available.empty() ? "" : ", ") + std::string(generator.name);
  }
  fail(where, "unknown generator " + quotedId(name) + " (available: " + available + ")");
}

/// Runs one generator; the types it defines join the scene's and `types`.
void runGenerator(const YAML::Node& node, const TableOptions& table, BrickTypeLibrary* types,
                  Scene* scene) {
  const std::string where = "generator";
  std::vector<BrickType> defined;
  findGenerator(node, where)
      .read(node, where, GeneratorContext{table, *types, &defined}, &scene->bricks);
  for (BrickType& type : defined) {
    if (Status added = types->add(type); !added) fail(where, added.message);
    scene->types.push_back(std::move(type));
  }
}

/// The generators of a scene: one, or a list of them.
std::vector<YAML::Node> generatorNodes(const YAML::Node& root) {
  const YAML::Node generators = root["generator"];
  if (!generators) return {};
  if (!generators.IsSequence()) return {generators};
  return std::vector<YAML::Node>(generators.begin(), generators.end());
}

/// Counts what every generator and the `bricks` list would place, before
/// anything is built, and fails at the first that passes `max_bricks`
/// (docs/ros_interface.md, "Refusals and limits").
void checkBrickCount(const YAML::Node& root, int max_bricks) {
  const std::string limit =
      " bricks: at most " + std::to_string(max_bricks) + " (scene_max_bricks)";
  const std::vector<YAML::Node> generators = generatorNodes(root);
  std::int64_t total = 0;
  for (std::size_t i = 0; i < generators.size(); ++i) {
    const GeneratorEntry& generator = findGenerator(generators[i], "generator");
    total += generator.count(generators[i], "generator");
    if (total > max_bricks)
      throw SceneError{"generator " + std::to_string(i + 1) + " (" + generator.name +
                       ") would bring the scene to " + std::to_string(total) + limit};
  }
  const YAML::Node listed = root["bricks"];
  if (listed && listed.IsSequence() &&
      total + static_cast<std::int64_t>(listed.size()) > max_bricks)
    fail("bricks", "the list of " + std::to_string(listed.size()) + " would bring the scene to " +
                       std::to_string(total + listed.size()) + limit);
}

/// Whether anything (a file, a FIFO, a directory...) is at `path`: what is
/// there is judged by readSceneFile, which says what is wrong with it.
bool exists(const std::string& path) {
  struct stat info;
  return ::stat(path.c_str(), &info) == 0;
}

/// The text of the scene file at `path`: a regular file (after links) of at
/// most `max_bytes`, read once. Opened without blocking, so that a FIFO with
/// no writer cannot hang the caller between the check and the read.
Status readSceneFile(const std::string& path, int max_bytes, std::string* text) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0)
    return Status::error("scene file " + shortText(path) +
                         " cannot be opened: " + std::strerror(errno));
  struct stat info;
  Status status;
  if (::fstat(fd, &info) != 0) {
    status = Status::error("scene file " + shortText(path) +
                           " cannot be examined: " + std::strerror(errno));
  } else if (S_ISDIR(info.st_mode)) {
    status = Status::error("scene " + shortText(path) + " is a directory, not a scene file");
  } else if (!S_ISREG(info.st_mode)) {
    status = Status::error("scene " + shortText(path) +
                           " is not a regular file (a FIFO, socket or device): refused unread");
  } else if (info.st_size > max_bytes) {
    status = Status::error("scene file " + shortText(path) + " has " +
                           std::to_string(info.st_size) + " bytes, more than the limit of " +
                           std::to_string(max_bytes) + " (parameter scene_max_bytes)");
  } else {
    std::string read(static_cast<std::size_t>(info.st_size), '\0');
    std::size_t filled = 0;
    // A file that grows while it is read is cut at the size it had.
    while (filled < read.size()) {
      const ssize_t got = ::read(fd, &read[filled], read.size() - filled);
      if (got < 0 && errno == EINTR) continue;
      if (got < 0) {
        status = Status::error("scene file " + shortText(path) +
                               " cannot be read: " + std::strerror(errno));
        break;
      }
      if (got == 0) break;
      filled += static_cast<std::size_t>(got);
    }
    read.resize(filled);
    *text = std::move(read);
  }
  ::close(fd);
  return status;
}

std::string stem(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
  const std::size_t dot = base.rfind(".yaml");
  return dot == std::string::npos ? base : base.substr(0, dot);
}

}  // namespace

Status mergeSceneTypes(const Scene& scene, BrickTypeLibrary* types) {
  for (const BrickType& type : scene.types) {
    if (Status added = types->add(type); !added) return added;
  }
  if (!scene.friction) return Status::success();
  // Every type, the library's too: a brick placed later by name (a node's
  // ~place_brick) meets the scene's friction as well.
  for (const std::string& name : types->names()) {
    BrickType type = *types->find(name);
    type.friction = *scene.friction;
    if (Status added = types->add(std::move(type)); !added) return added;
  }
  return Status::success();
}

WorldOptions sceneWorldOptions(const Scene& scene, const WorldOptions& options) {
  WorldOptions result = options;
  if (scene.table) result.table = *scene.table;
  if (scene.friction) result.table.friction = *scene.friction;
  return result;
}

Status parseScene(const std::string& yaml_text, const std::string& name,
                  const BrickTypeLibrary& types, Scene* scene, const SceneLimits& limits) {
  Scene result;
  try {
    const YAML::Node root = YAML::Load(yaml_text);
    if (!root.IsMap())
      return Status::error("scene " + quotedPath(name) + ": expected a map at the top");
    requireKnownKeys(
        root, "scene",
        {"name", "table", "types", "generator", "bricks", "expect", "friction", "pose_noise"});
    result.name = readString(root, "name", "scene", name);
    readSceneSettings(root, &result);
    if (root["types"]) {
      if (!root["types"].IsMap()) fail("types", "expected a map of name: {size, mass, ...}");
      for (const auto& entry : root["types"])
        result.types.push_back(
            scene_yaml::readSceneType(entry.first.as<std::string>(), entry.second));
    }
    BrickTypeLibrary all_types = types;
    if (Status merged = mergeSceneTypes(result, &all_types); !merged) fail("types", merged.message);
    checkBrickCount(root, limits.max_bricks);
    const TableOptions table = result.table.value_or(TableOptions());
    for (const YAML::Node& generator : generatorNodes(root))
      runGenerator(generator, table, &all_types, &result);
    if (root["bricks"]) {
      if (!root["bricks"].IsSequence()) fail("bricks", "expected a list");
      std::size_t index = 0;
      for (const auto& node : root["bricks"]) result.bricks.push_back(readBrick(node, index++));
    }
    std::set<std::string> ids;
    for (const ScheduledBrick& brick : result.bricks) {
      const std::string& id = brick.placement.id;
      if (!id.empty() && !ids.insert(id).second)
        fail("bricks", "id " + quotedId(id) + " appears twice");
      // A generator's long schedule ends here too.
      if (!(brick.at <= kMaxSceneTime))
        fail("bricks", "brick " + quotedId(id) + " is placed at " + formatNumber(brick.at) +
                           " s, after the latest allowed " +
                           std::to_string(static_cast<long>(kMaxSceneTime)) + " s");
      const std::string& type = brick.placement.type;
      if (!type.empty() && !all_types.find(type))
        fail("bricks", "brick " + quotedId(id) + " has unknown type " + quotedId(type));
    }
  } catch (const SceneError& error) {
    return Status::error("scene " + quotedPath(name) + ": " + error.message);
  } catch (const YAML::Exception& error) {
    return Status::error("scene " + quotedPath(name) + ": " + error.what());
  }
  std::stable_sort(result.bricks.begin(), result.bricks.end(),
                   [](const ScheduledBrick& a, const ScheduledBrick& b) { return a.at < b.at; });
  if (result.pose_noise) applyPoseNoise(*result.pose_noise, &result.bricks);
  *scene = std::move(result);
  return Status::success();
}

Status loadScene(const std::string& name_or_path, const std::vector<std::string>& scene_dirs,
                 const BrickTypeLibrary& types, Scene* scene, const SceneLimits& limits) {
  if (name_or_path.empty()) return Status::error("no scene given");
  std::string path;
  if (exists(name_or_path)) {
    path = name_or_path;
  } else {
    for (const std::string& dir : scene_dirs) {
      const std::string candidate = dir + "/" + name_or_path + ".yaml";
      if (exists(candidate)) {
        path = candidate;
        break;
      }
    }
  }
  if (path.empty()) {
    // Each directory once, in the order searched, however often it was given.
    std::vector<std::string> searched;
    for (const std::string& dir : scene_dirs)
      if (std::find(searched.begin(), searched.end(), dir) == searched.end())
        searched.push_back(dir);
    for (std::string& dir : searched) dir = shortText(dir);
    return Status::error("unknown scene " + quotedPath(name_or_path) + ": no such file, and no " +
                         shortText(name_or_path + ".yaml") + " in [" + joinNames(searched) + "]");
  }
  std::string text;
  if (Status read = readSceneFile(path, limits.max_bytes, &text); !read) return read;
  return parseScene(text, stem(path), types, scene, limits);
}

}  // namespace brick_stack_sim
