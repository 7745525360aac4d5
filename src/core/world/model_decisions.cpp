// The decision path: every call of the model goes through decide(), and
// every decision is applied here (bricks change mode, events are emitted).
#include "world/world_state.h"

namespace brick_stack_sim {

void applyDecisions(WorldState* w, const StabilityDecisions& decisions) {
  // Whatever the model described anew, decisions or not (a brick placed on
  // the stack changes the load on every frozen brick under it).
  if (w->model) {
    for (BodyHandle handle : w->model->takeRedescribed())
      if (BrickRecord* brick = w->bricks.find(handle)) w->stampChanged(brick);
  }
  if (decisions.empty()) return;
  // Contacts read before bodies changed hands would name bricks that moved
  // in or out of Bullet's world; the next Bullet step reads them afresh.
  w->contacts.clear();
  w->model_changed = true;
  for (const FreezeDecision& d : decisions.freeze) {
    BrickRecord* brick = w->bricks.find(d.brick);
    if (!brick) continue;
    w->sets.transfer(brick, frozenMode(d.kind));
    w->stampChanged(brick);
    w->emit(SimEventKind::kFrozen, brick->id, d.reason);
  }
  for (const WakeDecision& d : decisions.wake) {
    BrickRecord* brick = w->bricks.find(d.brick);
    if (!brick) continue;
    w->sets.transfer(brick, BrickMode::kDynamic);
    w->stampChanged(brick);
    if (d.repeats) ++w->cost.wake_cycles;
    w->emit(SimEventKind::kWoken, brick->id, d.reason);
  }
}

/// Hands `input` to the model and applies what it decides; returns the
/// decisions (empty without a model).
StabilityDecisions decide(WorldState* w, const StabilityInput& input) {
  StabilityDecisions decisions;
  if (!w->model) return decisions;
  w->model->decide(input, &decisions);
  // Judged as a whole unless more bricks of this instant are to come.
  w->judgement_pending = input.more_to_come;
  applyDecisions(w, decisions);
  return decisions;
}

}  // namespace brick_stack_sim
