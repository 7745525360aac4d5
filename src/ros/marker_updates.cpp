#include "brick_stack_sim/ros/marker_updates.h"

#include <algorithm>

#include "brick_stack_sim/ros/markers.h"

namespace brick_stack_sim {
namespace ros_adapter {

void MarkerUpdates::appendBrick(const MirroredBrick& brick, const ros::Time& stamp,
                                visualization_msgs::MarkerArray* array) {
  const std::size_t first = array->markers.size();
  if (brick.finite) {
    appendBodyMarkers(brick.snapshot, frame_id_, stamp, array);
    if (brick.described)
      appendStabilityMarkers(brick.snapshot, brick.geometry, frame_id_, stamp, array);
  }
  std::vector<Key>& keys = shown_[brick.snapshot.serial];
  keys.clear();
  for (std::size_t i = first; i < array->markers.size(); ++i)
    keys.emplace_back(array->markers[i].ns, array->markers[i].id);
  if (keys.empty()) shown_.erase(brick.snapshot.serial);
}

visualization_msgs::Marker MarkerUpdates::deletion(const Key& key, const ros::Time& stamp) const {
  visualization_msgs::Marker marker;
  marker.header.frame_id = frame_id_;
  marker.header.stamp = stamp;
  marker.ns = key.first;
  marker.id = key.second;
  marker.action = visualization_msgs::Marker::DELETE;
  marker.pose.orientation.w = 1.0;
  return marker;
}

bool MarkerUpdates::edgeGroup(const BrickMirror& mirror, int id, const ros::Time& stamp,
                              visualization_msgs::Marker* marker) const {
  const std::vector<MirroredBrick>& bricks = mirror.bricks();
  const unsigned first = static_cast<unsigned>(id) * kBricksPerEdgeMarker;
  auto brick = std::lower_bound(
      bricks.begin(), bricks.end(), first,
      [](const MirroredBrick& b, unsigned serial) { return b.snapshot.serial < serial; });
  *marker = makeEdgeMarker(id, frame_id_, stamp);
  for (; brick != bricks.end() && brick->snapshot.serial < first + kBricksPerEdgeMarker; ++brick)
    if (brick->finite) appendEdges(brick->snapshot, &marker->points);
  return !marker->points.empty();
}

visualization_msgs::MarkerArray MarkerUpdates::full(const BrickMirror& mirror,
                                                    const TableOptions& table,
                                                    const ros::Time& stamp) {
  shown_.clear();
  edge_groups_shown_.clear();
  // makeMarkers() of no bricks: the DELETEALL, the table and the legend.
  visualization_msgs::MarkerArray array = makeMarkers({}, {}, table, frame_id_, stamp, legend_);
  for (const MirroredBrick& brick : mirror.bricks()) appendBrick(brick, stamp, &array);
  for (const MirroredBrick& brick : mirror.bricks()) {
    const int id = edgeMarkerId(brick.snapshot);
    if (!brick.finite || edge_groups_shown_.count(id)) continue;
    visualization_msgs::Marker edges;
    if (!edgeGroup(mirror, id, stamp, &edges)) continue;
    array.markers.push_back(std::move(edges));
    edge_groups_shown_.insert(id);
  }
  return array;
}

visualization_msgs::MarkerArray MarkerUpdates::delta(const BrickMirror& mirror,
                                                     const BrickMirror::Changes& changes,
                                                     const ros::Time& stamp) {
  visualization_msgs::MarkerArray array;
  std::set<int> outlines;  // groups to send again
  for (const RemovedBrick& gone : changes.removed) {
    const auto shown = shown_.find(gone.serial);
    if (shown != shown_.end()) {
      for (const Key& key : shown->second) array.markers.push_back(deletion(key, stamp));
      shown_.erase(shown);
    }
    outlines.insert(edgeMarkerId(gone.serial));
  }
  for (std::size_t index : changes.changed) {
    const MirroredBrick& brick = mirror.bricks()[index];
    std::vector<Key> before;
    if (const auto shown = shown_.find(brick.snapshot.serial); shown != shown_.end())
      before = shown->second;
    const std::size_t first = array.markers.size();
    appendBrick(brick, stamp, &array);
    // What it showed and no longer has (a ray without support, forces
    // statics no longer solves for): deleted by id.
    for (const Key& key : before) {
      const bool kept = std::any_of(array.markers.begin() + static_cast<std::ptrdiff_t>(first),
                                    array.markers.end(), [&](const visualization_msgs::Marker& m) {
                                      return m.ns == key.first && m.id == key.second;
                                    });
      if (!kept) array.markers.push_back(deletion(key, stamp));
    }
  }
  for (std::size_t index : changes.moved)
    outlines.insert(edgeMarkerId(mirror.bricks()[index].snapshot));
  for (int id : outlines) {
    visualization_msgs::Marker edges;
    if (edgeGroup(mirror, id, stamp, &edges)) {
      array.markers.push_back(std::move(edges));
      edge_groups_shown_.insert(id);
    } else if (edge_groups_shown_.erase(id) > 0) {
      array.markers.push_back(deletion(Key(kBrickEdgeMarkerNamespace, id), stamp));
    }
  }
  return array;
}

}  // namespace ros_adapter
}  // namespace brick_stack_sim
