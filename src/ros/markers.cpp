#include "brick_stack_sim/ros/markers.h"

namespace brick_stack_sim {
namespace ros_adapter {

visualization_msgs::MarkerArray makeMarkers(const std::vector<BrickSnapshot>& bricks,
                                            const SupportGeometryMap& supports,
                                            const TableOptions& table, const std::string& frame_id,
                                            const ros::Time& stamp, const LegendStyle& legend) {
  visualization_msgs::MarkerArray array = makeBrickMarkers(bricks, frame_id, stamp);
  for (const visualization_msgs::MarkerArray& part :
       {makeTableMarkers(table, frame_id, stamp), makeLegendMarkers(table, frame_id, stamp, legend),
        makeStabilityMarkers(bricks, supports, frame_id, stamp)})
    array.markers.insert(array.markers.end(), part.markers.begin(), part.markers.end());
  return array;
}

}  // namespace ros_adapter
}  // namespace brick_stack_sim
