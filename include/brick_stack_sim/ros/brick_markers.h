#pragma once
// The bricks and the table as markers: a box and an outline per brick.

#include <string>
#include <vector>

#include <geometry_msgs/Point.h>
#include <ros/time.h>
#include <visualization_msgs/MarkerArray.h>

#include "brick_stack_sim/core/types/brick.h"
#include "brick_stack_sim/core/types/world_options.h"
#include "brick_stack_sim/ros/marker_style.h"

namespace brick_stack_sim {
namespace ros_adapter {

/// Marker id of a brick: its placement serial, so a brick keeps its marker for
/// its whole life and a new brick never inherits an old one's.
int brickMarkerId(const BrickSnapshot& brick);

/// The outline marker of a brick: its serial / kBricksPerEdgeMarker.
int edgeMarkerId(const BrickSnapshot& brick);
/// The outline marker of the brick with placement serial `serial`.
int edgeMarkerId(unsigned serial);
/// An empty outline marker (LINE_LIST, dark, kBrickEdgeWidth) with `id`.
visualization_msgs::Marker makeEdgeMarker(int id, const std::string& frame_id,
                                          const ros::Time& stamp);
/// The 24 points of a brick's twelve edges, kBrickEdgeInflation outside its
/// box; nothing for a brick with a non-finite pose or size.
void appendEdges(const BrickSnapshot& brick, std::vector<geometry_msgs::Point>* lines);
/// A brick's box: a CUBE (scale = size [m], pose of its centre, opaque,
/// brickColor(brick)) in kBrickMarkerNamespace, id brickMarkerId(); nothing
/// for a brick with a non-finite pose or size.
void appendBoxMarker(const BrickSnapshot& brick, const std::string& frame_id,
                     const ros::Time& stamp, visualization_msgs::MarkerArray* array);

/// After one DELETEALL marker (so that bricks removed since the last array
/// disappear, and with them everything else the display shows), per brick in
/// `frame_id`: a CUBE (scale = size [m], pose of its centre, opaque,
/// brickColor(brick)) in kBrickMarkerNamespace; then the outline markers
/// (appendEdges() of each brick in the order of `bricks`, grouped by
/// edgeMarkerId(), none without bricks). Bricks with a non-finite pose or size are left
/// out (RViz would drop the whole array).
visualization_msgs::MarkerArray makeBrickMarkers(const std::vector<BrickSnapshot>& bricks,
                                                 const std::string& frame_id,
                                                 const ros::Time& stamp);

/// The table of `table` in kTableMarkerNamespace, in `frame_id` (the table
/// top's centre is its origin): the top, a CUBE `table.size` by
/// `table.thickness` [m] whose upper face is z = 0, in a grey that neither
/// wood nor any tint is; the floor `table.height` below, a wide darker
/// plate, where fallen bricks land; and four legs between them. Nothing for a
/// table with a non-finite or non-positive dimension.
visualization_msgs::MarkerArray makeTableMarkers(const TableOptions& table,
                                                 const std::string& frame_id,
                                                 const ros::Time& stamp);

}  // namespace ros_adapter
}  // namespace brick_stack_sim
