#include "stability/contact_loads.h"

#include <algorithm>

#include "physics/body_handle.h"

namespace brick_stack_sim {

namespace {

/// The forces on `brick` at the points of `pair` (which touches it) [N]:
/// each point's normal and friction impulses, which the engine gives as
/// applied to `a`, over the step.
std::vector<PointForce> forcesOn(BodyHandle brick, const PairContact& pair, double dt,
                                 double force_scale) {
  const double sign = (brick == pair.a ? 1.0 : -1.0) * force_scale / dt;
  std::vector<PointForce> forces;
  forces.reserve(pair.manifold.size());
  for (const ContactPoint& point : pair.manifold) {
    const Eigen::Vector3d force = sign * (point.impulse * point.normal + point.friction_impulse);
    if (!force.allFinite() || force.isZero()) continue;
    forces.push_back(PointForce{force, point.position});
  }
  return forces;
}

}  // namespace

void ContactLoads::record(const std::vector<PairContact>& contacts, double dt, int window,
                          double force_scale, const BodyTest& measured, const BodyTest& source) {
  if (!(dt > 0.0)) return;
  const std::size_t steps = static_cast<std::size_t>(std::max(window, 1));
  for (auto& entry : windows_) entry.second.seen = false;
  for (const PairContact& pair : contacts) {
    for (const auto& [brick, other] : {std::pair{pair.a, pair.b}, std::pair{pair.b, pair.a}}) {
      if (isGround(brick) || isGround(other) || !measured(brick) || !source(other)) continue;
      Sample sample;
      sample.forces = forcesOn(brick, pair, dt, force_scale);
      if (sample.forces.empty()) continue;
      Eigen::Vector3d total = Eigen::Vector3d::Zero();
      for (const PointForce& force : sample.forces) total += force.force;
      sample.magnitude = total.norm();
      Window& w = windows_[{brick, other}];
      if (w.steps.size() != steps) w = Window{std::vector<Sample>(steps), 0, false};
      if (w.seen) {  // a second manifold of the same pair
        Sample& now = w.steps[w.next];
        now.forces.insert(now.forces.end(), sample.forces.begin(), sample.forces.end());
        total.setZero();
        for (const PointForce& force : now.forces) total += force.force;
        now.magnitude = total.norm();
        continue;
      }
      w.steps[w.next] = std::move(sample);
      w.seen = true;
    }
  }
  for (auto it = windows_.begin(); it != windows_.end();) {
    Window& w = it->second;
    if (!w.seen) w.steps[w.next] = Sample();
    w.next = (w.next + 1) % w.steps.size();
    touched_.push_back(it->first.first);
    const bool empty = std::all_of(w.steps.begin(), w.steps.end(),
                                   [](const Sample& s) { return s.forces.empty(); });
    it = empty ? windows_.erase(it) : std::next(it);
  }
}

const ContactLoads::Sample* ContactLoads::median(const Window& window) {
  std::vector<const Sample*> order;
  order.reserve(window.steps.size());
  for (const Sample& sample : window.steps) order.push_back(&sample);
  const std::size_t middle = order.size() / 2;
  std::nth_element(order.begin(), order.begin() + middle, order.end(),
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
    const bool involved =
        it->first.second == body || (as_loaded_brick && it->first.first == body);
    if (involved) touched_.push_back(it->first.first);
    it = involved ? windows_.erase(it) : std::next(it);
  }
}

}  // namespace brick_stack_sim
