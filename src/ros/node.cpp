#include "brick_stack_sim/ros/node.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <set>
#include <sstream>

#include <geometry_msgs/TransformStamped.h>
#include <rosgraph_msgs/Clock.h>
#include <visualization_msgs/MarkerArray.h>

#include "brick_stack_sim/BrickArray.h"
#include "brick_stack_sim/StabilityEvent.h"
#include "brick_stack_sim/core/scene/scene.h"
#include "brick_stack_sim/ros/conversions.h"
#include "brick_stack_sim/ros/markers.h"

namespace brick_stack_sim {
namespace ros_adapter {

namespace {

/// Wall time [s] the world may fall behind real_time_factor before the node
/// gives up catching up: longer than any scheduling hiccup, short enough that
/// a user sees sim time slow down rather than jump.
constexpr double kMaxLag = 0.1;

/// Wall time [s] a ~step keeps the world before it looks whether a client
/// waits for it: short against the 100 ms a client may wait, long against
/// the cost of a hand-over, so the step still makes progress under a flood.
constexpr double kStepSlice = 0.002;

/// ~bricks (with tf and markers) follows sim time, but never comes more often
/// than this many times publish_rate x max(1, real_time_factor) per second of
/// wall time: with real_time_factor 0 or during a ~step sim time runs far
/// ahead of wall time, and nobody can read thousands of messages a second.
constexpr double kMaxPublishRateRatio = 2.0;

std::string formatTime(double t) {
  std::ostringstream text;
  text.precision(3);
  text << std::fixed << "t=" << t << " s";
  return text.str();
}

}  // namespace

Status SimNode::create(const ros::NodeHandle& private_node_handle, const NodeOptions& options,
                       const BrickTypeLibrary& types, std::unique_ptr<SimNode>* node) {
  // Options built in code (tests, other programs) are checked like parameters.
  if (Status valid = validate(options.config.world); !valid) return prefixed("parameter ~", valid);
  if (Status valid = validate(options.config.publish); !valid)
    return prefixed("parameter ~", valid);
  if (types.empty()) return Status::error("no brick types: check ~types_urdf");
  std::unique_ptr<SimNode> result(new SimNode(private_node_handle, options));
  if (Status created = Simulation::create(options.config.world, types, &result->simulation_);
      !created)
    return created;

  SimNode& self = *result;
  ros::NodeHandle& nh = self.node_handle_;
  self.marker_updates_ = std::make_unique<MarkerUpdates>(options.config.publish.frame_id);
  // A new subscriber gets everything at once, alone: with deltas it could
  // not start otherwise, and a viewer that connects while nothing changes
  // (paused, or a fully frozen stack) would wait for the next change.
  self.bricks_publisher_ = nh.advertise<BrickArray>(
      kBricksTopic, 10,
      [&self](const ros::SingleSubscriberPublisher& s) { self.onBricksSubscriber(s); });
  self.events_publisher_ = nh.advertise<StabilityEvent>(kEventsTopic, kEventQueueSize);
  self.markers_publisher_ = nh.advertise<visualization_msgs::MarkerArray>(
      kMarkersTopic, 2,
      [&self](const ros::SingleSubscriberPublisher& s) { self.onMarkersSubscriber(s); });
  if (options.config.publish.clock) {
    self.clock_publisher_ = nh.advertise<rosgraph_msgs::Clock>(kClockTopic, 10);
    // Every stamp is then sim time; nodes on wall time would find tf and
    // ~bricks some 1.8e9 s in the past. /use_sim_time must be set before the
    // nodes start, so this node can only say so.
    if (!ros::Time::isSimTime())
      ROS_WARN(
          "publish_clock is true but /use_sim_time is not: this node stamps everything in sim "
          "time while nodes started without /use_sim_time read wall time; set /use_sim_time "
          "before starting the nodes (sim.launch does with publish_clock:=true)");
  }

  const std::string& initial_scene = options.config.data.scene;
  if (!initial_scene.empty()) {
    Scene scene;
    std::string message;
    Status played = self.loadNamedScene(initial_scene, &scene);
    if (played) {
      std::lock_guard<TicketMutex> lock(self.world_mutex_);
      played = self.resetWorld(initial_scene, scene, &message);
    }
    if (!played)
      return Status::error("parameter ~scene = '" + initial_scene + "': " + played.message);
    ROS_INFO("%s", message.c_str());
  }

  // The long requests get their own queue and thread.
  ros::AdvertiseServiceOptions step_options;
  step_options.init<StepSimulation::Request, StepSimulation::Response>(
      kStepService, [&self](StepSimulation::Request& request, StepSimulation::Response& response) {
        return self.step(request, response);
      });
  step_options.callback_queue = &self.long_work_queue_;
  ros::AdvertiseServiceOptions reset_options;
  reset_options.init<ResetScene::Request, ResetScene::Response>(
      kResetService, [&self](ResetScene::Request& request, ResetScene::Response& response) {
        return self.reset(request, response);
      });
  reset_options.callback_queue = &self.long_work_queue_;
  self.long_work_spinner_ = std::make_unique<ros::AsyncSpinner>(1, &self.long_work_queue_);
  self.long_work_spinner_->start();

  self.services_.push_back(nh.advertiseService(kPlaceBrickService, &SimNode::placeBrick, &self));
  self.services_.push_back(nh.advertiseService(kRemoveBrickService, &SimNode::removeBrick, &self));
  self.services_.push_back(nh.advertiseService(reset_options));
  self.services_.push_back(nh.advertiseService(kGetBricksService, &SimNode::getBricks, &self));
  self.services_.push_back(nh.advertiseService(kPushBrickService, &SimNode::pushBrick, &self));
  self.services_.push_back(
      nh.advertiseService(kQueryPlacementService, &SimNode::queryPlacement, &self));
  self.services_.push_back(nh.advertiseService(kPauseService, &SimNode::pause, &self));
  self.services_.push_back(nh.advertiseService(step_options));
  self.services_.push_back(nh.advertiseService(kGraspBrickService, &SimNode::graspBrick, &self));
  self.services_.push_back(
      nh.advertiseService(kReleaseBrickService, &SimNode::releaseBrick, &self));
  self.held_target_subscriber_ = nh.subscribe(kHeldTargetTopic, 10, &SimNode::onHeldTarget, &self);

  self.transforms_ = std::make_unique<BrickTransforms>(nh, options.config.publish.frame_id,
                                                       options.config.publish.frame_prefix,
                                                       kStaticTransformsPeriod);
  self.transforms_->clear(self.stamp());
  {
    std::lock_guard<TicketMutex> lock(self.world_mutex_);
    self.restartPacing();
  }
  self.timer_rate_ = options.step_timer_rate;
  self.step_timer_ = nh.createWallTimer(ros::WallDuration(1.0 / options.step_timer_rate),
                                        &SimNode::onStepTimer, &self);
  ROS_INFO(
      "brick_sim: mode %s, time step %g s, %d iterations, real time factor %g%s, types: %zu "
      "(default %s)",
      options.config.world.stability.mode.c_str(), options.config.world.time_step,
      options.config.world.solver_iterations, options.config.publish.real_time_factor,
      options.config.publish.real_time_factor == 0.0 ? " (as fast as possible)" : "",
      types.names().size(), types.defaultType().c_str());
  *node = std::move(result);
  return Status::success();
}

SimNode::SimNode(const ros::NodeHandle& private_node_handle, const NodeOptions& options)
    : options_(options), node_handle_(private_node_handle) {}

SimNode::~SimNode() {
  if (long_work_spinner_) long_work_spinner_->stop();
}

double SimNode::simTime() const { return simulation_->time(); }

// --- stepping ------------------------------------------------------------------

void SimNode::restartPacing() {
  pacing_wall_start_ = ros::WallTime::now();
  pacing_sim_start_ = simTime();
}

void SimNode::onStepTimer(const ros::WallTimerEvent& /*event*/) {
  std::lock_guard<TicketMutex> lock(world_mutex_);
  if (!paused_) {
    const ros::WallTime start = ros::WallTime::now();
    // Stepping stops after this share of the timer period so that services
    // are still answered when the world is too heavy for real time.
    const ros::WallTime deadline =
        start + ros::WallDuration(options_.max_step_budget / options_.step_timer_rate);
    const double time_step = options_.config.world.time_step;
    double wanted = options_.max_steps_per_tick;
    if (options_.config.publish.real_time_factor > 0.0) {
      const double target = pacing_sim_start_ + (start - pacing_wall_start_).toSec() *
                                                    options_.config.publish.real_time_factor;
      // The small epsilon keeps a step that is due "exactly now" from slipping
      // to the next tick through rounding.
      wanted = std::max(0.0, std::floor((target - simTime()) / time_step + 1e-6));
    }
    const long limit = static_cast<long>(std::min<double>(wanted, options_.max_steps_per_tick));
    long done = 0;
    while (done < limit) {
      stepOnce();
      ++done;
      if (ros::WallTime::now() > deadline) break;
    }
    const double lag =
        (wanted - done) * time_step / std::max(options_.config.publish.real_time_factor, 1e-9);
    if (options_.config.publish.real_time_factor > 0.0 && lag > kMaxLag) {
      // A late tick is made up by the next ones; a lag this long means the
      // world is too heavy, and catching up would only come back as a burst:
      // keep the pace from here on.
      ROS_WARN_THROTTLE(10.0,
                        "the world cannot keep up with real_time_factor %g (%.0f steps behind); "
                        "sim time runs slower than requested",
                        options_.config.publish.real_time_factor, wanted - done);
      restartPacing();
    }
    if (done > 0) publishClock();
  } else if (ros::WallTime::now() >=
             last_state_publish_ + ros::WallDuration(1.0 / options_.config.publish.rate)) {
    // Paused, the graph still sees the simulation, as Gazebo's does: a
    // client that joins now gets the clock and the state, at publish_rate
    // of wall time (a ~step publishing meanwhile counts).
    publishClock();
    state_dirty_ = true;
  }
  adaptTimerRate();
  publishEvents();
  // Running, the sim-time schedule publishes what changed; paused, changes
  // go out at most at publish_rate, however many requests made them.
  if (state_dirty_ && paused_ &&
      ros::WallTime::now() >=
          last_state_publish_ + ros::WallDuration(1.0 / options_.config.publish.rate))
    publishState();
}

void SimNode::advance() {
  simulation_->step();
  logRefusedPlacements(simulation_->takeRefused());
}

void SimNode::stepOnce() {
  advance();
  const double now = simTime();
  if (now + 1e-9 < next_publish_time_) return;
  const double fastest = kMaxPublishRateRatio * options_.config.publish.rate *
                         std::max(1.0, options_.config.publish.real_time_factor);
  // Left due: the next step after the cap publishes it.
  if (ros::WallTime::now() < last_state_publish_ + ros::WallDuration(1.0 / fastest)) return;
  publishClock();
  publishState();
  const double period = 1.0 / options_.config.publish.rate;
  next_publish_time_ += period;
  if (next_publish_time_ <= now) next_publish_time_ = now + period;
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
  const double rate =
      idle ? std::min(publish.rate, options_.step_timer_rate) : options_.step_timer_rate;
  if (rate == timer_rate_) return;
  timer_rate_ = rate;
  step_timer_.setPeriod(ros::WallDuration(1.0 / rate), false);
}

// --- publishing ------------------------------------------------------------------

ros::Time SimNode::stamp() const {
  return options_.config.publish.clock ? ros::Time(simTime()) : ros::Time::now();
}

void SimNode::publishClock() {
  if (!options_.config.publish.clock) return;
  rosgraph_msgs::Clock clock;
  clock.clock = ros::Time(simTime());
  clock_publisher_.publish(clock);
}

void SimNode::publishEvents() {
  for (const SimEvent& event : simulation_->takeEvents()) {
    StabilityEvent msg = toMsg(event);
    const double t = event.time;
    msg.header.stamp =
        options_.config.publish.clock && std::isfinite(t) && t >= 0.0 ? ros::Time(t) : stamp();
    msg.header.frame_id = options_.config.publish.frame_id;
    if (event.kind == SimEventKind::kNonFinite) {
      // NaN, Inf or a runaway speed: the reason says which and how it was repaired.
      ROS_WARN("brick %s at %s: %s", event.brick_id.c_str(), formatTime(t).c_str(),
               event.reason.c_str());
    }
    events_publisher_.publish(msg);
  }
}

void SimNode::publishState() {
  state_dirty_ = false;
  last_state_publish_ = ros::WallTime::now();
  const ros::Time now = stamp();
  // The world names what may have changed; only that is read, compared and sent.
  const BrickMirror::Changes changes = mirror_.update(simulation_->world());
  // After a reset, ~get_bricks' mirror starts from this one rather than
  // reading every brick again in the first call (a copy costs a fraction).
  if (answers_.forgotten()) answers_ = mirror_;
  int not_finite = 0;
  transforms_->publish(mirror_, changes, now, &not_finite);
  if (not_finite > 0) ROS_WARN_THROTTLE(5.0, "%d bricks left off tf: pose not finite", not_finite);
  for (std::size_t index : changes.changed) {
    const MirroredBrick& brick = mirror_.bricks()[index];
    if (!brick.finite)
      ROS_WARN_THROTTLE(5.0, "not published: brick %s has a number that is not finite",
                        brick.snapshot.id.c_str());
  }
  if (bricks_publisher_.getNumSubscribers() > 0) {
    ++bricks_sequence_;
    bricks_publisher_.publish(
        makeBrickArray(options_.config.publish.bricks_delta ? &changes : nullptr, now));
  }
  if (markers_publisher_.getNumSubscribers() > 0) {
    // The world's table, not the parameters': a scene may bring its own.
    if (changes.replaced || markers_full_due_) {
      markers_publisher_.publish(
          marker_updates_->full(mirror_, simulation_->world().options().table, now));
      markers_full_due_ = false;
    } else {
      visualization_msgs::MarkerArray update = marker_updates_->delta(mirror_, changes, now);
      if (!update.markers.empty()) markers_publisher_.publish(update);
    }
  } else {
    markers_full_due_ = true;  // what viewers show is no longer followed
  }
}

BrickArray SimNode::makeBrickArray(const BrickMirror::Changes* changes,
                                   const ros::Time& stamp) const {
  BrickArray array;
  array.header.stamp = stamp;
  array.header.frame_id = options_.config.publish.frame_id;
  array.sequence = bricks_sequence_;
  const std::vector<MirroredBrick>& bricks = mirror_.bricks();
  if (!changes) {
    array.kind = BrickArray::FULL;
    array.bricks.reserve(bricks.size());
    for (const MirroredBrick& brick : bricks)
      if (brick.finite) array.bricks.push_back(brick.msg);
    return array;
  }
  array.kind = BrickArray::DELTA;
  for (const MirroredBrick& gone : changes->removed) array.removed.push_back(gone.snapshot.id);
  for (std::size_t index : changes->changed) {
    const MirroredBrick& brick = bricks[index];
    // One that stopped being finite leaves the subscriber's view, as it
    // leaves a full array, until it is again.
    if (brick.finite) {
      array.bricks.push_back(brick.msg);
    } else {
      array.removed.push_back(brick.snapshot.id);
    }
  }
  return array;
}

void SimNode::onBricksSubscriber(const ros::SingleSubscriberPublisher& subscriber) {
  std::lock_guard<TicketMutex> lock(world_mutex_);
  subscriber.publish(makeBrickArray(nullptr, stamp()));
}

void SimNode::onMarkersSubscriber(const ros::SingleSubscriberPublisher& subscriber) {
  std::lock_guard<TicketMutex> lock(world_mutex_);
  // From the mirror, which every other viewer shows: the deltas that follow
  // apply to this viewer as to them.
  subscriber.publish(marker_updates_->full(mirror_, simulation_->world().options().table, stamp()));
  markers_full_due_ = false;
}

void SimNode::logRefusedPlacements(const std::vector<RefusedPlacement>& refused) {
  for (const RefusedPlacement& placement : refused) {
    ROS_WARN("scene placement of %s at %s refused: %s", placement.id.c_str(),
             formatTime(placement.t).c_str(), placement.reason.c_str());
  }
}

// --- services --------------------------------------------------------------------

template <typename Response>
bool SimNode::refuse(const char* service, const Status& status, Response* response) {
  // The caller has the message; the log only shows that refusals happen, so
  // a client that floods bad requests does not flood the log.
  ROS_INFO_THROTTLE(1.0, "~%s refused: %s", service, status.message.c_str());
  response->success = false;
  response->message = status.message;
  return true;
}

bool SimNode::placeBrick(PlaceBrick::Request& request, PlaceBrick::Response& response) {
  BrickPlacement placement;
  if (Status converted = fromMsg(request, &placement); !converted)
    return refuse(kPlaceBrickService, converted, &response);
  std::lock_guard<TicketMutex> lock(world_mutex_);
  std::string id;
  if (Status added = simulation_->world().addBrick(placement, &id); !added)
    return refuse(kPlaceBrickService, added, &response);
  response.success = true;
  response.id = id;
  response.message = "placed " + id + " at " + formatTime(simTime());
  state_dirty_ = true;
  publishEvents();
  return true;
}

bool SimNode::queryPlacement(QueryPlacement::Request& request, QueryPlacement::Response& response) {
  BrickPlacement placement;
  placement.type = request.type;
  if (Status converted = fromMsg(request.pose, "pose", &placement.pose); !converted)
    return refuse(kQueryPlacementService, converted, &response);
  PlacementReport report;
  {
    std::lock_guard<TicketMutex> lock(world_mutex_);
    if (Status answered = simulation_->world().evaluatePlacement(placement, &report); !answered)
      return refuse(kQueryPlacementService, answered, &response);
  }
  response.success = true;
  response.message = report.reason;
  response.stable = report.stable;
  response.state = static_cast<std::uint8_t>(report.state);
  response.margin = report.margin;
  response.acceleration_margin = report.acceleration_margin;
  response.supported_by = report.supported_by;
  response.would_fall = report.would_fall;
  return true;
}

bool SimNode::removeBrick(RemoveBrick::Request& request, RemoveBrick::Response& response) {
  std::lock_guard<TicketMutex> lock(world_mutex_);
  if (Status removed = simulation_->world().removeBrick(request.id); !removed)
    return refuse(kRemoveBrickService, removed, &response);
  response.success = true;
  response.message = "removed " + request.id;
  state_dirty_ = true;
  publishEvents();
  return true;
}

Status SimNode::loadNamedScene(const std::string& scene_name, Scene* scene) const {
  if (scene_name.empty()) return Status::success();
  // The types of the simulation, not of its current world: they never change.
  return loadScene(scene_name, options_.config.data.scene_dirs, simulation_->types(), scene,
                   options_.config.data.scene_max_bytes);
}

Status SimNode::resetWorld(const std::string& scene_name, const Scene& scene,
                           std::string* message) {
  if (Status reset = simulation_->reset(scene); !reset)
    return Status::error("scene '" + scene_name + "': " + reset.message);
  publishEvents();   // the removed events, then the new scene's first placements
  mirror_.forget();  // a new world: its serials and revisions start again
  answers_.forget();
  const std::vector<RefusedPlacement> refused = simulation_->takeRefused();
  logRefusedPlacements(refused);
  state_dirty_ = true;
  next_publish_time_ = simTime();
  restartPacing();

  std::ostringstream text;
  if (scene_name.empty()) {
    text << "cleared the table at " << formatTime(simTime());
  } else {
    text << "playing scene '" << (scene.name.empty() ? scene_name : scene.name) << "' from "
         << formatTime(simTime()) << ": " << scene.bricks.size() << " bricks scheduled";
    if (!refused.empty()) text << ", " << refused.size() << " refused at once (see the log)";
  }
  *message = text.str();
  return Status::success();
}

bool SimNode::reset(ResetScene::Request& request, ResetScene::Response& response) {
  // Reading and checking a big scene takes a while: others are served meanwhile.
  Scene scene;
  if (Status loaded = loadNamedScene(request.scene, &scene); !loaded)
    return refuse(kResetService, loaded, &response);
  std::string message;
  {
    std::lock_guard<TicketMutex> lock(world_mutex_);
    if (Status done = resetWorld(request.scene, scene, &message); !done)
      return refuse(kResetService, done, &response);
  }
  ROS_INFO("%s", message.c_str());
  response.success = true;
  response.message = message;
  response.bricks_scheduled = static_cast<unsigned>(scene.bricks.size());
  return true;
}

bool SimNode::getBricks(GetBricks::Request& request, GetBricks::Response& response) {
  std::set<std::string> asked;
  for (const std::string& id : request.ids)
    if (!asked.insert(id).second)
      return refuse(kGetBricksService,
                    Status::error("brick id '" + id + "' asked for twice: ask once"), &response);
  std::vector<BrickSnapshot> bricks;
  double time = 0.0;
  std::size_t left_out = 0;
  {
    std::lock_guard<TicketMutex> lock(world_mutex_);
    if (request.ids.empty()) {
      // Every brick, from a mirror of its own: what changed since the last
      // call is read, the rest is a copy of messages already built.
      answers_.update(simulation_->world());
      response.bricks.reserve(answers_.bricks().size());
      for (const MirroredBrick& brick : answers_.bricks()) {
        if (brick.finite) {
          response.bricks.push_back(brick.msg);
        } else {
          ++left_out;
        }
      }
    } else {
      bricks.resize(request.ids.size());
      for (std::size_t i = 0; i < request.ids.size(); ++i)
        if (!simulation_->world().find(request.ids[i], &bricks[i]))
          return refuse(kGetBricksService,
                        Status::error("no brick with id '" + request.ids[i] + "'"), &response);
    }
    time = simTime();
    response.header.stamp = stamp();
  }
  response.header.frame_id = options_.config.publish.frame_id;
  for (const BrickSnapshot& brick : bricks) {
    Brick msg;
    if (Status converted = toMsg(brick, &msg); !converted) {
      ROS_WARN_THROTTLE(5.0, "not published: %s", converted.message.c_str());
      ++left_out;
      continue;
    }
    response.bricks.push_back(std::move(msg));
  }
  response.success = true;
  response.message = std::to_string(response.bricks.size()) + " bricks at " + formatTime(time);
  if (left_out > 0) response.message += "; " + std::to_string(left_out) + " left out: not finite";
  return true;
}

bool SimNode::pushBrick(PushBrick::Request& request, PushBrick::Response& response) {
  Eigen::Vector3d impulse;
  Eigen::Vector3d point;
  if (Status converted = fromMsg(request, &impulse, &point); !converted)
    return refuse(kPushBrickService, converted, &response);
  std::lock_guard<TicketMutex> lock(world_mutex_);
  // An all-zero point is a message whose point nobody filled in: the centre.
  BrickSnapshot brick;
  if (point.isZero() && simulation_->world().find(request.id, &brick))
    point = brick.pose.translation();
  if (Status pushed = simulation_->world().applyImpulse(request.id, impulse, point); !pushed)
    return refuse(kPushBrickService, pushed, &response);
  response.success = true;
  response.message = "pushed " + request.id;
  state_dirty_ = true;
  publishEvents();
  return true;
}

bool SimNode::pause(std_srvs::SetBool::Request& request, std_srvs::SetBool::Response& response) {
  std::lock_guard<TicketMutex> lock(world_mutex_);
  response.success = true;
  if (request.data == paused_) {
    response.message = paused_ ? "already paused" : "already running";
    return true;
  }
  paused_ = request.data;
  if (!paused_) restartPacing();  // wall time spent paused is not owed to the world
  response.message = (paused_ ? "paused at " : "resumed at ") + formatTime(simTime());
  ROS_INFO("%s", response.message.c_str());
  return true;
}

bool SimNode::step(StepSimulation::Request& request, StepSimulation::Response& response) {
  std::unique_lock<TicketMutex> lock(world_mutex_);
  response.sim_time = simTime();
  if (!paused_)
    return refuse(kStepService,
                  Status::error("the simulation is running: pause it with ~pause first"),
                  &response);
  if (request.steps == 0)
    return refuse(kStepService, Status::error("steps = 0: must be at least 1"), &response);
  if (request.steps > kMaxStepsPerRequest)
    return refuse(kStepService,
                  Status::error("steps = " + std::to_string(request.steps) + ": at most " +
                                std::to_string(kMaxStepsPerRequest) + " per request"),
                  &response);
  // Published at publish_rate of wall time, not of sim time: a million steps
  // would otherwise send tens of thousands of messages in a few seconds.
  const ros::WallDuration publish_period(1.0 / options_.config.publish.rate);
  const ros::WallDuration slice(kStepSlice);
  ros::WallTime next_publish = ros::WallTime::now() + publish_period;
  ros::WallTime slice_end = ros::WallTime::now() + slice;
  unsigned done = 0;
  std::string interrupted;
  while (done < request.steps) {
    advance();
    ++done;
    const ros::WallTime now = ros::WallTime::now();
    if (now >= next_publish) {
      publishClock();
      publishEvents();
      publishState();
      next_publish = now + publish_period;
    }
    if (done == request.steps || now < slice_end) continue;
    if (!ros::ok()) {
      interrupted = "the node is shutting down";
      break;
    }
    if (world_mutex_.contended()) {
      // The ticket lock puts this thread behind everyone who asked meanwhile.
      lock.unlock();
      lock.lock();
      if (!paused_) {
        interrupted = "another client resumed the simulation";
        break;
      }
    }
    slice_end = ros::WallTime::now() + slice;
  }
  publishClock();
  publishEvents();
  publishState();
  response.sim_time = simTime();
  if (!interrupted.empty()) {
    return refuse(kStepService,
                  Status::error("stopped after " + std::to_string(done) + " of " +
                                std::to_string(request.steps) + " steps at " +
                                formatTime(simTime()) + ": " + interrupted),
                  &response);
  }
  response.success = true;
  response.message = "stepped " + std::to_string(request.steps) + " to " + formatTime(simTime());
  return true;
}

bool SimNode::graspBrick(GraspBrick::Request& request, GraspBrick::Response& response) {
  std::lock_guard<TicketMutex> lock(world_mutex_);
  if (Status grasped = simulation_->world().graspBrick(request.id); !grasped)
    return refuse(kGraspBrickService, grasped, &response);
  response.success = true;
  response.message = "holding " + request.id + ": it follows ~" + kHeldTargetTopic;
  state_dirty_ = true;
  publishEvents();
  return true;
}

bool SimNode::releaseBrick(ReleaseBrick::Request& request, ReleaseBrick::Response& response) {
  Eigen::Vector3d linear, angular;
  if (Status converted = fromMsg(request.twist, "twist", &linear, &angular); !converted)
    return refuse(kReleaseBrickService, converted, &response);
  std::lock_guard<TicketMutex> lock(world_mutex_);
  if (Status released = simulation_->world().releaseBrick(request.id, linear, angular); !released)
    return refuse(kReleaseBrickService, released, &response);
  response.success = true;
  response.message = "released " + request.id;
  state_dirty_ = true;
  publishEvents();
  return true;
}

void SimNode::onHeldTarget(const geometry_msgs::PoseStamped::ConstPtr& target) {
  const std::string& frame = options_.config.publish.frame_id;
  if (!target->header.frame_id.empty() && target->header.frame_id != frame) {
    ROS_WARN_THROTTLE(2.0, "~%s ignored: frame '%s', expected '%s'", kHeldTargetTopic,
                      target->header.frame_id.c_str(), frame.c_str());
    return;
  }
  Eigen::Isometry3d pose;
  Status accepted = fromMsg(target->pose, "pose", &pose);
  if (accepted) {
    std::lock_guard<TicketMutex> lock(world_mutex_);
    accepted = simulation_->world().setHeldTarget(pose);
  }
  if (!accepted)
    ROS_WARN_THROTTLE(2.0, "~%s ignored: %s", kHeldTargetTopic, accepted.message.c_str());
}

}  // namespace ros_adapter
}  // namespace brick_stack_sim
