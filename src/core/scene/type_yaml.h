#pragma once
// A scene's `types` entry: a brick type of any shape, read with messages
// that name the field's place ("types.arch.parts[1].size: ...").

#include <string>

#include <yaml-cpp/yaml.h>

#include "brick_stack_sim/core/types/brick_type.h"

namespace brick_stack_sim {
namespace scene_yaml {

/// A convex shape with more vertices than this is refused [-].
constexpr std::size_t kMaxSceneVertices = 10000;
/// A compound with more parts than this is refused [-].
constexpr std::size_t kMaxCompoundParts = 256;

/// The type `name` of a scene, finished (solid, inertia, validation);
/// throws SceneError naming the field that is wrong.
BrickType readSceneType(const std::string& name, const YAML::Node& node);

}  // namespace scene_yaml
}  // namespace brick_stack_sim
