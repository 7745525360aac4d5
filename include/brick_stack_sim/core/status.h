#pragma once

#include <string>
#include <utility>

namespace brick_stack_sim {

/// Outcome of a request to the core: on failure, `message` says what was wrong
/// in words a user of a service or a command line can act on.
struct Status {
  bool ok = true;
  std::string message;

  static Status success() { return {}; }
  static Status error(std::string what) { return {false, std::move(what)}; }
  explicit operator bool() const { return ok; }
};

/// `status` with `prefix` in front of its message when it is a failure: a
/// module's message names its field ("size = 0: ..."), its parent says where
/// the module sits ("table/").
inline Status prefixed(const std::string& prefix, Status status) {
  if (!status.ok) status.message = prefix + status.message;
  return status;
}

}  // namespace brick_stack_sim
