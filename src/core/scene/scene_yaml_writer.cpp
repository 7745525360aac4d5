// Scenes written back as YAML that the scene reader reads: a scene's types,
// so that another program (the blueprint builder) can hand them to a
// simulator that does not know them, and a whole scene, such as the state a
// run ended in, to be run again from there.
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

void emitTypes(YAML::Emitter& out, const std::vector<BrickType>& types) {
  out << YAML::Key << "types" << YAML::Value << YAML::BeginMap;
  for (const BrickType& type : types) {
    out << YAML::Key << type.name << YAML::Value << YAML::BeginMap;
    emitShape(out, type.shape);
    out << YAML::Key << "mass" << YAML::Value << type.mass;
    out << YAML::Key << "friction" << YAML::Value << type.friction;
    out << YAML::Key << "restitution" << YAML::Value << type.restitution;
    out << YAML::Key << "rolling_friction" << YAML::Value << type.rolling_friction;
    out << YAML::EndMap;
  }
  out << YAML::EndMap;
}

void emitTable(YAML::Emitter& out, const TableOptions& table) {
  out << YAML::Key << "table" << YAML::Value << YAML::Flow << YAML::BeginMap;
  out << YAML::Key << "size" << YAML::Value << YAML::BeginSeq << table.size.x() << table.size.y()
      << YAML::EndSeq;
  out << YAML::Key << "thickness" << YAML::Value << table.thickness;
  out << YAML::Key << "height" << YAML::Value << table.height;
  out << YAML::Key << "friction" << YAML::Value << table.friction;
  out << YAML::Key << "restitution" << YAML::Value << table.restitution;
  out << YAML::EndMap;
}

void emitBrick(YAML::Emitter& out, const ScheduledBrick& brick) {
  const BrickPlacement& placement = brick.placement;
  out << YAML::Flow << YAML::BeginMap;
  out << YAML::Key << "id" << YAML::Value << placement.id;
  out << YAML::Key << "type" << YAML::Value << placement.type;
  out << YAML::Key << "at" << YAML::Value << brick.at;
  out << YAML::Key << "position" << YAML::Value;
  emitVector(out, placement.pose.translation());
  // The rotation as it is, not as roll, pitch and yaw, which lose bits
  // near their poles.
  const Eigen::Quaterniond q(placement.pose.linear());
  out << YAML::Key << "orientation" << YAML::Value << YAML::BeginSeq << q.x() << q.y() << q.z()
      << q.w() << YAML::EndSeq;
  if (!placement.linear_velocity.isZero(0.0)) {
    out << YAML::Key << "linear_velocity" << YAML::Value;
    emitVector(out, placement.linear_velocity);
  }
  if (!placement.angular_velocity.isZero(0.0)) {
    out << YAML::Key << "angular_velocity" << YAML::Value;
    emitVector(out, placement.angular_velocity);
  }
  out << YAML::EndMap;
}

}  // namespace

std::string sceneAsYaml(const Scene& scene) {
  YAML::Emitter out;
  out.SetDoublePrecision(17);
  out << YAML::BeginMap;
  if (!scene.name.empty()) out << YAML::Key << "name" << YAML::Value << scene.name;
  if (scene.expect == ExpectedOutcome::kCollapses)
    out << YAML::Key << "expect" << YAML::Value << "collapses";
  if (scene.table) emitTable(out, *scene.table);
  if (scene.friction) out << YAML::Key << "friction" << YAML::Value << *scene.friction;
  if (!scene.types.empty()) emitTypes(out, scene.types);
  out << YAML::Key << "bricks" << YAML::Value << YAML::BeginSeq;
  for (const ScheduledBrick& brick : scene.bricks) emitBrick(out, brick);
  out << YAML::EndSeq << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

std::string typesAsScene(const std::vector<BrickType>& types) {
  // Always a `types` map, even an empty one.
  YAML::Emitter out;
  out.SetDoublePrecision(17);
  out << YAML::BeginMap;
  emitTypes(out, types);
  out << YAML::Key << "bricks" << YAML::Value << YAML::Flow << YAML::BeginSeq << YAML::EndSeq
      << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

}  // namespace brick_stack_sim
