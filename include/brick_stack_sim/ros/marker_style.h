#pragma once
// How the node's markers look: their namespaces, sizes and colours, a
// brick's look by its state, and the legend that says what each colour means.

#include <string>
#include <vector>

#include <geometry_msgs/Point.h>
#include <ros/time.h>
#include <std_msgs/ColorRGBA.h>
#include <visualization_msgs/MarkerArray.h>
#include <Eigen/Core>

#include "brick_stack_sim/core/types/brick.h"
#include "brick_stack_sim/core/types/world_options.h"

namespace brick_stack_sim {
namespace ros_adapter {

// Marker namespaces (docs/ros_interface.md, "What you see in RViz"): the
// bricks, the stability layer, and what makes the picture readable. Each its
// own namespace, so that RViz's MarkerArray display can switch it off on its
// own.
/// A body per brick (its box, cylinder, hull, or a compound's parts as
/// one triangle list), opaque wood tinted by state.
constexpr char kBrickMarkerNamespace[] = "bricks";
/// A ray per brick from its COM-above straight down to its support height.
constexpr char kComAboveMarkerNamespace[] = "com_above";
/// Per brick: its support patches, and their combined hull.
constexpr char kContactMeshMarkerNamespace[] = "contact_mesh";
/// Per brick that statics solved for: its contact points, the contact
/// forces on it as arrows and the friction cones they must stay in.
constexpr char kLeaningMarkerNamespace[] = "leaning";
/// The edges of every brick's body (a box's twelve, a hull's, a cylinder's
/// two cap rims), dark, kBricksPerEdgeMarker bricks to a marker (ids
/// edgeMarkerId(), from kBrickEdgesMarkerId). Bodies of one
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
/// Height of the title's letters [m] ("mode com", over the table's centre,
/// one title height above the legend's first line): large enough to name a
/// table from a view of two of them (config/compare.rviz).
constexpr double kLegendTitleHeight = 0.04;
/// The title's id in the legend namespace, clear of the lines' ids.
constexpr int kLegendTitleMarkerId = 100;
/// The diagonal of the table the sizes above are for (TableOptions' default,
/// 1.2 m by 0.8 m) [m]: a larger table scales them up, a smaller one down.
constexpr double kLegendReferenceTableDiagonal = 1.4422205101855958;

/// What the legend shows beyond its lines, and how large: a title, and a
/// scale on top of the table's (docs/ros_interface.md, "What you see in RViz").
struct LegendStyle {
  std::string title;   ///< Over the table's centre; empty: no title.
  double scale = 1.0;  ///< Times every size and offset; not finite or <= 0: 1.
};

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

/// Colour of a COM-above ray: green while the projection of the COM-above is
/// inside the support hull (margin > 0 [m]), red on or outside its edge.
std_msgs::ColorRGBA comAboveColor(double margin);

// The colours of the stability layer, shared with the legend.
std_msgs::ColorRGBA contactPointColor();  ///< White.
std_msgs::ColorRGBA forceArrowColor();    ///< Magenta.
std_msgs::ColorRGBA frictionConeColor();  ///< Cyan, faint.
std_msgs::ColorRGBA patchColor();         ///< Blue.
std_msgs::ColorRGBA hullColor();          ///< Translucent yellow.

/// A colour from its components [0, 1].
std_msgs::ColorRGBA rgb(float r, float g, float b, float a = 1.0f);

/// Appends the segment `from`-`to` [m] to the points of a LINE_LIST.
void appendSegment(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                   std::vector<geometry_msgs::Point>* lines);

/// A marker with everything but its geometry: header, namespace, id, ADD, and
/// an identity pose (RViz warns about the all-zero quaternion of a default one).
visualization_msgs::Marker newMarker(const std::string& frame_id, const ros::Time& stamp,
                                     const char* ns, int id, int type);

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
/// The factor on the legend's sizes and offsets: the table's diagonal over
/// kLegendReferenceTableDiagonal, times `style.scale` (1 for a scale that
/// is not finite or not positive).
double legendScale(const TableOptions& table, const LegendStyle& style);
/// legendEntries() as TEXT_VIEW_FACING markers (id = line number from 0),
/// kLegendTextHeight tall, kLegendLineSpacing apart, in a column over the
/// table at (kLegendOffsetX, kLegendOffsetY) [m] from its centre (at most
/// its corner), from kLegendTop down, each size and offset times
/// legendScale(), so that config/demo.rviz's default view shows it beside
/// the bricks; and the style's title (id kLegendTitleMarkerId),
/// kLegendTitleHeight tall (scaled too), over the table's centre one title
/// height above the first line. Nothing for a table with a non-finite or
/// non-positive size.
visualization_msgs::MarkerArray makeLegendMarkers(const TableOptions& table,
                                                  const std::string& frame_id,
                                                  const ros::Time& stamp,
                                                  const LegendStyle& style = LegendStyle());

}  // namespace ros_adapter
}  // namespace brick_stack_sim
