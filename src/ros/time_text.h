// How the node's messages and logs write a sim time ("t=1.250 s") and a
// count ("1 brick", "2 bricks").
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

/// `n` and `noun`, plural unless `n` is one: "1 brick", "0 bricks".
inline std::string counted(std::size_t n, const std::string& noun) {
  return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

}  // namespace ros_adapter
}  // namespace brick_stack_sim
