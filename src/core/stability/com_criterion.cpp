#include "stability/com_criterion.h"

#include <algorithm>
#include <cmath>

#include "stability/statics_assembly.h"
#include "stability/support_evaluation.h"
#include "util/text_format.h"

namespace brick_stack_sim {

namespace {

/// The unit every load passed between bricks is measured in [m/s^2]
/// (LoadShare holds masses, PointForce newtons; statics, the same g).
const double kGravity = StaticsOptions().gravity;

/// A frozen brick is judged with the loads measured on it from bodies the
/// stack does not hold taken this much smaller [-]: the engine measures a
/// steady load within a fraction of a percent, and a structure that statics
/// holds within that noise of its limit must not wake, freeze again where
/// it is and wake at the next jitter. A load that tips what it rests on
/// (a brick tipping off it, a hand pressing) is far past it.
constexpr double kMeasuredLoadFactor = 0.98;

/// The resultant of a brick's vertical load (`mass` acting through
/// `centre`) and `pushes`, where its line of action crosses the plane
/// z = `height`.
struct Resultant {
  Eigen::Vector2d point = Eigen::Vector2d::Zero();     ///< [m]
  double mass = 0.0;                                   ///< Its vertical part, as a mass [kg].
  Eigen::Vector2d sideways = Eigen::Vector2d::Zero();  ///< [N]
};

/// False when the resultant does not press the brick down on its supports.
bool resultantOnPlane(double mass, const Eigen::Vector2d& centre,
                      const std::vector<PointForce>& pushes, double height, Resultant* out) {
  Eigen::Vector3d force(0.0, 0.0, -mass * kGravity);
  Eigen::Vector3d moment = Eigen::Vector3d(centre.x(), centre.y(), 0.0).cross(force);
  for (const PointForce& push : pushes) {
    force += push.force;
    moment += push.point.cross(push.force);
  }
  if (!(force.z() < 0.0)) return false;
  // The point q on the plane with q x force = moment (the torque along the
  // force, a twist about the vertical, is not a tipping question).
  out->point =
      Eigen::Vector2d(height * force.x() - moment.y(), moment.x() + height * force.y()) / force.z();
  out->mass = -force.z() / kGravity;
  out->sideways = force.head<2>();
  return true;
}

double leastFriction(const std::vector<SupportPatch>& patches) {
  double friction = patches.empty() ? 0.0 : patches.front().friction;
  for (const SupportPatch& patch : patches) friction = std::min(friction, patch.friction);
  return friction;
}

// ComCriterion::passLoadDown's steps, in the order it takes them.

/// COM-above before any push, into `com_above`: the centre of a brick's
/// own mass and the shares it receives, each share where it acts and at
/// the height of what passed it down. Returns that total mass [kg].
double massAbove(const SupportGraph::Node& node, Eigen::Vector3d* com_above) {
  double mass = node.mass;
  Eigen::Vector3d moment = node.mass * node.com;
  for (const LoadShare& load : node.received) {
    mass += load.mass;
    moment += load.mass * Eigen::Vector3d(load.point.x(), load.point.y(), load.height);
  }
  *com_above = moment / mass;
  return mass;
}

/// Leaning bricks, movers and held bricks push the brick: the resultant
/// crosses its support plane where it would tip about, and its sideways
/// part must stay in friction. Moves `com_above` and `mass` to the
/// resultant and judges the support there again; a sideways part beyond
/// friction wakes it (`stays` false) and is cut to what friction passes on.
/// False, and it wakes, when the pushes lift it.
bool resolvePushes(BodyHandle handle, SupportGraph::Node* node, double* mass,
                   Eigen::Vector3d* com_above, Resultant* resultant, bool* stays,
                   std::vector<WakeDecision>* unstable) {
  if (!resultantOnPlane(*mass, com_above->head<2>(), node->pushes, node->stability.support_height,
                        resultant)) {
    unstable->push_back(WakeDecision{handle, WakeCause::kOutsideSupport, handle, 0.0,
                                     "what presses on it lifts it"});
    return false;
  }
  com_above->head<2>() = resultant->point;
  node->stability.mass_above = *mass = resultant->mass;
  evaluateSupport(*com_above, &node->stability);
  const double holds = leastFriction(node->supports) * *mass * kGravity;
  if (resultant->sideways.norm() > holds) {
    unstable->push_back(WakeDecision{
        handle, WakeCause::kOutsideSupport, handle, node->stability.margin,
        "what presses on it pushes it sideways with " + newtons(resultant->sideways.norm()) +
            ", more than friction holds (" + newtons(holds) + ")"});
    *stays = false;
    resultant->sideways *= holds / resultant->sideways.norm();  // all friction passes on
  }
  return true;
}

/// Each frozen supporter of `node` receives its share of the brick's
/// `mass`, at `height` (the table carries anything), and, in proportion,
/// the `sideways` part of its load, which friction at the interface carries.
void passSharesDown(SupportGraph* graph, BodyHandle handle, const SupportGraph::Node& node,
                    double mass, double height, const Eigen::Vector2d& sideways,
                    std::vector<LoadShare>* shares) {
  for (std::size_t i = 0; i < node.supports.size(); ++i) {
    SupportGraph::Node* below = graph->find(node.supports[i].supporter);
    if (!below) continue;  // the table carries anything
    LoadShare& share = (*shares)[i];
    share.height = height;
    below->received.push_back(share);
    below->received_from.push_back(handle);
    // Friction at the interface carries the sideways part, in proportion.
    if (!sideways.isZero())
      below->pushes.push_back(
          PointForce{Eigen::Vector3d(sideways.x(), sideways.y(), 0.0) * (share.mass / mass),
                     Eigen::Vector3d(share.point.x(), share.point.y(), node.supports[i].height)});
  }
}

}  // namespace

ComCriterion::ComCriterion(const StabilityOptions& options, BodyNamer name_of)
    : options_(options), name_of_(std::move(name_of)) {}

void ComCriterion::evaluate(const BodyMotion& brick, BrickStability* stability) const {
  evaluateSupport(brick.com, stability);
  if (stability->external_loads.empty() || stability->supports.empty()) return;
  // What presses on it from outside the stack moves its COM-above to where
  // the resultant crosses its support plane.
  Resultant resultant;
  if (!resultantOnPlane(brick.mass, brick.com.head<2>(), stability->external_loads,
                        stability->support_height, &resultant))
    return;  // lifted: admits() says no
  const Eigen::Vector3d point(resultant.point.x(), resultant.point.y(), brick.com.z());
  evaluateSupport(point, stability);
  stability->mass_above = resultant.mass;
}

bool ComCriterion::loadsHold(const BodyMotion& brick, const BrickStability& stability) const {
  if (stability.external_loads.empty()) return true;
  Resultant resultant;
  if (!resultantOnPlane(brick.mass, brick.com.head<2>(), stability.external_loads,
                        stability.support_height, &resultant))
    return false;
  return resultant.sideways.norm() <= leastFriction(stability.supports) * resultant.mass * kGravity;
}

bool ComCriterion::inclined(const BrickStability& stability) const {
  // A vertical force on a support whose normal leans by t from vertical
  // needs friction tan t; the statics LP's pyramid holds cos(pi / faces) of
  // the cone in every direction.
  const double held = std::cos(M_PI / StaticsOptions().friction_faces);
  for (const SupportPatch& patch : stability.supports) {
    for (const Eigen::Vector3d& normal : patch.normals) {
      const double sideways = normal.head<2>().norm();
      if (sideways > held * patch.friction * normal.z()) return true;
    }
  }
  return false;
}

bool ComCriterion::stands(const std::vector<BodyMotion>& bricks,
                          const std::vector<const BrickStability*>& stability) const {
  const StaticsSolution solution = solveFree(bricks, stability);
  return solution.solved && solution.feasible;
}

StaticsSolution ComCriterion::solveFree(const std::vector<BodyMotion>& bricks,
                                        const std::vector<const BrickStability*>& stability,
                                        StaticsBasis* basis) const {
  StaticsAssembly assembly(options_);
  for (const BodyMotion& brick : bricks) assembly.addFree(brick.handle, brick.mass, brick.com);
  for (std::size_t i = 0; i < bricks.size(); ++i) {
    assembly.addPatches(static_cast<int>(i), stability[i]->supports);
    assembly.addPatches(static_cast<int>(i), stability[i]->side_contacts);
    for (const PointForce& load : stability[i]->external_loads)
      assembly.addLoad(static_cast<int>(i), load);
  }
  return basis ? assembly.solve(basis) : memo_.solve(assembly);
}

FreezeDecision ComCriterion::admittedByStatics(const BodyMotion& brick,
                                               const BrickStability& stability) const {
  FreezeDecision decision;
  decision.brick = brick.handle;
  decision.kind = leans(stability, options_) ? BrickState::kLeaning : BrickState::kStable;
  decision.margin = stability.margin;
  decision.supporters = supportersOf(stability);
  std::string names;
  for (BodyHandle supporter : decision.supporters)
    names += (names.empty() ? "" : ", ") + name_of_(supporter);
  decision.reason = std::string(decision.kind == BrickState::kLeaning ? "leans on " : "rests on ") +
                    names + ": contact forces within friction balance it (statics)";
  return decision;
}

bool ComCriterion::admits(const BodyMotion& brick, const BrickStability& stability,
                          FreezeDecision* decision) const {
  // On supports steeper than friction holds a vertical load on, the COM
  // rule cannot tell a brick that rests from one that slides: statics can.
  if (!stability.supports.empty() && stability.margin > options_.min_margin &&
      loadsHold(brick, stability) && (!inclined(stability) || stands({brick}, {&stability}))) {
    *decision = FreezeDecision{brick.handle, BrickState::kStable, stability.margin, {}, ""};
    std::string on;
    for (const SupportPatch& patch : stability.supports) {
      decision->supporters.push_back(patch.supporter);
      on += (on.empty() ? "" : ", ") + name_of_(patch.supporter);
    }
    decision->reason = "rests stably on " + on + " (margin " + millimetres(stability.margin) + ")";
    return true;
  }
  // Without anything to lean on, the LP of one brick on fixed supporters
  // says no more than the COM rule.
  if (!leans(stability, options_) || !stands({brick}, {&stability})) return false;
  *decision = admittedByStatics(brick, stability);
  return true;
}

bool ComCriterion::admitsGroup(const std::vector<BodyMotion>& group,
                               const std::vector<BrickStability>& stability,
                               std::vector<FreezeDecision>* decisions,
                               std::vector<BodyHandle>* cannot_stay) const {
  std::vector<const BrickStability*> members;
  for (const BrickStability& s : stability) members.push_back(&s);
  const StaticsSolution solution = solveFree(group, members, &group_basis_);
  if (!solution.solved) return false;
  if (!solution.feasible) {
    // The collapse mechanism the LP's dual names. (Taking out only the
    // bricks left unbalanced where it moves them all freed nothing more on
    // a pile, and cost an LP of the whole group per round.)
    if (cannot_stay)
      for (std::size_t i = 0; i < group.size(); ++i)
        if (solution.moves[i]) cannot_stay->push_back(group[i].handle);
    return false;
  }
  decisions->clear();
  for (std::size_t i = 0; i < group.size(); ++i) {
    decisions->push_back(admittedByStatics(group[i], stability[i]));
    decisions->back().reason +=
        ", with " + std::to_string(group.size() - 1) + " brick(s) placed with it";
  }
  return true;
}

WakeDecision ComCriterion::outsideSupport(BodyHandle brick, double margin) const {
  return WakeDecision{brick, WakeCause::kOutsideSupport, brick, margin,
                      "COM-above left its support: margin " + millimetres(margin)};
}

bool ComCriterion::passLoadDown(SupportGraph* graph, BodyHandle handle,
                                std::vector<LoadShare>* shares,
                                std::vector<WakeDecision>* unstable) const {
  SupportGraph::Node& node = *graph->find(handle);
  // COM-above: the resultant of its own weight and the loads it receives,
  // each where it acts, at the height of the centre of mass of it and all
  // it carries (each share at the height of what passed it down).
  Eigen::Vector3d com_above;
  double mass = massAbove(node, &com_above);
  node.stability.frozen = true;
  node.stability.mass_above = mass;
  node.stability.supports = node.supports;
  evaluateSupport(com_above, &node.stability);
  bool stays = true;
  Resultant resultant;
  resultant.mass = mass;
  if (!node.pushes.empty() &&
      !resolvePushes(handle, &node, &mass, &com_above, &resultant, &stays, unstable))
    return false;
  node.supports = node.stability.supports;  // keep the hulls
  Eigen::Vector2d acts_at = com_above.head<2>();
  if (stays && node.stability.margin <= options_.min_margin) {
    unstable->push_back(outsideSupport(handle, node.stability.margin));
    stays = false;
  }
  // A brick that cannot stay starts to tip about the edge of its support,
  // still pressing with its load there: what carries it must bear that too,
  // so that a stack that fails as a whole wakes as a whole.
  if (!stays) acts_at = nearestPoint(node.stability.combined_hull, acts_at);
  std::vector<Polygon2d> patches;
  for (const SupportPatch& patch : node.supports) patches.push_back(patch.hull);
  if (distributeLoad(mass, acts_at, patches, shares) == LoadSplitRule::kUnsupported) {
    if (stays) unstable->push_back(outsideSupport(handle, node.stability.margin));
    return false;
  }
  passSharesDown(graph, handle, node, mass, com_above.z(), resultant.sideways, shares);
  return stays;
}

void ComCriterion::balanceLeaning(SupportGraph* graph, const std::vector<BodyHandle>& group,
                                  std::vector<WakeDecision>* unstable) const {
  StaticsAssembly assembly(options_);
  for (BodyHandle handle : group) {
    SupportGraph::Node& node = *graph->find(handle);
    const int body = assembly.addFree(handle, node.mass, node.com);
    double mass = node.mass;
    for (const LoadShare& load : node.received) {
      assembly.addLoad(body, PointForce{Eigen::Vector3d(0.0, 0.0, -load.mass * kGravity),
                                        Eigen::Vector3d(load.point.x(), load.point.y(), 0.0)});
      mass += load.mass;
    }
    for (const PointForce& push : node.pushes) assembly.addLoad(body, push);
    node.stability.frozen = true;
    node.stability.mass_above = mass;
    node.stability.supports = node.supports;
    evaluateSupport(node.com, &node.stability);
    node.supports = node.stability.supports;
  }
  // A member that is not leaning (a level brick on a V) passes its load
  // down its supports only, as everywhere else.
  for (std::size_t i = 0; i < group.size(); ++i) {
    const SupportGraph::Node& node = *graph->find(group[i]);
    assembly.addPatches(static_cast<int>(i), node.supports);
    if (node.leaning) assembly.addPatches(static_cast<int>(i), node.side_contacts);
  }
  const StaticsSolution solution = memo_.solve(assembly);
  if (!solution.solved) {
    // Never keep a leaning brick frozen on no answer: Bullet will tell.
    for (BodyHandle handle : group)
      unstable->push_back(WakeDecision{handle, WakeCause::kOutsideSupport, handle, 0.0,
                                       "statics could not be solved: " + solution.message});
    return;
  }
  bool balanced = true;
  for (std::size_t i = 0; i < group.size(); ++i) {
    if (solution.imbalance[i] <= 0.0) continue;
    balanced = false;
    unstable->push_back(WakeDecision{
        group[i], WakeCause::kOutsideSupport, group[i], graph->find(group[i])->stability.margin,
        "no contact forces within friction balance it (statics: " + percent(solution.imbalance[i]) +
            " of a brick's weight unbalanced)"});
  }
  if (!balanced) return;
  std::vector<std::vector<ContactForce>> forces = assembly.contactForces(solution);
  for (std::size_t i = 0; i < group.size(); ++i)
    graph->find(group[i])->stability.contact_forces = std::move(forces[i]);
  for (std::size_t c = 0; c < assembly.contacts().size(); ++c) {
    const BodyHandle other = assembly.otherOf(c);
    if (assembly.isFree(other)) continue;
    if (SupportGraph::Node* pushed = graph->find(other))
      pushed->pushes.push_back(PointForce{-solution.forces[c], assembly.contacts()[c].point});
  }
}

std::vector<WakeDecision> ComCriterion::check(SupportGraph* graph,
                                              const std::vector<BodyHandle>& component) const {
  // Balanced by statics when last judged, and judged by statics again
  // whatever the COM rule says (its split of shared loads is one of many):
  // where only loads changed, statics around them answers first.
  if (balanced_.stillBalanced(graph, component, options_, kMeasuredLoadFactor)) return {};
  bool shared = false;
  std::vector<WakeDecision> unstable = checkLoadsDown(graph, component, &shared);
  if (unstable.empty() || !(shared || statics_on_every_failure_)) return unstable;
  return judgeByStatics(graph, component, std::move(unstable));
}

std::vector<WakeDecision> ComCriterion::checkLoadsDown(SupportGraph* graph,
                                                       const std::vector<BodyHandle>& component,
                                                       bool* shared) const {
  for (BodyHandle handle : component) {
    SupportGraph::Node& node = *graph->find(handle);
    node.received.clear();
    node.received_from.clear();
    // What movers and held bricks press on it, then what bricks of the
    // stack push it with.
    node.pushes = node.stability.external_loads;
    for (PointForce& push : node.pushes) push.force *= kMeasuredLoadFactor;
    node.stability.contact_forces.clear();
    if (node.supports.size() > 1) *shared = true;
  }
  const SupportGraph::LeaningTest leans_on = [this](const SupportPatch& patch) {
    return leansOn(patch, options_);
  };
  std::vector<WakeDecision> unstable;
  std::vector<LoadShare> shares;
  // Each group's loads arrive from the groups above it, all before its own
  // turn, and are summed in the order they arrive.
  for (const std::vector<BodyHandle>& group : graph->loadOrder(component, leans_on)) {
    const bool leaning = std::any_of(group.begin(), group.end(), [&](BodyHandle handle) {
      return graph->find(handle)->leaning;
    });
    if (leaning) {
      *shared = true;
      balanceLeaning(graph, group, &unstable);
    } else if (group.size() > 1) {
      // Bricks resting on each other in a ring: nothing can be said to carry them.
      for (BodyHandle handle : group)
        unstable.push_back(WakeDecision{handle, WakeCause::kSupportCycle, handle, 0.0,
                                        "its supports form a cycle"});
    } else {
      passLoadDown(graph, group.front(), &shares, &unstable);
    }
  }
  return unstable;
}

std::vector<WakeDecision> ComCriterion::judgeByStatics(SupportGraph* graph,
                                                       const std::vector<BodyHandle>& component,
                                                       std::vector<WakeDecision> by_com) const {
  const StaticsAssembly assembly =
      assembleStatics(*graph, component, options_, kMeasuredLoadFactor);
  const StaticsSolution solution = assembly.solve(&basis_);
  // A solver failure keeps the COM rule's answer: never freeze on no answer.
  if (!solution.solved) {
    balanced_.forget(component);
    return by_com;
  }
  std::vector<std::vector<ContactForce>> forces = assembly.contactForces(solution);
  for (std::size_t i = 0; i < component.size(); ++i)
    graph->find(component[i])->stability.contact_forces = std::move(forces[i]);
  if (solution.feasible) {
    balanced_.keep(*graph, component);
    return {};
  }
  balanced_.forget(component);
  // What wakes is the collapse mechanism: every brick that moves in it, at
  // once. A part of it would be held by the bricks the same failure must
  // move, and would stand there frozen again.
  double unbalanced = 0.0;
  for (double imbalance : solution.imbalance) unbalanced += imbalance;
  std::vector<WakeDecision> mechanism;
  for (std::size_t i = 0; i < component.size(); ++i) {
    if (!solution.moves[i]) continue;
    mechanism.push_back(
        WakeDecision{component[i], WakeCause::kOutsideSupport, component[i],
                     graph->find(component[i])->stability.margin,
                     "no contact forces within friction balance the structure; it moves in its "
                     "collapse mechanism (statics: " +
                         percent(unbalanced) + " of a brick's weight unbalanced)"});
  }
  return mechanism.empty() ? by_com : mechanism;
}

}  // namespace brick_stack_sim
