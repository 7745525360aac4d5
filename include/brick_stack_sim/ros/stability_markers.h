#pragma once
// The stability layer's picture: COM-above rays, contact meshes, and the
// contact forces with their friction cones.

#include <map>
#include <string>
#include <vector>

#include <ros/time.h>
#include <visualization_msgs/MarkerArray.h>

#include "brick_stack_sim/core/types/brick.h"
#include "brick_stack_sim/ros/marker_style.h"

namespace brick_stack_sim {
namespace ros_adapter {

/// Support geometry per brick id, as BrickWorld::supportGeometry() gives it.
/// Bricks the stability model does not describe are simply absent.
using SupportGeometryMap = std::map<std::string, SupportGeometry>;

/// Marker ids of a brick in kContactMeshMarkerNamespace: its support patches
/// and its combined hull, two per brick so both keep their ids for the brick's
/// whole life. In kComAboveMarkerNamespace the id is brickMarkerId().
int patchMarkerId(const BrickSnapshot& brick);
int hullMarkerId(const BrickSnapshot& brick);
/// Marker ids of a brick in kLeaningMarkerNamespace: three per brick, for
/// its contact points, force arrows and friction cones.
int contactPointsMarkerId(const BrickSnapshot& brick);
int forceArrowsMarkerId(const BrickSnapshot& brick);
int frictionConesMarkerId(const BrickSnapshot& brick);

/// Length per newton of a brick's force arrows [m/N] (kWeightArrowFraction);
/// 0 for a brick without mass or size.
double forceArrowScale(const BrickSnapshot& brick);

/// The stability layer's picture of every brick of `bricks` found in
/// `supports`, in `frame_id`:
/// - kComAboveMarkerNamespace: a LINE_LIST whose first segment runs from the
///   COM-above straight down to the support height (the z of the combined
///   hull), followed by a cross at its foot (arms kComAboveFootSize along x
///   and y), kComAboveLineWidth wide, coloured by comAboveColor().
///   Left out when the brick has no support (nothing to point at).
/// - kContactMeshMarkerNamespace: a TRIANGLE_LIST of the support patches (a
///   fan per patch polygon of three or more vertices) and a translucent one of
///   the combined hull, each lifted kContactMeshLift above its polygon.
///   Degenerate polygons (a point or an edge) have no area and draw nothing.
/// - kLeaningMarkerNamespace, for bricks with contact forces (frozen leaning
///   bricks and their groups; in mode equilibrium any brick whose component
///   statics solved): a SPHERE_LIST of the contact points; a LINE_LIST of
///   arrows, one per patch (the points shared with one body along one
///   normal: their resultant at its centre of pressure), each ending at
///   that point and pointing into the brick, scaled by forceArrowScale()
///   (the whole contact force,
///   normal and friction, so that its place in the cone shows how close
///   the contact is to slipping); and a LINE_LIST of the friction cones,
///   apex at the point, opening away from the brick around the normal
///   (four generators and a rim), each as tall as its force's normal part: an arrow whose tail lies
///   inside its cone's base is inside the cone.
/// Anything with a non-finite number is left out: RViz drops a whole array
/// for one NaN. No DELETEALL: see makeMarkers().
visualization_msgs::MarkerArray makeStabilityMarkers(const std::vector<BrickSnapshot>& bricks,
                                                     const SupportGeometryMap& supports,
                                                     const std::string& frame_id,
                                                     const ros::Time& stamp);

/// makeStabilityMarkers() for one brick and its geometry.
void appendStabilityMarkers(const BrickSnapshot& brick, const SupportGeometry& geometry,
                            const std::string& frame_id, const ros::Time& stamp,
                            visualization_msgs::MarkerArray* array);

}  // namespace ros_adapter
}  // namespace brick_stack_sim
