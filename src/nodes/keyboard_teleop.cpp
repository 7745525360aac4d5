// The terminal teleop: parameters -> options -> raw terminal -> KeyboardTeleop.
#include <unistd.h>

#include <csignal>
#include <memory>

#include <ros/ros.h>

#include "brick_stack_sim/ros/xmlrpc_parameters.h"
#include "brick_stack_sim/teleop/keyboard_teleop.h"

using namespace brick_stack_sim;

namespace {

/// roscpp's own handler would only request a shutdown; the terminal must be
/// given back at once, whatever the main loop is waiting for.
void onInterrupt(int /*signal_number*/) {
  teleop::RawTerminal::restoreFromSignal();
  ros::requestShutdown();
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "keyboard_teleop", ros::init_options::NoSigintHandler);
  std::signal(SIGINT, onInterrupt);
  // Held for the whole run: roscpp shuts the node (and its logging) down
  // when the last NodeHandle goes away.
  ros::NodeHandle private_node_handle("~");
  ParameterValue parameters;
  teleop::KeyboardOptions options;
  std::unique_ptr<teleop::RawTerminal> terminal;
  Status status = ros_adapter::readPrivateParameters(private_node_handle, &parameters);
  if (status) status = teleop::loadKeyboardOptions(parameters, &options);
  if (status) status = teleop::RawTerminal::open(STDIN_FILENO, &terminal);
  if (!status) {
    ROS_FATAL("keyboard_teleop cannot start: %s", status.message.c_str());
    return 1;
  }
  teleop::KeyboardTeleop teleop(options);
  teleop.run(*terminal);
  return 0;
}
