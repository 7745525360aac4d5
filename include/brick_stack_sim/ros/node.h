#pragma once

#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include <geometry_msgs/PoseStamped.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <std_srvs/SetBool.h>

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
#include "brick_stack_sim/StepSimulation.h"
#include "brick_stack_sim/core/scene/scene.h"
#include "brick_stack_sim/core/simulation/simulation.h"
#include "brick_stack_sim/core/status.h"
#include "brick_stack_sim/core/types/brick_type.h"
#include "brick_stack_sim/ros/brick_mirror.h"
#include "brick_stack_sim/ros/interface_names.h"
#include "brick_stack_sim/ros/node_options.h"
#include "brick_stack_sim/ros/state_publisher.h"
#include "brick_stack_sim/ros/step_pacer.h"
#include "brick_stack_sim/ros/ticket_mutex.h"

namespace brick_stack_sim {
namespace ros_adapter {

/// Most steps one ~step request may ask for: 1e6 steps are 1000 s of sim time
/// at the default step (seconds to minutes of wall time; other clients are
/// served meanwhile).
constexpr unsigned kMaxStepsPerRequest = 1000000;
/// Threads serving the short requests, the step timer and ~held_target
/// (main() spins them): a ~get_bricks is answered while a ~place_brick
/// waits for the world.
constexpr int kServiceThreads = 4;

/// The ROS face of a Simulation: publishes its state, serves its requests and
/// steps it on a wall timer so that sim time follows wall time times
/// `real_time_factor`. Each request is checked and then handed to one core
/// call, which changes nothing when it refuses.
///
/// Threads: the short requests and the timer run on the global callback queue,
/// which main() spins with kServiceThreads threads; ~step and ~reset, which may
/// take seconds, run on a queue of their own with one thread, so they never
/// hold up the others; ~simulate_plan runs on a third queue with one thread
/// more than plans may run at once (max_concurrent_plans), so that the one
/// past the bound is refused at once while the others simulate. The world
/// and everything the node keeps about it are guarded by one fair lock
/// (world_mutex_), taken once per request or tick, so requests and steps never
/// interleave; a long ~step hands the lock over between steps whenever
/// someone waits for it, and a plan holds it only while it copies the world.
class SimNode {
 public:
  /// Creates the simulation, advertises every topic and service and, when
  /// the parameter `scene` is set, plays that scene; fails (and advertises
  /// nothing) when the simulation or the scene cannot be created.
  static Status create(const ros::NodeHandle& private_node_handle, const NodeOptions& options,
                       const BrickTypeLibrary& types, std::unique_ptr<SimNode>* node);

  SimNode(const SimNode&) = delete;
  SimNode& operator=(const SimNode&) = delete;
  /// Stops the long-work and plan threads before what they use goes away (a
  /// plan under way is waited for: runPlan cannot be interrupted).
  ~SimNode();

 private:
  SimNode(const ros::NodeHandle& private_node_handle, const NodeOptions& options);

  // Every member function below but the service handlers, onStepTimer,
  // onHeldTarget, playInitialScene and resetWorld expects world_mutex_ to be
  // held by the caller.

  /// Sim time [s]; never goes backwards, across resets included.
  double simTime() const;

  // --- set-up (node.cpp) -----------------------------------------------------
  /// Plays the parameter `scene`, if any, before anything is advertised.
  Status playInitialScene();
  /// Every service and ~held_target; ~step and ~reset on the long-work queue,
  /// ~simulate_plan on the plan queue.
  void advertiseServices();
  /// Advertises `handler` as `service` on `queue` (null: the global one); an
  /// allocation failure inside it is answered as a refusal with a message
  /// (refuseOnAllocationFailure), never as a bare exception.
  template <typename Request, typename Response>
  ros::ServiceServer advertiseGuarded(const char* service,
                                      bool (SimNode::*handler)(Request&, Response&),
                                      ros::CallbackQueue* queue = nullptr);
  void logStart(const BrickTypeLibrary& types) const;

  // --- stepping (node.cpp) ---------------------------------------------------
  void onStepTimer(const ros::WallTimerEvent& event);
  /// The steps the pacer asks for, until the tick's share of wall time is spent.
  void stepTick();
  /// One world step with the scene's due placements.
  void advance();
  /// advance(), then the state publication when it is due in sim time and
  /// the wall-time cap allows it (StepPacer says why there is a cap).
  void stepOnce();
  /// The timer ticks at publish_rate while the world is settled, else at
  /// step_timer_rate.
  void adaptTimerRate();
  /// Restarts the wall/sim time pacing from now (after a pause, a reset, or
  /// when the world cannot keep up).
  void restartPacing();
  /// publisher_->publishState(), and ~get_bricks' mirror starts from it
  /// after a reset.
  void publishState();
  void logRefusedPlacements(const std::vector<RefusedPlacement>& refused);

