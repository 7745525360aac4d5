#include "world/numerical_guard.h"

#include "util/text_format.h"
#include "world/world_state.h"

namespace brick_stack_sim {

void guardMovers(WorldState* w) {
  for (BrickRecord* brick : w->sets.movers()) {
    const BodyHandle h = brick->handle;
    if (!w->scene.isActive(h)) continue;
    const Eigen::Isometry3d pose = w->scene.pose(h);
    const Eigen::Vector3d velocity = w->scene.linearVelocity(h);
    const Eigen::Vector3d spin = w->scene.angularVelocity(h);
    const bool finite = pose.matrix().allFinite() && velocity.allFinite() && spin.allFinite();
    const double blow_up = WorldOptions::kBlowUpFactor;
    const bool runaway = finite && (velocity.norm() > blow_up * w->options.max_linear_speed ||
                                    spin.norm() > blow_up * w->options.max_angular_speed);
    if (!finite || runaway) {
      const std::string reason = finite ? "numerical blow-up: " + formatNumber(velocity.norm()) +
                                              " m/s, " + formatNumber(spin.norm()) + " rad/s"
                                        : std::string("Bullet produced NaN/Inf");
      w->scene.restoreAtRest(h, brick->last_good_pose);
      ++(finite ? w->cost.blowups : w->cost.nonfinite);
      w->emit(SimEventKind::kNonFinite, brick->id,
              reason + "; restored its last good pose at rest");
      continue;
    }
    brick->last_good_pose = pose;
    if (!insideWorld(w->options, pose.translation())) {
      w->left_world.emplace_back(brick->id, "left the world box at " +
                                                formatVector(pose.translation()) + " (" +
                                                describeWorldBox(w->options) + "): removed");
      continue;
    }
    if (!brick->fell_off && pose.translation().z() < -w->options.fall_off_depth) {
      brick->fell_off = true;
      w->emit(SimEventKind::kFellOff, brick->id,
              "centre dropped below the table top at " + formatVector(pose.translation()));
    }
  }
}

}  // namespace brick_stack_sim
