// The node's world lock: mutual exclusion, and waiters served in the order
// they came, so that a long ~step that hands the lock over cannot take it
// back before a client that was waiting.
#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "brick_stack_sim/ros/ticket_mutex.h"

namespace brick_stack_sim {
namespace ros_adapter {
namespace {

TEST(TicketMutex, ExcludesEveryOtherHolder) {
  TicketMutex mutex;
  long counter = 0;  // not atomic: only the lock keeps the increments whole
  std::vector<std::thread> threads;
  for (int t = 0; t < 8; ++t) {
    threads.emplace_back([&] {
      for (int i = 0; i < 20000; ++i) {
        std::lock_guard<TicketMutex> lock(mutex);
        ++counter;
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  EXPECT_EQ(counter, 8 * 20000);
}

TEST(TicketMutex, AHolderThatTakesItAgainQueuesBehindAWaiter) {
  TicketMutex mutex;
  std::unique_lock<TicketMutex> holder(mutex);
  EXPECT_FALSE(mutex.contended());
  std::atomic<bool> waiter_had_it{false};
  std::thread waiter([&] {
    std::lock_guard<TicketMutex> lock(mutex);
    waiter_had_it = true;
  });
  while (!mutex.contended()) std::this_thread::yield();
  // Released and taken again at once, as a ~step does between slices: with
  // std::mutex this thread would usually win; here the waiter goes first.
  holder.unlock();
  holder.lock();
  EXPECT_TRUE(waiter_had_it);
  holder.unlock();
  waiter.join();
}

}  // namespace
}  // namespace ros_adapter
}  // namespace brick_stack_sim
