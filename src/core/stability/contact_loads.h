#pragma once

#include <functional>
#include <unordered_map>
#include <utility>
#include <vector>

#include "physics/contact.h"

namespace brick_stack_sim {

/// The loads that bodies the stack does not hold (moving and held bricks)
/// put on the bricks they touch, measured from the physics engine's contact
/// impulses: the impulse a point applied in a step, over the step, is its
/// force. A frozen brick is a static collider, so the engine already
/// computes what a brick tipping off it, leaning on it, sliding across it or
/// pressed onto it by a hand does to it; these forces enter its statics.
///
/// A load counts only once it has acted in at least half of the last
/// `window` steps, and then as the step of median magnitude among them: a
/// bounce, a brush or a landing's blow lasts a step or two and is no load
/// (short hard hits are the impact rule's). A steady load is seen half a
/// window after it starts; a tipping brick's load changes slowly enough.
class ContactLoads {
 public:
  using BodyTest = std::function<bool(BodyHandle)>;

  /// One step of `dt` [s] over `window` steps: the forces `contacts` apply
  /// to every brick for which `measured` holds, from the bodies for which
  /// `source` holds (never the ground), times `force_scale` [-] (statics
  /// weighs bricks in its own g). A pair seen in no contact this step adds
  /// an empty step to its window.
  void record(const std::vector<PairContact>& contacts, double dt, int window, double force_scale,
              const BodyTest& measured, const BodyTest& source);
  /// The loads on `brick` now: per source, its forces at their points [N],
  /// world. Empty when none counts. With `counts`, only the sources for
  /// which it holds.
  std::vector<PointForce> on(BodyHandle brick, const BodyTest& counts = nullptr) const;
  /// The sources whose loads on `brick` count now, in handle order.
  std::vector<BodyHandle> sourcesOn(BodyHandle brick) const;
  /// Bricks whose loads may differ from what on() said before the last
  /// record() or forget(); forgets the list.
  std::vector<BodyHandle> takeTouched();
  /// `body` leaves the measurement, as a brick loaded and as a source: it
  /// left the world.
  void forget(BodyHandle body);
  /// `body` no longer counts as a source: it froze, and its weight now
  /// passes through the stack.
  void forgetSource(BodyHandle body);
  /// Whether any load is being measured.
  bool empty() const { return by_brick_.empty(); }

 private:
  /// One step of one pair: the source's forces on the brick.
  struct Sample {
    std::vector<PointForce> forces;
    double magnitude = 0.0;  ///< Of their sum [N].
  };
  /// The last steps of one pair, oldest overwritten first. A step's slot
  /// keeps its storage when it is overwritten: every pair of a pile writes
  /// one a step.
  struct Window {
    std::vector<Sample> steps;
    std::size_t next = 0;
    std::size_t touching = 0;  ///< Steps with forces; none: the pair is forgotten.
    bool seen = false;         ///< In this step's contacts; cleared as the step ends.
  };

  /// The median step of `window`; null when the pair touched in fewer than
  /// half of its steps.
  static const Sample* median(const Window& window);

  /// The window of (brick, source), made when there is none.
  Window& windowOf(BodyHandle brick, BodyHandle source);
  void forgetWhere(BodyHandle body, bool as_loaded_brick);

  /// A loaded brick's sources, each with its window, in the order of their
  /// handles (on() sums their loads in that order). A brick has a few
  /// sources; a pile has thousands of pairs, looked up every step.
  using Sources = std::vector<std::pair<BodyHandle, Window>>;
  std::unordered_map<BodyHandle, Sources> by_brick_;
  std::vector<BodyHandle> touched_;
  std::vector<PointForce> step_forces_;  ///< record()'s, kept for its storage.
};

}  // namespace brick_stack_sim
