#include "scene/yaml_fields.h"

#include <cmath>

namespace brick_stack_sim {
namespace scene_yaml {

void fail(const std::string& where, const std::string& what) {
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

std::uint64_t readSeed(const YAML::Node& map, const char* key, const std::string& where,
                       std::uint64_t fallback) {
  if (!map[key]) return fallback;
  long long seed = -1;
  try {
    seed = map[key].as<long long>();
  } catch (const YAML::Exception&) {
    fail(where + "." + key, "expected an integer >= 0");
  }
  if (seed < 0) fail(where + "." + key, "must be >= 0");
  return static_cast<std::uint64_t>(seed);
}

std::string readString(const YAML::Node& map, const char* key, const std::string& where,
                       const std::string& fallback) {
  if (!map[key]) return fallback;
  if (!map[key].IsScalar()) fail(where + "." + key, "expected a string");
  return map[key].as<std::string>();
}

}  // namespace scene_yaml
}  // namespace brick_stack_sim
