#pragma once
// The bricks and the table as markers: a body (one marker per convex part)
// and an outline per brick.

#include <cstddef>
#include <string>
#include <vector>

#include <geometry_msgs/Point.h>
#include <ros/time.h>
#include <std_msgs/ColorRGBA.h>
#include <visualization_msgs/MarkerArray.h>

#include "brick_stack_sim/core/geometry/convex_solid.h"
#include "brick_stack_sim/core/types/brick.h"
#include "brick_stack_sim/core/types/world_options.h"
#include "brick_stack_sim/ros/marker_style.h"

namespace brick_stack_sim {
namespace ros_adapter {

/// Marker id of a brick: its placement serial, so a brick keeps its marker for
/// its whole life and a new brick never inherits an old one's.
int brickMarkerId(const BrickSnapshot& brick);

/// Segments of each cylinder cap rim in the outlines and of nothing else [-]:
/// a circle at tower scale, at 128 points a cylinder.
constexpr int kCylinderRimSegments = 32;

/// The outline marker of a brick: its serial / kBricksPerEdgeMarker.
int edgeMarkerId(const BrickSnapshot& brick);
/// The outline marker of the brick with placement serial `serial`.
int edgeMarkerId(unsigned serial);
/// An empty outline marker (LINE_LIST, dark, kBrickEdgeWidth) with `id`.
visualization_msgs::Marker makeEdgeMarker(int id, const std::string& frame_id,
                                          const ros::Time& stamp);
/// The segments (pairs of points, world frame [m]) of a brick's outline,
/// kBrickEdgeInflation outside its body: a box part's twelve edges (a brick
/// without a solid: the box of its size), a hull part's edges, a cylinder
/// part's two cap rims (kCylinderRimSegments each). Nothing for a brick with
/// a non-finite pose or size, nor for a part that is not finite.
void appendEdges(const BrickSnapshot& brick, std::vector<geometry_msgs::Point>* lines);
/// The outline segments of `part` of a solid at `solid_pose` [m], world
/// frame, `inflation` [m] outside it; nothing when not finite.
void appendPartOutline(const ConvexPart& part, const Eigen::Isometry3d& solid_pose,
                       double inflation, std::vector<geometry_msgs::Point>* lines);

/// The geometry of `part` of a solid at `solid_pose` as a marker's type,
/// pose, scale and points (its header, namespace, id and colour untouched):
/// a box part a CUBE (scale = its size), a cylinder part a CYLINDER (scale
/// 2r, 2r, length), any other a TRIANGLE_LIST of its faces (each face loop
/// fanned from its first vertex, counter-clockwise seen from outside, scale
/// 1) whose points are in the part's own frame; the pose is always
/// solid_pose * part.pose. False, the marker untouched, for a part with a
/// non-finite number or nothing to draw.
bool partBodyMarker(const ConvexPart& part, const Eigen::Isometry3d& solid_pose,
                    visualization_msgs::Marker* marker);
/// The bodies of a solid at `pose` [m] in `color`, one marker per part that
/// partBodyMarker() draws (a CUBE of `size` [m] when `solid` is null or has
/// no part), without header, namespace or id: for a marker given relative
/// to another, as in an interactive marker's control (a teleop's ghost).
std::vector<visualization_msgs::Marker> solidBodyMarkers(const ConvexSolid* solid,
                                                         const Eigen::Vector3d& size,
                                                         const Eigen::Isometry3d& pose,
                                                         const std_msgs::ColorRGBA& color);
/// A brick's body, opaque, brickColor(brick), id brickMarkerId(): without a
/// solid, or with one box part centred on the brick frame, a CUBE (scale =
/// size [m], pose of its centre) in kBrickMarkerNamespace, as bricks were
/// before shapes; else its one part's partBodyMarker(), or for a compound
/// one TRIANGLE_LIST of every part's faces in the brick's frame: one body
/// marker per brick, so its id is its serial in kBrickMarkerNamespace.
/// Nothing for a brick with a non-finite pose or size, nor for a part that
/// is not finite.
void appendBodyMarkers(const BrickSnapshot& brick, const std::string& frame_id,
                       const ros::Time& stamp, visualization_msgs::MarkerArray* array);

/// After one DELETEALL marker (so that bricks removed since the last array
/// disappear, and with them everything else the display shows), per brick in
/// `frame_id`: its body (appendBodyMarkers()); then the outline markers
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
