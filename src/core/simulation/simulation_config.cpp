#include "brick_stack_sim/core/simulation/simulation_config.h"

#include <algorithm>
#include <cctype>

#include "brick_stack_sim/core/options/options_reader.h"
#include "brick_stack_sim/core/options/yaml_parameters.h"
#include "util/text_format.h"
#include "util/validation.h"

namespace brick_stack_sim {

namespace {

Status readPublishOptions(OptionsReader& reader, PublishOptions* options) {
  return readAndValidate(reader, false, options, [&reader](PublishOptions& publish) {
    reader.read("publish_rate", &publish.rate);
    reader.read("publish_clock", &publish.clock);
    reader.read("real_time_factor", &publish.real_time_factor);
    reader.read("frame_id", &publish.frame_id);
    reader.read("frame_prefix", &publish.frame_prefix);
    reader.read("bricks_delta", &publish.bricks_delta);
    reader.read("legend_scale", &publish.legend_scale);
  });
}

/// Paths: whether they can be read is found where they are used.
Status readDataOptions(OptionsReader& reader, DataOptions* options) {
  return readAndValidate(reader, false, options, [&reader](DataOptions& data) {
    reader.read("types_urdf", &data.types_urdf);
    reader.read("materials_yaml", &data.materials_yaml);
    reader.read("scene_dirs", &data.scene_dirs);
    reader.read("scene", &data.scene);
    reader.read("scene_max_bytes", &data.scene_max_bytes);
    reader.read("scene_max_bricks", &data.scene_max_bricks);
  });
}

/// The fixed frame may not be one the node names itself: tf2 refuses a
/// frame that is its own parent (TF_SELF_TRANSFORM). docs/ros_interface.md,
/// "Frames and units".
Status checkFixedFrame(const PublishOptions& p) {
  std::string unprefixed = p.frame_id;
  const std::string prefix = prefixedFrame(p.frame_prefix, "");
  if (unprefixed.compare(0, prefix.size(), prefix) != 0) return Status::success();
  unprefixed.erase(0, prefix.size());
  std::string lower(unprefixed);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  const std::string number = lower.compare(0, 6, "brick_") == 0 ? lower.substr(6) : "";
  const bool unnamed = !number.empty() && std::all_of(number.begin(), number.end(), [](char c) {
    return std::isdigit(static_cast<unsigned char>(c));
  });
  // "world" is no frame of the node's: compare.launch runs "left/world" under "left/".
  if (lower == "table" || lower == "floor" || unnamed)
    return bad("frame_id", "'" + p.frame_id + "'",
               "is a frame the node names itself (" + prefix + "table, " + prefix + "floor and " +
                   prefix + "brick_<n> are its own, in any case, under frame_prefix '" +
                   p.frame_prefix + "'): choose another fixed frame or another frame_prefix");
  return Status::success();
}

}  // namespace

Status validate(const DataOptions& d) {
  // Below a kilobyte no scene with a generator fits; above a gigabyte the
  // node would hold the text, the YAML tree and the bricks at once.
  if (d.scene_max_bytes < 1024 || d.scene_max_bytes > (1 << 30))
    return bad("scene_max_bytes", d.scene_max_bytes, "must be in [1024, 2^30] bytes");
  // A million bricks is ten times the largest tower or pile a generator
  // places; the count is checked before any brick is built.
  if (d.scene_max_bricks < 1 || d.scene_max_bricks > 1000000)
    return bad("scene_max_bricks", d.scene_max_bricks, "must be in [1, 1000000] bricks");
  return Status::success();
}

SceneLimits sceneLimits(const DataOptions& options) {
  SceneLimits limits;
  limits.max_bytes = options.scene_max_bytes;
  limits.max_bricks = options.scene_max_bricks;
  return limits;
}

void fillPackageData(const std::string& package_dir, DataOptions* data) {
  if (data->types_urdf.empty()) data->types_urdf = package_dir + "/urdf/bricks.urdf";
  if (data->materials_yaml.empty()) data->materials_yaml = package_dir + "/config/bricks.yaml";
  if (data->scene_dirs.empty()) data->scene_dirs.push_back(package_dir + "/scenes");
}

Status validate(const PublishOptions& p) {
  // Above 10 kHz of sim time a subscriber learns nothing more and the node
  // spends its time serialising.
  if (!positive(p.rate) || p.rate > 10000.0)
    return bad("publish_rate", p.rate, "must be in (0, 10000] Hz");
  if (!std::isfinite(p.real_time_factor) || p.real_time_factor < 0.0 || p.real_time_factor > 1e6)
    return bad("real_time_factor", p.real_time_factor,
               "must be in [0, 1e6] (0: as fast as possible)");
  // tf2 refuses frame ids with a leading slash; an empty one matches nothing.
  if (p.frame_id.empty() || p.frame_id.front() == '/' ||
      p.frame_id.find_first_of(" \t\n") != std::string::npos)
    return bad("frame_id", "'" + p.frame_id + "'",
               "must be a non-empty tf frame id without a leading '/' or spaces");
  if ((!p.frame_prefix.empty() && p.frame_prefix.front() == '/') ||
      p.frame_prefix.find_first_of(" \t\n") != std::string::npos)
    return bad("frame_prefix", "'" + p.frame_prefix + "'",
               "must be empty or a tf name prefix without a leading '/' or spaces");
  if (Status own = checkFixedFrame(p); !own) return own;
  if (!positive(p.legend_scale) || p.legend_scale > 100.0)
    return bad("legend_scale", p.legend_scale, "must be in (0, 100]");
  return Status::success();
}

std::string prefixedFrame(const std::string& frame_prefix, const std::string& name) {
  if (frame_prefix.empty() || frame_prefix.back() == '/') return frame_prefix + name;
  return frame_prefix + "/" + name;
}

Status readSimulationConfig(OptionsReader& reader, SimulationConfig* config) {
  SimulationConfig result = *config;
  if (Status world = readWorldOptions(reader, &result.world); !world) return world;
  if (Status publish = readPublishOptions(reader, &result.publish); !publish) return publish;
  if (Status data = readDataOptions(reader, &result.data); !data) return data;
  // Wrong types of the data keys, and any key nobody read.
  if (Status known = reader.finish(); !known) return known;
  *config = std::move(result);
  return Status::success();
}

Status loadSimulationConfig(const std::vector<std::string>& yaml_paths, SimulationConfig* config) {
  ParameterValue tree;
  for (const std::string& path : yaml_paths) {
    ParameterValue file;
    if (Status loaded = loadYamlParameters(path, &file); !loaded) return loaded;
    tree.merge(file);
  }
  OptionsReader reader(tree);
  return prefixed(joinNames(yaml_paths) + ": parameter ", readSimulationConfig(reader, config));
}

}  // namespace brick_stack_sim
