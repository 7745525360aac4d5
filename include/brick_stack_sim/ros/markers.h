#pragma once

#include <map>
#include <string>
#include <vector>

#include <ros/time.h>
#include <std_msgs/ColorRGBA.h>
#include <visualization_msgs/MarkerArray.h>

#include "brick_stack_sim/core/brick.h"

namespace brick_stack_sim {
namespace ros_adapter {

// Marker namespaces (DESIGN.md section 3).
/// A box per brick, coloured by state.
constexpr char kBrickMarkerNamespace[] = "bricks";
/// A ray per brick from its COM-above straight down to its support height.
constexpr char kComAboveMarkerNamespace[] = "com_above";
/// Per brick: its support patches, and their combined hull.
constexpr char kContactMeshMarkerNamespace[] = "contact_mesh";
/// Per brick that statics solved for: its contact points, the contact
/// forces on it as arrows and the friction cones they must stay in.
constexpr char kLeaningMarkerNamespace[] = "leaning";

/// Alpha of the brick boxes when stability markers are drawn: the COM-above
/// rays and contact meshes lie inside the stack (a patch is the interface of
/// two bricks), so opaque boxes would hide every one of them.
constexpr float kTranslucentBrickAlpha = 0.45f;
/// How far the contact meshes are drawn above the support surface [m]: enough
/// to win the depth test against the supporting face, far below anything a
/// viewer could read as a gap.
constexpr double kContactMeshLift = 1e-4;
/// Line width of the COM-above rays [m]: visible next to an 8 mm brick.
constexpr double kComAboveLineWidth = 0.0012;
/// Half the arms of the cross marking the foot of a COM-above ray [m].
constexpr double kComAboveFootSize = 0.004;

/// Scale of the contact-force arrows: an arrow of this fraction of a brick's
/// longest side is a force equal to the brick's weight (9.81 m/s^2), so the
/// arrows of any brick type read at the brick's own size.
constexpr double kWeightArrowFraction = 0.3;
/// Diameter of the contact points' spheres [m].
constexpr double kContactPointSize = 0.003;
/// Line width of force arrows and cones [m].
constexpr double kForceLineWidth = 0.0008;

/// Support geometry per brick id, as BrickWorld::supportGeometry() gives it.
/// Bricks the stability model does not describe are simply absent.
using SupportGeometryMap = std::map<std::string, SupportGeometry>;

/// What a brick's colour shows, most telling first: a brick that fell off is
/// shown as such whatever the simulator does with it, and Bullet's sleep is
/// shown only for dynamic bricks.
enum class BrickLook { kFellOff, kHeld, kLeaning, kStable, kAsleep, kDynamic };

BrickLook brickLook(const BrickSnapshot& brick);
/// Fixed colours per look, opaque, far enough apart to tell in RViz.
std_msgs::ColorRGBA brickColor(BrickLook look);

/// Marker id of a brick: its placement serial, so a brick keeps its marker for
/// its whole life and a new brick never inherits an old one's.
int brickMarkerId(const BrickSnapshot& brick);

/// One CUBE per brick (scale = size [m], pose of its centre) in `frame_id`,
/// namespace kBrickMarkerNamespace, after one DELETEALL marker so that bricks
/// removed since the last array disappear. Bricks with a non-finite pose or
/// size are left out (RViz would drop the whole array). `alpha` is the
/// opacity of every box [0, 1].
visualization_msgs::MarkerArray makeBrickMarkers(const std::vector<BrickSnapshot>& bricks,
                                                 const std::string& frame_id,
                                                 const ros::Time& stamp, float alpha = 1.0f);

/// Colour of a COM-above ray: green while the projection of the COM-above is
/// inside the support hull (margin > 0 [m]), red on or outside its edge.
std_msgs::ColorRGBA comAboveColor(double margin);

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
///   hull), followed by a small cross at its foot; coloured by comAboveColor().
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

/// Everything the node publishes on ~markers: makeBrickMarkers() (DELETEALL
/// first, boxes with `brick_alpha`) followed by makeStabilityMarkers().
visualization_msgs::MarkerArray makeMarkers(const std::vector<BrickSnapshot>& bricks,
                                            const SupportGeometryMap& supports,
                                            const std::string& frame_id, const ros::Time& stamp,
                                            float brick_alpha);

}  // namespace ros_adapter
}  // namespace brick_stack_sim
