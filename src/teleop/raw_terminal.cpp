#include "brick_stack_sim/teleop/raw_terminal.h"

#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <string>

namespace brick_stack_sim {
namespace teleop {

namespace {

// Signal handlers can reach nothing but globals.
int g_open_fd = -1;
termios g_saved_settings;
volatile sig_atomic_t g_raw_active = 0;

constexpr int kRestoredSignals[] = {SIGTERM, SIGHUP, SIGQUIT};

void restoreAndReraise(int signal_number) {
  RawTerminal::restoreFromSignal();
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

}  // namespace

Status RawTerminal::open(int fd, std::unique_ptr<RawTerminal>* terminal) {
  if (g_raw_active) return Status::error("a raw terminal is already open");
  if (!isatty(fd))
    return Status::error("file descriptor " + std::to_string(fd) +
                         " is not a terminal: run the keyboard teleop in a terminal (rosrun), "
                         "not from a launch file without one");
  termios settings;
  if (tcgetattr(fd, &settings) != 0)
    return Status::error(std::string("cannot read the terminal settings: ") + std::strerror(errno));
  g_saved_settings = settings;
  g_open_fd = fd;
  termios raw = settings;
  // ISIG stays on: Ctrl-C must still stop the program.
  raw.c_lflag &= ~static_cast<tcflag_t>(ICANON | ECHO);
  raw.c_cc[VMIN] = 0;
  raw.c_cc[VTIME] = 0;
  if (tcsetattr(fd, TCSANOW, &raw) != 0) {
    g_open_fd = -1;
    return Status::error(std::string("cannot switch the terminal to raw input: ") +
                         std::strerror(errno));
  }
  g_raw_active = 1;
  for (int signal_number : kRestoredSignals) std::signal(signal_number, restoreAndReraise);
  terminal->reset(new RawTerminal(fd));
  return Status::success();
}

RawTerminal::~RawTerminal() {
  restoreFromSignal();
  for (int signal_number : kRestoredSignals) std::signal(signal_number, SIG_DFL);
  g_open_fd = -1;
}

void RawTerminal::restoreFromSignal() {
  if (!g_raw_active) return;
  tcsetattr(g_open_fd, TCSANOW, &g_saved_settings);
  g_raw_active = 0;
}

bool RawTerminal::readKey(double timeout, char* key) {
  if (input_ended_) return false;
  pollfd request{fd_, POLLIN, 0};
  const int ready = poll(&request, 1, static_cast<int>(timeout * 1000.0));
  if (ready <= 0) return false;  // timeout, or a signal: the caller looks again
  if (request.revents & (POLLHUP | POLLERR | POLLNVAL)) {
    input_ended_ = !(request.revents & POLLIN);
    if (input_ended_) return false;
  }
  const ssize_t count = read(fd_, key, 1);
  if (count == 0) input_ended_ = true;
  return count == 1;
}

}  // namespace teleop
}  // namespace brick_stack_sim
