// The names of the node's interface (docs/ros_interface.md), the one place a
// program of this package finds them: the node advertises them, the client
// library calls them.
#pragma once

namespace brick_stack_sim {
namespace ros_adapter {

/// The node's name when main() starts it; its private namespace
/// ("/brick_sim") is where clients find it unless it runs elsewhere.
constexpr char kNodeName[] = "brick_sim";
constexpr char kDefaultNamespace[] = "/brick_sim";

// Relative to the node's private namespace (`~bricks` is kBricksTopic on a
// ros::NodeHandle("~")), except the clock.
constexpr char kBricksTopic[] = "bricks";
constexpr char kEventsTopic[] = "events";
constexpr char kMarkersTopic[] = "markers";
constexpr char kClockTopic[] = "/clock";
constexpr char kHeldTargetTopic[] = "held_target";
constexpr char kPlaceBrickService[] = "place_brick";
constexpr char kRemoveBrickService[] = "remove_brick";
constexpr char kResetService[] = "reset";
constexpr char kGetBricksService[] = "get_bricks";
constexpr char kPushBrickService[] = "push_brick";
constexpr char kQueryPlacementService[] = "query_placement";
constexpr char kQueryPlacementsService[] = "query_placements";
constexpr char kPauseService[] = "pause";
constexpr char kStepService[] = "step";
constexpr char kGraspBrickService[] = "grasp_brick";
constexpr char kReleaseBrickService[] = "release_brick";
constexpr char kSimulatePlanService[] = "simulate_plan";

/// Parameters a client reads from the node's namespace.
constexpr char kPublishRateParameter[] = "publish_rate";
/// How many ~simulate_plan requests the node runs at once.
constexpr char kMaxConcurrentPlansParameter[] = "max_concurrent_plans";

/// The frame of the poses a client sends (~held_target, the requests): the
/// default of the node's parameter frame_id.
constexpr char kWorldFrame[] = "world";

}  // namespace ros_adapter
}  // namespace brick_stack_sim
