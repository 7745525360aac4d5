// How the node's messages and logs write a sim time: "t=1.250 s".
#pragma once

#include <sstream>
#include <string>

namespace brick_stack_sim {
namespace ros_adapter {

inline std::string formatTime(double t) {
  std::ostringstream text;
  text.precision(3);
  text << std::fixed << "t=" << t << " s";
  return text.str();
}

}  // namespace ros_adapter
}  // namespace brick_stack_sim
