#pragma once

#include <vector>

#include "physics/contact.h"

namespace brick_stack_sim {

class BulletScene;

/// The touching pairs of the scene's last step, read from Bullet's contact
/// manifolds: per pair, every point closer than `contact_distance` [m] with
/// its position, normal, depth and the normal and friction impulses the
/// solver applied, the mean normal, the fastest closing speed and the pair's
/// combined friction.
/// Pairs without such a point are left out. `points` is filled with the
/// points' positions; refining it into a support patch is not Bullet's job.
void readContacts(const BulletScene& scene, double contact_distance,
                  std::vector<PairContact>* contacts);

}  // namespace brick_stack_sim
