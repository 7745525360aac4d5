#pragma once
// BulletScene's state, shared by the files that implement it (the scene, its
// copy). Not part of any interface.

#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include <btBulletDynamicsCommon.h>

#include "bullet/apart_pair_dispatcher.h"
#include "bullet/brick_dynamics_world.h"
#include "bullet/bullet_conversions.h"
#include "bullet/bullet_scene.h"

namespace brick_stack_sim {

struct BulletScene::Impl {
  struct Body {
    std::unique_ptr<btRigidBody> rigid;
    bool in_world = false;
    /// The centre of mass and principal axes in the type frame: Bullet's
    /// body frame. Identity (the body frame is the type frame) for a box.
    Eigen::Isometry3d mass_frame = Eigen::Isometry3d::Identity();
    bool centred = true;
  };

  WorldOptions options;
  // Declaration order is destruction order in reverse: the world goes first.
  std::unique_ptr<btDefaultCollisionConfiguration> collision_configuration;
  std::unique_ptr<ApartPairDispatcher> dispatcher;
  std::unique_ptr<btCollisionAlgorithmCreateFunc> box_box_algorithm;
  std::unique_ptr<btBroadphaseInterface> broadphase;
  std::unique_ptr<btSequentialImpulseConstraintSolver> solver;
  std::map<std::string, std::unique_ptr<btCollisionShape>> shapes;  // one per brick type
  // A compound's children, a hull's shrunk copies: owned apart from the shapes.
  std::vector<std::unique_ptr<btCollisionShape>> child_shapes;
  std::unique_ptr<btBoxShape> table_shape;
  std::unique_ptr<btStaticPlaneShape> floor_shape;
  std::unique_ptr<btRigidBody> table_body;
  std::unique_ptr<btRigidBody> floor_body;
  // By handle. A map, not a vector indexed by serial: serials are never
  // reused, and a node that places and removes bricks for hours would keep
  // an entry for every brick it ever had.
  std::unordered_map<BodyHandle, Body> bodies;
  std::unique_ptr<BrickDynamicsWorld> world;

  explicit Impl(const WorldOptions& world_options);
  ~Impl();
  btCollisionShape* shapeFor(const BrickType& type);
  /// Bullet's transform of a brick's body for the type frame at `pose`, and back.
  btTransform toBody(const Body& body, const Eigen::Isometry3d& pose) const {
    return convertEigenToBt(body.centred ? pose : pose * body.mass_frame);
  }
  Eigen::Isometry3d fromBody(const Body& body, const btTransform& transform) const {
    const Eigen::Isometry3d at = convertBtToEigen(transform);
    return body.centred ? at : at * body.mass_frame.inverse();
  }
  Body& body(BodyHandle handle) { return bodies.at(handle); }
  const Body& body(BodyHandle handle) const { return bodies.at(handle); }
  btRigidBody& rigid(BodyHandle handle) { return *body(handle).rigid; }
  const btRigidBody& rigid(BodyHandle handle) const { return *body(handle).rigid; }
  /// A brick's body, or the table's; null for the floor.
  const btRigidBody* bodyOrTable(BodyHandle handle) const {
    if (handle == kTableHandle) return table_body.get();
    if (isGround(handle)) return nullptr;
    const auto found = bodies.find(handle);  // a removed brick's: none
    return found == bodies.end() ? nullptr : found->second.rigid.get();
  }
};

}  // namespace brick_stack_sim
