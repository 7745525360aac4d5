#pragma once

#include "stability/stability_model.h"
#include "stability/support_graph.h"

namespace brick_stack_sim {

/// Whether the COM rule still passes, with a margin above `min_margin` [m],
/// on `brick` (evaluated on its supports as `stability`) and on every frozen
/// brick its weight would reach, were it to join `graph` at rest: the
/// cheap answer to a placement what-if, in time that follows the bricks
/// below it and without copying the graph.
///
/// Only the bricks under the new one receive a changed load, and each of
/// them is judged as the COM rule judges it (ComCriterion), from the loads
/// its carriers pass down: those of bricks the new weight does not reach
/// are the ones the graph's last check left on it. False means "not
/// decided here", not "unstable": a load that reaches a leaning brick, a
/// brick pushed sideways or by an outside load, a cycle of supports, a
/// brick the new one would touch from below or beside, a graph with
/// changes not yet judged, or any brick where the rule fails. The caller
/// then judges the what-if in full.
bool comRuleBearsPlacement(const SupportGraph& graph, const BodyMotion& brick,
                           const BrickStability& stability, double min_margin);

}  // namespace brick_stack_sim
