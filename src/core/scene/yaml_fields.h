#pragma once
// Typed reading of scene YAML with messages that name the field's place
// ("bricks[2].position[1]: must be finite"). Used inside the scene parser
// only: a SceneError thrown here becomes a Status at parseScene's boundary.

#include <cstdint>
#include <set>
#include <string>

#include <yaml-cpp/yaml.h>
#include <Eigen/Core>

namespace brick_stack_sim {
namespace scene_yaml {

/// Thrown inside the parser only, turned into a Status at its boundary.
struct SceneError {
  std::string message;
};

[[noreturn]] void fail(const std::string& where, const std::string& what);

/// Fails unless `node` is a map whose keys are all in `known`.
void requireKnownKeys(const YAML::Node& node, const std::string& where,
                      const std::set<std::string>& known);

double readNumber(const YAML::Node& node, const std::string& where);
double readNumber(const YAML::Node& map, const char* key, const std::string& where,
                  double fallback);
int readInt(const YAML::Node& map, const char* key, const std::string& where, int fallback);
/// An integer in [0, 2^63 - 1]: the seed of a random generator.
std::uint64_t readSeed(const YAML::Node& map, const char* key, const std::string& where,
                       std::uint64_t fallback);
std::string readString(const YAML::Node& map, const char* key, const std::string& where,
                       const std::string& fallback = "");

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

}  // namespace scene_yaml
}  // namespace brick_stack_sim
