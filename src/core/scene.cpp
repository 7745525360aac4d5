#include "brick_stack_sim/core/scene.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <set>
#include <sstream>

#include <yaml-cpp/yaml.h>

namespace brick_stack_sim {

namespace {

/// Thrown inside the parser only, turned into a Status at its boundary.
struct SceneError {
  std::string message;
};

[[noreturn]] void fail(const std::string& where, const std::string& what) {
  throw SceneError{where + ": " + what};
}

void requireKnownKeys(const YAML::Node& node, const std::string& where,
                      const std::set<std::string>& known) {
  if (!node.IsMap()) fail(where, "expected a map");
  for (const auto& entry : node) {
    const std::string key = entry.first.as<std::string>();
    if (!known.count(key)) {
      std::string list;
      for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
      fail(where, "unknown key '" + key + "' (known: " + list + ")");
    }
  }
}

double readNumber(const YAML::Node& node, const std::string& where) {
  double value = 0.0;
  try {
    value = node.as<double>();
  } catch (const YAML::Exception&) {
    fail(where, "expected a number");
  }
  if (!std::isfinite(value)) fail(where, "must be finite");
  return value;
}

double readNumber(const YAML::Node& map, const char* key, const std::string& where,
                  double fallback) {
  return map[key] ? readNumber(map[key], where + "." + key) : fallback;
}

int readInt(const YAML::Node& map, const char* key, const std::string& where, int fallback) {
  if (!map[key]) return fallback;
  try {
    return map[key].as<int>();
  } catch (const YAML::Exception&) {
    fail(where + "." + key, "expected an integer");
  }
}

std::string readString(const YAML::Node& map, const char* key, const std::string& where,
                       const std::string& fallback = "") {
  if (!map[key]) return fallback;
  if (!map[key].IsScalar()) fail(where + "." + key, "expected a string");
  return map[key].as<std::string>();
}

template <int N>
Eigen::Matrix<double, N, 1> readVector(const YAML::Node& map, const char* key,
                                       const std::string& where,
                                       const Eigen::Matrix<double, N, 1>& fallback) {
  const YAML::Node node = map[key];
  if (!node) return fallback;
  const std::string field = where + "." + key;
  if (!node.IsSequence() || node.size() != N)
    fail(field, "expected a list of " + std::to_string(N) + " numbers");
  Eigen::Matrix<double, N, 1> v;
  for (int i = 0; i < N; ++i) v[i] = readNumber(node[i], field + "[" + std::to_string(i) + "]");
  return v;
}

Eigen::Matrix3d rotationFromRpy(const Eigen::Vector3d& rpy) {
  // ROS convention (REP 103): fixed-axis roll about x, then pitch about y, then yaw about z.
  return (Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

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

BrickType readType(const std::string& name, const YAML::Node& node) {
  const std::string where = "types." + name;
  requireKnownKeys(node, where, {"size", "mass", "friction", "restitution", "rolling_friction"});
  if (!node["size"] || !node["mass"]) fail(where, "needs 'size' [m] and 'mass' [kg]");
  BrickType type;
  type.name = name;
  type.size = readVector<3>(node, "size", where, type.size);
  type.mass = readNumber(node, "mass", where, 0.0);
  // A uniform box: m/12 (b^2 + c^2) about each axis.
  const Eigen::Vector3d squared = type.size.cwiseProduct(type.size);
  type.inertia = type.mass / 12.0 *
                 Eigen::Vector3d(squared.y() + squared.z(), squared.x() + squared.z(),
                                 squared.x() + squared.y());
  type.friction = readNumber(node, "friction", where, type.friction);
  type.restitution = readNumber(node, "restitution", where, type.restitution);
  type.rolling_friction = readNumber(node, "rolling_friction", where, type.rolling_friction);
  if (Status valid = validateBrickType(type); !valid) fail(where, valid.message);
  return type;
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
  if (brick.at < 0.0) fail(where + ".at", "must be >= 0 s");
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

/// The fields every generator that places bricks one by one shares.
template <typename Params>
void readTypeAndTiming(const YAML::Node& node, const std::string& where, Params* params) {
  params->type = readString(node, "type", where);
  params->start = readNumber(node, "start", where, params->start);
  params->interval = readNumber(node, "interval", where, params->interval);
}

void runGenerator(const YAML::Node& node, const TableOptions& table, const BrickTypeLibrary& types,
                  std::vector<ScheduledBrick>* bricks) {
  const std::string where = "generator";
  if (!node.IsMap() || !node["name"]) fail(where, "needs a 'name'");
  const std::string name = readString(node, "name", where);
  if (name == "tower") {
    requireKnownKeys(node, where,
                     {"name", "layers", "bricks_per_layer", "type", "start", "interval", "gap",
                      "origin", "grid", "spacing"});
    TowerParams params;
    params.origin = readVector<2>(node, "origin", where, params.origin);
    const Eigen::Vector2d grid =
        readVector<2>(node, "grid", where, Eigen::Vector2d(params.grid_x, params.grid_y));
    params.grid_x = static_cast<int>(grid.x());
    params.grid_y = static_cast<int>(grid.y());
    if (params.grid_x != grid.x() || params.grid_y != grid.y())
      fail(where + ".grid", "expected two integers");
    params.spacing = readNumber(node, "spacing", where, params.spacing);
    params.layers = readInt(node, "layers", where, params.layers);
    params.bricks_per_layer = readInt(node, "bricks_per_layer", where, params.bricks_per_layer);
    readTypeAndTiming(node, where, &params);
    params.gap = readNumber(node, "gap", where, params.gap);
    if (Status generated = generateTower(params, types, bricks); !generated)
      fail(where, generated.message);
    return;
  }
  if (name == "harmonic") {
    requireKnownKeys(node, where, {"name", "bricks", "factor", "type", "start", "interval"});
    HarmonicParams params;
    params.bricks = readInt(node, "bricks", where, params.bricks);
    params.factor = readNumber(node, "factor", where, params.factor);
    readTypeAndTiming(node, where, &params);
    if (Status generated = generateHarmonic(params, table, types, bricks); !generated)
      fail(where, generated.message);
    return;
  }
  if (name == "slant_tower") {
    requireKnownKeys(node, where, {"name", "layers", "offset", "type", "start", "interval"});
    SlantTowerParams params;
    params.layers = readInt(node, "layers", where, params.layers);
    params.offset = readNumber(node, "offset", where, params.offset);
    readTypeAndTiming(node, where, &params);
    if (Status generated = generateSlantTower(params, types, bricks); !generated)
      fail(where, generated.message);
    return;
  }
  if (name == "pyramid") {
    requireKnownKeys(node, where, {"name", "base", "gap", "type", "start", "interval"});
    PyramidParams params;
    params.base = readInt(node, "base", where, params.base);
    params.gap = readNumber(node, "gap", where, params.gap);
    readTypeAndTiming(node, where, &params);
    if (Status generated = generatePyramid(params, types, bricks); !generated)
      fail(where, generated.message);
    return;
  }
  if (name == "pile") {
    requireKnownKeys(node, where,
                     {"name", "bricks", "columns", "rows", "cell", "layer_height", "base_height",
                      "max_tilt", "seed", "type", "start", "origin"});
    PileParams params;
    params.origin = readVector<2>(node, "origin", where, params.origin);
    params.bricks = readInt(node, "bricks", where, params.bricks);
    params.columns = readInt(node, "columns", where, params.columns);
    params.rows = readInt(node, "rows", where, params.rows);
    params.cell = readNumber(node, "cell", where, params.cell);
    params.layer_height = readNumber(node, "layer_height", where, params.layer_height);
    params.base_height = readNumber(node, "base_height", where, params.base_height);
    params.max_tilt = readNumber(node, "max_tilt", where, params.max_tilt);
    params.seed =
        static_cast<unsigned>(readInt(node, "seed", where, static_cast<int>(params.seed)));
    params.type = readString(node, "type", where);
    params.start = readNumber(node, "start", where, params.start);
    if (Status generated = generatePile(params, types, bricks); !generated)
      fail(where, generated.message);
    return;
  }
  fail(where,
       "unknown generator '" + name + "' (available: tower, harmonic, slant_tower, pyramid, pile)");
}

bool isFile(const std::string& path) {
  std::ifstream file(path);
  return file.good();
}

std::string stem(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
  const std::size_t dot = base.rfind(".yaml");
  return dot == std::string::npos ? base : base.substr(0, dot);
}

}  // namespace

namespace {

Status checkTiming(const char* generator, double start, double interval) {
  if (!std::isfinite(start) || start < 0.0 || !std::isfinite(interval) || interval < 0.0)
    return Status::error(std::string(generator) + " start and interval must be finite and >= 0 s");
  return Status::success();
}

const BrickType* generatorType(const std::string& requested, const BrickTypeLibrary& types) {
  return types.find(requested.empty() ? types.defaultType() : requested);
}

}  // namespace

Status generateTower(const TowerParams& params, const BrickTypeLibrary& types,
                     std::vector<ScheduledBrick>* bricks) {
  if (params.layers < 1 || params.layers > 10000)
    return Status::error("tower layers = " + std::to_string(params.layers) +
                         ": must be in [1, 10000]");
  if (params.bricks_per_layer != 2 && params.bricks_per_layer != 3)
    return Status::error("tower bricks_per_layer = " + std::to_string(params.bricks_per_layer) +
                         ": must be 2 or 3");
  if (Status timing = checkTiming("tower", params.start, params.interval); !timing) return timing;
  if (!std::isfinite(params.gap) || params.gap < 0.0)
    return Status::error("tower gap must be finite and >= 0 m");
  const BrickType* type = generatorType(params.type, types);
  if (!type) return Status::error("tower type '" + params.type + "' is not a known brick type");
  const std::string& type_name = type->name;

  const double length = type->size.x(), width = type->size.y(), height = type->size.z();
  // Bricks of a layer lie under the ends of the crosswise layer above.
  const double offset = 0.5 * (length - width);
  std::vector<double> lanes = {-offset, offset};
  if (params.bricks_per_layer == 3) lanes.insert(lanes.begin() + 1, 0.0);

  if (params.grid_x < 1 || params.grid_y < 1 || params.grid_x * params.grid_y > 10000)
    return Status::error("tower grid must have 1 to 10000 copies");
  // The same bound as a pile: more bricks than any table holds is a typo.
  const long total =
      static_cast<long>(params.layers) * params.bricks_per_layer * params.grid_x * params.grid_y;
  if (total > 100000)
    return Status::error("tower of " + std::to_string(total) +
                         " bricks: at most 100000 (layers x bricks_per_layer x grid)");
  if (!params.origin.allFinite() || !std::isfinite(params.spacing) || params.spacing < 0.0)
    return Status::error("tower origin and spacing must be finite, spacing >= 0 m");

  int index = static_cast<int>(bricks->size());
  int placed = 0;
  for (int gx = 0; gx < params.grid_x; ++gx) {
    for (int gy = 0; gy < params.grid_y; ++gy) {
      const Eigen::Vector2d centre = params.origin + params.spacing * Eigen::Vector2d(gx, gy);
      for (int layer = 0; layer < params.layers; ++layer) {
        const bool along_y = layer % 2 == 1;
        const double z = 0.5 * height + layer * (height + params.gap);
        for (double lane : lanes) {
          ScheduledBrick brick;
          brick.placement.id = "b" + std::to_string(index++);
          brick.placement.type = type_name;
          brick.placement.pose.translation() =
              along_y ? Eigen::Vector3d(centre.x() + lane, centre.y(), z)
                      : Eigen::Vector3d(centre.x(), centre.y() + lane, z);
          if (along_y)
            brick.placement.pose.linear() =
                Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
          brick.at = params.start + params.interval * placed++;
          bricks->push_back(brick);
        }
      }
    }
  }
  return Status::success();
}

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

Status generateSlantTower(const SlantTowerParams& params, const BrickTypeLibrary& types,
                          std::vector<ScheduledBrick>* bricks) {
  if (params.layers < 1 || params.layers > 10000)
    return Status::error("slant_tower layers = " + std::to_string(params.layers) +
                         ": must be in [1, 10000]");
  if (!std::isfinite(params.offset) || std::abs(params.offset) > 1.0)
    return Status::error("slant_tower offset must be finite and at most 1 m");
  if (Status timing = checkTiming("slant_tower", params.start, params.interval); !timing)
    return timing;
  const BrickType* type = generatorType(params.type, types);
  if (!type)
    return Status::error("slant_tower type '" + params.type + "' is not a known brick type");
  int index = static_cast<int>(bricks->size());
  for (int layer = 0; layer < params.layers; ++layer) {
    ScheduledBrick brick;
    brick.placement.id = "b" + std::to_string(index++);
    brick.placement.type = type->name;
    brick.placement.pose.translation() =
        Eigen::Vector3d(layer * params.offset, 0.0, (layer + 0.5) * type->size.z());
    brick.at = params.start + params.interval * layer;
    bricks->push_back(brick);
  }
  return Status::success();
}

Status generatePyramid(const PyramidParams& params, const BrickTypeLibrary& types,
                       std::vector<ScheduledBrick>* bricks) {
  if (params.base < 1 || params.base > 200)
    return Status::error("pyramid base = " + std::to_string(params.base) + ": must be in [1, 200]");
  if (!std::isfinite(params.gap) || params.gap < 0.0 || params.gap > 0.1)
    return Status::error("pyramid gap must be in [0, 0.1] m");
  if (Status timing = checkTiming("pyramid", params.start, params.interval); !timing) return timing;
  const BrickType* type = generatorType(params.type, types);
  if (!type) return Status::error("pyramid type '" + params.type + "' is not a known brick type");
  const double pitch = type->size.x() + params.gap;
  int index = static_cast<int>(bricks->size());
  int placed = 0;
  for (int row = 0; row < params.base; ++row) {
    const int count = params.base - row;
    for (int i = 0; i < count; ++i) {
      ScheduledBrick brick;
      brick.placement.id = "b" + std::to_string(index++);
      brick.placement.type = type->name;
      brick.placement.pose.translation() =
          Eigen::Vector3d((i - 0.5 * (count - 1)) * pitch, 0.0, (row + 0.5) * type->size.z());
      brick.at = params.start + params.interval * placed++;
      bricks->push_back(brick);
    }
  }
  return Status::success();
}

Status generatePile(const PileParams& params, const BrickTypeLibrary& types,
                    std::vector<ScheduledBrick>* bricks) {
  if (params.bricks < 1 || params.bricks > 100000)
    return Status::error("pile bricks = " + std::to_string(params.bricks) +
                         ": must be in [1, 100000]");
  if (params.columns < 1 || params.rows < 1)
    return Status::error("pile columns and rows must be >= 1");
  if (!params.origin.allFinite()) return Status::error("pile origin must be finite");
  if (!std::isfinite(params.cell) || !std::isfinite(params.layer_height) ||
      !std::isfinite(params.base_height) || !std::isfinite(params.max_tilt) || params.cell <= 0.0 ||
      params.layer_height <= 0.0 || params.base_height <= 0.0 || params.max_tilt < 0.0 ||
      params.max_tilt > 1.5)
    return Status::error(
        "pile cell, layer_height and base_height must be > 0 m, max_tilt in "
        "[0, 1.5] rad");
  if (Status timing = checkTiming("pile", params.start, 0.0); !timing) return timing;
  const BrickType* type = generatorType(params.type, types);
  if (!type) return Status::error("pile type '" + params.type + "' is not a known brick type");
  // Raw mt19937 output scaled by hand: std's distributions differ between
  // standard libraries, and a scene must be the same scene everywhere.
  std::mt19937 random(params.seed);
  auto uniform = [&random](double low, double high) {
    return low + (high - low) * (static_cast<double>(random()) / 4294967296.0);
  };
  const int per_layer = params.columns * params.rows;
  // Offsets stay within what keeps two neighbours apart whatever their yaw.
  const double footprint_radius = 0.5 * std::hypot(type->size.x(), type->size.y());
  const double slack = 0.5 * params.cell - footprint_radius;
  int index = static_cast<int>(bricks->size());
  for (int i = 0; i < params.bricks; ++i) {
    const int layer = i / per_layer, column = i % params.columns,
              row = (i % per_layer) / params.columns;
    ScheduledBrick brick;
    brick.placement.id = "b" + std::to_string(index++);
    brick.placement.type = type->name;
    const double jitter = std::max(slack, 0.0);
    brick.placement.pose.translation() =
        Eigen::Vector3d(params.origin.x() + (column - 0.5 * (params.columns - 1)) * params.cell +
                            uniform(-jitter, jitter),
                        params.origin.y() + (row - 0.5 * (params.rows - 1)) * params.cell +
                            uniform(-jitter, jitter),
                        params.base_height + layer * params.layer_height);
    const double yaw = uniform(-M_PI, M_PI), pitch = uniform(-params.max_tilt, params.max_tilt),
                 roll = uniform(-params.max_tilt, params.max_tilt);
    brick.placement.pose.linear() = rotationFromRpy(Eigen::Vector3d(roll, pitch, yaw));
    brick.at = params.start;
    bricks->push_back(brick);
  }
  return Status::success();
}

Status mergeSceneTypes(const Scene& scene, BrickTypeLibrary* types) {
  for (const BrickType& type : scene.types) {
    if (Status added = types->add(type); !added) return added;
  }
  return Status::success();
}

Status parseScene(const std::string& yaml_text, const std::string& name,
                  const BrickTypeLibrary& types, Scene* scene) {
  Scene result;
  try {
    const YAML::Node root = YAML::Load(yaml_text);
    if (!root.IsMap()) return Status::error("scene '" + name + "': expected a map at the top");
    requireKnownKeys(root, "scene", {"name", "table", "types", "generator", "bricks"});
    result.name = readString(root, "name", "scene", name);
    if (root["table"]) result.table = readTable(root["table"]);
    if (root["types"]) {
      if (!root["types"].IsMap()) fail("types", "expected a map of name: {size, mass, ...}");
      for (const auto& entry : root["types"])
        result.types.push_back(readType(entry.first.as<std::string>(), entry.second));
    }
    BrickTypeLibrary all_types = types;
    if (Status merged = mergeSceneTypes(result, &all_types); !merged) fail("types", merged.message);
    if (const YAML::Node generators = root["generator"]) {
      const TableOptions table = result.table.value_or(TableOptions());
      if (generators.IsSequence()) {
        for (const YAML::Node& generator : generators)
          runGenerator(generator, table, all_types, &result.bricks);
      } else {
        runGenerator(generators, table, all_types, &result.bricks);
      }
    }
    if (root["bricks"]) {
      if (!root["bricks"].IsSequence()) fail("bricks", "expected a list");
      std::size_t index = 0;
      for (const auto& node : root["bricks"]) result.bricks.push_back(readBrick(node, index++));
    }
    std::set<std::string> ids;
    for (const ScheduledBrick& brick : result.bricks) {
      const std::string& id = brick.placement.id;
      if (!id.empty() && !ids.insert(id).second) fail("bricks", "id '" + id + "' appears twice");
      const std::string& type = brick.placement.type;
      if (!type.empty() && !all_types.find(type))
        fail("bricks", "brick '" + id + "' has unknown type '" + type + "'");
    }
  } catch (const SceneError& error) {
    return Status::error("scene '" + name + "': " + error.message);
  } catch (const YAML::Exception& error) {
    return Status::error("scene '" + name + "': " + error.what());
  }
  std::stable_sort(result.bricks.begin(), result.bricks.end(),
                   [](const ScheduledBrick& a, const ScheduledBrick& b) { return a.at < b.at; });
  *scene = std::move(result);
  return Status::success();
}

Status loadScene(const std::string& name_or_path, const std::vector<std::string>& scene_dirs,
                 const BrickTypeLibrary& types, Scene* scene) {
  if (name_or_path.empty()) return Status::error("no scene given");
  std::string path;
  if (isFile(name_or_path)) {
    path = name_or_path;
  } else {
    for (const std::string& dir : scene_dirs) {
      const std::string candidate = dir + "/" + name_or_path + ".yaml";
      if (isFile(candidate)) {
        path = candidate;
        break;
      }
    }
  }
  if (path.empty()) {
    std::string searched;
    for (const std::string& dir : scene_dirs) searched += (searched.empty() ? "" : ", ") + dir;
    return Status::error("unknown scene '" + name_or_path + "': no such file, and no " +
                         name_or_path + ".yaml in [" + searched + "]");
  }
  std::ifstream file(path);
  std::ostringstream text;
  text << file.rdbuf();
  return parseScene(text.str(), stem(path), types, scene);
}

}  // namespace brick_stack_sim
