// A scene's types written back as a scene, so that another program (the
// blueprint builder) can hand them to a simulator that does not know them.
#include <yaml-cpp/yaml.h>

#include "brick_stack_sim/core/scene/scene.h"

namespace brick_stack_sim {

namespace {

void emitVector(YAML::Emitter& out, const Eigen::Vector3d& v) {
  out << YAML::Flow << YAML::BeginSeq << v.x() << v.y() << v.z() << YAML::EndSeq;
}

/// The keys of one convex part's geometry (not its pose).
void emitGeometry(YAML::Emitter& out, const ShapePart& part) {
  out << YAML::Key << "shape" << YAML::Value << toString(part.kind);
  if (part.kind == ShapeKind::kBox) {
    out << YAML::Key << "size" << YAML::Value;
    emitVector(out, part.size);
  } else if (part.kind == ShapeKind::kCylinder) {
    out << YAML::Key << "radius" << YAML::Value << part.radius;
    out << YAML::Key << "length" << YAML::Value << part.length;
  } else {
    out << YAML::Key << "vertices" << YAML::Value << YAML::BeginSeq;
    for (const Eigen::Vector3d& vertex : part.vertices) emitVector(out, vertex);
    out << YAML::EndSeq;
  }
}

void emitShape(YAML::Emitter& out, const BrickShape& shape) {
  if (shape.kind != ShapeKind::kCompound && shape.parts.size() == 1 &&
      shape.parts[0].pose.matrix().isIdentity(0.0)) {
    emitGeometry(out, shape.parts[0]);
    return;
  }
  out << YAML::Key << "shape" << YAML::Value << "compound";
  out << YAML::Key << "parts" << YAML::Value << YAML::BeginSeq;
  for (const ShapePart& part : shape.parts) {
    out << YAML::BeginMap;
    emitGeometry(out, part);
    out << YAML::Key << "position" << YAML::Value;
    emitVector(out, part.pose.translation());
    // Fixed-axis roll, pitch, yaw: R = Rz(yaw) Ry(pitch) Rx(roll).
    const Eigen::Vector3d ypr = part.pose.linear().eulerAngles(2, 1, 0);
    out << YAML::Key << "rpy" << YAML::Value;
    emitVector(out, Eigen::Vector3d(ypr.z(), ypr.y(), ypr.x()));
    out << YAML::EndMap;
  }
  out << YAML::EndSeq;
}

}  // namespace

std::string typesAsScene(const std::vector<BrickType>& types) {
  YAML::Emitter out;
  out.SetDoublePrecision(17);
  out << YAML::BeginMap << YAML::Key << "types" << YAML::Value << YAML::BeginMap;
  for (const BrickType& type : types) {
    out << YAML::Key << type.name << YAML::Value << YAML::BeginMap;
    emitShape(out, type.shape);
    out << YAML::Key << "mass" << YAML::Value << type.mass;
    out << YAML::Key << "friction" << YAML::Value << type.friction;
    out << YAML::Key << "restitution" << YAML::Value << type.restitution;
    out << YAML::Key << "rolling_friction" << YAML::Value << type.rolling_friction;
    out << YAML::EndMap;
  }
  out << YAML::EndMap << YAML::Key << "bricks" << YAML::Value << YAML::Flow << YAML::BeginSeq
      << YAML::EndSeq << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

}  // namespace brick_stack_sim
