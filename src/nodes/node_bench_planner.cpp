// stack_sim_node_bench's planner case (node_bench_planner.h): towers of 50
// planks, frozen, queried about and planned on from this client while the
// node runs them at its own pace.
#include "node_bench_planner.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <thread>
#include <vector>

#include "brick_stack_sim/client/pose_msg.h"

namespace brick_stack_sim {
namespace node_bench {

namespace {

constexpr double kPlankLength = 0.117;     ///< [m]
constexpr double kPlankWidth = 0.0234;     ///< [m]
constexpr double kPlankHeight = 0.0078;    ///< [m]
constexpr int kTowerLayers = 25;           ///< Two planks a layer: 50 a tower.
constexpr double kTowerSpacing = 0.13;     ///< [m] between tower centres
constexpr double kSettleSimSeconds = 30;   ///< [s] at most, before a structure is given up
constexpr int kQueryGrid[2] = {40, 25};    ///< Poses along x and y: 1000.
constexpr double kQueryHalfExtent = 0.16;  ///< [m] the grid's reach from the centre
constexpr int kQueryRepeats = 5;
constexpr int kPlanRuns = 3;
constexpr int kPlanPlacements = 20;
constexpr double kPlanInterval = 0.5;   ///< [s] between placements
constexpr double kPlanDuration = 12.0;  ///< [s]
/// Planks are let go this far above where they come to rest [m], as a hand
/// lets go: each lands, so that the plan simulates more than a clock.
constexpr double kReleaseHeight = 0.002;
constexpr int kIdleGetCalls = 200;

/// What the planner case measured.
struct PlannerResult {
  // --- ~query_placements against ~query_placement -----------------------------
  int query_structure_bricks = 0;  ///< The frozen structure queried about.
  int query_poses = 0;             ///< Poses in one ~query_placements request.
  int query_repeats = 0;           ///< Requests of them, one after another.
  double batch_poses_per_second = 0.0;
  double single_poses_per_second = 0.0;  ///< The same poses through ~query_placement.
  int stable_poses = 0;                  ///< Of the poses, those judged stable.
  // --- ~simulate_plan ------------------------------------------------------------
  int plan_structure_bricks = 0;
  int plan_placements = 0;
  int plan_runs = 0;
  double plan_sim_seconds = 0.0;   ///< Simulated per plan [s].
  double plan_wall_seconds = 0.0;  ///< The node's wall time around runPlan, mean [s].
  double plan_round_trip = 0.0;    ///< The client's call, mean [s].
  bool plan_stands = false;        ///< Of the last run.
  bool plan_exact = false;         ///< The copy was exact (last run).
  double get_p50_during = 0.0, get_p99_during = 0.0;  ///< ~get_bricks during the plans [ms].
  int get_calls_during = 0;
  double get_p50_idle = 0.0, get_p99_idle = 0.0;  ///< ~get_bricks with no plan [ms].
};

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point since) {
  return std::chrono::duration<double>(Clock::now() - since).count();
}

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return NAN;
  std::sort(values.begin(), values.end());
  const std::size_t index =
      std::min(values.size() - 1, static_cast<std::size_t>(std::ceil(p * values.size())) - 1);
  return values[index];
}

/// Centre of tower `index` of a `columns` x `rows` grid centred on the table [m].
void towerCentre(int index, int columns, int rows, double* x, double* y) {
  *x = (index / rows - (columns - 1) / 2.0) * kTowerSpacing;
  *y = (index % rows - (rows - 1) / 2.0) * kTowerSpacing;
}

/// A scene of `columns` x `rows` towers of 50 planks, as towerCentre() places them.
std::string writeTowers(int columns, int rows, const std::string& directory) {
  const std::string name = "planner_towers" + std::to_string(columns * rows);
  const std::string path = directory + "/" + name + ".yaml";
  std::ofstream out(path);
  out << "name: " << name << "\n";
  out << "generator:\n  - {name: tower, layers: " << kTowerLayers << ", grid: [" << columns << ", "
      << rows << "], spacing: " << kTowerSpacing << ", origin: ["
      << -(columns - 1) * kTowerSpacing / 2 << ", " << -(rows - 1) * kTowerSpacing / 2 << "]}\n";
  return path;
}

/// Plays the scene paused and steps it until every brick is frozen; the node
/// is left paused.
bool settle(client::SimClient& sim, const std::string& scene, int bricks) {
  if (!sim.pause(true).ok) return false;
  const auto reset = sim.reset(scene);
  if (!reset.ok) {
    std::fprintf(stderr, "~reset %s: %s\n", scene.c_str(), reset.message.c_str());
    return false;
  }
  for (double t = 0.0; t < kSettleSimSeconds; t += 0.5) {
    if (!sim.step(500).ok) return false;
    const auto get = sim.getBricks();
    if (!get.ok) return false;
    const auto& all = get.response.bricks;
    if (static_cast<int>(all.size()) == bricks &&
        std::none_of(all.begin(), all.end(),
                     [](const Brick& b) { return b.state == Brick::DYNAMIC; }))
      return true;
  }
  std::fprintf(stderr, "%d bricks did not settle in %.0f s of sim time\n", bricks,
               kSettleSimSeconds);
  return false;
}

/// A plank at rest on top of the structure's height, on a grid over the
/// towers and the gaps around them, turned along x or y in turn.
std::vector<geometry_msgs::Pose> queryPoses() {
  std::vector<geometry_msgs::Pose> poses;
  const double z = (kTowerLayers + 0.5) * kPlankHeight;
  for (int i = 0; i < kQueryGrid[0]; ++i)
    for (int j = 0; j < kQueryGrid[1]; ++j)
      poses.push_back(
          client::poseAt(-kQueryHalfExtent + 2 * kQueryHalfExtent * i / (kQueryGrid[0] - 1),
                         -kQueryHalfExtent + 2 * kQueryHalfExtent * j / (kQueryGrid[1] - 1), z,
                         (i + j) % 2 ? M_PI / 2 : 0.0));
  return poses;
}

bool measureQueries(client::SimClient& sim, const std::string& directory, PlannerResult* result) {
  result->query_structure_bricks = 4 * 2 * kTowerLayers;
  if (!settle(sim, writeTowers(2, 2, directory), result->query_structure_bricks)) return false;
  if (!sim.pause(false).ok) return false;
  QueryPlacements::Request batch;
  batch.poses = queryPoses();
  result->query_poses = static_cast<int>(batch.poses.size());
  result->query_repeats = kQueryRepeats;
  const Clock::time_point start = Clock::now();
  for (int i = 0; i < kQueryRepeats; ++i) {
    const auto reply = sim.queryPlacements(batch);
    if (!reply.ok || reply.response.verdicts.size() != batch.poses.size()) {
      std::fprintf(stderr, "~query_placements: %s\n", reply.message.c_str());
      return false;
    }
    result->stable_poses = static_cast<int>(
        std::count_if(reply.response.verdicts.begin(), reply.response.verdicts.end(),
                      [](const PlacementVerdict& v) { return v.valid && v.stable; }));
  }
  result->batch_poses_per_second = kQueryRepeats * batch.poses.size() / seconds(start);
  const Clock::time_point single_start = Clock::now();
  for (const geometry_msgs::Pose& p : batch.poses) {
    QueryPlacement::Request one;
    one.pose = p;
    if (!sim.queryPlacement(one).reached) return false;
  }
  result->single_poses_per_second = batch.poses.size() / seconds(single_start);
  return true;
}

/// kPlanPlacements planks, two across the top of each tower in turn.
SimulatePlan::Request planOnTop(int columns, int rows) {
  SimulatePlan::Request request;
  const double offset = 0.5 * (kPlankLength - kPlankWidth);
  for (int k = 0; k < kPlanPlacements; ++k) {
    double x = 0.0, y = 0.0;
    towerCentre((k / 2) % (columns * rows), columns, rows, &x, &y);
    PlanStep step;
    step.action = PlanStep::PLACE;
    step.at = kPlanInterval * k;
    step.id = "plan" + std::to_string(k);
    // The tower's top layer lies along x; the next one across it, along y.
    step.pose = client::poseAt(x + (k % 2 ? offset : -offset), y,
                               (kTowerLayers + 0.5) * kPlankHeight + kReleaseHeight, M_PI / 2);
    request.steps.push_back(step);
  }
  request.duration = kPlanDuration;
  return request;
}

/// ~get_bricks over and over from a client of its own until `stop`, timed [ms].
void callGetBricks(const std::atomic<bool>& stop, int most, std::vector<double>* latencies) {
  client::SimClient getter;
  getter.getBricks();  // connected before timing
  while (!stop && static_cast<int>(latencies->size()) < most) {
    const Clock::time_point start = Clock::now();
    getter.getBricks();
    latencies->push_back(1e3 * seconds(start));
  }
}

bool measurePlans(client::SimClient& sim, const std::string& directory, PlannerResult* result) {
  const int columns = 5, rows = 2;
  result->plan_structure_bricks = columns * rows * 2 * kTowerLayers;
  if (!settle(sim, writeTowers(columns, rows, directory), result->plan_structure_bricks))
    return false;
  if (!sim.pause(false).ok) return false;
  std::vector<double> idle, during;
  callGetBricks(std::atomic<bool>(false), kIdleGetCalls, &idle);
  const SimulatePlan::Request request = planOnTop(columns, rows);
  result->plan_placements = kPlanPlacements;
  result->plan_runs = kPlanRuns;
  for (int run = 0; run < kPlanRuns; ++run) {
    std::atomic<bool> stop(false);
    std::thread getter(callGetBricks, std::cref(stop), 1 << 30, &during);
    const Clock::time_point start = Clock::now();
    const auto reply = sim.simulatePlan(request);
    const double round_trip = seconds(start);
    stop = true;
    getter.join();
    if (!reply.ok) {
      std::fprintf(stderr, "~simulate_plan: %s\n", reply.message.c_str());
      return false;
    }
    result->plan_sim_seconds = reply.response.sim_time;
    result->plan_wall_seconds += reply.response.wall_time / kPlanRuns;
    result->plan_round_trip += round_trip / kPlanRuns;
    result->plan_stands = reply.response.stands;
    result->plan_exact = reply.response.exact_copy;
  }
  result->get_p50_idle = percentile(idle, 0.5);
  result->get_p99_idle = percentile(idle, 0.99);
  result->get_p50_during = percentile(during, 0.5);
  result->get_p99_during = percentile(during, 0.99);
  result->get_calls_during = static_cast<int>(during.size());
  return true;
}

void writePlannerCsv(const std::string& path, const PlannerResult& r) {
  std::ofstream csv(path);
  csv << "query_bricks,query_poses,query_repeats,batch_poses_per_s,single_poses_per_s,"
         "batch_over_single,stable_poses,plan_bricks,plan_placements,plan_runs,plan_sim_s,"
         "plan_wall_s,plan_real_time_factor,plan_round_trip_s,plan_round_trip_factor,"
         "plan_stands,plan_exact,get_bricks_during_p50_ms,get_bricks_during_p99_ms,"
         "get_bricks_during_calls,get_bricks_idle_p50_ms,get_bricks_idle_p99_ms\n";
  csv << r.query_structure_bricks << ',' << r.query_poses << ',' << r.query_repeats << ','
      << r.batch_poses_per_second << ',' << r.single_poses_per_second << ','
      << r.batch_poses_per_second / r.single_poses_per_second << ',' << r.stable_poses << ','
      << r.plan_structure_bricks << ',' << r.plan_placements << ',' << r.plan_runs << ','
      << r.plan_sim_seconds << ',' << r.plan_wall_seconds << ','
      << r.plan_sim_seconds / r.plan_wall_seconds << ',' << r.plan_round_trip << ','
      << r.plan_sim_seconds / r.plan_round_trip << ',' << r.plan_stands << ',' << r.plan_exact
      << ',' << r.get_p50_during << ',' << r.get_p99_during << ',' << r.get_calls_during << ','
      << r.get_p50_idle << ',' << r.get_p99_idle << '\n';
}

void printPlanner(const PlannerResult& r) {
  std::fprintf(stderr,
               "planner: ~query_placements of %d poses over %d frozen bricks: %.0f poses/s; one "
               "by one through ~query_placement: %.0f poses/s (batch %.1f x); %d stable\n",
               r.query_poses, r.query_structure_bricks, r.batch_poses_per_second,
               r.single_poses_per_second, r.batch_poses_per_second / r.single_poses_per_second,
               r.stable_poses);
  std::fprintf(stderr,
               "planner: ~simulate_plan of %d placements on %d frozen bricks: %.1f s simulated in "
               "%.3f s (real-time factor %.1f; round trip %.3f s, %.1f); stands %d, exact %d; "
               "~get_bricks during the plans p50 %.2f / p99 %.2f ms over %d calls (no plan: "
               "%.2f / %.2f ms)\n",
               r.plan_placements, r.plan_structure_bricks, r.plan_sim_seconds, r.plan_wall_seconds,
               r.plan_sim_seconds / r.plan_wall_seconds, r.plan_round_trip,
               r.plan_sim_seconds / r.plan_round_trip, r.plan_stands, r.plan_exact,
               r.get_p50_during, r.get_p99_during, r.get_calls_during, r.get_p50_idle,
               r.get_p99_idle);
}

}  // namespace

bool runPlanner(client::SimClient& sim, const std::string& directory, const std::string& output) {
  PlannerResult result;
  if (!measureQueries(sim, directory, &result) || !measurePlans(sim, directory, &result))
    return false;
  printPlanner(result);
  writePlannerCsv(output.substr(0, output.rfind(".csv")) + "_planner.csv", result);
  return true;
}

}  // namespace node_bench
}  // namespace brick_stack_sim
