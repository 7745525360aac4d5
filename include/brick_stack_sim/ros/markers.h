#pragma once
// Every marker of the node: the bricks and the table, the legend and the
// stability layer, as one array for a viewer that starts from nothing.

#include <string>
#include <vector>

#include <ros/time.h>
#include <visualization_msgs/MarkerArray.h>

#include "brick_stack_sim/core/types/brick.h"
#include "brick_stack_sim/core/types/world_options.h"
#include "brick_stack_sim/ros/brick_markers.h"
#include "brick_stack_sim/ros/marker_style.h"
#include "brick_stack_sim/ros/stability_markers.h"

namespace brick_stack_sim {
namespace ros_adapter {

/// Everything a viewer that starts from nothing needs: makeBrickMarkers()
/// (DELETEALL first), makeTableMarkers(), makeLegendMarkers() and
/// makeStabilityMarkers(). The table and the legend come in every such
/// array, since the DELETEALL at its head removes every marker of the
/// display. (The node sends such an array to a new subscriber and after a
/// reset, and only what changed in between: MarkerUpdates.)
visualization_msgs::MarkerArray makeMarkers(const std::vector<BrickSnapshot>& bricks,
                                            const SupportGeometryMap& supports,
                                            const TableOptions& table, const std::string& frame_id,
                                            const ros::Time& stamp,
                                            const LegendStyle& legend = LegendStyle());

}  // namespace ros_adapter
}  // namespace brick_stack_sim
