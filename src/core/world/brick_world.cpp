#include "brick_stack_sim/core/world/brick_world.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <sstream>
#include <unordered_map>

#include <BulletCollision/BroadphaseCollision/btDbvt.h>
#include <BulletCollision/CollisionDispatch/btBoxBoxCollisionAlgorithm.h>
#include <BulletCollision/CollisionDispatch/btManifoldResult.h>

#include "brick_stack_sim/core/geometry/box_geometry.h"
#include "stability/com_stability_model.h"
#include "bullet/bullet_conversions.h"

namespace brick_stack_sim {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

constexpr const char* kTableId = "table";
constexpr const char* kWorldId = "world";
constexpr std::size_t kMaxIdLength = 128;
// Bullet's user index of the static bodies; bricks carry their serial.
constexpr int kTableUserIndex = -2;
constexpr int kFloorUserIndex = -3;

BodyHandle handleOf(const btCollisionObject* object) {
  const int index = object->getUserIndex();
  if (index == kTableUserIndex) return kTableHandle;
  if (index == kFloorUserIndex) return kFloorHandle;
  return static_cast<BodyHandle>(index);
}

/// Bullet multiplies the two friction coefficients of a pair, which turns pine
/// on pine (0.5 each) into 0.25. The geometric mean keeps a material's own
/// coefficient against itself and stays symmetric for mixed pairs.
btScalar combinedFriction(const btCollisionObject* a, const btCollisionObject* b) {
  return std::sqrt(a->getFriction() * b->getFriction());
}

bool validId(const std::string& id) {
  if (id.empty() || id.size() > kMaxIdLength) return false;
  if (!std::isalpha(static_cast<unsigned char>(id[0]))) return false;
  return std::all_of(id.begin(), id.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
  });
}

std::string formatVector(const Eigen::Vector3d& v) {
  std::ostringstream text;
  text.precision(6);
  text << "(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
  return text.str();
}

std::string millimetres(double metres) {
  std::ostringstream text;
  text.precision(3);
  text << metres * 1000.0 << " mm";
  return text.str();
}

}  // namespace

struct BrickRecord {
  std::string id;
  BrickType type;
  std::unique_ptr<btRigidBody> body;
  Eigen::Isometry3d placed_pose = Eigen::Isometry3d::Identity();
  double placed_at = 0.0;
  unsigned serial = 0;
  bool fell_off = false;
  bool frozen = false;  // taken out of Bullet's dynamics by the stability model
  // A frozen brick is in Bullet's world only while a moving brick is near it.
  bool in_bullet = false;
  btDbvtNode* frozen_leaf = nullptr;
  std::uint64_t needed_at_step = 0;
  // The last state known to be finite, restored if Bullet ever produces NaN.
  btTransform last_good_transform;
};

struct BrickWorld::Impl {
  WorldOptions options;
  BrickTypeLibrary types;

  // Declaration order is destruction order in reverse: the world goes first.
  std::unique_ptr<btDefaultCollisionConfiguration> collision_configuration;
  std::unique_ptr<btCollisionDispatcher> dispatcher;
  std::unique_ptr<btCollisionAlgorithmCreateFunc> box_box_algorithm;
  std::unique_ptr<btBroadphaseInterface> broadphase;
  std::unique_ptr<btSequentialImpulseConstraintSolver> solver;
  std::unique_ptr<btDiscreteDynamicsWorld> world;
  std::map<std::string, std::unique_ptr<btBoxShape>> shapes;  // one per brick type
  std::unique_ptr<btBoxShape> table_shape;
  std::unique_ptr<btStaticPlaneShape> floor_shape;
  std::unique_ptr<btRigidBody> table_body;
  std::unique_ptr<btRigidBody> floor_body;

  std::vector<std::unique_ptr<BrickRecord>> bricks;  // placement order
  std::unordered_map<std::string, BrickRecord*> by_id;
  std::unordered_map<BodyHandle, BrickRecord*> by_handle;
  // The bricks Bullet simulates, in placement order: a settled scene's frozen
  // bricks cost nothing per step, not even a look.
  std::vector<BrickRecord*> movers;
  // Every frozen brick by its box. Bullet loops over all its collision objects
  // every step (AABBs, islands), so a frozen brick is added to Bullet, as a
  // static collider, only while some moving brick could reach it.
  btDbvt frozen_tree;
  std::vector<BrickRecord*> frozen_in_bullet;
  std::unique_ptr<StabilityModel> model;  // null in mode none
  std::vector<PairContact> contacts;      // of the last Bullet step
  // The model has something new to look at without a Bullet step: a brick
  // placed, removed, frozen or woken.
  bool model_changed = false;
  unsigned next_serial = 0;
  CostCounters cost;
  std::vector<SimEvent> events;

  ~Impl() { destroyWorld(); }

  double time() const { return static_cast<double>(cost.steps) * options.time_step; }

  void buildWorld();
  void destroyWorld();
  btBoxShape* shapeFor(const BrickType& type);
  std::unique_ptr<btRigidBody> makeBrickBody(const BrickType& type, const BrickPlacement& p);
  std::string nextFreeId();
  void emit(SimEventKind kind, const std::string& id, std::string reason,
            std::vector<std::string> affected = {});
  std::vector<std::string> wakeTouching(const BrickRecord& brick);
  void checkAfterStep();
  BrickSnapshot snapshotOf(const BrickRecord& brick) const;
  std::string nameOf(BodyHandle handle) const;
  OrientedBox boxOf(BodyHandle handle) const;

