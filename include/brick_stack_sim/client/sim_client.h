#pragma once
// The client library of the simulator node: every service of the node behind
// one method, every topic behind a subscribe or publish helper, the names
// from ros/interface_names.h alone (docs/ros_interface.md describes the
// interface). The planner, the teleop nodes, the node benchmark and the
// rostests reach the node through it.

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <geometry_msgs/Pose.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/Twist.h>
#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <ros/service_client.h>
#include <ros/subscriber.h>
#include <rosgraph_msgs/Clock.h>
#include <std_srvs/SetBool.h>
#include <visualization_msgs/MarkerArray.h>

#include "brick_stack_sim/BrickArray.h"
#include "brick_stack_sim/GetBricks.h"
#include "brick_stack_sim/GraspBrick.h"
#include "brick_stack_sim/PlaceBrick.h"
#include "brick_stack_sim/PushBrick.h"
#include "brick_stack_sim/QueryPlacement.h"
#include "brick_stack_sim/QueryPlacements.h"
#include "brick_stack_sim/ReleaseBrick.h"
#include "brick_stack_sim/RemoveBrick.h"
#include "brick_stack_sim/ResetScene.h"
#include "brick_stack_sim/SimulatePlan.h"
#include "brick_stack_sim/StabilityEvent.h"
#include "brick_stack_sim/StepSimulation.h"
#include "brick_stack_sim/ros/interface_names.h"

namespace brick_stack_sim {
namespace client {

/// How a SimClient reaches the node.
struct ClientOptions {
  /// The node's private namespace: its services and topics are found under it.
  std::string sim_namespace = ros_adapter::kDefaultNamespace;
  /// How long a call waits for its service to come up [s] (wall time) when it
  /// has no connection yet, or has to make a new one after its connection
  /// failed. 0: the service must be there at once.
  double service_wait = 5.0;
  /// Keep one connection per service from call to call (roscpp's persistent
  /// clients), as a frequent caller should: a connection made for each call
  /// costs a master lookup and a handshake, and under load such calls fail
  /// now and then without the node's doing. false: one connection per call.
  bool persistent = true;
};

/// What became of one call to a service of the node.
struct CallResult {
  /// The node answered and accepted the request (its response's success).
  bool ok = false;
  /// The node answered, accepting or refusing. false: the request never got
  /// there, or no answer came back (service not available, transport failed
  /// also after reconnecting); the response is then a default one.
  bool reached = false;
  /// When reached: the node's message, unchanged (why it refused, or what it
  /// did). Otherwise why the call did not get through, naming the service.
  std::string message;
  /// The full name of the service called (its namespace and its name).
  std::string service;

  /// Whether the node accepted the request.
  explicit operator bool() const { return ok; }
};

/// A CallResult with the node's response (default-constructed when !reached).
template <typename Response>
struct Reply : CallResult {
  Response response;
};

/// The node's interface for one thread. A SimClient is not safe to use from
/// two threads at once: give each thread its own (they are cheap, and each
/// keeps its own connections). Topic callbacks run wherever the node
/// handle's callback queue is served (a spinner), not in the calling thread.
///
/// Calls block until the node answers; roscpp has no timeout on a call once
/// it is connected. A connection that is missing or no longer valid is made
/// (again) after waiting up to options.service_wait for the service; a call
/// that fails in transport is tried once more on a new connection. Such a
/// retry may repeat a request the node carried out before its answer was
/// lost (a ~place_brick then answers that the id is taken).
class SimClient {
 public:
  /// A client of the node under options.sim_namespace, through `node_handle`
  /// (ros::init must have been called). Makes no connection yet: each service
  /// is connected at its first call.
  explicit SimClient(ClientOptions options = ClientOptions(),
                     ros::NodeHandle node_handle = ros::NodeHandle());

  SimClient(const SimClient&) = delete;
  SimClient& operator=(const SimClient&) = delete;
  SimClient(SimClient&&) = default;
  SimClient& operator=(SimClient&&) = default;

  const ClientOptions& options() const { return options_; }

  /// The full name of `name`, one of interface_names.h's topic, service or
  /// parameter names: under the node's namespace, or as it is when absolute
  /// (the clock).
  std::string resolve(const std::string& name) const;

  /// Waits up to `timeout` [s] (wall time, all services together) for every
  /// service of the node. ok when all came up; otherwise the message names
  /// the first that did not.
  CallResult waitForNode(double timeout);

  // --- services: one method each, in the order of interface_names.h ----------

