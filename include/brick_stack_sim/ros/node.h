#pragma once

#include <memory>
#include <string>
#include <vector>

#include <geometry_msgs/PoseStamped.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <std_srvs/SetBool.h>

#include "brick_stack_sim/BrickArray.h"
#include "brick_stack_sim/GetBricks.h"
#include "brick_stack_sim/GraspBrick.h"
#include "brick_stack_sim/PlaceBrick.h"
#include "brick_stack_sim/PushBrick.h"
#include "brick_stack_sim/QueryPlacement.h"
#include "brick_stack_sim/ReleaseBrick.h"
#include "brick_stack_sim/RemoveBrick.h"
#include "brick_stack_sim/ResetScene.h"
#include "brick_stack_sim/StepSimulation.h"
#include "brick_stack_sim/core/brick_type.h"
#include "brick_stack_sim/core/scene/scene.h"
#include "brick_stack_sim/core/status.h"
#include "brick_stack_sim/core/world/simulation.h"
#include "brick_stack_sim/ros/brick_mirror.h"
#include "brick_stack_sim/ros/brick_transforms.h"
#include "brick_stack_sim/ros/marker_updates.h"
#include "brick_stack_sim/ros/node_options.h"
#include "brick_stack_sim/ros/ticket_mutex.h"

namespace brick_stack_sim {
namespace ros_adapter {

// Names of DESIGN.md section 3, relative to the node's private namespace
// (`~bricks` is kBricksTopic on a ros::NodeHandle("~")) except the clock.
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
constexpr char kPauseService[] = "pause";
constexpr char kStepService[] = "step";
constexpr char kGraspBrickService[] = "grasp_brick";
constexpr char kReleaseBrickService[] = "release_brick";

/// Most steps one ~step request may ask for: 1e6 steps are 1000 s of sim time
/// at the default step (seconds to minutes of wall time; other clients are
/// served meanwhile).
constexpr unsigned kMaxStepsPerRequest = 1000000;
/// Threads serving the short requests, the step timer and ~held_target
/// (main() spins them): a ~get_bricks is answered while a ~place_brick
/// waits for the world.
constexpr int kServiceThreads = 4;
/// Events queued per subscriber before the oldest is dropped: a reset of a
/// large scene emits a removed and a spawned event per brick in one burst.
constexpr int kEventQueueSize = 10000;
/// Wall time [s] between two sends of the resting bricks on /tf_static: each
/// is the whole set, and only listeners that join later need it.
constexpr double kStaticTransformsPeriod = 1.0;

/// The ROS face of a Simulation: publishes its state, serves its requests and
/// steps it on a wall timer so that sim time follows wall time times
/// `real_time_factor`. Each request is checked and then handed to one core
/// call, which changes nothing when it refuses.
///
/// Threads: the short requests and the timer run on the global callback queue,
/// which main() spins with kServiceThreads threads; ~step and ~reset, which may
/// take seconds, run on a queue of their own with one thread, so they never
/// hold up the others. The world and everything the node keeps about it are
/// guarded by one fair lock (world_mutex_), taken once per request or tick, so
/// requests and steps never interleave; a long ~step hands the lock over
/// between steps whenever someone waits for it.
class SimNode {
 public:
  /// Creates the simulation, advertises every topic and service and, when
  /// the parameter `scene` is set, plays that scene; fails (and advertises
  /// nothing) when the simulation or the scene cannot be created.
  static Status create(const ros::NodeHandle& private_node_handle, const NodeOptions& options,
                       const BrickTypeLibrary& types, std::unique_ptr<SimNode>* node);

  SimNode(const SimNode&) = delete;
  SimNode& operator=(const SimNode&) = delete;
  /// Stops the long-work thread before the world it uses goes away.
  ~SimNode();

 private:
  SimNode(const ros::NodeHandle& private_node_handle, const NodeOptions& options);

  // Every member function below but the service handlers, onStepTimer and
  // onHeldTarget expects world_mutex_ to be held by the caller.

  /// Sim time [s]; never goes backwards, across resets included.
  double simTime() const;

  // --- stepping --------------------------------------------------------------
  void onStepTimer(const ros::WallTimerEvent& event);
  /// One world step with the scene's due placements.
  void advance();
  /// advance(), then the state publication when it is due in sim time and
  /// the wall-time cap allows it (node.cpp says why there is a cap).
  void stepOnce();
  /// The timer ticks at publish_rate while the world is settled, else at
  /// step_timer_rate.
  void adaptTimerRate();
  /// Restarts the wall/sim time pacing from now (after a pause, a reset, or
  /// when the world cannot keep up).
  void restartPacing();

