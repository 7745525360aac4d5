#pragma once
// stack_sim_node_bench's planner case: what a planner's batch of candidate
// poses costs through ~query_placements against ~query_placement one by one,
// and how fast ~simulate_plan foretells a sequence on a copy of a large
// frozen structure while another client calls ~get_bricks.

#include <string>

#include "brick_stack_sim/client/sim_client.h"

namespace brick_stack_sim {
namespace node_bench {

/// Runs the planner case against the node `sim` reaches, with its scenes
/// written under `directory` (the node is left running), prints it on stderr
/// and writes it to `output` with "_planner" before its ".csv" (one header
/// line, one row). False (the reason on stderr) when a call failed or a
/// structure did not settle.
bool runPlanner(client::SimClient& sim, const std::string& directory, const std::string& output);

}  // namespace node_bench
}  // namespace brick_stack_sim
