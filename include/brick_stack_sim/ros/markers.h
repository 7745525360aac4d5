#pragma once

#include <map>
#include <string>
#include <vector>

#include <ros/time.h>
#include <std_msgs/ColorRGBA.h>
#include <visualization_msgs/MarkerArray.h>

#include "brick_stack_sim/core/brick.h"
#include "brick_stack_sim/core/world/world_options.h"

namespace brick_stack_sim {
namespace ros_adapter {

// Marker namespaces: the four of DESIGN.md section 3, and what makes the
// picture readable. Each its own namespace, so that RViz's MarkerArray display
// can switch it off on its own.
/// A box per brick, opaque wood tinted by state.
constexpr char kBrickMarkerNamespace[] = "bricks";
/// A ray per brick from its COM-above straight down to its support height.
constexpr char kComAboveMarkerNamespace[] = "com_above";
/// Per brick: its support patches, and their combined hull.
constexpr char kContactMeshMarkerNamespace[] = "contact_mesh";
/// Per brick that statics solved for: its contact points, the contact
/// forces on it as arrows and the friction cones they must stay in.
constexpr char kLeaningMarkerNamespace[] = "leaning";
/// The twelve edges of every brick's box, dark, kBricksPerEdgeMarker bricks
/// to a marker (ids edgeMarkerId(), from kBrickEdgesMarkerId). Boxes of one
/// wood that touch would otherwise run together into one block; and with
/// `bricks` switched off the outlines stay, so the stack reads as a wire
/// frame around the rays and meshes inside it.
constexpr char kBrickEdgeMarkerNamespace[] = "brick_edges";
constexpr int kBrickEdgesMarkerId = 0;
/// Bricks whose outlines share one marker, by serial: RViz builds an object
/// per marker, so one per brick would double its work for lines that all
/// look alike; one for every brick would be resent whole whenever one brick
/// moves. Bricks placed together (and so moving together) share one.
constexpr unsigned kBricksPerEdgeMarker = 64;
/// The table top (id 0), the floor under it (id 1) and four legs (ids 2-5).
constexpr char kTableMarkerNamespace[] = "table";
/// Text facing the viewer over the table: what each colour means.
constexpr char kLegendMarkerNamespace[] = "legend";

// Why the bricks are opaque and how the stability layer still shows:
// translucent boxes of one colour per state ran together (a tower read as one
// pale block). Opaque wood with dark edges reads as planks, and
// every brick's state shows on its faces. What lies inside the stack (the
// rays' passage through the planks, the patches between them) is hidden by
// opaque boxes whatever they are drawn like, so
// - the rays are thick and run the whole way from the COM-above (of the
//   brick and its load: for a lower brick, high in the tower) down to the
//   support plane; they show in the gaps of a tower, beside a V of a card
//   house and in a collapse, and the foot cross reaches past a plank's width;
// - the contact forces (namespace `leaning`) start outside the brick and
//   end at the contact, so they show on opaque bricks;
// - and every layer is a namespace of its own: switching `bricks` off in the
//   MarkerArray display leaves the outlines (`brick_edges`) with every ray,
//   patch and arrow inside them visible. The legend says so.

/// Line width of the COM-above rays [m]: thicker than a plank's edges, so a
/// ray reads as a line at tower scale (a 25-layer tower is 0.2 m tall).
constexpr double kComAboveLineWidth = 0.0035;
/// Half the arms of the cross marking the foot of a COM-above ray [m]: more
/// than half a KAPLA's width (11.7 mm), so the arms across a plank show on
/// both of its sides where the foot itself lies between two planks.
constexpr double kComAboveFootSize = 0.015;
/// How far the contact meshes are drawn above the support surface [m]: enough
/// to win the depth test against the supporting face, far below anything a
/// viewer could read as a gap.
constexpr double kContactMeshLift = 1e-4;

/// Line width of the brick outlines [m]: about a pixel at tower scale, a
/// seam rather than a frame.
constexpr double kBrickEdgeWidth = 0.0006;
/// The outline is this much larger than the box on every side [m] (half the
/// line width), so that its lines lie on the faces rather than in them.
constexpr double kBrickEdgeInflation = 0.5 * kBrickEdgeWidth;
/// Largest change of a brick's brightness from its state's tint [-]: enough
/// to tell two planks of one state apart, too little to mistake one state's
/// tint for another's.
constexpr double kWoodToneSpread = 0.1;

/// Scale of the contact-force arrows: an arrow of this fraction of a brick's
/// longest side is a force equal to the brick's weight (9.81 m/s^2), so the
/// arrows of any brick type read at the brick's own size.
constexpr double kWeightArrowFraction = 0.3;
/// Diameter of the contact points' spheres [m].
constexpr double kContactPointSize = 0.003;
/// Line width of the force arrows [m]: thinner than the rays, which they
/// cross, but a line at tower scale.
constexpr double kForceLineWidth = 0.0015;
/// Line width of the friction cones [m]: a cone is as tall as its force, so
/// a card house's lower cones are a plank high; thin and faint (alpha 0.3),
/// they frame the arrows instead of hiding the bricks.
constexpr double kFrictionConeLineWidth = 0.0006;

/// Height of the legend's letters [m], and the distance between its lines:
/// about 13 pixels in config/demo.rviz's default view.
constexpr double kLegendTextHeight = 0.012;
constexpr double kLegendLineSpacing = 1.5 * kLegendTextHeight;
/// Where the legend's column stands [m]: this far from the table centre
/// toward +x and +y (at most to the table's corner), its first line this
/// high above the table top. A table's corner is 0.7 m from its centre, out
/// of any view close enough to read a plank's rays; here the default view
/// shows it top right, clear of a 25-layer tower, the card house and the
/// slant tower's collapse, all three at the table centre.
constexpr double kLegendOffsetX = 0.2;
constexpr double kLegendOffsetY = 0.12;
constexpr double kLegendTop = 0.37;

/// Support geometry per brick id, as BrickWorld::supportGeometry() gives it.
/// Bricks the stability model does not describe are simply absent.
using SupportGeometryMap = std::map<std::string, SupportGeometry>;

/// What a brick's colour shows, most telling first: a brick that fell off is
/// shown as such whatever the simulator does with it, and Bullet's sleep is
/// shown only for dynamic bricks.
enum class BrickLook { kFellOff, kHeld, kLeaning, kStable, kAsleep, kDynamic };

BrickLook brickLook(const BrickSnapshot& brick);
/// Every look, in the order the legend lists them.
constexpr BrickLook kAllBrickLooks[] = {BrickLook::kStable,  BrickLook::kLeaning,
                                        BrickLook::kDynamic, BrickLook::kAsleep,
                                        BrickLook::kHeld,    BrickLook::kFellOff};
/// The look's name in the legend: "stable", "leaning", ...
const char* lookName(BrickLook look);
/// The tint of a look, opaque: warm pine for a stable brick, the others
/// far enough from it and from each other to tell on a plank at a glance
/// (amber leaning, blue-grey dynamic, slate asleep, violet held, red fell off).
std_msgs::ColorRGBA brickColor(BrickLook look);
/// The colour of one brick's box: its look's tint, lighter or darker by up to
/// kWoodToneSpread by its marker id (serial), as two planks of one wood
/// differ. The id's step along the golden ratio makes bricks placed one after another (a
/// layer's neighbours, a brick and the one on it) differ by at least 0.38 of
/// the spread, and the same brick keep its tone for its whole life.
std_msgs::ColorRGBA brickColor(const BrickSnapshot& brick);

/// Marker id of a brick: its placement serial, so a brick keeps its marker for
/// its whole life and a new brick never inherits an old one's.
int brickMarkerId(const BrickSnapshot& brick);

/// The outline marker of a brick: its serial / kBricksPerEdgeMarker.
int edgeMarkerId(const BrickSnapshot& brick);
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

/// One line of the legend and its colour.
struct LegendEntry {
  std::string text;
  std_msgs::ColorRGBA color;
};
/// The legend, top to bottom: a title, one line per look in kAllBrickLooks
/// order (its name first, in its tint), then what the rays, the contact
/// meshes, the arrows and the cones mean (each in its marker's colour), and
/// how to see inside the stack.
std::vector<LegendEntry> legendEntries();
/// legendEntries() as TEXT_VIEW_FACING markers (id = line number from 0),
/// kLegendTextHeight tall, kLegendLineSpacing apart, in a column over the
/// table at (kLegendOffsetX, kLegendOffsetY) [m] from its centre (at most
/// its corner), from kLegendTop down, so that config/demo.rviz's default
/// view shows it beside the bricks. Nothing for a table with a non-finite
/// or non-positive size.
visualization_msgs::MarkerArray makeLegendMarkers(const TableOptions& table,
                                                  const std::string& frame_id,
                                                  const ros::Time& stamp);

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

/// Everything a viewer that starts from nothing needs: makeBrickMarkers()
/// (DELETEALL first), makeTableMarkers(), makeLegendMarkers() and
/// makeStabilityMarkers(). The table and the legend come in every such
/// array, since the DELETEALL at its head removes every marker of the
/// display. (The node sends such an array to a new subscriber and after a
/// reset, and only what changed in between: MarkerUpdates.)
visualization_msgs::MarkerArray makeMarkers(const std::vector<BrickSnapshot>& bricks,
                                            const SupportGeometryMap& supports,
                                            const TableOptions& table, const std::string& frame_id,
                                            const ros::Time& stamp);

}  // namespace ros_adapter
}  // namespace brick_stack_sim
