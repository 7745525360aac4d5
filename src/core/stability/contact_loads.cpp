#include "stability/contact_loads.h"

#include <algorithm>
#include <array>

#include "physics/body_handle.h"

namespace brick_stack_sim {

namespace {

/// The forces on `brick` at the points of `pair` (which touches it) [N]:
/// each point's normal and friction impulses, which the engine gives as
/// applied to `a`, over the step.
void forcesOn(BodyHandle brick, const PairContact& pair, double dt, double force_scale,
              std::vector<PointForce>* forces) {
  const double sign = (brick == pair.a ? 1.0 : -1.0) * force_scale / dt;
  forces->clear();
  for (const ContactPoint& point : pair.manifold) {
    const Eigen::Vector3d force = sign * (point.impulse * point.normal + point.friction_impulse);
    if (!force.allFinite() || force.isZero()) continue;
    forces->push_back(PointForce{force, point.position});
  }
}

/// The larger windows are rare: their median is sorted on the heap.
constexpr std::size_t kWindowOnStack = 64;

}  // namespace

void ContactLoads::record(const std::vector<PairContact>& contacts, double dt, int window,
                          double force_scale, const BodyTest& measured, const BodyTest& source) {
  if (!(dt > 0.0)) return;
  const std::size_t steps = static_cast<std::size_t>(std::max(window, 1));
  for (auto& entry : windows_) entry.second.seen = false;
  for (const PairContact& pair : contacts) {
    for (const auto& [brick, other] : {std::pair{pair.a, pair.b}, std::pair{pair.b, pair.a}}) {
      if (isGround(brick) || isGround(other) || !measured(brick) || !source(other)) continue;
      forcesOn(brick, pair, dt, force_scale, &step_forces_);
      if (step_forces_.empty()) continue;
      Window& w = windows_[{brick, other}];
      if (w.steps.size() != steps) w = Window{std::vector<Sample>(steps), 0, 0, false};
      Sample& now = w.steps[w.next];
      if (w.seen) {  // a second manifold of the same pair
        now.forces.insert(now.forces.end(), step_forces_.begin(), step_forces_.end());
      } else {
        w.touching += now.forces.empty() ? 1 : 0;
        now.forces.assign(step_forces_.begin(), step_forces_.end());
        w.seen = true;
      }
      Eigen::Vector3d total = Eigen::Vector3d::Zero();
      for (const PointForce& force : now.forces) total += force.force;
      now.magnitude = total.norm();
    }
  }
  for (auto it = windows_.begin(); it != windows_.end();) {
    Window& w = it->second;
    Sample& now = w.steps[w.next];
    if (!w.seen && !now.forces.empty()) {
      now.forces.clear();
      now.magnitude = 0.0;
      --w.touching;
    }
    w.next = (w.next + 1) % w.steps.size();
    touched_.push_back(it->first.first);
    it = w.touching == 0 ? windows_.erase(it) : std::next(it);
  }
}

const ContactLoads::Sample* ContactLoads::median(const Window& window) {
  const std::size_t count = window.steps.size();
  std::array<const Sample*, kWindowOnStack> on_stack;
  std::vector<const Sample*> on_heap(count > kWindowOnStack ? count : 0);
  const Sample** order = count > kWindowOnStack ? on_heap.data() : on_stack.data();
  for (std::size_t i = 0; i < count; ++i) order[i] = &window.steps[i];
  const std::size_t middle = count / 2;
  std::nth_element(order, order + middle, order + count,
                   [](const Sample* x, const Sample* y) { return x->magnitude < y->magnitude; });
  return order[middle]->forces.empty() ? nullptr : order[middle];
}

std::vector<PointForce> ContactLoads::on(BodyHandle brick, const BodyTest& counts) const {
  std::vector<PointForce> loads;
  for (auto it = windows_.lower_bound({brick, 0}); it != windows_.end() && it->first.first == brick;
       ++it) {
    if (counts && !counts(it->first.second)) continue;
    if (const Sample* sample = median(it->second))
      loads.insert(loads.end(), sample->forces.begin(), sample->forces.end());
  }
  return loads;
}

std::vector<BodyHandle> ContactLoads::takeTouched() {
  std::sort(touched_.begin(), touched_.end());
  touched_.erase(std::unique(touched_.begin(), touched_.end()), touched_.end());
  std::vector<BodyHandle> taken;
  taken.swap(touched_);
  return taken;
}

void ContactLoads::forget(BodyHandle body) { forgetWhere(body, true); }

void ContactLoads::forgetSource(BodyHandle body) { forgetWhere(body, false); }

void ContactLoads::forgetWhere(BodyHandle body, bool as_loaded_brick) {
  for (auto it = windows_.begin(); it != windows_.end();) {
    const bool involved = it->first.second == body || (as_loaded_brick && it->first.first == body);
    if (involved) touched_.push_back(it->first.first);
    it = involved ? windows_.erase(it) : std::next(it);
  }
}

}  // namespace brick_stack_sim