  // --- services (node_services.cpp): one handler each; they always return
  // true so the caller gets success and message, false would only say "call
  // failed".
  bool placeBrick(PlaceBrick::Request& request, PlaceBrick::Response& response);
  bool removeBrick(RemoveBrick::Request& request, RemoveBrick::Response& response);
  bool reset(ResetScene::Request& request, ResetScene::Response& response);
  bool getBricks(GetBricks::Request& request, GetBricks::Response& response);
  bool pushBrick(PushBrick::Request& request, PushBrick::Response& response);
  bool queryPlacement(QueryPlacement::Request& request, QueryPlacement::Response& response);
  bool queryPlacements(QueryPlacements::Request& request, QueryPlacements::Response& response);
  bool pause(std_srvs::SetBool::Request& request, std_srvs::SetBool::Response& response);
  bool step(StepSimulation::Request& request, StepSimulation::Response& response);
  bool graspBrick(GraspBrick::Request& request, GraspBrick::Response& response);
  bool releaseBrick(ReleaseBrick::Request& request, ReleaseBrick::Response& response);
  /// ~simulate_plan (node_plans.cpp): checks the request, copies the world
  /// under the lock and runs the plan on the copy off it.
  bool simulatePlan(SimulatePlan::Request& request, SimulatePlan::Response& response);

  /// ~held_target: where the held brick goes. A target in another frame, not
  /// finite, or with nothing held is ignored with a (throttled) warning.
  void onHeldTarget(const geometry_msgs::PoseStamped::ConstPtr& target);

  /// Reads the scene `scene_name` (empty: no bricks); touches nothing of the
  /// world, so it runs without the lock.
  Status loadNamedScene(const std::string& scene_name, Scene* scene) const;
  /// Empties the table (scene empty) or replaces the bricks by the scene's;
  /// on failure nothing changes. `message` receives what was done. Takes
  /// the world lock itself, twice: the scene's world is built between,
  /// off the lock (node_reset.cpp).
  Status resetWorld(const std::string& scene_name, const Scene& scene, std::string* message);
  /// What a new world starts with: its events out, the mirrors forgotten,
  /// the publication and the pacing from now. Returns what was done.
  std::string startNewWorld(const std::string& scene_name, const Scene& scene);
  /// The bricks `ids` names for ~get_bricks into `asked`, or every brick
  /// into `response` when it names none; `left_out` counts those not finite.
  Status collectBricks(const std::vector<std::string>& ids, GetBricks::Response* response,
                       std::vector<BrickSnapshot>* asked, std::size_t* left_out);
  /// Steps a paused world `steps` times for ~step, handing the lock over
  /// between slices; empty, or why it stopped early.
  std::string stepPaused(unsigned steps, std::unique_lock<TicketMutex>* lock, unsigned* done);
  /// A request changed the world: ~bricks is due, and its events go out now.
  void changed();
  /// Logs a refused request at INFO (at most once a second) and fills the response fields.
  template <typename Response>
  bool refuse(const char* service, const Status& status, Response* response);

  NodeOptions options_;

  /// Guards simulation_ and every member after it up to the ROS handles.
  TicketMutex world_mutex_;
  std::unique_ptr<Simulation> simulation_;

  bool paused_ = false;
  /// ~reset is building the next world off the lock: the timer steps nothing.
  bool resetting_ = false;
  /// The world as ~get_bricks last answered (a mirror apart from the
  /// publisher's: an answer must not hide a change from the next publish).
  BrickMirror answers_;
  StepPacer pacer_;
  std::unique_ptr<StatePublisher> publisher_;

  ros::NodeHandle node_handle_;
  std::vector<ros::ServiceServer> services_;
  ros::Subscriber held_target_subscriber_;
  ros::WallTimer step_timer_;
  double timer_rate_ = 0.0;  ///< Its current rate [Hz].
  /// ~step and ~reset: served by their own thread.
  ros::CallbackQueue long_work_queue_;
  std::unique_ptr<ros::AsyncSpinner> long_work_spinner_;
  /// ~simulate_plan: max_concurrent_plans + 1 threads of their own.
  ros::CallbackQueue plan_queue_;
  std::unique_ptr<ros::AsyncSpinner> plan_spinner_;
  /// Plans simulating now (not guarded by world_mutex_: a plan runs off it).
  std::atomic<int> running_plans_{0};
  /// Set when the node shuts down: running plans end at their next step.
  std::atomic<bool> stopping_plans_{false};
};

}  // namespace ros_adapter
}  // namespace brick_stack_sim
