#pragma once
// Any call to the node, from a thread of its own, waited for with a timeout:
// node_fixture.h's callWithin for work that is not one of its services'
// requests (~simulate_plan, a call from a client of its own).

#include <chrono>
#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <thread>

#include <gtest/gtest.h>

namespace brick_stack_sim {
namespace test {

/// `work()` from a thread of its own, waited for at most `seconds` [s] of wall
/// time: a roscpp call has no timeout, and a node that never answers must fail
/// the test rather than hang it. Empty when it did not come back in time (the
/// thread is then left behind: what `work` uses must be shared with it, as a
/// std::shared_ptr to the client).
template <typename Result>
std::optional<Result> within(double seconds, std::function<Result()> work) {
  auto answer = std::make_shared<std::promise<Result>>();
  std::future<Result> done = answer->get_future();
  std::thread([work, answer] { answer->set_value(work()); }).detach();
  if (done.wait_for(std::chrono::duration<double>(seconds)) != std::future_status::ready) {
    ADD_FAILURE() << "no answer within " << seconds << " s";
    return std::nullopt;
  }
  return done.get();
}

}  // namespace test
}  // namespace brick_stack_sim
