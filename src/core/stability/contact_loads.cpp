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

ContactLoads::Window& ContactLoads::windowOf(BodyHandle brick, BodyHandle source) {
  Sources& sources = by_brick_[brick];
  auto it = std::lower_bound(
      sources.begin(), sources.end(), source,
      [](const std::pair<BodyHandle, Window>& entry, BodyHandle key) { return entry.first < key; });
  if (it == sources.end() || it->first != source) it = sources.insert(it, {source, Window{}});
  return it->second;
}

void ContactLoads::record(const std::vector<PairContact>& contacts, double dt, int window,
                          double force_scale, const BodyTest& measured, const BodyTest& source) {
  if (!(dt > 0.0)) return;
  const std::size_t steps = static_cast<std::size_t>(std::max(window, 1));
  for (const PairContact& pair : contacts) {
    for (const auto& [brick, other] : {std::pair{pair.a, pair.b}, std::pair{pair.b, pair.a}}) {
      if (isGround(brick) || isGround(other) || !measured(brick) || !source(other)) continue;
      forcesOn(brick, pair, dt, force_scale, &step_forces_);
      if (step_forces_.empty()) continue;
      Window& w = windowOf(brick, other);
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
  for (auto it = by_brick_.begin(); it != by_brick_.end();) {
    Sources& sources = it->second;
    for (auto& entry : sources) {
      Window& w = entry.second;
      Sample& now = w.steps[w.next];
      if (!w.seen && !now.forces.empty()) {
        now.forces.clear();
        now.magnitude = 0.0;
        --w.touching;
      }
      w.seen = false;  // for the next step, without a walk of its own
      w.next = (w.next + 1) % w.steps.size();
    }
    touched_.push_back(it->first);
    sources.erase(std::remove_if(sources.begin(), sources.end(),
                                 [](const auto& entry) { return entry.second.touching == 0; }),
                  sources.end());
    it = sources.empty() ? by_brick_.erase(it) : std::next(it);
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
  const auto found = by_brick_.find(brick);
  if (found == by_brick_.end()) return loads;
  for (const auto& [source, window] : found->second) {
    if (counts && !counts(source)) continue;
    if (const Sample* sample = median(window))
      loads.insert(loads.end(), sample->forces.begin(), sample->forces.end());
  }
  return loads;
}

std::vector<BodyHandle> ContactLoads::sourcesOn(BodyHandle brick) const {
  std::vector<BodyHandle> sources;
  const auto found = by_brick_.find(brick);
  if (found == by_brick_.end()) return sources;
  for (const auto& [source, window] : found->second)
    if (median(window)) sources.push_back(source);
  return sources;
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
  for (auto it = by_brick_.begin(); it != by_brick_.end();) {
    Sources& sources = it->second;
    const std::size_t before = sources.size();
    if (as_loaded_brick && it->first == body) {
      sources.clear();
    } else {
      sources.erase(std::remove_if(sources.begin(), sources.end(),
                                   [body](const auto& entry) { return entry.first == body; }),
                    sources.end());
    }
    if (sources.size() != before) touched_.push_back(it->first);
    it = sources.empty() ? by_brick_.erase(it) : std::next(it);
  }
}

}  // namespace brick_stack_sim
