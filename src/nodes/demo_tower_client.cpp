// Builds a tower through /brick_sim/place_brick, one brick per second of sim
// time, then prints how many bricks still stand where they were placed and how
// many of them the stability layer holds frozen (STABLE).
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <ros/ros.h>
#include <tf2/LinearMath/Quaternion.h>

#include "brick_stack_sim/GetBricks.h"
#include "brick_stack_sim/PlaceBrick.h"

namespace {

constexpr double kFallenDistance = 0.005;  ///< A brick this far from where it was placed fell [m].

struct Placed {
  std::string id;
  double x, y, z;
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "demo_tower_client");
  ros::NodeHandle nh("~");
  // Brick size L x W x H [m]; the defaults are a KAPLA plank (DESIGN.md section 5).
  const int layers = nh.param("layers", 10);
  const int per_layer = nh.param("bricks_per_layer", 2);
  const std::string type = nh.param<std::string>("type", "kapla");
  const double settle_time = nh.param("settle_time", 5.0);  // [s] sim time after the last brick
  const double interval = nh.param("interval", 1.0);        // [s] sim time between bricks
  const double length = nh.param("brick_length", 0.117);
  const double width = nh.param("brick_width", 0.0234);
  const double height = nh.param("brick_height", 0.0078);
  const double gap = nh.param("gap", 0.0);  // [m] drop height of each brick onto the layer below
  const std::string sim = nh.param<std::string>("sim", "/brick_sim");
  if (layers < 1 || (per_layer != 2 && per_layer != 3) || !(interval >= 0.0) ||
      !(settle_time >= 0.0) || !(length > width && width > 0.0 && height > 0.0) || !(gap >= 0.0)) {
    ROS_FATAL(
        "bad parameters: need ~layers >= 1, ~bricks_per_layer 2 or 3, ~interval >= 0, "
        "~settle_time >= 0, brick_length > brick_width > 0, brick_height > 0, gap >= 0");
    return 1;
  }

  const std::string place_name = sim + "/place_brick";
  const std::string get_name = sim + "/get_bricks";
  if (!ros::service::waitForService(place_name, ros::Duration(60.0)) ||
      !ros::service::waitForService(get_name, ros::Duration(10.0))) {
    ROS_FATAL("%s did not come up within 60 s", place_name.c_str());
    return 1;
  }
  // With use_sim_time the clock reads 0 until the simulator's first /clock.
  ros::Time::waitForValid();
  ros::ServiceClient place = nh.serviceClient<brick_stack_sim::PlaceBrick>(place_name);
  ros::ServiceClient get = nh.serviceClient<brick_stack_sim::GetBricks>(get_name);

  const int total = layers * per_layer;
  const double offset = 0.5 * (length - width);  // outer bricks rest across the ends below
  std::vector<Placed> placed;
  int refused = 0;
  const ros::Time start = ros::Time::now();
  for (int i = 0; i < total && ros::ok(); ++i) {
    const int layer = i / per_layer;
    const int slot = i % per_layer;
    // Slots: -offset, +offset, then the middle brick of a three-brick layer.
    const double across = slot == 0 ? -offset : slot == 1 ? offset : 0.0;
    const bool along_x = layer % 2 == 0;
    brick_stack_sim::PlaceBrick srv;
    srv.request.id = "tower_" + std::to_string(i);
    srv.request.type = type;
    srv.request.pose.position.x = along_x ? 0.0 : across;
    srv.request.pose.position.y = along_x ? across : 0.0;
    srv.request.pose.position.z = 0.5 * height + layer * (height + gap);
    tf2::Quaternion q;
    q.setRPY(0.0, 0.0, along_x ? 0.0 : M_PI / 2);
    srv.request.pose.orientation.x = q.x();
    srv.request.pose.orientation.y = q.y();
    srv.request.pose.orientation.z = q.z();
    srv.request.pose.orientation.w = q.w();

    ros::Time::sleepUntil(start + ros::Duration(i * interval));
    if (!place.call(srv)) {
      ROS_FATAL("call to %s failed", place_name.c_str());
      return 1;
    }
    if (!srv.response.success) {
      ++refused;
      std::printf("brick %d/%d (layer %d) refused: %s\n", i + 1, total, layer + 1,
                  srv.response.message.c_str());
    } else {
      const auto& p = srv.request.pose.position;
      // Compared later with where the brick rests, not where it was dropped from.
      placed.push_back({srv.response.id, p.x, p.y, 0.5 * height + layer * height});
      std::printf("placed brick %d/%d (layer %d) at t=%.1f s\n", i + 1, total, layer + 1,
                  ros::Time::now().toSec());
    }
    std::fflush(stdout);
  }

  ros::Duration(settle_time).sleep();
  brick_stack_sim::GetBricks bricks;
  if (!ros::ok()) return 1;
  if (!get.call(bricks) || !bricks.response.success) {
    ROS_FATAL("call to %s failed", get_name.c_str());
    return 1;
  }
  int fallen = 0;
  int stable = 0;  // frozen by the stability layer; always 0 in mode none
  for (const Placed& mine : placed) {
    bool found = false;
    for (const auto& brick : bricks.response.bricks) {
      if (brick.id != mine.id) continue;
      found = true;
      if (brick.state == brick_stack_sim::Brick::STABLE) ++stable;
      const auto& p = brick.pose.position;
      const double moved =
          std::sqrt((p.x - mine.x) * (p.x - mine.x) + (p.y - mine.y) * (p.y - mine.y) +
                    (p.z - mine.z) * (p.z - mine.z));
      if (brick.fell_off || moved > kFallenDistance) ++fallen;
    }
    if (!found) ++fallen;  // gone: removed by someone, or never there
  }
  const int count = static_cast<int>(placed.size());
  std::printf(
      "demo summary: placed %d, standing %d, fallen %d, refused %d, stable (frozen) %d "
      "(t=%.1f s)\n",
      count, count - fallen, fallen, refused, stable, ros::Time::now().toSec());
  std::fflush(stdout);
  return 0;
}
