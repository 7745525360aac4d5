#pragma once

#include <string>
#include <vector>

#include <ros/time.h>
#include <std_msgs/ColorRGBA.h>
#include <visualization_msgs/MarkerArray.h>

#include "brick_stack_sim/core/brick.h"

namespace brick_stack_sim {
namespace ros_adapter {

/// Marker namespace of the brick boxes (DESIGN.md section 3).
constexpr char kBrickMarkerNamespace[] = "bricks";

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
/// size are left out (RViz would drop the whole array).
visualization_msgs::MarkerArray makeBrickMarkers(const std::vector<BrickSnapshot>& bricks,
                                                 const std::string& frame_id,
                                                 const ros::Time& stamp);

}  // namespace ros_adapter
}  // namespace brick_stack_sim
