#include "brick_stack_sim/planner/blueprint_builder.h"

#include <unistd.h>

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>

#include <ros/console.h>
#include <ros/time.h>

#include "brick_stack_sim/core/scene/scene.h"
#include "brick_stack_sim/core/simulation/simulation_config.h"
#include "brick_stack_sim/core/types/brick_type.h"
#include "brick_stack_sim/ros/conversions.h"
#include "brick_stack_sim/ros/xmlrpc_parameters.h"

namespace brick_stack_sim {
namespace planner {
namespace {

/// A positive, finite time [s] read from `name`, or an error naming it.
Status readPositive(const ros::NodeHandle& nh, const std::string& name, double* value) {
  double read = *value;
  nh.param(name, read, read);
  if (!std::isfinite(read) || read <= 0.0 || read > 1e6)
    return Status::error("parameter ~" + name + " = " + std::to_string(read) +
                         ": must be in (0, 1e6]");
  *value = read;
  return Status::success();
}

ObservedBrick toObserved(const Brick& msg) {
  ObservedBrick brick;
  brick.id = msg.id;
  // The simulator never publishes a non-finite number; a bad quaternion
  // would leave the identity, which reads as a turned brick: fallen.
  ros_adapter::fromMsg(msg.pose, "pose", &brick.pose);
  ros_adapter::fromMsg(msg.twist, "twist", &brick.linear_velocity, &brick.angular_velocity);
  brick.frozen = msg.state == Brick::STABLE || msg.state == Brick::LEANING;
  brick.leaning = msg.state == Brick::LEANING;
  brick.asleep = msg.asleep;
  brick.fell_off = msg.fell_off;
  return brick;
}

bool isThrown(const ScheduledBrick& brick) {
  return !brick.placement.linear_velocity.isZero() || !brick.placement.angular_velocity.isZero();
}

/// The client's options: persistent connections, each (re)made within the
/// builder's service_wait.
client::ClientOptions clientOptions(const BuilderOptions& options) {
  client::ClientOptions client;
  client.sim_namespace = options.sim;
  client.service_wait = options.service_wait;
  client.persistent = true;
  return client;
}

/// Why a call that was not accepted failed: the simulator's refusal, or why
/// it was not reached.
std::string failure(const client::CallResult& reply) {
  return reply.reached ? reply.service + " refused: " + reply.message : reply.message;
}

}  // namespace

Status readBuilderOptions(const ros::NodeHandle& private_nh, const std::string& package_dir,
                          BuilderOptions* options) {
  BuilderOptions read = *options;
  private_nh.param("scene", read.scene, read.scene);
  if (read.scene.empty()) return Status::error("parameter ~scene is empty: name a scene or a path");
  private_nh.param("sim", read.sim, read.sim);
  if (read.sim.empty()) return Status::error("parameter ~sim is empty: the simulator's namespace");
  private_nh.param("label", read.label, read.label);
  DataOptions data;  // unset or empty: the package's own
  private_nh.param("types_urdf", data.types_urdf, data.types_urdf);
  private_nh.param("materials_yaml", data.materials_yaml, data.materials_yaml);
  // A list given on a rosrun line arrives as a string: read it as one.
  std::string list_note;
  if (Status listed =
          ros_adapter::readStringList(private_nh, "scene_dirs", &data.scene_dirs, &list_note);
      !listed)
    return listed;
  if (!list_note.empty()) ROS_INFO("%s", list_note.c_str());
  fillPackageData(package_dir, &data);
  read.types_urdf = data.types_urdf;
  read.materials_yaml = data.materials_yaml;
  read.scene_dirs = data.scene_dirs;
  for (const auto& [name, value] :
       {std::pair<const char*, double*>{"settle_timeout", &read.settle_timeout},
        {"final_wait", &read.final_wait},
        {"poll_period", &read.poll_period},
        {"service_wait", &read.service_wait},
        {"fall_distance", &read.ledger.fall_distance},
        {"fall_angle", &read.ledger.fall_angle}}) {
    if (Status checked = readPositive(private_nh, name, value); !checked) return checked;
  }
  *options = read;
  return Status::success();
}

std::string linePrefix(const BuilderOptions& options) {
  return options.label.empty() ? std::string() : "[" + options.label + "] ";
}

BlueprintBuilder::BlueprintBuilder(ros::NodeHandle nh, BuilderOptions options, std::FILE* progress)
    : options_(std::move(options)),
      progress_(progress),
      ledger_(options_.ledger),
      sim_(clientOptions(options_), nh) {}

Status BlueprintBuilder::loadScene(Scene* scene) const {
  BrickTypeLibrary types;
  if (Status loaded = BrickTypeLibrary::load(options_.types_urdf, options_.materials_yaml, &types);
      !loaded)
    return loaded;
  return brick_stack_sim::loadScene(options_.scene, options_.scene_dirs, types, scene);
}

double BlueprintBuilder::clock(const ros::Time& t) const { return (t - epoch_).toSec(); }

void BlueprintBuilder::say(const char* format, ...) const {
  std::fprintf(progress_, "%s[t=%6.2f s] ", linePrefix(options_).c_str(), clock(ros::Time::now()));
  va_list arguments;
  va_start(arguments, format);
  std::vfprintf(progress_, format, arguments);
  va_end(arguments);
  std::fputc('\n', progress_);
  std::fflush(progress_);
}

Status BlueprintBuilder::build(const Scene& scene, BuildOutcome* outcome) {
  if (const client::CallResult up = sim_.waitForNode(options_.service_wait); !up.ok)
    return Status::error(up.message);
  // With use_sim_time the clock reads 0 until the simulator's first /clock.
  if (!ros::Time::waitForValid(ros::WallDuration(options_.service_wait)))
    return Status::error("no /clock within " + std::to_string(options_.service_wait) +
                         " s: is the simulator's publish_clock on?");

  const ros::Time start = ros::Time::now();
  // Sim time reads as the simulator's own; wall time from the build's start.
  epoch_ = ros::Time::isSimTime() ? ros::Time() : start;
  if (Status handed = handOverTypes(scene); !handed) return handed;
  const std::vector<ScheduledBrick>& bricks = scene.bricks;
  say("building scene %s: %zu bricks over %.1f s", scene.name.c_str(), bricks.size(),
      bricks.empty() ? 0.0 : bricks.back().at);
  next_observation_ = start;
  for (std::size_t first = 0; first < bricks.size() && ros::ok();) {
    // Bricks meant to arrive together (the two halves of a V) go as one group.
    std::size_t last = first + 1;
    while (last < bricks.size() && bricks[last].at == bricks[first].at) ++last;
    if (Status watched = watch(start + ros::Duration(bricks[first].at), {}, ros::Time()); !watched)
      return watched;
    std::vector<std::string> group;
    if (Status placed = placeGroup(bricks, first, last, &group); !placed) return placed;
    const ros::Time placed_at = ros::Time::now();
    const ros::Time next =
        last < bricks.size() ? start + ros::Duration(bricks[last].at) : placed_at;
    if (Status watched = watch(next, group, placed_at + ros::Duration(options_.settle_timeout));
        !watched)
      return watched;
    for (const std::string& id : group)
      if (ledger_.find(id)->fate == BrickFate::kUnsettled)
        say("%s has not come to rest %.1f s after its placement; going on", id.c_str(),
            options_.settle_timeout);
    first = last;
  }
  if (!ros::ok()) return Status::error("ROS shut down during the build");
  if (Status watched =
          watch(ros::Time::now() + ros::Duration(options_.final_wait), {}, ros::Time());
      !watched)
    return watched;

  outcome->summary = ledger_.summary();
  outcome->met = ledger_.met(scene.expect, &outcome->verdict);
  outcome->summary_line = formatSummary(scene.name, outcome->summary, clock(ros::Time::now()));
  return Status::success();
}

Status BlueprintBuilder::handOverTypes(const Scene& scene) {
  if (scene.types.empty()) return Status::success();
  std::string names;
  for (const BrickType& type : scene.types) names += (names.empty() ? "" : ", ") + type.name;
  char path[] = "/tmp/brick_stack_sim_types_XXXXXX.yaml";
  const int fd = ::mkstemps(path, 5);
  if (fd < 0) return Status::error("cannot write the scene's types to /tmp for the simulator");
  const std::string text = typesAsScene(scene.types);
  const bool written = ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size());
  ::close(fd);
  client::Reply<ResetScene::Response> reset;
  if (written) reset = sim_.reset(path);
  std::remove(path);
  if (!written) return Status::error("cannot write the scene's types to " + std::string(path));
  if (!reset.ok)
    return Status::error("the simulator did not take the scene's types (" + names +
                         "): " + failure(reset));
  say("the scene defines brick types of its own (%s): handed to the simulator", names.c_str());
  return Status::success();
}

Status BlueprintBuilder::placeGroup(const std::vector<ScheduledBrick>& bricks, std::size_t first,
                                    std::size_t last, std::vector<std::string>* structure) {
  const bool together = last - first > 1;
  if (together) {
    if (const auto paused = sim_.pause(true); !paused.ok)
      return Status::error("could not pause the simulator to place bricks together: " +
                           failure(paused));
  }
  for (std::size_t i = first; i < last; ++i) {
    const BrickPlacement& brick = bricks[i].placement;
    PlaceBrick::Request request;
    request.id = brick.id;
    request.type = brick.type;
    request.pose = ros_adapter::toPoseMsg(brick.pose);
    request.twist.linear = ros_adapter::toVectorMsg(brick.linear_velocity);
    request.twist.angular = ros_adapter::toVectorMsg(brick.angular_velocity);
    const client::Reply<PlaceBrick::Response> place = sim_.placeBrick(request);
    if (!place.reached) return Status::error(place.message);
    if (!place.ok) {
      ledger_.recordRefused(brick.id, place.message);
      say("%s refused: %s", brick.id.c_str(), place.message.c_str());
      continue;
    }
    const std::string& id = place.response.id;
    const bool thrown = isThrown(bricks[i]);
    ledger_.recordPlaced(id, brick.pose, clock(ros::Time::now()), thrown);
    if (!thrown) structure->push_back(id);
    if (thrown)
      say("threw %s at %.2f m/s", id.c_str(), brick.linear_velocity.norm());
    else
      say("placed %s (%zu/%zu)", id.c_str(), i + 1, bricks.size());
  }
  if (together) {
    if (const auto resumed = sim_.pause(false); !resumed.ok)
      return Status::error("could not resume the simulator after placing bricks together: " +
                           failure(resumed));
  }
  return Status::success();
}

Status BlueprintBuilder::observe() {
  const client::Reply<GetBricks::Response> get = sim_.getBricks();
  if (!get.ok) return Status::error(failure(get));
  std::vector<ObservedBrick> observed;
  observed.reserve(get.response.bricks.size());
  for (const Brick& brick : get.response.bricks) observed.push_back(toObserved(brick));
  const double t = clock(get.response.header.stamp);
  for (const LedgerEntry* changed : ledger_.observe(t, observed)) {
    const char* what = changed->fate != BrickFate::kFallen ? "was shifted"
                       : changed->fell_after_throw         ? "was knocked"
                                                           : "FELL";
    say("%s %s: %s", changed->id.c_str(), what, changed->how.c_str());
  }
  next_observation_ = ros::Time::now() + ros::Duration(options_.poll_period);
  return Status::success();
}

bool BlueprintBuilder::restedAll(const std::vector<std::string>& ids) const {
  for (const std::string& id : ids)
    if (ledger_.find(id)->fate == BrickFate::kUnsettled) return false;
  return true;
}

Status BlueprintBuilder::watch(const ros::Time& until, const std::vector<std::string>& group,
                               const ros::Time& settle_until) {
  // At least one look per call: with a simulator faster than real time the
  // time to place the next brick may have come already.
  if (Status looked = observe(); !looked) return looked;
  while (ros::ok()) {
    const ros::Time now = ros::Time::now();
    const bool waiting_for_group = !restedAll(group) && now < settle_until;
    if (now >= until && !waiting_for_group) return Status::success();
    const ros::Time wake =
        std::min(next_observation_, waiting_for_group ? std::max(until, settle_until) : until);
    ros::Time::sleepUntil(wake);
    if (ros::Time::now() >= next_observation_) {
      if (Status looked = observe(); !looked) return looked;
    }
  }
  return Status::error("ROS shut down during the build");
}

}  // namespace planner
}  // namespace brick_stack_sim
