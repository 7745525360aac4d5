#include "brick_stack_sim/ros/state_publisher.h"

#include <cmath>

#include <rosgraph_msgs/Clock.h>
#include <visualization_msgs/MarkerArray.h>

#include "brick_stack_sim/StabilityEvent.h"
#include "brick_stack_sim/ros/conversions.h"
#include "brick_stack_sim/ros/interface_names.h"
#include "time_text.h"

namespace brick_stack_sim {
namespace ros_adapter {

namespace {

/// Events queued per subscriber before the oldest is dropped: a reset of a
/// large scene emits a removed and a spawned event per brick in one burst.
constexpr int kEventQueueSize = 10000;
/// Wall time [s] between two sends of the resting bricks on /tf_static: each
/// is the whole set, and only listeners that join later need it.
constexpr double kStaticTransformsPeriod = 1.0;
/// ~bricks messages queued per subscriber before the oldest is dropped. Each
/// full array is every brick (2 MB at 10 000), so few are kept; a delta is a
/// few changed bricks, and one dropped leaves its subscriber stale until it
/// subscribes again, so 10 s at the default publish_rate are kept.
constexpr int kFullBricksQueueSize = 10;
constexpr int kDeltaBricksQueueSize = 300;

}  // namespace

StatePublisher::StatePublisher(ros::NodeHandle& node_handle, const PublishOptions& options,
                               TicketMutex& world_mutex, Simulation& simulation)
    : options_(options),
      world_mutex_(world_mutex),
      simulation_(simulation),
      // The title says which mode runs: two simulators side by side
      // (compare.launch) are told apart at a glance.
      marker_updates_(options.frame_id, LegendStyle{"mode " + simulation.options().stability.mode,
                                                    options.legend_scale}),
      frames_(options.frame_id, options.frame_prefix) {
  // A new subscriber gets everything at once, alone: with deltas it could
  // not start otherwise, and a viewer that connects while nothing changes
  // (paused, or a fully frozen stack) would wait for the next change.
  bricks_publisher_ = node_handle.advertise<BrickArray>(
      kBricksTopic, options.bricks_delta ? kDeltaBricksQueueSize : kFullBricksQueueSize,
      [this](const ros::SingleSubscriberPublisher& s) { onBricksSubscriber(s); });
  events_publisher_ = node_handle.advertise<StabilityEvent>(kEventsTopic, kEventQueueSize);
  markers_publisher_ = node_handle.advertise<visualization_msgs::MarkerArray>(
      kMarkersTopic, 2,
      [this](const ros::SingleSubscriberPublisher& s) { onMarkersSubscriber(s); });
  if (options.clock) {
    clock_publisher_ = node_handle.advertise<rosgraph_msgs::Clock>(kClockTopic, 10);
    // Every stamp is then sim time; nodes on wall time would find tf and
    // ~bricks some 1.8e9 s in the past. /use_sim_time must be set before the
    // nodes start, so this node can only say so.
    if (!ros::Time::isSimTime())
      ROS_WARN(
          "publish_clock is true but /use_sim_time is not: this node stamps everything in sim "
          "time while nodes started without /use_sim_time read wall time; set /use_sim_time "
          "before starting the nodes (sim.launch does with publish_clock:=true)");
  }
  transforms_ = std::make_unique<BrickTransforms>(node_handle, frames_, kStaticTransformsPeriod);
  transforms_->clear(stamp());
  graph_checks_ = std::make_unique<GraphChecks>(node_handle, frames_.table(), options.clock,
                                                GraphChecks::Windows());
}

ros::Time StatePublisher::stamp() const {
  return options_.clock ? ros::Time(simulation_.time()) : ros::Time::now();
}

void StatePublisher::publishClock() {
  if (!options_.clock) return;
  rosgraph_msgs::Clock clock;
  clock.clock = ros::Time(simulation_.time());
  clock_publisher_.publish(clock);
}

void StatePublisher::publishEvents() {
  // ~events is not latched: with nobody listening a message reaches no one,
  // and a reset of 10 000 bricks would build 20 000 of them under the world
  // lock for nothing.
  const bool listened = events_publisher_.getNumSubscribers() > 0;
  for (const SimEvent& event : simulation_.takeEvents()) {
    const double t = event.time;
    if (event.kind == SimEventKind::kNonFinite) {
      // NaN, Inf or a runaway speed: the reason says which and how it was repaired.
      ROS_WARN("brick %s at %s: %s", event.brick_id.c_str(), formatTime(t).c_str(),
               event.reason.c_str());
    }
    if (!listened) continue;
    StabilityEvent msg = toMsg(event);
    msg.header.stamp = options_.clock && std::isfinite(t) && t >= 0.0 ? ros::Time(t) : stamp();
    msg.header.frame_id = options_.frame_id;
    events_publisher_.publish(msg);
  }
}

void StatePublisher::publishState() {
  dirty_ = false;
  last_state_wall_ = ros::WallTime::now().toSec();
  const ros::Time now = stamp();
  // The world names what may have changed; only that is read, compared and sent.
  const BrickMirror::Changes changes = mirror_.update(simulation_.world());
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
    bricks_publisher_.publish(makeBrickArray(options_.bricks_delta ? &changes : nullptr, now));
  }
  publishMarkers(changes, now);
}

void StatePublisher::publishMarkers(const BrickMirror::Changes& changes, const ros::Time& now) {
  if (markers_publisher_.getNumSubscribers() == 0) {
    markers_full_due_ = true;  // what viewers show is no longer followed
    return;
  }
  // The world's table, not the parameters': a scene may bring its own.
  if (changes.replaced || markers_full_due_) {
    markers_publisher_.publish(
        marker_updates_.full(mirror_, simulation_.world().options().table, now));
    markers_full_due_ = false;
  } else {
    visualization_msgs::MarkerArray update = marker_updates_.delta(mirror_, changes, now);
    if (!update.markers.empty()) markers_publisher_.publish(update);
  }
}

BrickArray StatePublisher::makeBrickArray(const BrickMirror::Changes* changes,
                                          const ros::Time& stamp) const {
  BrickArray array;
  array.header.stamp = stamp;
  array.header.frame_id = options_.frame_id;
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
  for (const RemovedBrick& gone : changes->removed) array.removed.push_back(gone.id);
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

void StatePublisher::onBricksSubscriber(const ros::SingleSubscriberPublisher& subscriber) {
  std::lock_guard<TicketMutex> lock(world_mutex_);
  subscriber.publish(makeBrickArray(nullptr, stamp()));
}

void StatePublisher::onMarkersSubscriber(const ros::SingleSubscriberPublisher& subscriber) {
  std::lock_guard<TicketMutex> lock(world_mutex_);
  // From the mirror, which every other viewer shows: the deltas that follow
  // apply to this viewer as to them.
  subscriber.publish(marker_updates_.full(mirror_, simulation_.world().options().table, stamp()));
  markers_full_due_ = false;
}

}  // namespace ros_adapter
}  // namespace brick_stack_sim
