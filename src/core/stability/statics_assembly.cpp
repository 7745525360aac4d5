#include "stability/statics_assembly.h"

#include <cmath>

namespace brick_stack_sim {

bool leansOn(const SupportPatch& side_contact, const StabilityOptions& options) {
  const double from_above = -std::cos(options.support_normal_tolerance);
  for (const Eigen::Vector3d& normal : side_contact.normals)
    if (normal.z() > from_above) return true;
  return false;
}

int StaticsAssembly::addFree(BodyHandle brick, double mass, const Eigen::Vector3d& com) {
  index_[brick] = static_cast<int>(bodies_.size());
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
    }
  }
}

StaticsSolution StaticsAssembly::solve() const {
  // Whether forces balance does not depend on g's size: the default is the
  // unit every load passed between bricks is measured in.
  return solveStatics(bodies_, contacts_, StaticsOptions());
}

}  // namespace brick_stack_sim
