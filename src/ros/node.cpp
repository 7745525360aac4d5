// The node's set-up and its stepping on the wall timer; the service handlers
// are in node_services.cpp, what it sends in state_publisher.cpp.
#include "brick_stack_sim/ros/node.h"

#include <algorithm>
#include <mutex>

#include "brick_stack_sim/core/allocation_guard.h"
#include "brick_stack_sim/core/options/parameter_value.h"
#include "time_text.h"

namespace brick_stack_sim {
namespace ros_adapter {

namespace {

StepPacer::Options pacerOptions(const NodeOptions& options) {
  StepPacer::Options pacing;
  pacing.time_step = options.config.world.time_step;
  pacing.real_time_factor = options.config.publish.real_time_factor;
  pacing.max_steps_per_tick = options.max_steps_per_tick;
  pacing.publish_rate = options.config.publish.rate;
  pacing.step_timer_rate = options.step_timer_rate;
  return pacing;
}

double wallNow() { return ros::WallTime::now().toSec(); }

}  // namespace

Status SimNode::create(const ros::NodeHandle& private_node_handle, const NodeOptions& options,
                       const BrickTypeLibrary& types, std::unique_ptr<SimNode>* node) {
  // Options built in code (tests, other programs) are checked like parameters.
  if (Status valid = validate(options.config.world); !valid) return prefixed("parameter ~", valid);
  if (Status valid = validate(options.config.publish); !valid)
    return prefixed("parameter ~", valid);
  if (Status valid = validateMaxConcurrentPlans(options.max_concurrent_plans); !valid) return valid;
  if (types.empty()) return Status::error("no brick types: check ~types_urdf");
  std::unique_ptr<SimNode> self(new SimNode(private_node_handle, options));
  if (Status created = Simulation::create(options.config.world, types, &self->simulation_);
      !created)
    return created;
  self->publisher_ = std::make_unique<StatePublisher>(self->node_handle_, options.config.publish,
                                                      self->world_mutex_, *self->simulation_);
  if (Status played = self->playInitialScene(); !played) return played;
  self->advertiseServices();
  {
    std::lock_guard<TicketMutex> lock(self->world_mutex_);
    self->restartPacing();
  }
  self->timer_rate_ = options.step_timer_rate;
  self->step_timer_ = self->node_handle_.createWallTimer(
      ros::WallDuration(1.0 / options.step_timer_rate), &SimNode::onStepTimer, self.get());
  self->logStart(types);
  *node = std::move(self);
  return Status::success();
}

SimNode::SimNode(const ros::NodeHandle& private_node_handle, const NodeOptions& options)
    : options_(options), pacer_(pacerOptions(options)), node_handle_(private_node_handle) {}

SimNode::~SimNode() {
  stopping_plans_ = true;
  if (long_work_spinner_) long_work_spinner_->stop();
  if (plan_spinner_) plan_spinner_->stop();
}

double SimNode::simTime() const { return simulation_->time(); }

// --- set-up ----------------------------------------------------------------------

Status SimNode::playInitialScene() {
  const std::string& initial_scene = options_.config.data.scene;
  if (initial_scene.empty()) return Status::success();
  Scene scene;
  std::string message;
  Status played = loadNamedScene(initial_scene, &scene);
  if (played) played = resetWorld(initial_scene, scene, &message);
  if (!played)
    return Status::error("parameter ~scene = '" + shortenForMessage(initial_scene, 200) +
                         "': " + played.message);
  ROS_INFO("%s", message.c_str());
  return Status::success();
}

template <typename Request, typename Response>
ros::ServiceServer SimNode::advertiseGuarded(const char* service,
                                             bool (SimNode::*handler)(Request&, Response&),
                                             ros::CallbackQueue* queue) {
  ros::AdvertiseServiceOptions options;
  options.init<Request, Response>(
      service, [this, service, handler](Request& request, Response& response) {
        bool answered = true;
        const Status guarded = refuseOnAllocationFailure("serving ~" + std::string(service), [&] {
          answered = (this->*handler)(request, response);
          return Status::success();
        });
        if (guarded) return answered;
        ROS_WARN_THROTTLE(1.0, "%s", guarded.message.c_str());
        response = Response();
        response.success = false;
        response.message = guarded.message;
        return true;
      });
  options.callback_queue = queue;
  return node_handle_.advertiseService(options);
}

void SimNode::advertiseServices() {
  // The long requests get their own queue and thread.
  long_work_spinner_ = std::make_unique<ros::AsyncSpinner>(1, &long_work_queue_);
  long_work_spinner_->start();
  // Plans get a queue of their own: one thread per plan that may run, and
  // one more that refuses the next request at once instead of queueing it
  // behind them. None of them holds up the short requests or ~step.
  plan_spinner_ =
      std::make_unique<ros::AsyncSpinner>(options_.max_concurrent_plans + 1, &plan_queue_);
  plan_spinner_->start();

  services_.push_back(advertiseGuarded(kPlaceBrickService, &SimNode::placeBrick));
  services_.push_back(advertiseGuarded(kRemoveBrickService, &SimNode::removeBrick));
  services_.push_back(advertiseGuarded(kResetService, &SimNode::reset, &long_work_queue_));
  services_.push_back(advertiseGuarded(kGetBricksService, &SimNode::getBricks));
  services_.push_back(advertiseGuarded(kPushBrickService, &SimNode::pushBrick));
  services_.push_back(advertiseGuarded(kQueryPlacementService, &SimNode::queryPlacement));
  services_.push_back(advertiseGuarded(kQueryPlacementsService, &SimNode::queryPlacements));
  services_.push_back(advertiseGuarded(kPauseService, &SimNode::pause));
  services_.push_back(advertiseGuarded(kStepService, &SimNode::step, &long_work_queue_));
  services_.push_back(advertiseGuarded(kGraspBrickService, &SimNode::graspBrick));
  services_.push_back(advertiseGuarded(kReleaseBrickService, &SimNode::releaseBrick));
  services_.push_back(advertiseGuarded(kSimulatePlanService, &SimNode::simulatePlan, &plan_queue_));
  held_target_subscriber_ =
      node_handle_.subscribe(kHeldTargetTopic, 10, &SimNode::onHeldTarget, this);
}

void SimNode::logStart(const BrickTypeLibrary& types) const {
  const NodeOptions& options = options_;
  ROS_INFO(
      "brick_sim: mode %s, time step %g s, %d iterations, real time factor %g%s, types: %zu "
      "(default %s)",
      options.config.world.stability.mode.c_str(), options.config.world.time_step,
      options.config.world.solver_iterations, options.config.publish.real_time_factor,
      options.config.publish.real_time_factor == 0.0 ? " (as fast as possible)" : "",
      types.names().size(), types.defaultType().c_str());
}

// --- stepping --------------------------------------------------------------------

void SimNode::restartPacing() { pacer_.restart(wallNow(), simTime()); }

void SimNode::onStepTimer(const ros::WallTimerEvent& /*event*/) {
  std::lock_guard<TicketMutex> lock(world_mutex_);
  const double publish_period = 1.0 / options_.config.publish.rate;
  if (resetting_) {
    // ~reset builds the next world: this one's clock stands still.
  } else if (!paused_) {
    stepTick();
  } else if (wallNow() >= publisher_->lastStateWall() + publish_period) {
    // Paused, the graph still sees the simulation, as Gazebo's does: a
    // client that joins now gets the clock and the state, at publish_rate
    // of wall time (a ~step publishing meanwhile counts).
    publisher_->publishClock();
    publisher_->markDirty();
  }
  adaptTimerRate();
  publisher_->publishEvents();
  // Running, the sim-time schedule publishes what changed; paused, changes
  // go out at most at publish_rate, however many requests made them.
  if (publisher_->dirty() && paused_ && wallNow() >= publisher_->lastStateWall() + publish_period)
    publishState();
}

void SimNode::stepTick() {
  const double start = wallNow();
  // Stepping stops after this share of the timer period so that services
  // are still answered when the world is too heavy for real time.
  const double deadline = start + options_.max_step_budget / options_.step_timer_rate;
  const double wanted = pacer_.stepsWanted(start, simTime());
  const long limit = pacer_.stepLimit(wanted);
  long done = 0;
  while (done < limit) {
    stepOnce();
    ++done;
    if (wallNow() > deadline) break;
  }
  if (pacer_.fellBehind(wanted, done)) {
    // A late tick is made up by the next ones; a lag this long means the
    // world is too heavy, and catching up would only come back as a burst:
    // keep the pace from here on.
    ROS_WARN_THROTTLE(10.0,
                      "the world cannot keep up with real_time_factor %g (%.0f steps behind); "
                      "sim time runs slower than requested",
                      options_.config.publish.real_time_factor, wanted - done);
    restartPacing();
  }
  if (done > 0) publisher_->publishClock();
}

void SimNode::advance() {
  simulation_->step();
  logRefusedPlacements(simulation_->takeRefused());
}

void SimNode::stepOnce() {
  advance();
  const double now = simTime();
  // Left due when the wall-time cap holds it back: the next step publishes it.
  if (!pacer_.publishDue(now, wallNow(), publisher_->lastStateWall())) return;
  publisher_->publishClock();
  publishState();
  pacer_.published(now);
}

void SimNode::adaptTimerRate() {
  // A settled world steps as cheaply 33 steps at a time as 5, and a paused
  // one only publishes at publish_rate: ticking at publish_rate instead of
  // step_timer_rate is most of what an idle node costs (the wake-ups, not
  // the steps). Not with real_time_factor 0, whose clock runs as fast as
  // the ticks let it, nor while /clock drives the graph: clients' sim-time
  // timers would fire no finer than the ticks.
  const PublishOptions& publish = options_.config.publish;
  const bool idle = paused_ || (publish.real_time_factor > 0.0 && !publish.clock &&
                                simulation_->world().settled() && simulation_->player().done());
  const double rate = pacer_.timerRate(idle);
  if (rate == timer_rate_) return;
  timer_rate_ = rate;
  step_timer_.setPeriod(ros::WallDuration(1.0 / rate), false);
}

void SimNode::publishState() {
  publisher_->publishState();
  // After a reset, ~get_bricks' mirror starts from the publisher's rather
  // than reading every brick again in the first call (a copy costs a fraction).
  if (answers_.forgotten()) answers_ = publisher_->mirror();
}

void SimNode::logRefusedPlacements(const std::vector<RefusedPlacement>& refused) {
  for (const RefusedPlacement& placement : refused) {
    ROS_WARN("scene placement of %s at %s refused: %s", placement.id.c_str(),
             formatTime(placement.t).c_str(), placement.reason.c_str());
  }
}

}  // namespace ros_adapter
}  // namespace brick_stack_sim
