#include "brick_stack_sim/core/types/brick_type.h"

#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>

#include <urdf_parser/urdf_parser.h>

#include "brick_stack_sim/core/options/options_reader.h"
#include "brick_stack_sim/core/options/yaml_parameters.h"

namespace brick_stack_sim {

namespace {

bool positiveFinite(double value) { return std::isfinite(value) && value > 0.0; }

Status readFile(const std::string& path, const char* what, std::string* text) {
  std::ifstream file(path);
  if (!file) return Status::error(std::string("cannot read ") + what + " '" + path + "'");
  std::ostringstream buffer;
  buffer << file.rdbuf();
  *text = buffer.str();
  return Status::success();
}

/// Friction and restitution of one section of the materials over `*type`;
/// a key it does not know is an error.
Status readMaterial(OptionsReader& reader, BrickType* type) {
  BrickType material = *type;
  reader.read("friction", &material.friction);
  reader.read("restitution", &material.restitution);
  reader.read("rolling_friction", &material.rolling_friction);
  if (Status read = reader.finish(); !read) return read;
  *type = material;
  return Status::success();
}

// BrickTypeLibrary::parse's steps, link by link and then over the materials.

/// The box a link is drawn as: its collision geometry's, else its visual
/// one's; null when that is no box.
urdf::BoxSharedPtr boxOf(const urdf::Link& link) {
  urdf::GeometrySharedPtr geometry;
  if (link.collision) geometry = link.collision->geometry;
  if (!geometry && link.visual) geometry = link.visual->geometry;
  return std::dynamic_pointer_cast<urdf::Box>(geometry);
}

/// The brick type of a link drawn as `box`: size, mass and inertia from the
/// URDF; friction, restitution and rolling friction from `defaults`, over
/// which its own section of `own_materials` (when it has one) is read.
Status brickTypeOfLink(const urdf::Link& link, const urdf::Box& box, const BrickType& defaults,
                       const ParameterValue* own_materials, BrickType* type) {
  if (!link.inertial) return Status::error("link '" + link.name + "' has no <inertial>");
  *type = defaults;
  type->name = link.name;
  type->size = Eigen::Vector3d(box.dim.x, box.dim.y, box.dim.z);
  type->mass = link.inertial->mass;
  type->inertia = Eigen::Vector3d(link.inertial->ixx, link.inertial->iyy, link.inertial->izz);
  const double off_diagonal =
      std::abs(link.inertial->ixy) + std::abs(link.inertial->ixz) + std::abs(link.inertial->iyz);
  if (off_diagonal > 1e-9 * type->inertia.cwiseAbs().sum())
    return Status::error("link '" + link.name +
                         "': inertia must be diagonal in the box frame (a uniform box)");
  if (const ParameterValue* own = own_materials ? own_materials->find(type->name) : nullptr) {
    OptionsReader own_reader(*own, "types/" + type->name + "/");
    if (Status read = readMaterial(own_reader, type); !read)
      return prefixed("brick materials yaml: ", read);
  }
  return Status::success();
}

/// A material section for a type the URDF does not define is a typo, not
/// something to ignore.
Status materialsNameKnownTypes(const ParameterValue* own_materials, const BrickTypeLibrary& types) {
  if (!own_materials) return Status::success();
  for (const auto& [name, material] : own_materials->map())
    if (!types.find(name))
      return Status::error("materials name type '" + name + "' that the URDF does not define");
  return Status::success();
}

}  // namespace

Status validateBrickType(const BrickType& t) {
  const std::string name = "brick type '" + t.name + "'";
  if (t.name.empty()) return Status::error("brick type without a name");
  if (!positiveFinite(t.size.x()) || !positiveFinite(t.size.y()) || !positiveFinite(t.size.z()))
    return Status::error(name + ": size must be positive and finite in x, y and z");
  if (!positiveFinite(t.mass)) return Status::error(name + ": mass must be positive and finite");
  const Eigen::Vector3d& i = t.inertia;
  if (!positiveFinite(i.x()) || !positiveFinite(i.y()) || !positiveFinite(i.z()))
    return Status::error(name + ": principal inertia must be positive and finite");
  // A real body's principal moments obey the triangle inequality; a violation
  // means a typo in the URDF, which would make Bullet spin the brick.
  const double slack = 1e-9 * i.sum();
  if (i.x() > i.y() + i.z() + slack || i.y() > i.x() + i.z() + slack ||
      i.z() > i.x() + i.y() + slack)
    return Status::error(name + ": principal inertia violates the triangle inequality");
  if (!std::isfinite(t.friction) || t.friction < 0.0)
    return Status::error(name + ": friction must be >= 0");
  if (!std::isfinite(t.restitution) || t.restitution < 0.0 || t.restitution > 1.0)
    return Status::error(name + ": restitution must be in [0, 1]");
  if (!std::isfinite(t.rolling_friction) || t.rolling_friction < 0.0)
    return Status::error(name + ": rolling_friction must be >= 0");
  return Status::success();
}

Status BrickTypeLibrary::add(const BrickType& type) {
  if (Status valid = validateBrickType(type); !valid) return valid;
  types_[type.name] = type;
  if (default_type_.empty()) default_type_ = types_.begin()->first;
  return Status::success();
}

const BrickType* BrickTypeLibrary::find(const std::string& name) const {
  auto it = types_.find(name);
  return it == types_.end() ? nullptr : &it->second;
}

std::vector<std::string> BrickTypeLibrary::names() const {
  std::vector<std::string> result;
  for (const auto& entry : types_) result.push_back(entry.first);
  return result;
}

Status BrickTypeLibrary::setDefaultType(const std::string& name) {
  if (!find(name)) return Status::error("default brick type '" + name + "' is not a known type");
  default_type_ = name;
  return Status::success();
}

Status BrickTypeLibrary::load(const std::string& urdf_path, const std::string& materials_path,
                              BrickTypeLibrary* library) {
  std::string urdf_xml, materials_yaml;
  if (Status read = readFile(urdf_path, "brick type URDF", &urdf_xml); !read) return read;
  if (!materials_path.empty()) {
    if (Status read = readFile(materials_path, "brick materials yaml", &materials_yaml); !read)
      return read;
  }
  Status parsed = parse(urdf_xml, materials_yaml, library);
  if (!parsed) parsed.message = urdf_path + ": " + parsed.message;
  return parsed;
}

Status BrickTypeLibrary::parse(const std::string& urdf_xml, const std::string& materials_yaml,
                               BrickTypeLibrary* library) {
  const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(urdf_xml);
  if (!model) return Status::error("not a valid URDF");

  ParameterValue materials;
  if (!materials_yaml.empty()) {
    if (Status parsed = parseYamlParameters(materials_yaml, "brick materials yaml", &materials);
        !parsed)
      return parsed;
  }
  OptionsReader reader(materials);
  BrickType defaults;
  reader.section("default", &readMaterial, &defaults);
  std::string default_type;
  reader.read("default_type", &default_type);
  // One section per type, named by the URDF: read below, type by type.
  const ParameterValue* own_materials = materials.find("types");
  reader.skip("types");
  if (Status read = reader.finish(); !read) return prefixed("brick materials yaml: ", read);
  if (own_materials && !own_materials->isMap())
    return Status::error("brick materials yaml: types is " + own_materials->describe() +
                         ", expected a map of type: {friction, restitution, rolling_friction}");

  BrickTypeLibrary result;
  for (const auto& entry : model->links_) {
    const urdf::Link& link = *entry.second;
    // Links without a box (a root that only ties the types together) are not bricks.
    const urdf::BoxSharedPtr box = boxOf(link);
    if (!box) continue;
    BrickType type;
    if (Status read = brickTypeOfLink(link, *box, defaults, own_materials, &type); !read)
      return read;
    if (Status added = result.add(type); !added) return added;
  }
  if (result.empty()) return Status::error("the URDF has no link with a box geometry");

  if (Status known = materialsNameKnownTypes(own_materials, result); !known) return known;
  if (!default_type.empty()) {
    if (Status set = result.setDefaultType(default_type); !set) return set;
  }
  *library = std::move(result);
  return Status::success();
}

}  // namespace brick_stack_sim
