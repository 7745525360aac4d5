#pragma once
// A request that asks for more memory than there is becomes a refusal with a
// message, never an uncaught exception (docs/ros_interface.md, "Refusals and
// limits").

#include <new>
#include <stdexcept>
#include <string>

#include "brick_stack_sim/core/status.h"

namespace brick_stack_sim {

/// Runs `request`, a callable returning Status, and returns what it returns;
/// an allocation failure inside it (std::bad_alloc, or std::length_error: a
/// container asked to hold more than it can) comes back as a refusal,
/// "out of memory while <what> (std::bad_alloc)". The guard undoes nothing:
/// put it round work that changes nothing until it has all it needs (a
/// scene read and its world built before the world is replaced).
template <typename Request>
Status refuseOnAllocationFailure(const std::string& what, Request&& request) {
  try {
    return request();
  } catch (const std::bad_alloc& error) {
    return Status::error("out of memory while " + what + " (" + error.what() + ")");
  } catch (const std::length_error& error) {
    return Status::error("out of memory while " + what + " (std::length_error: " + error.what() +
                         ")");
  }
}

}  // namespace brick_stack_sim
