#pragma once
// ~markers at a cost that follows what changes: a full array (DELETEALL and
// every marker) for a viewer that starts from nothing, then per publish only
// the markers of the bricks that changed (ADD, which RViz treats as modify
// for a marker it has) and DELETE for those that are gone, by id. A viewer
// that applies the arrays in order shows what a full array would.

#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <ros/time.h>
#include <visualization_msgs/MarkerArray.h>

#include "brick_stack_sim/core/types/world_options.h"
#include "brick_stack_sim/ros/brick_mirror.h"
#include "brick_stack_sim/ros/marker_style.h"

namespace brick_stack_sim {
namespace ros_adapter {

class MarkerUpdates {
 public:
  /// `legend`: the title and size of the legend over the table.
  explicit MarkerUpdates(std::string frame_id, LegendStyle legend = LegendStyle())
      : frame_id_(std::move(frame_id)), legend_(std::move(legend)) {}

  /// Every marker of the mirror's bricks from scratch, after a DELETEALL,
  /// with `table` and its legend (makeMarkers()); what is shown is then
  /// that array. For a new viewer, and for every viewer after a reset.
  visualization_msgs::MarkerArray full(const BrickMirror& mirror, const TableOptions& table,
                                       const ros::Time& stamp);

  /// What changed since the last full() or delta(): every marker of each
  /// brick in `changes.changed`, DELETE for the markers such a brick no
  /// longer has and for every marker of the removed bricks, and the outline
  /// markers of the groups where a brick moved, came or went. Empty when
  /// nothing changed. `changes` must not be a replacement (full() then).
  visualization_msgs::MarkerArray delta(const BrickMirror& mirror,
                                        const BrickMirror::Changes& changes,
                                        const ros::Time& stamp);

 private:
  using Key = std::pair<std::string, int>;  ///< Namespace and id.
  /// A brick's markers, appended to `array`; their keys into shown_.
  void appendBrick(const MirroredBrick& brick, const ros::Time& stamp,
                   visualization_msgs::MarkerArray* array);
  visualization_msgs::Marker deletion(const Key& key, const ros::Time& stamp) const;
  /// The outline marker `id` from the mirror's bricks in its serial range;
  /// false when none of them can be drawn.
  bool edgeGroup(const BrickMirror& mirror, int id, const ros::Time& stamp,
                 visualization_msgs::Marker* marker) const;

  std::string frame_id_;
  LegendStyle legend_;
  /// By serial: the keys of each brick's markers that a viewer shows.
  std::map<unsigned, std::vector<Key>> shown_;
  std::set<int> edge_groups_shown_;
};

}  // namespace ros_adapter
}  // namespace brick_stack_sim
