#include "brick_stack_sim/ros/marker_style.h"

#include <algorithm>
#include <cmath>

#include "brick_stack_sim/ros/conversions.h"

namespace brick_stack_sim {
namespace ros_adapter {

namespace {

std_msgs::ColorRGBA opaque(std_msgs::ColorRGBA color) {
  color.a = 1.0f;  // text: a translucent legend would be harder to read
  return color;
}

}  // namespace

std_msgs::ColorRGBA rgb(float r, float g, float b, float a) {
  std_msgs::ColorRGBA color;
  color.r = r;
  color.g = g;
  color.b = b;
  color.a = a;
  return color;
}

std_msgs::ColorRGBA contactPointColor() { return rgb(1.00f, 1.00f, 1.00f); }        // white
std_msgs::ColorRGBA forceArrowColor() { return rgb(0.95f, 0.10f, 0.85f); }          // magenta
std_msgs::ColorRGBA frictionConeColor() { return rgb(0.10f, 0.85f, 0.95f, 0.3f); }  // cyan
std_msgs::ColorRGBA patchColor() { return rgb(0.10f, 0.55f, 1.00f, 0.90f); }        // blue
std_msgs::ColorRGBA hullColor() { return rgb(1.00f, 0.85f, 0.10f, 0.35f); }  // translucent yellow

void appendSegment(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                   std::vector<geometry_msgs::Point>* lines) {
  lines->push_back(toPointMsg(from));
  lines->push_back(toPointMsg(to));
}

visualization_msgs::Marker newMarker(const std::string& frame_id, const ros::Time& stamp,
                                     const char* ns, int id, int type) {
  visualization_msgs::Marker marker;
  marker.header.frame_id = frame_id;
  marker.header.stamp = stamp;
  marker.ns = ns;
  marker.id = id;
  marker.type = type;
  marker.action = visualization_msgs::Marker::ADD;
  marker.pose.orientation.w = 1.0;
  marker.frame_locked = false;
  return marker;
}

BrickLook brickLook(const BrickSnapshot& brick) {
  if (brick.fell_off) return BrickLook::kFellOff;
  switch (brick.state) {
    case BrickState::kHeld:
      return BrickLook::kHeld;
    case BrickState::kLeaning:
      return BrickLook::kLeaning;
    case BrickState::kStable:
      return BrickLook::kStable;
    case BrickState::kDynamic:
      break;
  }
  return brick.asleep ? BrickLook::kAsleep : BrickLook::kDynamic;
}

const char* lookName(BrickLook look) {
  switch (look) {
    case BrickLook::kFellOff:
      return "fell off";
    case BrickLook::kHeld:
      return "held";
    case BrickLook::kLeaning:
      return "leaning";
    case BrickLook::kStable:
      return "stable";
    case BrickLook::kAsleep:
      return "asleep";
    case BrickLook::kDynamic:
      return "dynamic";
  }
  return "?";
}

std_msgs::ColorRGBA brickColor(BrickLook look) {
  // Stable is the common case and the calm one: the plank's own pine. The
  // others are tints a viewer names at once, each at least 0.25 from every
  // other in RGB, far more than the wood tone's spread, and no channel so
  // bright that the tone's lighter half would clip (test_markers checks).
  switch (look) {
    case BrickLook::kFellOff:
      return rgb(0.86f, 0.22f, 0.18f);  // red
    case BrickLook::kHeld:
      return rgb(0.72f, 0.42f, 0.90f);  // violet
    case BrickLook::kLeaning:
      return rgb(0.90f, 0.52f, 0.10f);  // amber
    case BrickLook::kStable:
      return rgb(0.87f, 0.71f, 0.47f);  // pine
    case BrickLook::kAsleep:
      return rgb(0.52f, 0.52f, 0.54f);  // slate grey
    case BrickLook::kDynamic:
      return rgb(0.58f, 0.70f, 0.88f);  // blue-grey
  }
  return rgb(1.0f, 1.0f, 1.0f);
}

std_msgs::ColorRGBA brickColor(const BrickSnapshot& brick) {
  // The fractional parts of n times the golden ratio spread evenly over [0, 1)
  // and consecutive ones are 0.382 or 0.618 apart: the tones of neighbours
  // never coincide, and nothing random makes two runs look different.
  constexpr double kGoldenRatioFraction = 0.6180339887498949;
  const double unit = std::fmod(kGoldenRatioFraction * static_cast<double>(brick.serial), 1.0);
  const float factor = static_cast<float>(1.0 + kWoodToneSpread * (2.0 * unit - 1.0));
  std_msgs::ColorRGBA color = brickColor(brickLook(brick));
  color.r = std::min(1.0f, color.r * factor);
  color.g = std::min(1.0f, color.g * factor);
  color.b = std::min(1.0f, color.b * factor);
  return color;
}

std_msgs::ColorRGBA comAboveColor(double margin) {
  // Brighter than the box colours, so a ray inside a green stable brick stands out.
  return margin > 0.0 ? rgb(0.20f, 1.00f, 0.20f) : rgb(1.00f, 0.10f, 0.10f);
}

std::vector<LegendEntry> legendEntries() {
  // Short lines: the legend stands beside the bricks in the default view,
  // where a long line would reach over them.
  std::vector<LegendEntry> entries;
  entries.push_back({"brick colour = state", rgb(0.95f, 0.95f, 0.95f)});
  for (BrickLook look : kAllBrickLooks) {
    const char* meaning = "";
    switch (look) {
      case BrickLook::kStable:
        meaning = "frozen, resting";
        break;
      case BrickLook::kLeaning:
        meaning = "frozen, by friction";
        break;
      case BrickLook::kDynamic:
        meaning = "moving (Bullet)";
        break;
      case BrickLook::kAsleep:
        meaning = "Bullet sleeps it";
        break;
      case BrickLook::kHeld:
        meaning = "teleop or planner";
        break;
      case BrickLook::kFellOff:
        meaning = "off the table";
        break;
    }
    entries.push_back({std::string(lookName(look)) + ": " + meaning, brickColor(look)});
  }
  entries.push_back({"ray: COM-above to support", comAboveColor(1.0)});
  entries.push_back({"red ray: COM-above outside", comAboveColor(-1.0)});
  entries.push_back({"blue: contacts, yellow: hull", opaque(patchColor())});
  entries.push_back({"arrows: force, 1/3 plank = weight", forceArrowColor()});
  entries.push_back({"cyan: friction cones", opaque(frictionConeColor())});
  entries.push_back({"untick 'bricks' to see inside", rgb(0.75f, 0.75f, 0.75f)});
  return entries;
}

double legendScale(const TableOptions& table, const LegendStyle& style) {
  const double own = std::isfinite(style.scale) && style.scale > 0.0 ? style.scale : 1.0;
  return own * table.size.norm() / kLegendReferenceTableDiagonal;
}

visualization_msgs::MarkerArray makeLegendMarkers(const TableOptions& table,
                                                  const std::string& frame_id,
                                                  const ros::Time& stamp,
                                                  const LegendStyle& style) {
  using visualization_msgs::Marker;
  visualization_msgs::MarkerArray array;
  if (!table.size.allFinite() || !(table.size.minCoeff() > 0.0)) return array;
  const double scale = legendScale(table, style);
  // Over the table, back right of the default view (config/demo.rviz looks
  // along +y, slightly toward -x): beside a tower or a card house at the
  // centre, in front of nothing. A small table pulls it in to its corner.
  const double x = std::min(scale * kLegendOffsetX, 0.5 * table.size.x());
  const double y = std::min(scale * kLegendOffsetY, 0.5 * table.size.y());
  const double top = scale * kLegendTop;
  const std::vector<LegendEntry> entries = legendEntries();
  for (std::size_t i = 0; i < entries.size(); ++i) {
    Marker line = newMarker(frame_id, stamp, kLegendMarkerNamespace, static_cast<int>(i),
                            Marker::TEXT_VIEW_FACING);
    line.pose.position.x = x;
    line.pose.position.y = y;
    line.pose.position.z = top - static_cast<double>(i) * scale * kLegendLineSpacing;
    // TEXT_VIEW_FACING: only z, the height of a capital
    line.scale.z = scale * kLegendTextHeight;
    line.text = entries[i].text;
    line.color = entries[i].color;
    array.markers.push_back(line);
  }
  if (!style.title.empty()) {
    // Over the centre, where the structure stands: the title names the
    // table, and in a view of two tables it stands over its own.
    Marker title = newMarker(frame_id, stamp, kLegendMarkerNamespace, kLegendTitleMarkerId,
                             Marker::TEXT_VIEW_FACING);
    title.pose.position.z = top + scale * kLegendTitleHeight;
    title.scale.z = scale * kLegendTitleHeight;
    title.text = style.title;
    title.color = rgb(1.0f, 1.0f, 1.0f);
    array.markers.push_back(title);
  }
  return array;
}

}  // namespace ros_adapter
}  // namespace brick_stack_sim
