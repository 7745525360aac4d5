// The node's service handlers and ~held_target: each request is checked,
// then handed to one core call under the world lock, which changes nothing
// when it refuses.
#include <mutex>
#include <set>
#include <sstream>

#include "brick_stack_sim/ros/conversions.h"
#include "brick_stack_sim/ros/node.h"
#include "time_text.h"

namespace brick_stack_sim {
namespace ros_adapter {

namespace {

/// Wall time [s] a ~step keeps the world before it looks whether a client
/// waits for it: short against the 100 ms a client may wait, long against
/// the cost of a hand-over, so the step still makes progress under a flood.
constexpr double kStepSlice = 0.002;

}  // namespace

template <typename Response>
bool SimNode::refuse(const char* service, const Status& status, Response* response) {
  // The caller has the message; the log only shows that refusals happen, so
  // a client that floods bad requests does not flood the log.
  ROS_INFO_THROTTLE(1.0, "~%s refused: %s", service, status.message.c_str());
  response->success = false;
  response->message = status.message;
  return true;
}
// ~simulate_plan (node_plans.cpp) refuses the same way.
template bool SimNode::refuse(const char*, const Status&, SimulatePlan::Response*);

void SimNode::changed() {
  publisher_->markDirty();
  publisher_->publishEvents();
}

bool SimNode::placeBrick(PlaceBrick::Request& request, PlaceBrick::Response& response) {
  BrickPlacement placement;
  if (Status converted = fromMsg(request, &placement); !converted)
    return refuse(kPlaceBrickService, converted, &response);
  // tf is the adapter's: the core knows no fixed frame (docs/design.md, "Layers").
  if (Status framed = publisher_->frames().checkBrickId(placement.id); !framed)
    return refuse(kPlaceBrickService, framed, &response);
  std::lock_guard<TicketMutex> lock(world_mutex_);
  std::string id;
  // Bricks placed while paused are placed at one instant: the structure is
  // judged as a whole when the world steps (docs/ros_interface.md, "Services").
  if (Status added = simulation_->world().addBrick(placement, &id, paused_); !added)
    return refuse(kPlaceBrickService, added, &response);
  response.success = true;
  response.id = id;
  response.message = "placed " + id + " at " + formatTime(simTime());
  changed();
  return true;
}

namespace {

/// What ~query_placement answers and ~query_placements answers per pose.
template <typename Answer>
void fillAnswer(const PlacementReport& report, Answer* answer) {
  answer->message = report.reason;
  answer->stable = report.stable;
  answer->state = static_cast<std::uint8_t>(report.state);
  answer->margin = report.margin;
  answer->acceleration_margin = report.acceleration_margin;
  answer->supported_by = report.supported_by;
  answer->would_fall = report.would_fall;
}

/// Most poses one ~query_placements may ask about: a planner's candidates,
/// not a map of the table (10^5 verdicts are some 10 MB).
constexpr std::size_t kMaxQueriedPoses = 100000;

}  // namespace

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
  fillAnswer(report, &response);
  return true;
}

bool SimNode::queryPlacements(QueryPlacements::Request& request,
                              QueryPlacements::Response& response) {
  const std::size_t count = request.poses.size();
  if (count > kMaxQueriedPoses)
    return refuse(kQueryPlacementsService,
                  Status::error(std::to_string(count) + " poses, more than " +
                                std::to_string(kMaxQueriedPoses) + " in one request"),
                  &response);
  if (request.types.size() > 1 && request.types.size() != count)
    return refuse(
        kQueryPlacementsService,
        Status::error("types has " + std::to_string(request.types.size()) + " entries for " +
                      std::to_string(count) + " poses: give one per pose, one for all, or none"),
        &response);
  std::vector<BrickPlacement> placements(count);
  std::vector<Status> converted(count);
  for (std::size_t i = 0; i < count; ++i) {
    if (!request.types.empty())
      placements[i].type = request.types[request.types.size() > 1 ? i : 0];
    converted[i] =
        fromMsg(request.poses[i], "poses[" + std::to_string(i) + "]", &placements[i].pose);
  }
  response.verdicts.resize(count);
  {
    // One hold of the world: every pose is judged against the same state.
    std::lock_guard<TicketMutex> lock(world_mutex_);
    for (std::size_t i = 0; i < count; ++i) {
      PlacementVerdict& verdict = response.verdicts[i];
      PlacementReport report;
      Status answered = converted[i];
      if (answered) answered = simulation_->world().evaluatePlacement(placements[i], &report);
      verdict.valid = answered.ok;
      if (answered) {
        fillAnswer(report, &verdict);
      } else {
        verdict.message = answered.message;
      }
    }
  }
  response.success = true;
  response.message = std::to_string(count) + " poses judged";
  return true;
}

bool SimNode::removeBrick(RemoveBrick::Request& request, RemoveBrick::Response& response) {
  std::lock_guard<TicketMutex> lock(world_mutex_);
  if (Status removed = simulation_->world().removeBrick(request.id); !removed)
    return refuse(kRemoveBrickService, removed, &response);
  response.success = true;
  response.message = "removed " + request.id;
  changed();
  return true;
}

bool SimNode::reset(ResetScene::Request& request, ResetScene::Response& response) {
  // Reading and checking a big scene takes a while: others are served meanwhile.
  Scene scene;
  if (Status loaded = loadNamedScene(request.scene, &scene); !loaded)
    return refuse(kResetService, loaded, &response);
  std::string message;
  if (Status done = resetWorld(request.scene, scene, &message); !done)
    return refuse(kResetService, done, &response);
  ROS_INFO("%s", message.c_str());
  response.success = true;
  response.message = message;
  response.bricks_scheduled = static_cast<unsigned>(scene.bricks.size());
  return true;
}

Status SimNode::collectBricks(const std::vector<std::string>& ids, GetBricks::Response* response,
                              std::vector<BrickSnapshot>* asked, std::size_t* left_out) {
  if (!ids.empty()) {
    asked->resize(ids.size());
    for (std::size_t i = 0; i < ids.size(); ++i)
      if (!simulation_->world().find(ids[i], &(*asked)[i]))
        return Status::error("no brick with id '" + ids[i] + "'");
    return Status::success();
  }
  // Every brick, from a mirror of its own: what changed since the last
  // call is read, the rest is a copy of messages already built.
  answers_.update(simulation_->world());
  response->bricks.reserve(answers_.bricks().size());
  for (const MirroredBrick& brick : answers_.bricks()) {
    if (brick.finite) {
      response->bricks.push_back(brick.msg);
    } else {
      ++*left_out;
    }
  }
  return Status::success();
}

bool SimNode::getBricks(GetBricks::Request& request, GetBricks::Response& response) {
  std::set<std::string> asked_once;
  for (const std::string& id : request.ids)
    if (!asked_once.insert(id).second)
      return refuse(kGetBricksService,
                    Status::error("brick id '" + id + "' asked for twice: ask once"), &response);
  std::vector<BrickSnapshot> asked;
  double time = 0.0;
  std::size_t left_out = 0;
  {
    std::lock_guard<TicketMutex> lock(world_mutex_);
    if (Status found = collectBricks(request.ids, &response, &asked, &left_out); !found)
      return refuse(kGetBricksService, found, &response);
    time = simTime();
    response.header.stamp = publisher_->stamp();
  }
  response.header.frame_id = options_.config.publish.frame_id;
  for (const BrickSnapshot& brick : asked) {
    Brick msg;
    if (Status converted = toMsg(brick, &msg); !converted) {
      ROS_WARN_THROTTLE(5.0, "not published: %s", converted.message.c_str());
      ++left_out;
      continue;
    }
    response.bricks.push_back(std::move(msg));
  }
  response.success = true;
  response.message = counted(response.bricks.size(), "brick") + " at " + formatTime(time);
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
  changed();
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

std::string SimNode::stepPaused(unsigned steps, std::unique_lock<TicketMutex>* lock,
                                unsigned* done) {
  // Published at publish_rate of wall time, not of sim time: a million steps
  // would otherwise send tens of thousands of messages in a few seconds.
  const ros::WallDuration publish_period(1.0 / options_.config.publish.rate);
  const ros::WallDuration slice(kStepSlice);
  ros::WallTime next_publish = ros::WallTime::now() + publish_period;
  ros::WallTime slice_end = ros::WallTime::now() + slice;
  while (*done < steps) {
    advance();
    ++*done;
    const ros::WallTime now = ros::WallTime::now();
    if (now >= next_publish) {
      publisher_->publishClock();
      publisher_->publishEvents();
      publishState();
      next_publish = now + publish_period;
    }
    if (*done == steps || now < slice_end) continue;
    if (!ros::ok()) return "the node is shutting down";
    if (world_mutex_.contended()) {
      // The ticket lock puts this thread behind everyone who asked meanwhile.
      lock->unlock();
      lock->lock();
      if (!paused_) return "another client resumed the simulation";
    }
    slice_end = ros::WallTime::now() + slice;
  }
  return "";
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
  unsigned done = 0;
  const std::string interrupted = stepPaused(request.steps, &lock, &done);
  publisher_->publishClock();
  publisher_->publishEvents();
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
  changed();
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
  changed();
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
