// Builds a tower through /brick_sim/place_brick, one brick per second of sim
// time, then prints how many bricks still stand where they were placed and how
// many of them the stability layer holds frozen (STABLE).
#include <cstdio>
#include <string>
#include <vector>

#include <ros/package.h>
#include <ros/ros.h>

#include "brick_stack_sim/GetBricks.h"
#include "brick_stack_sim/PlaceBrick.h"
#include "brick_stack_sim/core/brick_type.h"
#include "brick_stack_sim/core/scene/generators.h"
#include "brick_stack_sim/ros/conversions.h"

namespace {

constexpr double kFallenDistance = 0.005;  ///< A brick this far from where it was placed fell [m].

struct Placed {
  std::string id;
  Eigen::Vector3d position;  ///< Where it rests once down [m].
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "demo_tower_client");
  ros::NodeHandle nh("~");
  const std::string package = ros::package::getPath("brick_stack_sim");
  brick_stack_sim::TowerParams tower;
  tower.layers = nh.param("layers", 10);
  tower.bricks_per_layer = nh.param("bricks_per_layer", 2);
  tower.type = nh.param<std::string>("type", "kapla");
  tower.interval = nh.param("interval", 1.0);  // [s] sim time between bricks
  tower.gap = nh.param("gap", 0.0);            // [m] drop height of each brick onto the layer below
  const double settle_time = nh.param("settle_time", 5.0);  // [s] sim time after the last brick
  const std::string sim = nh.param<std::string>("sim", "/brick_sim");
  // The tower's geometry is the core's `tower` generator, with the brick
  // sizes of the package's URDF: the same tower as scenes/tower10.yaml.
  brick_stack_sim::BrickTypeLibrary types;
  std::vector<brick_stack_sim::ScheduledBrick> bricks;
  brick_stack_sim::Status status = brick_stack_sim::BrickTypeLibrary::load(
      nh.param<std::string>("types_urdf", package + "/urdf/bricks.urdf"),
      nh.param<std::string>("materials_yaml", package + "/config/bricks.yaml"), &types);
  if (status) status = brick_stack_sim::generateTower(tower, types, &bricks);
  if (!status || !(settle_time >= 0.0)) {
    ROS_FATAL("bad parameters: %s",
              status ? "~settle_time must be >= 0 s" : status.message.c_str());
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

  const int total = static_cast<int>(bricks.size());
  const double height = types.find(bricks.front().placement.type)->size.z();
  std::vector<Placed> placed;
  int refused = 0;
  const ros::Time start = ros::Time::now();
  for (int i = 0; i < total && ros::ok(); ++i) {
    const brick_stack_sim::BrickPlacement& brick = bricks[i].placement;
    const int layer = i / tower.bricks_per_layer;
    brick_stack_sim::PlaceBrick srv;
    srv.request.id = "tower_" + std::to_string(i);
    srv.request.type = brick.type;
    srv.request.pose = brick_stack_sim::ros_adapter::toPoseMsg(brick.pose);

    ros::Time::sleepUntil(start + ros::Duration(bricks[i].at));
    if (!place.call(srv)) {
      ROS_FATAL("call to %s failed", place_name.c_str());
      return 1;
    }
    if (!srv.response.success) {
      ++refused;
      std::printf("brick %d/%d (layer %d) refused: %s\n", i + 1, total, layer + 1,
                  srv.response.message.c_str());
    } else {
      // Compared later with where the brick rests, not where it was dropped from.
      Eigen::Vector3d rest = brick.pose.translation();
      rest.z() = (layer + 0.5) * height;
      placed.push_back({srv.response.id, rest});
      std::printf("placed brick %d/%d (layer %d) at t=%.1f s\n", i + 1, total, layer + 1,
                  ros::Time::now().toSec());
    }
    std::fflush(stdout);
  }

  ros::Duration(settle_time).sleep();
  brick_stack_sim::GetBricks response;
  if (!ros::ok()) return 1;
  if (!get.call(response) || !response.response.success) {
    ROS_FATAL("call to %s failed", get_name.c_str());
    return 1;
  }
  int fallen = 0;
  int stable = 0;  // frozen by the stability layer; always 0 in mode none
  for (const Placed& mine : placed) {
    bool found = false;
    for (const auto& brick : response.response.bricks) {
      if (brick.id != mine.id) continue;
      found = true;
      if (brick.state == brick_stack_sim::Brick::STABLE) ++stable;
      const auto& p = brick.pose.position;
      const double moved = (Eigen::Vector3d(p.x, p.y, p.z) - mine.position).norm();
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