  // Stability model plumbing.
  void readContacts();
  void runStabilityModel(bool bullet_stepped);
  void apply(const StabilityDecisions& decisions);
  void freezeBody(BrickRecord* brick);
  void addMover(BrickRecord* brick);
  void removeMover(BrickRecord* brick);
  void addToBullet(BrickRecord* brick);
  void removeFromBullet(BrickRecord* brick);
  void forgetFrozen(BrickRecord* brick);
  /// Frozen bricks whose boxes overlap `low`..`high`, in tree order.
  std::vector<BrickRecord*> frozenNear(const btVector3& low, const btVector3& high) const;
  /// Brings the frozen bricks that moving bricks may reach this step into
  /// Bullet, and sends back those no mover has come near for a while.
  void updateFrozenColliders();
  void wakeBody(BrickRecord* brick);
  std::string wakeReason(const WakeDecision& decision) const;
  /// Flush supports of a brick resting where it was just placed, from geometry.
  std::vector<PairContact> placementSupports(const BrickRecord& brick) const;
};

void BrickWorld::Impl::buildWorld() {
  collision_configuration = std::make_unique<btDefaultCollisionConfiguration>();
  dispatcher = std::make_unique<btCollisionDispatcher>(collision_configuration.get());
  // Bullet's default box-box path is GJK/EPA, which finds one contact point per
  // step and needs several steps to build a resting patch; a brick lying on
  // another wobbles meanwhile. The box-box clipper returns the whole face patch
  // (up to 4 points) in one step, which is what flat stacking needs.
  box_box_algorithm = std::make_unique<btBoxBoxCollisionAlgorithm::CreateFunc>();
  dispatcher->registerCollisionCreateFunc(BOX_SHAPE_PROXYTYPE, BOX_SHAPE_PROXYTYPE,
                                          box_box_algorithm.get());
  broadphase = std::make_unique<btDbvtBroadphase>();
  solver = std::make_unique<btSequentialImpulseConstraintSolver>();
  world = std::make_unique<btDiscreteDynamicsWorld>(dispatcher.get(), broadphase.get(),
                                                    solver.get(), collision_configuration.get());
  world->setGravity(btVector3(0, 0, -options.gravity));
  // Bodies at rest keep their AABB; recomputing every static brick's box each
  // step dominated the cost of large settled scenes.
  world->setForceUpdateAllAabbs(false);
  world->getDispatchInfo().m_deterministicOverlappingPairs = true;

  btContactSolverInfo& solver_info = world->getSolverInfo();
  solver_info.m_numIterations = options.solver_iterations;
  // Split impulse corrects penetration without feeding velocity back into the
  // stack. Bullet only splits below its threshold (-4 cm by default, five brick
  // thicknesses, so never at this scale); ours is scaled to the brick.
  solver_info.m_splitImpulse = 1;
  solver_info.m_splitImpulsePenetrationThreshold = options.split_impulse_penetration_threshold;
  solver_info.m_erp = options.erp;
  solver_info.m_erp2 = options.erp;
  // Never SOLVER_RANDMIZE_ORDER: the same inputs must give the same bits.
  solver_info.m_solverMode = SOLVER_USE_WARMSTARTING | SOLVER_SIMD;

  // Bullet keeps these two as globals; every world sets the same values.
  gCalculateCombinedFrictionCallback = &combinedFriction;
  gDeactivationTime = options.deactivation_time;

  const TableOptions& table = options.table;
  table_shape = std::make_unique<btBoxShape>(
      btVector3(table.size.x() / 2, table.size.y() / 2, table.thickness / 2));
  table_shape->setMargin(options.collision_margin);
  btRigidBody::btRigidBodyConstructionInfo table_info(0.0, nullptr, table_shape.get());
  table_info.m_startWorldTransform.setOrigin(btVector3(0, 0, -table.thickness / 2));
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

void BrickWorld::Impl::destroyWorld() {
  if (world) {
    for (auto& brick : bricks)
      if (brick->in_bullet) world->removeRigidBody(brick->body.get());
    if (table_body) world->removeRigidBody(table_body.get());
    if (floor_body) world->removeRigidBody(floor_body.get());
  }
  bricks.clear();
  by_id.clear();
  by_handle.clear();
  movers.clear();
  frozen_tree.clear();
  frozen_in_bullet.clear();
  contacts.clear();
  world.reset();
  solver.reset();
  broadphase.reset();
  dispatcher.reset();
  box_box_algorithm.reset();
  collision_configuration.reset();
  table_body.reset();
  floor_body.reset();
  table_shape.reset();
  floor_shape.reset();
  shapes.clear();
}

btBoxShape* BrickWorld::Impl::shapeFor(const BrickType& type) {
  std::unique_ptr<btBoxShape>& shape = shapes[type.name];
  if (!shape) {
    shape = std::make_unique<btBoxShape>(convertEigenToBt(type.halfExtents()));
    // btBoxShape keeps its outer size and puts the margin inside; Bullet's
    // 4 cm default would be clamped to 10 % of the half thickness anyway.
    shape->setMargin(std::min(options.collision_margin, 0.1 * type.halfExtents().minCoeff()));
  }
  return shape.get();
}

std::unique_ptr<btRigidBody> BrickWorld::Impl::makeBrickBody(const BrickType& type,
                                                             const BrickPlacement& p) {
  btRigidBody::btRigidBodyConstructionInfo info(type.mass, nullptr, shapeFor(type),
                                                convertEigenToBt(type.inertia));
  info.m_startWorldTransform = convertEigenToBt(p.pose);
  info.m_friction = type.friction;
  info.m_rollingFriction = type.rolling_friction;
  info.m_restitution = type.restitution;
  info.m_linearSleepingThreshold = options.linear_sleep_threshold;
  info.m_angularSleepingThreshold = options.angular_sleep_threshold;
  auto body = std::make_unique<btRigidBody>(info);
  body->setLinearVelocity(convertEigenToBt(p.linear_velocity));
  body->setAngularVelocity(convertEigenToBt(p.angular_velocity));
  // A brick moving more than its half thickness in one step could pass through
  // a thin neighbour; continuous collision catches that case only.
  const double thinnest_half = type.halfExtents().minCoeff();
  body->setCcdMotionThreshold(thinnest_half);
  body->setCcdSweptSphereRadius(0.5 * thinnest_half);
  if (!options.sleeping) body->setActivationState(DISABLE_DEACTIVATION);
  return body;
}

std::string BrickWorld::Impl::nextFreeId() {
  for (unsigned n = next_serial;; ++n) {
    std::string candidate = "brick_" + std::to_string(n);
    if (!by_id.count(candidate)) return candidate;
  }
}

void BrickWorld::Impl::emit(SimEventKind kind, const std::string& id, std::string reason,
                            std::vector<std::string> affected) {
  events.push_back(SimEvent{time(), kind, id, std::move(reason), std::move(affected)});
}

std::vector<std::string> BrickWorld::Impl::wakeTouching(const BrickRecord& brick) {
  // Anything whose bounding box comes within a millimetre may rest on or lean
  // against the brick; waking a few too many costs a few steps, missing one
  // would leave it floating.
  btVector3 low, high;
  brick.body->getAabb(low, high);
  const btVector3 reach(1e-3, 1e-3, 1e-3);
  low -= reach;
  high += reach;
  std::vector<std::string> woken;
  for (BrickRecord* other : movers) {  // the model wakes frozen ones
    if (other == &brick) continue;
    btVector3 other_low, other_high;
    other->body->getAabb(other_low, other_high);
    if (TestAabbAgainstAabb2(low, high, other_low, other_high)) {
      if (!other->body->isActive()) woken.push_back(other->id);
      other->body->activate(true);
    }
  }
  return woken;
}

void BrickWorld::Impl::checkAfterStep() {
  for (BrickRecord* brick : movers) {
    btRigidBody& body = *brick->body;
    if (!body.isActive()) continue;
    const btTransform& transform = body.getWorldTransform();
    const Eigen::Isometry3d pose = convertBtToEigen(transform);
    const Eigen::Vector3d velocity = convertBtToEigen(body.getLinearVelocity());
    const Eigen::Vector3d spin = convertBtToEigen(body.getAngularVelocity());
    const bool finite = pose.matrix().allFinite() && velocity.allFinite() && spin.allFinite();
    // Faster than any placement may throw a brick: the solver has diverged
    // (too long a step for the contacts), which ends in NaN if left alone.
    const bool runaway = finite && (velocity.norm() > options.max_linear_speed ||
                                    spin.norm() > options.max_angular_speed);
    if (!finite || runaway) {
      std::string reason = finite ? "numerical blow-up: " + std::to_string(velocity.norm()) +
                                        " m/s, " + std::to_string(spin.norm()) + " rad/s"
                                  : std::string("Bullet produced NaN/Inf");
      body.setWorldTransform(brick->last_good_transform);
      body.setInterpolationWorldTransform(brick->last_good_transform);
      body.setLinearVelocity(btVector3(0, 0, 0));
      body.setAngularVelocity(btVector3(0, 0, 0));
      body.clearForces();
      ++(finite ? cost.blowups : cost.nonfinite);
      emit(SimEventKind::kNonFinite, brick->id, reason + "; restored its last good pose at rest");
      continue;
    }
    brick->last_good_transform = transform;
    if (!brick->fell_off && pose.translation().z() < -options.fall_off_depth) {
      brick->fell_off = true;
      emit(SimEventKind::kFellOff, brick->id,
           "centre dropped below the table top at " + formatVector(pose.translation()));
    }
  }
}

BrickSnapshot BrickWorld::Impl::snapshotOf(const BrickRecord& brick) const {
  const btRigidBody& body = *brick.body;
  BrickSnapshot s;
  s.id = brick.id;
  s.type = brick.type.name;
  s.pose = convertBtToEigen(body.getWorldTransform());
  s.linear_velocity = convertBtToEigen(body.getLinearVelocity());
  s.angular_velocity = convertBtToEigen(body.getAngularVelocity());
  s.size = brick.type.size;
  s.mass = brick.type.mass;
  s.state = brick.frozen ? BrickState::kStable : BrickState::kDynamic;
  s.asleep = !brick.frozen && !body.isActive();
  s.fell_off = brick.fell_off;
  // Without a stability model a brick carries only itself.
  s.com_above = s.pose.translation();
  s.mass_above = s.mass;
  BrickStability stability;
  if (model && model->describe(brick.serial, &stability)) {
    s.com_above = stability.com_above;
    s.mass_above = stability.mass_above;
    s.margin = stability.margin;
    for (const SupportPatch& patch : stability.supports)
      s.supported_by.push_back(nameOf(patch.supporter));
  }
  s.placed_pose = brick.placed_pose;
  s.placed_at = brick.placed_at;
  s.serial = brick.serial;
  return s;
}

std::string BrickWorld::Impl::nameOf(BodyHandle handle) const {
  if (handle == kTableHandle) return kTableId;
  if (handle == kFloorHandle) return "floor";
  auto it = by_handle.find(handle);
  return it == by_handle.end() ? "brick#" + std::to_string(handle) : it->second->id;
}

OrientedBox BrickWorld::Impl::boxOf(BodyHandle handle) const {
  OrientedBox box;
  if (handle == kTableHandle) {
    box.half_extents = Eigen::Vector3d(options.table.size.x() / 2, options.table.size.y() / 2,
                                       options.table.thickness / 2);
    box.pose.translation().z() = -options.table.thickness / 2;
  } else if (handle == kFloorHandle) {
    // The floor plane as a slab far wider than anything that can land on it.
    box.half_extents = Eigen::Vector3d(1e3, 1e3, 0.5);
    box.pose.translation().z() = -options.table.height - 0.5;
  } else {
    const BrickRecord& brick = *by_handle.at(handle);
    box.pose = convertBtToEigen(brick.body->getWorldTransform());
    box.half_extents = brick.type.halfExtents();
  }
  return box;
}

void BrickWorld::Impl::readContacts() {
  contacts.clear();
  const int manifolds = dispatcher->getNumManifolds();
  for (int i = 0; i < manifolds; ++i) {
    const btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(i);
    if (manifold->getNumContacts() == 0) continue;
    const btRigidBody* a = btRigidBody::upcast(manifold->getBody0());
    const btRigidBody* b = btRigidBody::upcast(manifold->getBody1());
    PairContact pair;
    pair.a = handleOf(a);
    pair.b = handleOf(b);
    btVector3 normal_sum(0, 0, 0);
    for (int j = 0; j < manifold->getNumContacts(); ++j) {
      const btManifoldPoint& point = manifold->getContactPoint(j);
      if (point.getDistance() > options.stability.contact_distance) continue;
      const btVector3 position = 0.5 * (point.getPositionWorldOnA() + point.getPositionWorldOnB());
      const btVector3 relative =
          a->getVelocityInLocalPoint(position - a->getCenterOfMassPosition()) -
          b->getVelocityInLocalPoint(position - b->getCenterOfMassPosition());
      // The normal points from b to a: a negative relative speed along it closes the gap.
      pair.approach_speed = std::max(pair.approach_speed, -relative.dot(point.m_normalWorldOnB));
      pair.points.push_back(convertBtToEigen(position));
      normal_sum += point.m_normalWorldOnB;
    }
    if (pair.points.empty() || normal_sum.length2() == 0.0) continue;
    pair.normal = convertBtToEigen(normal_sum.normalized());
    if (std::abs(pair.normal.z()) >= std::cos(options.stability.support_normal_tolerance)) {
      const bool b_below = pair.normal.z() > 0.0;
      std::vector<Eigen::Vector3d> patch;
      if (flushContactPatch(boxOf(b_below ? pair.b : pair.a), boxOf(b_below ? pair.a : pair.b),
                            options.stability.flush_angle, options.stability.contact_distance,
                            &patch))
        pair.points = std::move(patch);
    }
    contacts.push_back(std::move(pair));
  }
}

void BrickWorld::Impl::runStabilityModel(bool bullet_stepped) {
  // Nothing moved and nothing is pending: the model would find what it found.
  if (!bullet_stepped && !model_changed) return;
  model_changed = false;
  // Only a brick at rest can join the stack: while every mover is faster than
  // the rest thresholds (a pile in the air), the contacts are not read at all.
  const StabilityOptions& thresholds = options.stability;
  const bool any_resting = std::any_of(movers.begin(), movers.end(), [&](const BrickRecord* b) {
    return b->body->getLinearVelocity().length() < thresholds.rest_linear_speed &&
           b->body->getAngularVelocity().length() < thresholds.rest_angular_speed;
  });
  if (bullet_stepped) {
    const Clock::time_point contacts_start = Clock::now();
    if (any_resting) {
      readContacts();
    } else {
      contacts.clear();
    }
    cost.contact_seconds += secondsSince(contacts_start);
  }
  const Clock::time_point model_start = Clock::now();
  std::vector<BodyMotion> motions;
  motions.reserve(movers.size());
  for (const BrickRecord* brick : movers) {
    const btRigidBody& body = *brick->body;
    motions.push_back(BodyMotion{brick->serial, convertBtToEigen(body.getCenterOfMassPosition()),
                                 brick->type.mass, convertBtToEigen(body.getLinearVelocity()),
                                 convertBtToEigen(body.getAngularVelocity())});
  }
  StabilityDecisions decisions;
  model->update(options.time_step, motions, contacts, &decisions);
  ++cost.stability_updates;
  apply(decisions);
  cost.stability_seconds += secondsSince(model_start);
}

void BrickWorld::Impl::addToBullet(BrickRecord* brick) {
  if (brick->in_bullet) return;
  world->addRigidBody(brick->body.get());
  brick->in_bullet = true;
  if (brick->frozen) frozen_in_bullet.push_back(brick);
}

void BrickWorld::Impl::removeFromBullet(BrickRecord* brick) {
  if (!brick->in_bullet) return;
  world->removeRigidBody(brick->body.get());
  brick->in_bullet = false;
  auto position = std::find(frozen_in_bullet.begin(), frozen_in_bullet.end(), brick);
  if (position != frozen_in_bullet.end()) frozen_in_bullet.erase(position);
}

void BrickWorld::Impl::forgetFrozen(BrickRecord* brick) {
  if (brick->frozen_leaf) frozen_tree.remove(brick->frozen_leaf);
  brick->frozen_leaf = nullptr;
}

void BrickWorld::Impl::freezeBody(BrickRecord* brick) {
  btRigidBody* body = brick->body.get();
  // Bullet keeps static and dynamic bodies in different broadphase groups,
  // chosen when a body is added: out, change, and back in only when needed.
  removeFromBullet(brick);
  body->setLinearVelocity(btVector3(0, 0, 0));
  body->setAngularVelocity(btVector3(0, 0, 0));
  body->setMassProps(0.0, btVector3(0, 0, 0));  // also sets CF_STATIC_OBJECT
  body->updateInertiaTensor();
  body->clearForces();
  brick->frozen = true;
  removeMover(brick);
  btVector3 low, high;
  body->getCollisionShape()->getAabb(body->getWorldTransform(), low, high);
  brick->frozen_leaf = frozen_tree.insert(btDbvtVolume::FromMM(low, high), brick);
}

std::vector<BrickRecord*> BrickWorld::Impl::frozenNear(const btVector3& low,
                                                       const btVector3& high) const {
  struct Collector : btDbvt::ICollide {
    std::vector<BrickRecord*> found;
    void Process(const btDbvtNode* leaf) override {
      found.push_back(static_cast<BrickRecord*>(leaf->data));
    }
  } collector;
  frozen_tree.collideTV(frozen_tree.m_root, btDbvtVolume::FromMM(low, high), collector);
  return collector.found;
}

void BrickWorld::Impl::updateFrozenColliders() {
  // How far a mover can get within this step. Its own speed is not enough:
  // gravity adds g dt during the step, and a collision inside the step can
  // hand it up to twice the speed of the fastest brick that may hit it. CCD
  // does not help against a body that is not in Bullet's world.
  double fastest = 0.0;
  for (const BrickRecord* mover : movers) {
    const btRigidBody& body = *mover->body;
    fastest =
        std::max(fastest, body.getLinearVelocity().length() + body.getAngularVelocity().length() *
                                                                  mover->type.halfExtents().norm());
  }
  const double dt = options.time_step;
  // Plus a millimetre, so that resting contacts stay in Bullet's manifolds.
  constexpr double kReach = 1e-3;
  const double travel = (2.0 * fastest + options.gravity * dt) * dt + kReach;
  const btVector3 reach(travel, travel, travel);
  for (const BrickRecord* mover : movers) {
    btVector3 low, high;
    mover->body->getAabb(low, high);
    std::vector<BrickRecord*> near = frozenNear(low - reach, high + reach);
    // Tree order depends on insertion history; Bullet's contact order on the
    // order bodies are added: placement order keeps that reproducible.
    std::sort(near.begin(), near.end(),
              [](const BrickRecord* a, const BrickRecord* b) { return a->serial < b->serial; });
    for (BrickRecord* frozen : near) {
      frozen->needed_at_step = cost.steps;
      addToBullet(frozen);
    }
  }
  // Sent back only after a while, so a brick rocking at a frozen brick's edge
  // does not cost a removal and an insertion every step.
  constexpr std::uint64_t kKeepSteps = 50;
  for (std::size_t i = frozen_in_bullet.size(); i-- > 0;) {
    BrickRecord* frozen = frozen_in_bullet[i];
    if (frozen->needed_at_step + kKeepSteps < cost.steps) removeFromBullet(frozen);
  }
}

void BrickWorld::Impl::addMover(BrickRecord* brick) {
  auto position = std::lower_bound(
      movers.begin(), movers.end(), brick,
      [](const BrickRecord* a, const BrickRecord* b) { return a->serial < b->serial; });
  movers.insert(position, brick);
}

void BrickWorld::Impl::removeMover(BrickRecord* brick) {
  auto position = std::find(movers.begin(), movers.end(), brick);
  if (position != movers.end()) movers.erase(position);
}

void BrickWorld::Impl::wakeBody(BrickRecord* brick) {
  btRigidBody* body = brick->body.get();
  removeFromBullet(brick);
  forgetFrozen(brick);
  brick->frozen = false;
  body->setMassProps(brick->type.mass, convertEigenToBt(brick->type.inertia));
  body->updateInertiaTensor();
  body->setLinearVelocity(btVector3(0, 0, 0));
  body->setAngularVelocity(btVector3(0, 0, 0));
  addToBullet(brick);
  body->forceActivationState(options.sleeping ? ACTIVE_TAG : DISABLE_DEACTIVATION);
  body->setDeactivationTime(0.0);
  brick->last_good_transform = body->getWorldTransform();
  addMover(brick);
}

std::vector<PairContact> BrickWorld::Impl::placementSupports(const BrickRecord& brick) const {
  const OrientedBox box = boxOf(brick.serial);
  std::vector<PairContact> supports;
  auto try_support = [&](BodyHandle lower) {
    const OrientedBox lower_box = boxOf(lower);
    const double gap = separation(lower_box, box);
    // Touching, not sunk in: an overlap the placement check let through is
    // Bullet's to resolve before the brick can rest.
    if (std::abs(gap) > options.stability.contact_distance) return;
    PairContact contact;
    contact.a = brick.serial;
    contact.b = lower;
    if (flushContactPatch(lower_box, box, options.stability.flush_angle,
                          options.stability.contact_distance, &contact.points))
      supports.push_back(std::move(contact));
  };
  try_support(kTableHandle);
  btVector3 low, high;
  brick.body->getCollisionShape()->getAabb(brick.body->getWorldTransform(), low, high);
  const btVector3 reach(options.stability.contact_distance, options.stability.contact_distance,
                        options.stability.contact_distance);
  std::vector<BrickRecord*> near = frozenNear(low - reach, high + reach);
  // Tree order depends on insertion history; placement order keeps supports deterministic.
  std::sort(near.begin(), near.end(),
            [](const BrickRecord* a, const BrickRecord* b) { return a->serial < b->serial; });
  for (const BrickRecord* other : near) try_support(other->serial);
  return supports;
}

std::string BrickWorld::Impl::wakeReason(const WakeDecision& d) const {
  switch (d.cause) {
    case WakeCause::kOutsideSupport:
      return "COM-above left its support: margin " + millimetres(d.margin);
    case WakeCause::kCarried:
      return "carried by " + nameOf(d.because_of) + ", which was woken";
    case WakeCause::kSupporterRemoved:
      return "its supporter " + nameOf(d.because_of) + " was removed";
    case WakeCause::kPushed:
      return "pushed";
    case WakeCause::kSupportCycle:
      return "its supports form a cycle";
  }
  return "woken";
}

void BrickWorld::Impl::apply(const StabilityDecisions& decisions) {
  if (decisions.empty()) return;
  // Contacts read before bodies changed hands would name bricks that moved
  // in or out of Bullet's world; the next Bullet step reads them afresh.
  contacts.clear();
  model_changed = true;
  for (const FreezeDecision& d : decisions.freeze) {
    auto it = by_handle.find(d.brick);
    if (it == by_handle.end()) continue;
    freezeBody(it->second);
    std::string on;
    for (BodyHandle supporter : d.supporters) on += (on.empty() ? "" : ", ") + nameOf(supporter);
    emit(SimEventKind::kFrozen, it->second->id,
         "rests stably on " + on + " (margin " + millimetres(d.margin) + ")");
  }
  for (const WakeDecision& d : decisions.wake) {
    auto it = by_handle.find(d.brick);
    if (it == by_handle.end()) continue;
    wakeBody(it->second);
    emit(SimEventKind::kWoken, it->second->id, wakeReason(d));
  }
}

// ---------------------------------------------------------------------------

BrickWorld::BrickWorld(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
BrickWorld::~BrickWorld() = default;

Status BrickWorld::create(const WorldOptions& options, const BrickTypeLibrary& types,
                          std::unique_ptr<BrickWorld>* world) {
  world->reset();
  if (Status valid = validate(options); !valid) return valid;
  if (types.empty()) return Status::error("no brick types: a world needs at least one");
  for (const std::string& name : types.names()) {
    if (Status valid = validateBrickType(*types.find(name)); !valid) return valid;
  }
  auto impl = std::make_unique<Impl>();
  impl->options = options;
  impl->types = types;
  impl->buildWorld();
  if (options.mode == StabilityMode::kCom)
    impl->model = std::make_unique<ComStabilityModel>(options.stability);
  world->reset(new BrickWorld(std::move(impl)));
  return Status::success();
}

Status BrickWorld::checkPlacement(const BrickPlacement& p) const {
  const Impl& w = *impl_;
  if (!p.id.empty()) {
    if (!validId(p.id))
      return Status::error("id '" + p.id +
                           "' is not valid: use a letter then letters, digits, '_' or '-' "
                           "(at most 128 characters)");
    if (p.id == kTableId || p.id == kWorldId) return Status::error("id '" + p.id + "' is reserved");
    if (w.by_id.count(p.id)) return Status::error("id '" + p.id + "' is already in use");
  }
  const std::string type_name = p.type.empty() ? w.types.defaultType() : p.type;
  const BrickType* type = w.types.find(type_name);
  if (!type) {
    std::string known;
    for (const std::string& name : w.types.names()) known += (known.empty() ? "" : ", ") + name;
    return Status::error("unknown brick type '" + type_name + "' (known: " + known + ")");
  }
  if (!p.pose.translation().allFinite())
    return Status::error("position is not finite: " + formatVector(p.pose.translation()));
  if (!isRotation(p.pose.linear()))
    return Status::error("orientation is not a proper rotation (NaN, Inf or not orthonormal)");
  if (!p.linear_velocity.allFinite() || !p.angular_velocity.allFinite())
    return Status::error("velocity is not finite");
  if (p.linear_velocity.norm() > w.options.max_linear_speed)
    return Status::error("linear speed " + std::to_string(p.linear_velocity.norm()) +
                         " m/s exceeds the limit of " + std::to_string(w.options.max_linear_speed));
  if (p.angular_velocity.norm() > w.options.max_angular_speed)
    return Status::error("angular speed " + std::to_string(p.angular_velocity.norm()) +
                         " rad/s exceeds the limit of " +
                         std::to_string(w.options.max_angular_speed));

  const OrientedBox box{p.pose, type->halfExtents()};
  Eigen::Vector3d low = box.pose.translation(), high = low;
  for (const Eigen::Vector3d& corner : corners(box)) {
    low = low.cwiseMin(corner);
    high = high.cwiseMax(corner);
  }
  if (low.z() < -w.options.overlap_tolerance)
    return Status::error("pose puts the brick " + millimetres(-low.z()) +
                         " below the table top (z = 0)");
  // Candidates: every moving brick, and the frozen ones whose boxes come near.
  std::vector<const BrickRecord*> candidates(w.movers.begin(), w.movers.end());
  for (const BrickRecord* frozen :
       w.frozenNear(convertEigenToBt(low) - btVector3(1e-3, 1e-3, 1e-3),
                    convertEigenToBt(high) + btVector3(1e-3, 1e-3, 1e-3)))
    candidates.push_back(frozen);
  std::sort(candidates.begin(), candidates.end(),
            [](const BrickRecord* a, const BrickRecord* b) { return a->serial < b->serial; });
  for (const BrickRecord* other : candidates) {
    const OrientedBox other_box{convertBtToEigen(other->body->getWorldTransform()),
                                other->type.halfExtents()};
    const double gap = separation(box, other_box);
    if (gap < -w.options.overlap_tolerance)
      return Status::error("pose overlaps brick '" + other->id + "' by " + millimetres(-gap));
  }
  return Status::success();
}

Status BrickWorld::addBrick(const BrickPlacement& placement, std::string* assigned_id) {
  if (Status ok = checkPlacement(placement); !ok) return ok;
  Impl& w = *impl_;
  auto brick = std::make_unique<BrickRecord>();
  brick->id = placement.id.empty() ? w.nextFreeId() : placement.id;
  brick->type = *w.types.find(placement.type.empty() ? w.types.defaultType() : placement.type);
  brick->body = w.makeBrickBody(brick->type, placement);
  brick->placed_pose = placement.pose;
  brick->placed_at = w.time();
  brick->serial = w.next_serial++;
  brick->last_good_transform = brick->body->getWorldTransform();
  brick->body->setUserIndex(static_cast<int>(brick->serial));
  w.addToBullet(brick.get());
  w.by_id[brick->id] = brick.get();
  w.by_handle[brick->serial] = brick.get();
  w.emit(SimEventKind::kSpawned, brick->id,
         "placed as '" + brick->type.name + "' at " + formatVector(placement.pose.translation()));
  if (assigned_id) *assigned_id = brick->id;
  BrickRecord* record = brick.get();
  w.bricks.push_back(std::move(brick));
  w.model_changed = true;
  w.movers.push_back(record);  // the newest serial: the end keeps the order
  if (w.model && placement.linear_velocity.isZero() && placement.angular_velocity.isZero()) {
    StabilityDecisions decisions;
    w.model->placedAtRest(
        BodyMotion{record->serial, placement.pose.translation(), record->type.mass,
                   Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()},
        w.placementSupports(*record), &decisions);
    w.apply(decisions);
  }
  return Status::success();
}

Status BrickWorld::removeBrick(const std::string& id) {
  Impl& w = *impl_;
  auto found = w.by_id.find(id);
  if (found == w.by_id.end()) return Status::error("no brick with id '" + id + "'");
  BrickRecord* brick = found->second;
  std::vector<std::string> woken;
  if (w.model) {
    StabilityDecisions decisions;
    w.model->remove(brick->serial, &decisions);
    w.apply(decisions);
    for (const WakeDecision& d : decisions.wake) woken.push_back(w.nameOf(d.brick));
  }
  for (std::string& touching : w.wakeTouching(*brick))
    if (std::find(woken.begin(), woken.end(), touching) == woken.end())
      woken.push_back(std::move(touching));
  w.removeFromBullet(brick);
  w.forgetFrozen(brick);
  w.removeMover(brick);
  w.contacts.clear();
  w.model_changed = true;
  w.by_id.erase(found);
  w.by_handle.erase(brick->serial);
  w.bricks.erase(std::find_if(w.bricks.begin(), w.bricks.end(),
                              [brick](const auto& entry) { return entry.get() == brick; }));
  w.emit(SimEventKind::kRemoved, id, "removed by request", std::move(woken));
  return Status::success();
}

Status BrickWorld::applyImpulse(const std::string& id, const Eigen::Vector3d& impulse,
                                const Eigen::Vector3d& point) {
  Impl& w = *impl_;
  auto found = w.by_id.find(id);
  if (found == w.by_id.end()) return Status::error("no brick with id '" + id + "'");
  if (!impulse.allFinite()) return Status::error("impulse is not finite");
  if (!point.allFinite()) return Status::error("point of application is not finite");
  btRigidBody& body = *found->second->body;
  const BrickType& type = found->second->type;
  // The speeds the push leaves the brick with, before Bullet sees it: a push
  // that would launch it past the placement limits is refused, not repaired.
  const Eigen::Vector3d lever = point - convertBtToEigen(body.getCenterOfMassPosition());
  const Eigen::Matrix3d rotation = convertBtToEigen(body.getWorldTransform()).linear();
  const Eigen::Matrix3d inverse_inertia =
      rotation * type.inertia.cwiseInverse().asDiagonal() * rotation.transpose();
  const bool frozen = found->second->frozen;
  const Eigen::Vector3d velocity =
      (frozen ? Eigen::Vector3d::Zero() : convertBtToEigen(body.getLinearVelocity())) +
      impulse / type.mass;
  const Eigen::Vector3d spin =
      (frozen ? Eigen::Vector3d::Zero() : convertBtToEigen(body.getAngularVelocity())) +
      inverse_inertia * lever.cross(impulse);
  if (velocity.norm() > w.options.max_linear_speed)
    return Status::error("impulse would leave the brick at " + std::to_string(velocity.norm()) +
                         " m/s, over the limit of " + std::to_string(w.options.max_linear_speed));
  if (spin.norm() > w.options.max_angular_speed)
    return Status::error("impulse would leave the brick spinning at " +
                         std::to_string(spin.norm()) + " rad/s, over the limit of " +
                         std::to_string(w.options.max_angular_speed));
  if (found->second->frozen) {
    StabilityDecisions decisions;
    w.model->wake(found->second->serial, WakeCause::kPushed, &decisions);
    w.apply(decisions);
  }
  body.activate(true);
  body.applyImpulse(convertEigenToBt(impulse),
                    convertEigenToBt(point) - body.getCenterOfMassPosition());
  return Status::success();
}

void BrickWorld::clear() {
  Impl& w = *impl_;
  // Removed in placement order so that observers see a deterministic sequence.
  for (const auto& brick : w.bricks) w.emit(SimEventKind::kRemoved, brick->id, "scene reset");
  // A fresh Bullet world: no pair cache or warm-starting data survives a reset,
  // so a scene loaded after a reset runs exactly as in a new world.
  w.destroyWorld();
  w.buildWorld();
  if (w.model) w.model->clear();
  w.next_serial = 0;
}

void BrickWorld::step() {
  Impl& w = *impl_;
  std::uint64_t awake = 0;
  for (const BrickRecord* brick : w.movers) awake += brick->body->isActive() ? 1 : 0;
  ++w.cost.steps;
  // Plain Bullet (mode none) is the baseline and always steps; with a stability
  // model, a world where nothing is awake has nothing for Bullet to do.
  const bool step_bullet = !w.model || awake > 0;
  if (step_bullet) {
    const Clock::time_point bullet_start = Clock::now();
    if (w.model) w.updateFrozenColliders();
    // maxSubSteps = 0: exactly one step of exactly time_step, no interpolation.
    w.world->stepSimulation(w.options.time_step, 0, w.options.time_step);
    ++w.cost.bullet_steps;
    w.cost.awake_brick_steps += awake;
    w.checkAfterStep();
    w.cost.bullet_seconds += secondsSince(bullet_start);
  }
  if (w.model) w.runStabilityModel(step_bullet);
}

double BrickWorld::time() const { return impl_->time(); }
const WorldOptions& BrickWorld::options() const { return impl_->options; }
const BrickTypeLibrary& BrickWorld::types() const { return impl_->types; }
const CostCounters& BrickWorld::cost() const { return impl_->cost; }
std::size_t BrickWorld::brickCount() const { return impl_->bricks.size(); }

std::vector<BrickSnapshot> BrickWorld::snapshot() const {
  std::vector<BrickSnapshot> result;
  result.reserve(impl_->bricks.size());
  for (const auto& brick : impl_->bricks) result.push_back(impl_->snapshotOf(*brick));
  return result;
}

bool BrickWorld::find(const std::string& id, BrickSnapshot* brick) const {
  auto found = impl_->by_id.find(id);
  if (found == impl_->by_id.end()) return false;
  if (brick) *brick = impl_->snapshotOf(*found->second);
  return true;
}

bool BrickWorld::supportGeometry(const std::string& id, SupportGeometry* geometry) const {
  auto found = impl_->by_id.find(id);
  BrickStability stability;
  if (found == impl_->by_id.end() || !impl_->model ||
      !impl_->model->describe(found->second->serial, &stability))
    return false;
  SupportGeometry result;
  for (const SupportPatch& patch : stability.supports) {
    SupportGeometry::Patch out;
    out.supporter = impl_->nameOf(patch.supporter);
    for (const Eigen::Vector2d& corner : patch.hull)
      out.polygon.emplace_back(corner.x(), corner.y(), patch.height);
    result.patches.push_back(std::move(out));
  }
  for (const Eigen::Vector2d& corner : stability.combined_hull)
    result.combined_hull.emplace_back(corner.x(), corner.y(), stability.support_height);
  result.com_above = stability.com_above;
  result.margin = stability.margin;
  *geometry = std::move(result);
  return true;
}

std::vector<SimEvent> BrickWorld::takeEvents() {
  std::vector<SimEvent> events;
  events.swap(impl_->events);
  return events;
}

}  // namespace brick_stack_sim
