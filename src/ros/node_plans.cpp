// The node's ~simulate_plan: the request is checked, the world copied under
// the world lock, and the plan run on the copy off it, so that the live
// simulation, the publishers and every other client go on meanwhile.
#include <malloc.h>

#include <chrono>
#include <mutex>
#include <sstream>

#include "brick_stack_sim/core/types/stability_modes.h"
#include "brick_stack_sim/ros/node.h"
#include "brick_stack_sim/ros/plan_conversions.h"
#include "time_text.h"

namespace brick_stack_sim {
namespace ros_adapter {

namespace {

/// A place among the plans that may run at once, held for as long as it
/// lives; taken() is false when every place was taken already.
class PlanSlot {
 public:
  PlanSlot(std::atomic<int>* running, int most) : running_(running) {
    int now = running_->load();
    // Taken only while below the bound: a request past it is refused, not queued.
    while (now < most)
      if (running_->compare_exchange_weak(now, now + 1)) {
        taken_ = true;
        return;
      }
    refused_at_ = now;
  }
  ~PlanSlot() {
    if (taken_) --*running_;
  }
  PlanSlot(const PlanSlot&) = delete;
  PlanSlot& operator=(const PlanSlot&) = delete;

  bool taken() const { return taken_; }
  /// How many plans ran when the place was refused.
  int refusedAt() const { return refused_at_; }

 private:
  std::atomic<int>* running_;
  bool taken_ = false;
  int refused_at_ = 0;
};

std::string boundMessage(int running, int most) {
  return counted(static_cast<std::size_t>(running), "plan") + (running == 1 ? " is" : " are") +
         " running, the most ~" + kMaxConcurrentPlansParameter + " allows (" +
         std::to_string(most) + "): ask again when one has ended";
}

/// What the answer says besides the verdict.
std::string planSummary(const SimulatePlan::Response& response, const std::string& mode,
                        std::size_t left_out) {
  std::ostringstream text;
  text.precision(3);
  text << "simulated " << response.sim_time << " s in " << response.wall_time
       << " s of wall time on " << (response.exact_copy ? "an exact" : "a") << " copy in mode "
       << mode << ": " << response.verdict;
  if (left_out > 0) text << "; " << left_out << " left out: not finite";
  return text.str();
}

}  // namespace

bool SimNode::simulatePlan(SimulatePlan::Request& request, SimulatePlan::Response& response) {
  Plan plan;
  if (Status read = fromMsg(request, &plan); !read)
    return refuse(kSimulatePlanService, read, &response);
  // The running mode never changes (a scene brings a table and types, not a
  // mode): options_ may be read off the lock.
  const std::string& running_mode = options_.config.world.stability.mode;
  const std::string mode = request.mode.empty() ? running_mode : request.mode;
  if (Status known = checkStabilityMode(mode); !known)
    return refuse(kSimulatePlanService, prefixed("mode: ", known), &response);
  const PlanSlot slot(&running_plans_, options_.max_concurrent_plans);
  if (!slot.taken())
    return refuse(kSimulatePlanService,
                  Status::error(boundMessage(slot.refusedAt(), options_.max_concurrent_plans)),
                  &response);

  // The copy is all the lock is held for: from here on the plan's world is
  // nobody else's, and neither the live world nor the node's members are read.
  std::unique_ptr<BrickWorld> world;
  bool exact = false;
  {
    std::lock_guard<TicketMutex> lock(world_mutex_);
    world = simulation_->world().copy();
    exact = simulation_->world().copiesExactly();
  }
  if (mode != running_mode) {
    // Rebuilt from the copy rather than the live world: the same bricks at
    // the same instant, without holding the world while a model judges them.
    std::unique_ptr<BrickWorld> rebuilt;
    if (Status copied = world->copyInMode(mode, &rebuilt); !copied)
      return refuse(kSimulatePlanService, copied, &response);
    world = std::move(rebuilt);
  }
  PlanOutcome outcome;
  const auto start = std::chrono::steady_clock::now();
  const Status ran = runPlan(plan, world.get(), &outcome, &stopping_plans_);
  const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - start;
  world.reset();
  // The copy's pages back to the system, as after a ~reset: a node asked
  // for plan after plan would otherwise keep the largest copy's worth.
  malloc_trim(0);
  if (!ran) return refuse(kSimulatePlanService, ran, &response);

  std::size_t left_out = 0;
  toMsg(outcome, options_.config.publish.frame_id, &response, &left_out);
  response.wall_time = wall.count();
  response.exact_copy = exact && mode == running_mode;
  response.success = true;
  response.message = planSummary(response, mode, left_out);
  return true;
}

}  // namespace ros_adapter
}  // namespace brick_stack_sim
