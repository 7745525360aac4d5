#pragma once

#include <condition_variable>
#include <cstdint>
#include <mutex>

namespace brick_stack_sim {
namespace ros_adapter {

/// A mutex that serves its waiters in the order they asked (a ticket lock).
/// The node's long work (a ~step of a million steps) releases the world
/// between chunks and takes it again at once; with std::mutex that thread
/// usually wins again and a waiting ~get_bricks starves. Here it queues
/// behind every client that asked meanwhile. BasicLockable: use it with
/// std::unique_lock / std::lock_guard.
class TicketMutex {
 public:
  void lock() {
    std::unique_lock<std::mutex> guard(mutex_);
    const std::uint64_t ticket = next_ticket_++;
    served_.wait(guard, [&] { return now_serving_ == ticket; });
  }

  void unlock() {
    {
      std::lock_guard<std::mutex> guard(mutex_);
      ++now_serving_;
    }
    served_.notify_all();
  }

  /// Whether another thread is waiting for the lock: the holder of long work
  /// hands it over only then, so a lone ~step pays nothing for the fairness.
  bool contended() {
    std::lock_guard<std::mutex> guard(mutex_);
    return next_ticket_ - now_serving_ > 1;
  }

 private:
  std::mutex mutex_;
  std::condition_variable served_;
  std::uint64_t next_ticket_ = 0;
  std::uint64_t now_serving_ = 0;
};

}  // namespace ros_adapter
}  // namespace brick_stack_sim
