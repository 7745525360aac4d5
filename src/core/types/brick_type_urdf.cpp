// BrickTypeLibrary's readers: the URDF (geometry and inertia per link) and
// the materials yaml (friction, restitution, rolling friction per type).
#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>

#include <urdf_parser/urdf_parser.h>

#include "brick_stack_sim/core/options/options_reader.h"
#include "brick_stack_sim/core/options/yaml_parameters.h"
#include "brick_stack_sim/core/types/brick_type.h"
#include "types/inertial.h"
#include "types/mesh_file.h"

namespace brick_stack_sim {

namespace {

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

Eigen::Isometry3d toIsometry(const urdf::Pose& pose) {
  Eigen::Isometry3d result = Eigen::Isometry3d::Identity();
  result.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
  result.linear() =
      Eigen::Quaterniond(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z)
          .normalized()
          .toRotationMatrix();
  return result;
}

/// The geometries a link is made of: its collisions', else its visuals'.
std::vector<std::pair<urdf::GeometrySharedPtr, urdf::Pose>> geometriesOf(const urdf::Link& link) {
  std::vector<std::pair<urdf::GeometrySharedPtr, urdf::Pose>> result;
  for (const urdf::CollisionSharedPtr& collision : link.collision_array)
    if (collision && collision->geometry)
      result.emplace_back(collision->geometry, collision->origin);
  if (!result.empty()) return result;
  for (const urdf::VisualSharedPtr& visual : link.visual_array)
    if (visual && visual->geometry) result.emplace_back(visual->geometry, visual->origin);
  return result;
}

/// One URDF geometry as a part of the link's shape; meshes are read from
/// files under `mesh_directory` (relative names) or their package.
Status partOf(const urdf::Geometry& geometry, const std::string& mesh_directory, ShapePart* part) {
  switch (geometry.type) {
    case urdf::Geometry::BOX: {
      const auto& box = static_cast<const urdf::Box&>(geometry);
      part->kind = ShapeKind::kBox;
      part->size = Eigen::Vector3d(box.dim.x, box.dim.y, box.dim.z);
      return Status::success();
    }
    case urdf::Geometry::CYLINDER: {
      const auto& cylinder = static_cast<const urdf::Cylinder&>(geometry);
      part->kind = ShapeKind::kCylinder;
      part->radius = cylinder.radius;
      part->length = cylinder.length;
      return Status::success();
    }
    case urdf::Geometry::MESH: {
      const auto& mesh = static_cast<const urdf::Mesh&>(geometry);
      std::string path;
      if (Status found = resolveMeshPath(mesh.filename, mesh_directory, &path); !found)
        return found;
      part->kind = ShapeKind::kConvex;
      return readMeshVertices(path, Eigen::Vector3d(mesh.scale.x, mesh.scale.y, mesh.scale.z),
                              &part->vertices);
    }
    case urdf::Geometry::SPHERE:
      break;
  }
  return Status::error("a sphere is no brick: give a box, a cylinder or a mesh");
}

/// The shape of a link: one part, or a compound of its several geometries.
Status shapeOfLink(const urdf::Link& link, const std::string& mesh_directory, BrickShape* shape) {
  const auto geometries = geometriesOf(link);
  shape->parts.assign(geometries.size(), ShapePart());
  for (std::size_t i = 0; i < geometries.size(); ++i) {
    if (Status read = partOf(*geometries[i].first, mesh_directory, &shape->parts[i]); !read)
      return Status::error("link '" + link.name + "': " + read.message);
    shape->parts[i].pose = toIsometry(geometries[i].second);
  }
  shape->kind = shape->parts.size() == 1 ? shape->parts[0].kind : ShapeKind::kCompound;
  return Status::success();
}

/// Mass and inertia of a link from its <inertial>; an inertia of all
/// zeros is a placeholder: the solid's, at uniform density, is used.
Status massOfLink(const urdf::Link& link, BrickType* type, bool* inertia_given) {
  if (!link.inertial) return Status::error("link '" + link.name + "' has no <inertial>");
  const urdf::Inertial& in = *link.inertial;
  type->mass = in.mass;
  Eigen::Matrix3d tensor;
  tensor << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
  *inertia_given = !tensor.isZero(0.0);
  if (!*inertia_given) return Status::success();
  if (Status frame =
          inertialFrame(toIsometry(in.origin), tensor, &type->inertia, &type->mass_frame);
      !frame)
    return Status::error("link '" + link.name + "': " + frame.message);
  return Status::success();
}

/// The brick type of a link: shape, mass and inertia from the URDF;
/// friction, restitution and rolling friction from `defaults`, over which
/// its own section of `own_materials` (when it has one) is read.
Status brickTypeOfLink(const urdf::Link& link, const std::string& mesh_directory,
                       const BrickType& defaults, const ParameterValue* own_materials,
                       BrickType* type) {
  *type = defaults;
  type->name = link.name;
  if (Status shape = shapeOfLink(link, mesh_directory, &type->shape); !shape) return shape;
  bool inertia_given = false;
  if (Status mass = massOfLink(link, type, &inertia_given); !mass) return mass;
  if (const ParameterValue* own = own_materials ? own_materials->find(type->name) : nullptr) {
    OptionsReader own_reader(*own, "types/" + type->name + "/");
    if (Status read = readMaterial(own_reader, type); !read)
      return prefixed("brick materials yaml: ", read);
  }
  return finishBrickType(type, inertia_given);
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

/// The materials yaml: defaults for every type, the default type's name and
/// the per-type sections (read with the types).
Status readMaterials(const std::string& materials_yaml, BrickType* defaults,
                     std::string* default_type, ParameterValue* materials,
                     const ParameterValue** own_materials) {
  if (!materials_yaml.empty()) {
    if (Status parsed = parseYamlParameters(materials_yaml, "brick materials yaml", materials);
        !parsed)
      return parsed;
  }
  OptionsReader reader(*materials);
  reader.section("default", &readMaterial, defaults);
  reader.read("default_type", default_type);
  *own_materials = materials->find("types");
  reader.skip("types");
  if (Status read = reader.finish(); !read) return prefixed("brick materials yaml: ", read);
  if (*own_materials && !(*own_materials)->isMap())
    return Status::error("brick materials yaml: types is " + (*own_materials)->describe() +
                         ", expected a map of type: {friction, restitution, rolling_friction}");
  return Status::success();
}

}  // namespace

Status BrickTypeLibrary::load(const std::string& urdf_path, const std::string& materials_path,
                              BrickTypeLibrary* library) {
  std::string urdf_xml, materials_yaml;
  if (Status read = readFile(urdf_path, "brick type URDF", &urdf_xml); !read) return read;
  if (!materials_path.empty()) {
    if (Status read = readFile(materials_path, "brick materials yaml", &materials_yaml); !read)
      return read;
  }
  const std::size_t slash = urdf_path.rfind('/');
  const std::string directory = slash == std::string::npos ? "." : urdf_path.substr(0, slash);
  Status parsed = parse(urdf_xml, materials_yaml, library, directory);
  if (!parsed) parsed.message = urdf_path + ": " + parsed.message;
  return parsed;
}

Status BrickTypeLibrary::parse(const std::string& urdf_xml, const std::string& materials_yaml,
                               BrickTypeLibrary* library, const std::string& mesh_directory) {
  const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(urdf_xml);
  if (!model) return Status::error("not a valid URDF");
  ParameterValue materials;
  BrickType defaults;
  std::string default_type;
  const ParameterValue* own_materials = nullptr;
  if (Status read =
          readMaterials(materials_yaml, &defaults, &default_type, &materials, &own_materials);
      !read)
    return read;

  BrickTypeLibrary result;
  for (const auto& entry : model->links_) {
    const urdf::Link& link = *entry.second;
    // Links without geometry (a root that only ties the types together) are not bricks.
    if (geometriesOf(link).empty()) continue;
    BrickType type;
    if (Status read = brickTypeOfLink(link, mesh_directory, defaults, own_materials, &type); !read)
      return read;
    if (Status added = result.add(type); !added) return added;
  }
  if (result.empty()) return Status::error("the URDF has no link with a geometry");

  if (Status known = materialsNameKnownTypes(own_materials, result); !known) return known;
  if (!default_type.empty()) {
    if (Status set = result.setDefaultType(default_type); !set) return set;
  }
  *library = std::move(result);
  return Status::success();
}

}  // namespace brick_stack_sim
