#pragma once

#include <cstdint>
#include <memory>

#include <ros/ros.h>

#include "brick_stack_sim/BrickArray.h"
#include "brick_stack_sim/core/simulation/simulation.h"
#include "brick_stack_sim/core/simulation/simulation_config.h"
#include "brick_stack_sim/ros/brick_mirror.h"
#include "brick_stack_sim/ros/brick_transforms.h"
#include "brick_stack_sim/ros/graph_checks.h"
#include "brick_stack_sim/ros/marker_updates.h"
#include "brick_stack_sim/ros/ticket_mutex.h"

namespace brick_stack_sim {
namespace ros_adapter {

/// Everything the node sends of its world: ~bricks, ~events, ~markers, tf
/// and /clock. It keeps the world as last published (a BrickMirror), so
/// that each publish reads, compares and sends only what changed, and a new
/// subscriber of ~bricks or ~markers starts from all of it.
///
/// Every member function expects the world lock to be held by the caller,
/// but the subscriber callbacks, which take it themselves.
class StatePublisher {
 public:
  /// Advertises every topic on `node_handle` (the node's private one, /clock
  /// aside). `world_mutex` guards `simulation`; both outlive this.
  StatePublisher(ros::NodeHandle& node_handle, const PublishOptions& options,
                 TicketMutex& world_mutex, Simulation& simulation);

  /// Every stamp: sim time with publish_clock, else wall time.
  ros::Time stamp() const;
  void publishClock();
  /// The simulation's events since the last call, on ~events.
  void publishEvents();
  /// Brings the mirror up to the world and sends what changed: tf always,
  /// ~bricks and ~markers while subscribed.
  void publishState();

  /// Something changed that ~bricks has not shown yet.
  void markDirty() { dirty_ = true; }
  bool dirty() const { return dirty_; }
  /// Wall time of the last publishState() [s].
  double lastStateWall() const { return last_state_wall_; }
  /// The world was replaced by the one `mirror` was brought up to, off the
  /// world lock (BrickMirror::adopt): the next publish sends it whole.
  void adopt(BrickMirror mirror) { mirror_.adopt(std::move(mirror)); }
  /// The world as last published.
  const BrickMirror& mirror() const { return mirror_; }
  /// The frames the node names on tf.
  const FrameNames& frames() const { return frames_; }

 private:
  /// ~bricks: every brick, or (bricks_delta) what `changes` found.
  BrickArray makeBrickArray(const BrickMirror::Changes* changes, const ros::Time& stamp) const;
  /// A new subscriber starts from every brick, or every marker: sent to it
  /// alone, from the mirror, so that it then follows the others' updates.
  void onBricksSubscriber(const ros::SingleSubscriberPublisher& subscriber);
  void onMarkersSubscriber(const ros::SingleSubscriberPublisher& subscriber);
  void publishMarkers(const BrickMirror::Changes& changes, const ros::Time& now);

  PublishOptions options_;
  TicketMutex& world_mutex_;
  Simulation& simulation_;

  bool dirty_ = true;
  double last_state_wall_ = 0.0;  ///< [s]
  /// The world as last published, and what viewers of ~markers show of it.
  BrickMirror mirror_;
  MarkerUpdates marker_updates_;
  /// The next ~markers is a full array for every viewer (after a reset).
  bool markers_full_due_ = true;
  /// BrickArray::sequence of the last ~bricks sent to every subscriber.
  std::uint32_t bricks_sequence_ = 0;

  ros::Publisher bricks_publisher_;
  ros::Publisher events_publisher_;
  ros::Publisher markers_publisher_;
  ros::Publisher clock_publisher_;
  /// /tf for what moved, latched /tf_static for the table and what rests.
  FrameNames frames_;
  std::unique_ptr<BrickTransforms> transforms_;
  /// Another publisher of the node's frames, a missing /clock: warned at start.
  std::unique_ptr<GraphChecks> graph_checks_;
};

}  // namespace ros_adapter
}  // namespace brick_stack_sim
