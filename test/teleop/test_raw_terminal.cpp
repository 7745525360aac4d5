// RawTerminal on a pseudo-terminal: raw while it lives, restored after,
// keys read one at a time, and refused on what is not a terminal.
#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include <cstdlib>
#include <memory>

#include <gtest/gtest.h>

#include "brick_stack_sim/teleop/raw_terminal.h"

namespace {

using brick_stack_sim::Status;
using brick_stack_sim::teleop::RawTerminal;

/// A pseudo-terminal pair in its default (cooked) mode, closed at the end.
class PseudoTerminal : public ::testing::Test {
 protected:
  void SetUp() override {
    master_ = posix_openpt(O_RDWR | O_NOCTTY);
    ASSERT_GE(master_, 0);
    ASSERT_EQ(grantpt(master_), 0);
    ASSERT_EQ(unlockpt(master_), 0);
    slave_ = open(ptsname(master_), O_RDWR | O_NOCTTY);
    ASSERT_GE(slave_, 0);
  }
  void TearDown() override {
    if (slave_ >= 0) close(slave_);
    if (master_ >= 0) close(master_);
  }
  tcflag_t localFlags() const {
    termios settings;
    EXPECT_EQ(tcgetattr(slave_, &settings), 0);
    return settings.c_lflag;
  }

  int master_ = -1;
  int slave_ = -1;
};

TEST_F(PseudoTerminal, RawWhileOpenRestoredAfter) {
  const tcflag_t before = localFlags();
  ASSERT_TRUE(before & ICANON);
  ASSERT_TRUE(before & ECHO);
  {
    std::unique_ptr<RawTerminal> terminal;
    const Status opened = RawTerminal::open(slave_, &terminal);
    ASSERT_TRUE(opened.ok) << opened.message;
    const tcflag_t raw = localFlags();
    EXPECT_FALSE(raw & ICANON);
    EXPECT_FALSE(raw & ECHO);
    EXPECT_TRUE(raw & ISIG) << "Ctrl-C must still raise SIGINT";
    // A second one at the same time would save the raw settings as "original".
    std::unique_ptr<RawTerminal> second;
    EXPECT_FALSE(RawTerminal::open(slave_, &second).ok);
  }
  EXPECT_EQ(localFlags(), before);
}

TEST_F(PseudoTerminal, RestoreFromSignalRestoresAtOnce) {
  const tcflag_t before = localFlags();
  std::unique_ptr<RawTerminal> terminal;
  ASSERT_TRUE(RawTerminal::open(slave_, &terminal).ok);
  RawTerminal::restoreFromSignal();
  EXPECT_EQ(localFlags(), before);
  RawTerminal::restoreFromSignal();  // twice: harmless
  terminal.reset();
  EXPECT_EQ(localFlags(), before);
}

TEST_F(PseudoTerminal, KeysArriveOneAtATimeWithoutEnter) {
  std::unique_ptr<RawTerminal> terminal;
  ASSERT_TRUE(RawTerminal::open(slave_, &terminal).ok);
  char key = 0;
  EXPECT_FALSE(terminal->readKey(0.05, &key)) << "a key before any was typed";
  ASSERT_EQ(write(master_, "wq", 2), 2);  // no newline: a cooked terminal would wait for one
  ASSERT_TRUE(terminal->readKey(1.0, &key));
  EXPECT_EQ(key, 'w');
  ASSERT_TRUE(terminal->readKey(1.0, &key));
  EXPECT_EQ(key, 'q');
  EXPECT_FALSE(terminal->readKey(0.05, &key));
  EXPECT_FALSE(terminal->inputEnded());
}

TEST_F(PseudoTerminal, HangUpEndsTheInput) {
  std::unique_ptr<RawTerminal> terminal;
  ASSERT_TRUE(RawTerminal::open(slave_, &terminal).ok);
  close(master_);
  master_ = -1;
  char key = 0;
  EXPECT_FALSE(terminal->readKey(1.0, &key));
  EXPECT_TRUE(terminal->inputEnded());
}

TEST(RawTerminal, RefusesWhatIsNotATerminal) {
  int pipe_ends[2];
  ASSERT_EQ(pipe(pipe_ends), 0);
  std::unique_ptr<RawTerminal> terminal;
  const Status opened = RawTerminal::open(pipe_ends[0], &terminal);
  EXPECT_FALSE(opened.ok);
  EXPECT_NE(opened.message.find("not a terminal"), std::string::npos) << opened.message;
  EXPECT_FALSE(terminal);
  close(pipe_ends[0]);
  close(pipe_ends[1]);
}

}  // namespace
