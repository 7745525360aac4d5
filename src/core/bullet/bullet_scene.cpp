#include "bullet/bullet_scene.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionDispatch/btBoxBoxCollisionAlgorithm.h>

#include "brick_stack_sim/core/types/table_solid.h"
#include "bullet/brick_dynamics_world.h"
#include "bullet/bullet_conversions.h"
#include "bullet/bullet_handles.h"
#include "bullet/bullet_scene_impl.h"
#include "bullet/cone_friction_solver.h"
#include "bullet/flush_box_box_algorithm.h"
#include "bullet/time_of_impact.h"

namespace brick_stack_sim {

namespace {

/// See gDbvtMargin below [m].
constexpr btScalar kBroadphaseMargin = 0.002;

/// Bullet multiplies the two friction coefficients of a pair, which turns pine
/// on pine (0.5 each) into 0.25. The geometric mean keeps a material's own
/// coefficient against itself and stays symmetric for mixed pairs.
btScalar combinedFriction(const btCollisionObject* a, const btCollisionObject* b) {
  return std::sqrt(a->getFriction() * b->getFriction());
}

/// The sequential-impulse solver's settings for bricks.
void configureSolver(const WorldOptions& options, btContactSolverInfo* solver_info) {
  solver_info->m_numIterations = options.solver_iterations;
  // Split impulse corrects penetration without feeding velocity back into the
  // stack. Bullet only splits below its threshold (-4 cm by default, five brick
  // thicknesses, so never at this scale); ours is scaled to the brick.
  solver_info->m_splitImpulse = 1;
  solver_info->m_splitImpulsePenetrationThreshold = options.split_impulse_penetration_threshold;
  solver_info->m_erp = options.erp;
  solver_info->m_erp2 = options.erp;
  // Never SOLVER_RANDMIZE_ORDER: the same inputs must give the same bits.
  solver_info->m_solverMode = SOLVER_USE_WARMSTARTING | SOLVER_SIMD;
  // Two directions, which ConeFrictionSolver holds to the cone together. The
  // cone is the same whichever way they point, so they are taken from the
  // contact normal alone, not from the slip: a pair that turned with the
  // slip would warm-start last step's friction in another direction, a
  // sideways kick each step that threw bricks at long steps.
  if (options.friction_cone)
    solver_info->m_solverMode |=
        SOLVER_USE_2_FRICTION_DIRECTIONS | SOLVER_DISABLE_VELOCITY_DEPENDENT_FRICTION_DIRECTION;
  if (options.full_warm_start) {
    // Started from the whole of the last step's impulses, 20 iterations
    // stay at the converged answer of a pile at rest instead of rebuilding
    // it; the ERP's push out of a penetration, in the velocities, would be
    // carried over with them and overshoot, so the split impulse, in a pass
    // of its own, takes every penetration.
    solver_info->m_warmstartingFactor = 1.0;
    solver_info->m_splitImpulsePenetrationThreshold = 0.0;
  }
}

}  // namespace

BulletScene::Impl::Impl(const WorldOptions& world_options) : options(world_options) {
  // The dispatcher's pool hands out blocks of the largest algorithm it knows
  // of; ours must fit in them.
  btDefaultCollisionConstructionInfo collision_info;
  collision_info.m_customCollisionAlgorithmMaxElementSize = sizeof(FlushBoxBoxAlgorithm);
  collision_configuration = std::make_unique<btDefaultCollisionConfiguration>(collision_info);
  dispatcher = std::make_unique<ApartPairDispatcher>(collision_configuration.get());
  // Bullet's default box-box path is GJK/EPA, which finds one contact point per
  // step and needs several steps to build a resting patch; a brick lying on
  // another wobbles meanwhile. The box-box clipper returns the whole face patch
  // (up to 4 points) in one step, which is what flat stacking needs.
  box_box_algorithm = std::make_unique<FlushBoxBoxAlgorithm::CreateFunc>();
  dispatcher->registerCollisionCreateFunc(BOX_SHAPE_PROXYTYPE, BOX_SHAPE_PROXYTYPE,
                                          box_box_algorithm.get());
  broadphase = std::make_unique<btDbvtBroadphase>();
  solver = std::make_unique<ConeFrictionSolver>(options.full_warm_start);
  world = std::make_unique<BrickDynamicsWorld>(dispatcher.get(), broadphase.get(), solver.get(),
                                               collision_configuration.get());
  dispatcher->watch(world.get());
  world->setGravity(btVector3(0, 0, -options.gravity));
  // Bodies at rest keep their AABB; recomputing every static brick's box each
  // step dominated the cost of large settled scenes.
  world->setForceUpdateAllAabbs(false);
  world->getDispatchInfo().m_deterministicOverlappingPairs = true;

  configureSolver(options, &world->getSolverInfo());

  // Bullet keeps these two as globals; every world sets the same values.
  gCalculateCombinedFrictionCallback = &combinedFriction;
  gDeactivationTime = options.sleeping.time;
  // The tree keeps each moving box this much larger, so that a box that
  // moves a little is not reinserted every step; pairs are made between the
  // larger boxes. Bullet's 5 cm paired every plank of a pile with its
  // neighbours' neighbours; 2 mm is what a brick falling off a table moves
  // in a few 1 ms steps.
  gDbvtMargin = kBroadphaseMargin;

  const TableOptions& table = options.table;
  table_shape = std::make_unique<btBoxShape>(convertEigenToBt(tableHalfExtents(table)));
  table_shape->setMargin(options.collision_margin);
  btRigidBody::btRigidBodyConstructionInfo table_info(0.0, nullptr, table_shape.get());
  table_info.m_startWorldTransform = convertEigenToBt(tablePose(table));
  table_info.m_friction = table.friction;
  table_info.m_restitution = table.restitution;
  table_body = std::make_unique<btRigidBody>(table_info);
  table_body->setUserIndex(kTableUserIndex);
  world->addRigidBody(table_body.get());

  // The floor catches what falls off the table, so no brick is ever lost.
  floor_shape = std::make_unique<btStaticPlaneShape>(btVector3(0, 0, 1), -table.height);
  btRigidBody::btRigidBodyConstructionInfo floor_info(0.0, nullptr, floor_shape.get());
  floor_info.m_friction = table.friction;
  floor_info.m_restitution = table.restitution;
  floor_body = std::make_unique<btRigidBody>(floor_info);
  floor_body->setUserIndex(kFloorUserIndex);
  world->addRigidBody(floor_body.get());
}

BulletScene::Impl::~Impl() {
  for (auto& [handle, body] : bodies)
    if (body.in_world) world->removeRigidBody(body.rigid.get());
  world->removeRigidBody(table_body.get());
  world->removeRigidBody(floor_body.get());
  bodies.clear();
  world.reset();
}

namespace {

/// A hull's margin lies outside its points, so it is kept far below the
/// contact distance: Bullet clips two hulls (or a hull and a box) on their
/// points, and measures a gap with GJK on points plus margins; both then
/// agree within it [m].
constexpr double kHullMargin = 1e-5;

/// A box in its own frame. btBoxShape keeps its outer size and puts the
/// margin inside; Bullet's 4 cm default would be clamped to 10 % of the
/// half thickness anyway.
std::unique_ptr<btBoxShape> boxShape(const ShapePart& part, double margin) {
  const Eigen::Vector3d half = 0.5 * part.size;
  auto box = std::make_unique<btBoxShape>(convertEigenToBt(half));
  box->setMargin(std::min(margin, 0.1 * half.minCoeff()));
  // Box-box pairs take the box clipper; against a hull, Bullet clips
  // polyhedra only when both have their features.
  box->initializePolyhedralFeatures();
  return box;
}

/// The hull of `polyhedron`'s vertices carried by `placement`.
std::unique_ptr<btConvexHullShape> hullShape(const ConvexPolyhedron& polyhedron,
                                             const Eigen::Isometry3d& placement, double margin) {
  auto hull = std::make_unique<btConvexHullShape>();
  for (const Eigen::Vector3d& vertex : polyhedron.vertices)
    hull->addPoint(convertEigenToBt(placement * vertex), false);
  hull->recalcLocalAabb();
  hull->setMargin(std::min(margin, kHullMargin));
  hull->initializePolyhedralFeatures();
  return hull;
}

}  // namespace

btCollisionShape* BulletScene::Impl::shapeFor(const BrickType& type) {
  std::unique_ptr<btCollisionShape>& shape = shapes[type.name];
  if (shape) return shape.get();
  const double margin = options.collision_margin;
  const std::vector<ShapePart>& parts = type.shape.parts;
  // The body frame is the mass frame: each part sits where the type frame puts it.
  const Eigen::Isometry3d to_body = type.mass_frame.inverse();
  std::vector<Eigen::Isometry3d> placements;
  for (const ConvexPart& part : type.solid->parts) placements.push_back(to_body * part.pose);
  // A cylinder is its inscribed prism, the solid the stability layer judges:
  // rolling freely on the table, Bullet's btCylinderShape gained 70 % of its
  // speed in 3 s, the prism 25 % (docs/design.md, "Brick shapes").
  if (parts.size() == 1 && parts[0].kind != ShapeKind::kBox) {
    shape = hullShape(type.solid->parts[0].polyhedron, placements[0], margin);
  } else if (parts.size() == 1 && placements[0].matrix().isIdentity(1e-12)) {
    shape = boxShape(parts[0], margin);
  } else {
    auto compound = std::make_unique<btCompoundShape>(false, static_cast<int>(parts.size()));
    for (std::size_t i = 0; i < parts.size(); ++i) {
      std::unique_ptr<btCollisionShape> child;
      if (parts[i].kind != ShapeKind::kBox) {
        child = hullShape(type.solid->parts[i].polyhedron, Eigen::Isometry3d::Identity(), margin);
      } else {
        child = boxShape(parts[i], margin);
      }
      compound->addChildShape(convertEigenToBt(placements[i]), child.get());
      child_shapes.push_back(std::move(child));
    }
    shape = std::move(compound);
  }
  return shape.get();
}

BulletScene::BulletScene(const WorldOptions& options) : impl_(std::make_unique<Impl>(options)) {}
BulletScene::~BulletScene() = default;

void BulletScene::addBrick(BodyHandle handle, const BrickType& type,
                           const BrickPlacement& placement) {
  btRigidBody::btRigidBodyConstructionInfo info(type.mass, nullptr, impl_->shapeFor(type),
                                                convertEigenToBt(type.inertia));
  Impl::Body& record = impl_->bodies[handle];
  record.mass_frame = type.mass_frame;
  record.centred = type.mass_frame.matrix().isIdentity(0.0);
  info.m_startWorldTransform = impl_->toBody(record, placement.pose);
  info.m_friction = type.friction;
  info.m_rollingFriction = type.rolling_friction;
  info.m_restitution = type.restitution;
  info.m_linearSleepingThreshold = impl_->options.sleeping.linear_threshold;
  info.m_angularSleepingThreshold = impl_->options.sleeping.angular_threshold;
  auto body = std::make_unique<btRigidBody>(info);
  body->setLinearVelocity(convertEigenToBt(placement.linear_velocity));
  body->setAngularVelocity(convertEigenToBt(placement.angular_velocity));
  // Moving more than half its thickness in one step, a brick could sink so
  // far into a thin one before the next step's contact that the shallowest
  // way out is through it: it sweeps its own shape along the step instead
  // (BrickDynamicsWorld). Slower, the discrete contact is cheaper and as
  // good. Bullet's swept sphere is not used.
  const double thinnest_half = type.thinnestHalfWidth();
  body->setCcdMotionThreshold(thinnest_half);
  body->setCcdSweptSphereRadius(0.5 * thinnest_half);
  if (!impl_->options.sleeping.enabled) body->setActivationState(DISABLE_DEACTIVATION);
  body->setUserIndex(static_cast<int>(handle));
  record.rigid = std::move(body);
  addToWorld(handle);
}

void BulletScene::removeBrick(BodyHandle handle) {
  removeFromWorld(handle);
  impl_->bodies.erase(handle);
}

void BulletScene::addToWorld(BodyHandle handle) {
  Impl::Body& body = impl_->body(handle);
  if (body.in_world) return;
  impl_->world->addRigidBody(body.rigid.get());
  body.in_world = true;
}

void BulletScene::removeFromWorld(BodyHandle handle) {
  Impl::Body& body = impl_->body(handle);
  if (!body.in_world) return;
  impl_->world->removeRigidBody(body.rigid.get());
  body.in_world = false;
}

bool BulletScene::inWorld(BodyHandle handle) const {
  const auto found = impl_->bodies.find(handle);  // a removed brick is in no world
  return found != impl_->bodies.end() && found->second.in_world;
}

void BulletScene::makeDynamic(BodyHandle handle, const BrickType& type) {
  btRigidBody& body = impl_->rigid(handle);
  body.setCollisionFlags(body.getCollisionFlags() & ~btCollisionObject::CF_KINEMATIC_OBJECT);
  body.setMassProps(type.mass, convertEigenToBt(type.inertia));
  body.updateInertiaTensor();
  body.setLinearVelocity(btVector3(0, 0, 0));
  body.setAngularVelocity(btVector3(0, 0, 0));
}

void BulletScene::makeStatic(BodyHandle handle) {
  btRigidBody& body = impl_->rigid(handle);
  body.setCollisionFlags(body.getCollisionFlags() & ~btCollisionObject::CF_KINEMATIC_OBJECT);
  body.setLinearVelocity(btVector3(0, 0, 0));
  body.setAngularVelocity(btVector3(0, 0, 0));
  body.setMassProps(0.0, btVector3(0, 0, 0));  // also sets CF_STATIC_OBJECT
  body.updateInertiaTensor();
  body.clearForces();
}

void BulletScene::makeKinematic(BodyHandle handle) {
  btRigidBody& body = impl_->rigid(handle);
  body.setLinearVelocity(btVector3(0, 0, 0));
  body.setAngularVelocity(btVector3(0, 0, 0));
  body.setMassProps(0.0, btVector3(0, 0, 0));
  body.updateInertiaTensor();
  body.clearForces();
  body.setCollisionFlags((body.getCollisionFlags() & ~btCollisionObject::CF_STATIC_OBJECT) |
                         btCollisionObject::CF_KINEMATIC_OBJECT);
  // Bullet computes a kinematic body's velocity from its motion each step,
  // and only while it is awake.
  body.forceActivationState(DISABLE_DEACTIVATION);
}

BodyDynamics BulletScene::dynamics(BodyHandle handle) const {
  const btRigidBody& body = impl_->rigid(handle);
  if (body.isKinematicObject()) return BodyDynamics::kKinematic;
  return body.isStaticObject() ? BodyDynamics::kStatic : BodyDynamics::kDynamic;
}

void BulletScene::wakeUp(BodyHandle handle) {
  btRigidBody& body = impl_->rigid(handle);
  body.forceActivationState(impl_->options.sleeping.enabled ? ACTIVE_TAG : DISABLE_DEACTIVATION);
  body.setDeactivationTime(0.0);
}

void BulletScene::activate(BodyHandle handle) { impl_->rigid(handle).activate(true); }
bool BulletScene::isActive(BodyHandle handle) const { return impl_->rigid(handle).isActive(); }

Eigen::Isometry3d BulletScene::pose(BodyHandle handle) const {
  const Impl::Body& body = impl_->body(handle);
  return impl_->fromBody(body, body.rigid->getWorldTransform());
}

Eigen::Vector3d BulletScene::centreOfMass(BodyHandle handle) const {
  return convertBtToEigen(impl_->rigid(handle).getCenterOfMassPosition());
}

Eigen::Vector3d BulletScene::linearVelocity(BodyHandle handle) const {
  return convertBtToEigen(impl_->rigid(handle).getLinearVelocity());
}

Eigen::Vector3d BulletScene::angularVelocity(BodyHandle handle) const {
  return convertBtToEigen(impl_->rigid(handle).getAngularVelocity());
}

double BulletScene::linearSpeed(BodyHandle handle) const {
  return impl_->rigid(handle).getLinearVelocity().length();
}

double BulletScene::angularSpeed(BodyHandle handle) const {
  return impl_->rigid(handle).getAngularVelocity().length();
}

std::vector<BodyHandle> BulletScene::inWorldNear(const Eigen::Vector3d& low,
                                                 const Eigen::Vector3d& high) const {
  struct Collector : btBroadphaseAabbCallback {
    std::vector<BodyHandle> found;
    bool process(const btBroadphaseProxy* proxy) override {
      const auto* object = static_cast<const btCollisionObject*>(proxy->m_clientObject);
      const int index = object->getUserIndex();
      if (index >= 0 && index != kTableUserIndex && index != kFloorUserIndex)
        found.push_back(static_cast<BodyHandle>(index));
      return true;
    }
  } collector;
  impl_->world->getBroadphase()->aabbTest(convertEigenToBt(low), convertEigenToBt(high), collector);
  std::sort(collector.found.begin(), collector.found.end());
  return collector.found;
}

void BulletScene::bounds(BodyHandle handle, Eigen::Vector3d* low, Eigen::Vector3d* high) const {
  btVector3 bt_low, bt_high;
  impl_->rigid(handle).getAabb(bt_low, bt_high);
  *low = convertBtToEigen(bt_low);
  *high = convertBtToEigen(bt_high);
}

void BulletScene::restoreAtRest(BodyHandle handle, const Eigen::Isometry3d& pose) {
  btRigidBody& body = impl_->rigid(handle);
  const btTransform transform = impl_->toBody(impl_->body(handle), pose);
  body.setWorldTransform(transform);
  body.setInterpolationWorldTransform(transform);
  body.setLinearVelocity(btVector3(0, 0, 0));
  body.setAngularVelocity(btVector3(0, 0, 0));
  body.clearForces();
}

void BulletScene::applyImpulse(BodyHandle handle, const Eigen::Vector3d& impulse,
                               const Eigen::Vector3d& point) {
  btRigidBody& body = impl_->rigid(handle);
  body.applyImpulse(convertEigenToBt(impulse),
                    convertEigenToBt(point) - body.getCenterOfMassPosition());
}

void BulletScene::setVelocity(BodyHandle handle, const Eigen::Vector3d& linear,
                              const Eigen::Vector3d& angular) {
  btRigidBody& body = impl_->rigid(handle);
  body.setLinearVelocity(convertEigenToBt(linear));
  body.setAngularVelocity(convertEigenToBt(angular));
}

void BulletScene::moveKinematic(BodyHandle handle, const Eigen::Isometry3d& pose) {
  // Bullet's saveKinematicState takes the velocity from the interpolation
  // transform (where it was) to the world transform (where it goes).
  impl_->rigid(handle).setWorldTransform(impl_->toBody(impl_->body(handle), pose));
}

void BulletScene::moveStatic(BodyHandle handle, const Eigen::Isometry3d& pose) {
  restoreAtRest(handle, pose);
  if (impl_->body(handle).in_world) impl_->world->updateBodyAabb(&impl_->rigid(handle));
}

bool BulletScene::closestPoints(BodyHandle a, const Eigen::Isometry3d& pose_a, BodyHandle b,
                                ClosestPoints* points) const {
  const btRigidBody* body_a = impl_->bodyOrTable(a);
  const btRigidBody* body_b = impl_->bodyOrTable(b);
  if (!body_a || !body_b) return false;
  SurfaceGap gap;
  if (!surfaceGapOfShapes(*body_a->getCollisionShape(), impl_->toBody(impl_->body(a), pose_a),
                          *body_b->getCollisionShape(), body_b->getWorldTransform(), &gap))
    return false;
  points->normal = convertBtToEigen(gap.normal);
  points->distance = gap.distance;
  points->on_b = convertBtToEigen(gap.on_b);
  return points->normal.allFinite();
}

bool BulletScene::firstContact(BodyHandle a, const Eigen::Isometry3d& from,
                               const Eigen::Isometry3d& to, BodyHandle b, double* fraction) const {
  const btRigidBody* body_a = impl_->bodyOrTable(a);
  const btRigidBody* body_b = impl_->bodyOrTable(b);
  if (!body_a || !body_b) return false;
  btScalar at = 1;
  SurfaceGap gap;
  const Impl::Body& moving = impl_->body(a);
  if (!timeOfImpactOfShapes(*body_a->getCollisionShape(), impl_->toBody(moving, from),
                            impl_->toBody(moving, to), *body_b->getCollisionShape(),
                            body_b->getWorldTransform(), kImpactTolerance, &at, &gap))
    return false;
  *fraction = at;
  return true;
}

void BulletScene::step(double dt) {
  impl_->world->resetStageSeconds();
  // maxSubSteps = 0: exactly one step of exactly dt, no interpolation.
  impl_->world->stepSimulation(dt, 0, dt);
}

BulletStageSeconds BulletScene::lastStepStageSeconds() const {
  return impl_->world->stageSeconds();
}

const btCollisionDispatcher& BulletScene::dispatcher() const { return *impl_->dispatcher; }

void BulletScene::passOverApartPairs(bool enabled) {
  impl_->dispatcher->watch(enabled ? impl_->world.get() : nullptr);
}

std::uint64_t BulletScene::apartPairsPassedOver() const { return impl_->dispatcher->passedOver(); }

}  // namespace brick_stack_sim
