#include "scene/type_yaml.h"

#include "scene/generators/generator_support.h"
#include "scene/yaml_fields.h"

namespace brick_stack_sim {
namespace scene_yaml {

namespace {

ShapeKind readKind(const YAML::Node& node, const std::string& where) {
  const std::string kind = readString(node, "shape", where, "box");
  for (ShapeKind k :
       {ShapeKind::kBox, ShapeKind::kCylinder, ShapeKind::kConvex, ShapeKind::kCompound})
    if (kind == toString(k)) return k;
  fail(where + ".shape", "'" + kind + "' is no shape: box, cylinder, convex or compound");
}

std::vector<Eigen::Vector3d> readVertices(const YAML::Node& node, const std::string& where) {
  const YAML::Node list = node["vertices"];
  const std::string field = where + ".vertices";
  if (!list || !list.IsSequence()) fail(field, "expected a list of points [[x, y, z], ...] [m]");
  if (list.size() > kMaxSceneVertices)
    fail(field, "more than " + std::to_string(kMaxSceneVertices) + " points");
  std::vector<Eigen::Vector3d> vertices;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string at = field + "[" + std::to_string(i) + "]";
    if (!list[i].IsSequence() || list[i].size() != 3) fail(at, "expected a list of 3 numbers");
    Eigen::Vector3d v;
    for (int k = 0; k < 3; ++k) v[k] = readNumber(list[i][k], at + "[" + std::to_string(k) + "]");
    vertices.push_back(v);
  }
  return vertices;
}

/// The geometry keys of one convex part (`kind` is never compound here).
void readPartGeometry(const YAML::Node& node, ShapeKind kind, const std::string& where,
                      ShapePart* part) {
  part->kind = kind;
  if (kind == ShapeKind::kBox) {
    if (!node["size"]) fail(where, "a box needs 'size' [m]");
    part->size = readVector<3>(node, "size", where, Eigen::Vector3d::Zero());
  } else if (kind == ShapeKind::kCylinder) {
    if (!node["radius"] || !node["length"])
      fail(where, "a cylinder needs 'radius' and 'length' [m]");
    part->radius = readNumber(node, "radius", where, 0.0);
    part->length = readNumber(node, "length", where, 0.0);
  } else {
    part->vertices = readVertices(node, where);
  }
}

const std::set<std::string> kGeometryKeys = {"shape", "size", "radius", "length", "vertices"};

std::set<std::string> withKeys(std::set<std::string> keys, const std::set<std::string>& more) {
  keys.insert(more.begin(), more.end());
  return keys;
}

ShapePart readPart(const YAML::Node& node, const std::string& where) {
  requireKnownKeys(node, where, withKeys(kGeometryKeys, {"position", "rpy"}));
  const ShapeKind kind = readKind(node, where);
  if (kind == ShapeKind::kCompound) fail(where + ".shape", "a part cannot itself be compound");
  ShapePart part;
  readPartGeometry(node, kind, where, &part);
  part.pose.translation() = readVector<3>(node, "position", where, Eigen::Vector3d::Zero());
  part.pose.linear() = rotationFromRpy(readVector<3>(node, "rpy", where, Eigen::Vector3d::Zero()));
  return part;
}

BrickShape readShape(const YAML::Node& node, const std::string& where) {
  BrickShape shape;
  shape.kind = readKind(node, where);
  if (shape.kind != ShapeKind::kCompound) {
    shape.parts.resize(1);
    readPartGeometry(node, shape.kind, where, &shape.parts[0]);
    return shape;
  }
  const YAML::Node parts = node["parts"];
  if (!parts || !parts.IsSequence() || parts.size() == 0)
    fail(where + ".parts", "a compound needs a list of parts [{shape, ..., position, rpy}]");
  if (parts.size() > kMaxCompoundParts)
    fail(where + ".parts", "more than " + std::to_string(kMaxCompoundParts) + " parts");
  for (std::size_t i = 0; i < parts.size(); ++i)
    shape.parts.push_back(readPart(parts[i], where + ".parts[" + std::to_string(i) + "]"));
  return shape;
}

}  // namespace

BrickType readSceneType(const std::string& name, const YAML::Node& node) {
  const std::string where = "types." + name;
  requireKnownKeys(
      node, where,
      withKeys(kGeometryKeys, {"parts", "mass", "friction", "restitution", "rolling_friction"}));
  if (!node["mass"]) fail(where, "needs 'mass' [kg]");
  BrickType type;
  type.name = name;
  type.shape = readShape(node, where);
  type.mass = readNumber(node, "mass", where, 0.0);
  type.friction = readNumber(node, "friction", where, type.friction);
  type.restitution = readNumber(node, "restitution", where, type.restitution);
  type.rolling_friction = readNumber(node, "rolling_friction", where, type.rolling_friction);
  if (Status finished = finishBrickType(&type, false); !finished) fail(where, finished.message);
  return type;
}

}  // namespace scene_yaml
}  // namespace brick_stack_sim