  // --- publishing ------------------------------------------------------------
  ros::Time stamp() const;
  void publishEvents();
  /// Brings the mirror up to the world and sends what changed: tf always,
  /// ~bricks and ~markers while subscribed.
  void publishState();
  /// ~bricks: every brick, or (bricks_delta) what `changes` found.
  BrickArray makeBrickArray(const BrickMirror::Changes* changes, const ros::Time& stamp) const;
  /// A new subscriber starts from every brick, or every marker: sent to it
  /// alone, from the mirror, so that it then follows the others' updates.
  void onBricksSubscriber(const ros::SingleSubscriberPublisher& subscriber);
  void onMarkersSubscriber(const ros::SingleSubscriberPublisher& subscriber);
  void publishClock();
  void logRefusedPlacements(const std::vector<RefusedPlacement>& refused);

  // --- services: one handler each; they always return true so the caller
  // gets success and message, false would only say "call failed".
  bool placeBrick(PlaceBrick::Request& request, PlaceBrick::Response& response);
  bool removeBrick(RemoveBrick::Request& request, RemoveBrick::Response& response);
  bool reset(ResetScene::Request& request, ResetScene::Response& response);
  bool getBricks(GetBricks::Request& request, GetBricks::Response& response);
  bool pushBrick(PushBrick::Request& request, PushBrick::Response& response);
  bool queryPlacement(QueryPlacement::Request& request, QueryPlacement::Response& response);
  bool pause(std_srvs::SetBool::Request& request, std_srvs::SetBool::Response& response);
  bool step(StepSimulation::Request& request, StepSimulation::Response& response);
  bool graspBrick(GraspBrick::Request& request, GraspBrick::Response& response);
  bool releaseBrick(ReleaseBrick::Request& request, ReleaseBrick::Response& response);

  /// ~held_target: where the held brick goes. A target in another frame, not
  /// finite, or with nothing held is ignored with a (throttled) warning.
  void onHeldTarget(const geometry_msgs::PoseStamped::ConstPtr& target);

  /// Reads the scene `scene_name` (empty: no bricks); touches nothing of the
  /// world, so it runs without the lock.
  Status loadNamedScene(const std::string& scene_name, Scene* scene) const;
  /// Empties the table (scene empty) or replaces the bricks by the scene's;
  /// on failure nothing changes. `message` receives what was done.
  Status resetWorld(const std::string& scene_name, const Scene& scene, std::string* message);
  /// Logs a refused request at INFO (at most once a second) and fills the response fields.
  template <typename Response>
  bool refuse(const char* service, const Status& status, Response* response);

  NodeOptions options_;

  /// Guards simulation_ and every member after it up to the ROS handles.
  TicketMutex world_mutex_;
  std::unique_ptr<Simulation> simulation_;

  bool paused_ = false;
  /// Something changed that ~bricks has not shown yet.
  bool state_dirty_ = true;
  /// The world as last published, and what viewers of ~markers show of it.
  BrickMirror mirror_;
  /// The world as ~get_bricks last answered (a mirror apart: an answer
  /// must not hide a change from the next publish).
  BrickMirror answers_;
  std::unique_ptr<MarkerUpdates> marker_updates_;
  /// The next ~markers is a full array for every viewer (after a reset).
  bool markers_full_due_ = true;
  /// BrickArray::sequence of the last ~bricks sent to every subscriber.
  std::uint32_t bricks_sequence_ = 0;
  double next_publish_time_ = 0.0;    ///< Sim time of the next ~bricks [s].
  ros::WallTime last_state_publish_;  ///< Wall time of the last ~bricks.
  ros::WallTime pacing_wall_start_;
  double pacing_sim_start_ = 0.0;  ///< [s]

  ros::NodeHandle node_handle_;
  ros::Publisher bricks_publisher_;
  ros::Publisher events_publisher_;
  ros::Publisher markers_publisher_;
  ros::Publisher clock_publisher_;
  /// /tf for what moved, latched /tf_static for the table and what rests.
  std::unique_ptr<BrickTransforms> transforms_;
  std::vector<ros::ServiceServer> services_;
  ros::Subscriber held_target_subscriber_;
  ros::WallTimer step_timer_;
  double timer_rate_ = 0.0;  ///< Its current rate [Hz].
  /// ~step and ~reset: served by their own thread.
  ros::CallbackQueue long_work_queue_;
  std::unique_ptr<ros::AsyncSpinner> long_work_spinner_;
};

}  // namespace ros_adapter
}  // namespace brick_stack_sim
