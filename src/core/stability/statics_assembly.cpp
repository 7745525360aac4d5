#include "stability/statics_assembly.h"

#include <algorithm>
#include <cmath>

namespace brick_stack_sim {

bool leansOn(const SupportPatch& side_contact, const StabilityOptions& options) {
  const double from_above = -std::cos(options.support_normal_tolerance);
  for (const Eigen::Vector3d& normal : side_contact.normals)
    if (normal.z() > from_above) return true;
  return false;
}

bool leans(const BrickStability& stability, const StabilityOptions& options) {
  return std::any_of(stability.side_contacts.begin(), stability.side_contacts.end(),
                     [&](const SupportPatch& patch) { return leansOn(patch, options); });
}

int StaticsAssembly::addFree(BodyHandle brick, double mass, const Eigen::Vector3d& com) {
  index_[brick] = static_cast<int>(bodies_.size());
  handles_.push_back(brick);
  StaticsBody body;
  body.mass = mass;
  body.com = com;
  bodies_.push_back(body);
  return index_[brick];
}

void StaticsAssembly::addLoad(int body, const PointForce& load) {
  StaticsBody& target = bodies_[body];
  target.applied_force += load.force;
  target.applied_torque += (load.point - target.com).cross(load.force);
}

void StaticsAssembly::addPatches(int body, const std::vector<SupportPatch>& patches) {
  for (const SupportPatch& patch : patches) {
    auto supporter = index_.find(patch.supporter);
    const bool fixed = supporter == index_.end();
    if (fixed && !leansOn(patch, options_)) continue;
    const int other = fixed ? kStaticsGround : supporter->second;
    for (std::size_t i = 0; i < patch.points.size(); ++i) {
      contacts_.push_back(
          StaticsContact{body, other, patch.points[i], patch.normals[i], patch.friction});
      others_.push_back(patch.supporter);
      // Unique in practice; a collision costs the warm start pivots only.
      contact_keys_.push_back(((std::uint64_t{handles_[body]} << 32) | patch.supporter) ^
                              ((i + 1) * 0x9E3779B97F4A7C15ull));
    }
  }
}

namespace {

/// Adds `force` to `forces`, onto the entry for the same contact (same
/// body, point and normal) when there is one. Two edges that touch are named
/// from each side with that side's face normal: those stay two forces, each
/// in its own friction cone (a rounded edge may push along either).
void accumulate(const ContactForce& force, std::vector<ContactForce>* forces) {
  // Far below any contact patch, far above the points' rounding [m], [-].
  constexpr double kSamePoint = 1e-7;
  constexpr double kSameNormal = 1e-9;
  for (ContactForce& known : *forces) {
    if (known.other == force.other && (known.point - force.point).norm() < kSamePoint &&
        (known.normal - force.normal).norm() < kSameNormal) {
      known.force += force.force;
      return;
    }
  }
  forces->push_back(force);
}

}  // namespace

std::vector<std::vector<ContactForce>> StaticsAssembly::contactForces(
    const StaticsSolution& solution) const {
  std::vector<std::vector<ContactForce>> forces(bodies_.size());
  if (solution.forces.size() != contacts_.size()) return forces;
  for (std::size_t c = 0; c < contacts_.size(); ++c) {
    const StaticsContact& contact = contacts_[c];
    accumulate(ContactForce{others_[c], contact.point, contact.normal, solution.forces[c],
                            contact.friction},
               &forces[contact.a]);
    if (contact.b != kStaticsGround)
      accumulate(ContactForce{handles_[contact.a], contact.point, -contact.normal,
                              -solution.forces[c], contact.friction},
                 &forces[contact.b]);
  }
  return forces;
}

StaticsAssembly assembleStatics(const SupportGraph& graph, const std::vector<BodyHandle>& bricks,
                                const StabilityOptions& options, double load_factor) {
  StaticsAssembly assembly(options);
  for (BodyHandle handle : bricks) {
    const SupportGraph::Node& node = *graph.find(handle);
    assembly.addFree(handle, node.mass, node.com);
  }
  for (std::size_t i = 0; i < bricks.size(); ++i) {
    const SupportGraph::Node& node = *graph.find(bricks[i]);
    assembly.addPatches(static_cast<int>(i), node.supports);
    assembly.addPatches(static_cast<int>(i), node.side_contacts);
    for (const PointForce& load : node.stability.external_loads)
      assembly.addLoad(static_cast<int>(i), PointForce{load_factor * load.force, load.point});
  }
  return assembly;
}

StaticsSolution StaticsAssembly::solve(StaticsBasis* basis) const {
  // Whether forces balance does not depend on g's size: the default is the
  // unit every load passed between bricks is measured in.
  if (!basis) return solveStatics(bodies_, contacts_, StaticsOptions());
  StaticsWarmStart warm;
  warm.body_keys.assign(handles_.begin(), handles_.end());
  warm.contact_keys = contact_keys_;
  warm.basis = basis;
  return solveStatics(bodies_, contacts_, StaticsOptions(), &warm);
}

}  // namespace brick_stack_sim
