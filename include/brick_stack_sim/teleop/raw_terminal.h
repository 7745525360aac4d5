#pragma once

#include <memory>

#include "brick_stack_sim/core/status.h"

namespace brick_stack_sim {
namespace teleop {

/// A terminal switched to key-at-a-time input (no line buffering, no echo)
/// for as long as the object lives. Its settings are restored by the
/// destructor and, should the process be stopped by SIGTERM, SIGHUP or
/// SIGQUIT, by a signal handler before the signal takes its course: a user is
/// never left with a shell that does not echo. Ctrl-C still raises SIGINT;
/// whoever handles it calls restoreFromSignal() (roscpp's own handler would
/// only request a shutdown). One terminal at a time.
class RawTerminal {
 public:
  /// Switches `fd` (standard input by default) to raw input. Fails, changing
  /// nothing, when `fd` is not a terminal or another RawTerminal is open.
  static Status open(int fd, std::unique_ptr<RawTerminal>* terminal);

  RawTerminal(const RawTerminal&) = delete;
  RawTerminal& operator=(const RawTerminal&) = delete;
  ~RawTerminal();

  /// Waits up to `timeout` [s] for one key; false when none came. After the
  /// input has ended (end of file, hang-up) it returns false at once and
  /// inputEnded() is true.
  bool readKey(double timeout, char* key);
  bool inputEnded() const { return input_ended_; }

  /// Puts back the settings of the open terminal, if any. Async-signal-safe
  /// (one tcsetattr), so a signal handler may call it; calling it twice is harmless.
  static void restoreFromSignal();

 private:
  explicit RawTerminal(int fd) : fd_(fd) {}

  int fd_;
  bool input_ended_ = false;
};

}  // namespace teleop
}  // namespace brick_stack_sim