  /// ~place_brick: a brick of request.type at request.pose (frame world,
  /// centre [m]) with request.twist [m/s, rad/s]; the response names it.
  Reply<PlaceBrick::Response> placeBrick(const PlaceBrick::Request& request);
  /// ~remove_brick of brick `id`.
  Reply<RemoveBrick::Response> removeBrick(const std::string& id);
  /// ~reset: clears the table (`scene` empty) or plays a scene (a name in the
  /// node's scene folders, or a path).
  Reply<ResetScene::Response> reset(const std::string& scene = "");
  /// ~get_bricks: the bricks `ids` in their order, or every brick when empty.
  Reply<GetBricks::Response> getBricks(const std::vector<std::string>& ids = {});
  /// ~push_brick: request.impulse [N s] at request.point [m] (frame world).
  Reply<PushBrick::Response> pushBrick(const PushBrick::Request& request);
  /// ~query_placement: would a brick of request.type rest at request.pose?
  Reply<QueryPlacement::Response> queryPlacement(const QueryPlacement::Request& request);
  /// ~query_placements: query_placement for every pose of request.poses at once.
  Reply<QueryPlacements::Response> queryPlacements(const QueryPlacements::Request& request);
  /// ~pause (std_srvs/SetBool): pauses (true) or resumes (false) the node.
  Reply<std_srvs::SetBool::Response> pause(bool paused);
  /// ~step: advances a paused node by `steps` fixed time steps.
  Reply<StepSimulation::Response> step(std::uint32_t steps);
  /// ~grasp_brick: brick `id` becomes HELD and follows ~held_target.
  Reply<GraspBrick::Response> graspBrick(const std::string& id);
  /// ~release_brick: the held brick `id` lets go with `twist` [m/s, rad/s].
  Reply<ReleaseBrick::Response> releaseBrick(
      const std::string& id, const geometry_msgs::Twist& twist = geometry_msgs::Twist());
  /// ~simulate_plan: request.steps run on a copy of the world, which the live
  /// world never sees; the response says what would stand and what would
  /// fall. Blocks for as long as the plan simulates (seconds for a long one).
  Reply<SimulatePlan::Response> simulatePlan(const SimulatePlan::Request& request);

  // --- topics ----------------------------------------------------------------

  using BricksCallback = std::function<void(const BrickArray::ConstPtr&)>;
  using EventsCallback = std::function<void(const StabilityEvent::ConstPtr&)>;
  using MarkersCallback = std::function<void(const visualization_msgs::MarkerArray::ConstPtr&)>;
  using ClockCallback = std::function<void(const rosgraph_msgs::Clock::ConstPtr&)>;

  /// ~bricks (BrickArray), up to `queue_size` messages queued.
  ros::Subscriber subscribeBricks(const BricksCallback& callback, std::uint32_t queue_size);
  /// ~events (StabilityEvent).
  ros::Subscriber subscribeEvents(const EventsCallback& callback, std::uint32_t queue_size);
  /// ~markers (visualization_msgs/MarkerArray).
  ros::Subscriber subscribeMarkers(const MarkersCallback& callback, std::uint32_t queue_size);
  /// The clock the node publishes with its parameter publish_clock.
  ros::Subscriber subscribeClock(const ClockCallback& callback, std::uint32_t queue_size);

  /// The publisher of ~held_target (geometry_msgs/PoseStamped), advertised at
  /// the first call (later calls return it as it is, whatever `queue_size`).
  /// Advertise it early: a message published before the node has connected
  /// is lost.
  const ros::Publisher& advertiseHeldTarget(std::uint32_t queue_size = 10);
  /// Publishes `pose` [m] as ~held_target, stamped now in frame "world".
  void publishHeldTarget(const geometry_msgs::Pose& pose);
  /// Publishes `target` as it is, its stamp and frame included.
  void publishHeldTarget(const geometry_msgs::PoseStamped& target);

 private:
  /// The node's services, an index into connections_.
  enum Slot {
    kPlace,
    kRemove,
    kReset,
    kGet,
    kPush,
    kQuery,
    kQueryMany,
    kPause,
    kStep,
    kGrasp,
    kRelease,
    kSimulatePlan,
    kSlots
  };

  /// Calls service `name` through connections_[slot], (re)connecting and
  /// retrying as the class says.
  template <typename Service>
  Reply<typename Service::Response> call(Slot slot, const char* name,
                                         const typename Service::Request& request);
  /// Waits up to options_.service_wait for service `name` and makes a new
  /// connection to it in connections_[slot]; false when it did not come up.
  template <typename Service>
  bool connect(Slot slot, const std::string& name);

  ClientOptions options_;
  ros::NodeHandle node_handle_;
  /// Default-constructed (invalid) until the service's first call.
  std::array<ros::ServiceClient, kSlots> connections_;
  ros::Publisher held_target_;
};

}  // namespace client
}  // namespace brick_stack_sim
