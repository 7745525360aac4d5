// stack_sim_node_bench: what a running brick_sim node costs, from the outside.
// For settled scenes of 100 to 10 000 bricks, with 0 or 10 bricks kept
// moving, and with 0, 1 (~bricks) or 3 (~bricks, ~markers, /tf) subscribers
// (with --delta, for a node run with bricks_delta: the scenes with 10 moving
// bricks and one ~bricks subscriber),
// it measures the node's CPU (from /proc, as a share of one core), the rates
// and sizes of what it publishes, and the latency of ~get_bricks,
// ~query_placement and ~place_brick from this C++ client. One CSV row per
// case; first the planner case (node_bench_planner.h; --planner: it alone).
// scripts/run_node_bench.sh starts the node and plots the rows.
//
//   stack_sim_node_bench OUTPUT.csv [--quick] [--delta] [--planner] [--window SECONDS]
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <ros/master.h>
#include <ros/network.h>
#include <ros/ros.h>
#include <tf2_msgs/TFMessage.h>
#include <visualization_msgs/MarkerArray.h>
#include <xmlrpcpp/XmlRpcClient.h>

#include "brick_stack_sim/client/sim_client.h"
#include "brick_stack_sim/ros/interface_names.h"
#include "node_bench_planner.h"

namespace {

using namespace brick_stack_sim;

/// The node measured: its name is its private namespace.
const std::string kNode = ros_adapter::kDefaultNamespace;
constexpr int kTowerBricks = 50;          ///< 25 layers of two planks
constexpr double kTowerSpacing = 0.13;    ///< [m] between tower centres
constexpr double kPlankHeight = 0.0078;   ///< [m]
constexpr double kLooseSpacing = 0.13;    ///< [m] between the loose planks, along x
constexpr int kLatencyCalls = 100;        ///< per service and case
constexpr double kPushPeriod = 0.2;       ///< [s] wall, between pushes of a moving brick
constexpr double kSettleSimSeconds = 30;  ///< [s] at most, before a case is given up

struct Case {
  int bricks = 0;  ///< settled, in towers of 50
  int moving = 0;  ///< loose planks beside the towers, pushed all the time
};

struct Point2 {
  double x = 0.0, y = 0.0;
};

struct Row {
  Case scene;
  int subscribers = 0;
  double node_cpu = 0.0;  ///< share of one core [-]
  double bricks_hz = 0.0, markers_hz = 0.0, tf_hz = 0.0;
  double bricks_bytes = 0.0, markers_bytes = 0.0, tf_bytes = 0.0;  ///< per message
  double get_p50 = 0.0, get_p99 = 0.0;                             ///< [ms]
  double query_p50 = 0.0, query_p99 = 0.0;
  double place_p50 = 0.0, place_p99 = 0.0;
};

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return NAN;
  std::sort(values.begin(), values.end());
  const std::size_t index =
      std::min(values.size() - 1, static_cast<std::size_t>(std::ceil(p * values.size())) - 1);
  return values[index];
}

/// The node's process id, asked of the node itself through the master.
int nodePid() {
  XmlRpc::XmlRpcValue args, result, payload;
  args[0] = ros::this_node::getName();
  args[1] = kNode;
  if (!ros::master::execute("lookupNode", args, result, payload, true)) return -1;
  std::string host;
  std::uint32_t port = 0;
  if (!ros::network::splitURI(static_cast<std::string>(payload), host, port)) return -1;
  XmlRpc::XmlRpcClient client(host.c_str(), static_cast<int>(port), "/");
  XmlRpc::XmlRpcValue request, response;
  request[0] = ros::this_node::getName();
  if (!client.execute("getPid", request, response) || response.size() < 3) return -1;
  return static_cast<int>(response[2]);
}

/// User plus system CPU time of a process [s].
double processCpuSeconds(int pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string text((std::istreambuf_iterator<char>(stat)), std::istreambuf_iterator<char>());
  // The command may hold spaces; the fields after it are counted from ')'.
  const std::size_t close = text.rfind(')');
  if (close == std::string::npos) return NAN;
  std::istringstream fields(text.substr(close + 2));
  std::string field;
  double utime = 0.0, stime = 0.0;
  for (int i = 3; i <= 15 && fields >> field; ++i) {
    if (i == 14) utime = std::stod(field);
    if (i == 15) stime = std::stod(field);
  }
  return (utime + stime) / static_cast<double>(sysconf(_SC_CLK_TCK));
}

/// Messages and bytes per topic while subscribed.
struct TopicCount {
  long messages = 0;
  double bytes = 0.0;
};

/// A subscriber callback that counts each message of type Message and its bytes.
template <typename Message>
std::function<void(const boost::shared_ptr<const Message>&)> countMessages(std::mutex* mutex,
                                                                           TopicCount* count) {
  return [mutex, count](const boost::shared_ptr<const Message>& msg) {
    std::lock_guard<std::mutex> lock(*mutex);
    ++count->messages;
    count->bytes += ros::serialization::serializationLength(*msg);
  };
}

class NodeBench {
 public:
  /// Measures the node `sim` reaches (persistent connections), process `pid`.
  NodeBench(double window, int pid, client::SimClient sim)
      : window_(window), pid_(pid), sim_(std::move(sim)) {}

  /// Every subscriber count of one scene; false when the scene never settled.
  bool run(const Case& scene, const std::string& scene_file, const std::vector<int>& counts,
           std::vector<Row>* rows) {
    if (!settle(scene, scene_file)) return false;
    for (int subscribers : counts) {
      Row row;
      row.scene = scene;
      row.subscribers = subscribers;
      measureLoad(scene, subscribers, &row);
      measureLatency(scene, &row);
      rows->push_back(row);
      std::fprintf(stderr,
                   "%5d settled %2d moving %d subscribers: node %.1f %% of a core; ~bricks %.1f Hz "
                   "(%.0f kB), ~markers %.1f Hz, /tf %.1f Hz; get_bricks p99 %.1f ms\n",
                   scene.bricks, scene.moving, subscribers, 100 * row.node_cpu, row.bricks_hz,
                   row.bricks_bytes / 1000, row.markers_hz, row.tf_hz, row.get_p99);
    }
    return true;
  }

 private:
  bool setPaused(bool paused) { return sim_.pause(paused).ok; }

  /// Plays the scene paused and steps it until every tower brick is frozen,
  /// then lets it run at the node's own pace.
  bool settle(const Case& scene, const std::string& scene_file) {
    if (!setPaused(true)) return false;
    const auto reset = sim_.reset(scene_file);
    if (!reset.ok) {
      std::fprintf(stderr, "~reset %s: %s\n", scene_file.c_str(), reset.message.c_str());
      return false;
    }
    for (double t = 0.0; t < kSettleSimSeconds; t += 0.5) {
      if (!sim_.step(500).ok) return false;
      const auto get = sim_.getBricks();
      if (!get.ok) return false;
      const long frozen = std::count_if(get.response.bricks.begin(), get.response.bricks.end(),
                                        [](const Brick& b) { return b.state != Brick::DYNAMIC; });
      if (static_cast<int>(get.response.bricks.size()) == scene.bricks + scene.moving &&
          frozen >= scene.bricks) {
        moving_ids_.clear();
        for (const Brick& b : get.response.bricks)
          if (b.id.rfind("loose", 0) == 0) moving_ids_.push_back(b.id);
        return setPaused(false);
      }
    }
    std::fprintf(stderr, "%d bricks did not settle in %.0f s of sim time\n", scene.bricks,
                 kSettleSimSeconds);
    return false;
  }

  /// Keeps the loose planks sliding: each gets a small push along its length
  /// every kPushPeriod, back and forth, so that they never come to rest.
  void pushMovers(int round) {
    for (std::size_t i = 0; i < moving_ids_.size(); ++i) {
      PushBrick::Request push;
      push.id = moving_ids_[i];
      push.impulse.x = (round % 2 ? -1.0 : 1.0) * 0.004;  // [N s]: about 0.34 m/s
      sim_.pushBrick(push);
    }
  }

  /// Waits `seconds` [s] of wall time, pushing the loose planks meanwhile.
  void keepMoving(const Case& scene, double seconds, int* round) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < end) {
      if (scene.moving > 0) pushMovers((*round)++);
      std::this_thread::sleep_for(std::chrono::duration<double>(kPushPeriod));
    }
  }

  void measureLoad(const Case& scene, int subscribers, Row* row) {
    std::mutex mutex;
    TopicCount bricks, markers, tf;
    std::vector<ros::Subscriber> subs;
    if (subscribers >= 1)
      subs.push_back(sim_.subscribeBricks(countMessages<BrickArray>(&mutex, &bricks), 1000));
    if (subscribers >= 3) {
      subs.push_back(sim_.subscribeMarkers(
          countMessages<visualization_msgs::MarkerArray>(&mutex, &markers), 1000));
      subs.push_back(nh_.subscribe<tf2_msgs::TFMessage>(
          "/tf", 1000, countMessages<tf2_msgs::TFMessage>(&mutex, &tf)));
    }
    // Connected and past the first full messages before counting.
    int round = 0;
    keepMoving(scene, 2.0, &round);
    TopicCount bricks0, markers0, tf0;
    {
      std::lock_guard<std::mutex> lock(mutex);
      bricks0 = bricks, markers0 = markers, tf0 = tf;
    }
    const double cpu0 = processCpuSeconds(pid_);
    const auto start = std::chrono::steady_clock::now();
    keepMoving(scene, window_, &round);
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    row->node_cpu = (processCpuSeconds(pid_) - cpu0) / wall;
    std::lock_guard<std::mutex> lock(mutex);
    auto rate = [&](const TopicCount& now, const TopicCount& before, double* hz, double* bytes) {
      const long n = now.messages - before.messages;
      *hz = n / wall;
      *bytes = n > 0 ? (now.bytes - before.bytes) / n : 0.0;
    };
    rate(bricks, bricks0, &row->bricks_hz, &row->bricks_bytes);
    rate(markers, markers0, &row->markers_hz, &row->markers_bytes);
    rate(tf, tf0, &row->tf_hz, &row->tf_bytes);
  }

  /// How long `call` took [ms].
  template <typename Call>
  static double timedMs(const Call& call) {
    const auto start = std::chrono::steady_clock::now();
    call();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
  }

  /// ~get_bricks, ~query_placement on top of a tower, and a ~place_brick
  /// (removed again, untimed) on free table, one at a time.
  void measureLatency(const Case& scene, Row* row) {
    std::vector<double> get, query, place;
    // Free table on the side away from the loose planks.
    const double depth = towerRows(scene.bricks) * kTowerSpacing;
    const double free_y = depth / 2 + 0.2;
    // On top of the first tower, crossing its top layer.
    const Point2 first = firstTower(scene.bricks);
    QueryPlacement::Request q;
    q.pose.position.x = first.x;
    q.pose.position.y = first.y;
    q.pose.position.z = 25.5 * kPlankHeight;
    q.pose.orientation.w = 1.0;
    PlaceBrick::Request p;
    p.id = "bench_probe";
    p.pose.position.x = 0.0;
    p.pose.position.y = free_y;
    p.pose.position.z = kPlankHeight / 2;
    p.pose.orientation.w = 1.0;
    for (int i = 0; i < kLatencyCalls; ++i) {
      get.push_back(timedMs([&] { sim_.getBricks(); }));
      query.push_back(timedMs([&] { sim_.queryPlacement(q); }));
      place.push_back(timedMs([&] { sim_.placeBrick(p); }));
      sim_.removeBrick(p.id);
    }
    row->get_p50 = percentile(get, 0.5), row->get_p99 = percentile(get, 0.99);
    row->query_p50 = percentile(query, 0.5), row->query_p99 = percentile(query, 0.99);
    row->place_p50 = percentile(place, 0.5), row->place_p99 = percentile(place, 0.99);
  }

 public:
  /// Towers in rows of at most 20 along x; this many rows along y (an empty
  /// scene counts as one tower's place).
  static int towerRows(int bricks) {
    const int towers = std::max(1, bricks / kTowerBricks);
    return (towers + 19) / 20;
  }
  static int towerColumns(int bricks) { return std::min(std::max(1, bricks / kTowerBricks), 20); }
  /// The grid is centred on the table; its first tower is at the -x, -y corner.
  static Point2 firstTower(int bricks) {
    return {(1 - towerColumns(bricks)) * kTowerSpacing / 2,
            (1 - towerRows(bricks)) * kTowerSpacing / 2};
  }

 private:
  ros::NodeHandle nh_;
  double window_;
  int pid_;
  client::SimClient sim_;
  std::vector<std::string> moving_ids_;
};

/// The scene of a case as a file: towers of 50 planks on a grid centred on
/// the table (at 0.13 m, as settled2000_moving10), and the loose planks in a
/// row beside them, lying flat 0.2 m apart.
std::string writeScene(const Case& scene, const std::string& directory) {
  const int columns = NodeBench::towerColumns(scene.bricks);
  const int rows = NodeBench::towerRows(scene.bricks);
  const double width = columns * kTowerSpacing, depth = rows * kTowerSpacing;
  const Point2 first = NodeBench::firstTower(scene.bricks);
  const std::string path = directory + "/settled" + std::to_string(scene.bricks) + "_moving" +
                           std::to_string(scene.moving) + ".yaml";
  std::ofstream out(path);
  out << "name: settled" << scene.bricks << "_moving" << scene.moving << "\n";
  out << "table: {size: [" << std::max(1.6, width + 0.6) << ", " << depth + 0.8 << "]}\n";
  if (scene.bricks > 0) {
    out << "generator:\n  - {name: tower, layers: 25, grid: [" << columns << ", " << rows
        << "], spacing: " << kTowerSpacing << ", origin: [" << first.x << ", " << first.y << "]}\n";
  }
  if (scene.moving > 0) {
    out << "bricks:\n";
    for (int i = 0; i < scene.moving; ++i)
      out << "  - {id: loose" << i << ", at: 0.0, position: ["
          << (i - (scene.moving - 1) / 2.0) * kLooseSpacing << ", " << -depth / 2 - 0.2 << ", "
          << kPlankHeight / 2 << "]}\n";
  }
  return path;
}

/// The command line: OUTPUT.csv [--quick] [--delta] [--window SECONDS].
struct Arguments {
  std::string output;
  bool quick = false;
  bool delta = false;    ///< The node runs with bricks_delta: the busy scenes, one subscriber.
  bool planner = false;  ///< Only the planner case.
  double window = 5.0;   ///< [s]
};

/// False (with the reason on stderr) when the command line is not one.
bool parseArguments(const std::vector<std::string>& args, Arguments* parsed) {
  if (args.size() < 2) {
    std::fprintf(stderr,
                 "usage: stack_sim_node_bench OUTPUT.csv [--quick] [--delta] [--planner] "
                 "[--window SECONDS]\n");
    return false;
  }
  parsed->output = args[1];
  for (std::size_t i = 2; i < args.size(); ++i) {
    if (args[i] == "--quick") {
      parsed->quick = true;
    } else if (args[i] == "--delta") {
      parsed->delta = true;
    } else if (args[i] == "--planner") {
      parsed->planner = true;
    } else if (args[i] == "--window" && i + 1 < args.size()) {
      parsed->window = std::atof(args[++i].c_str());
    } else {
      std::fprintf(stderr, "stack_sim_node_bench: unknown argument '%s'\n", args[i].c_str());
      return false;
    }
  }
  if (!(parsed->window > 0.0 && parsed->window <= 600.0)) {
    std::fprintf(stderr, "stack_sim_node_bench: --window must be in (0, 600] s\n");
    return false;
  }
  return true;
}

/// The scenes measured, and with how many subscribers each.
void planCases(const Arguments& arguments, std::vector<Case>* cases,
               std::vector<int>* subscriber_counts) {
  // The 10 moving bricks alone are the yardstick of the settled scenes' cost.
  *cases = {{0, 10}};
  for (int bricks :
       arguments.quick ? std::vector<int>{100, 2000} : std::vector<int>{100, 1000, 2000, 10000})
    for (int moving : {0, 10}) cases->push_back({bricks, moving});
  *subscriber_counts = {0, 1, 3};
  if (arguments.delta) {
    *cases = arguments.quick ? std::vector<Case>{{2000, 10}}
                             : std::vector<Case>{{2000, 10}, {10000, 10}};
    *subscriber_counts = {1};
  }
}

void writeCsv(const std::string& path, const std::vector<Row>& rows) {
  std::ofstream csv(path);
  csv << "bricks,moving,subscribers,node_cpu,bricks_hz,markers_hz,tf_hz,bricks_bytes,"
         "markers_bytes,tf_bytes,get_bricks_p50_ms,get_bricks_p99_ms,query_p50_ms,query_p99_ms,"
         "place_p50_ms,place_p99_ms\n";
  for (const Row& r : rows) {
    csv << r.scene.bricks << ',' << r.scene.moving << ',' << r.subscribers << ',' << r.node_cpu
        << ',' << r.bricks_hz << ',' << r.markers_hz << ',' << r.tf_hz << ',' << r.bricks_bytes
        << ',' << r.markers_bytes << ',' << r.tf_bytes << ',' << r.get_p50 << ',' << r.get_p99
        << ',' << r.query_p50 << ',' << r.query_p99 << ',' << r.place_p50 << ',' << r.place_p99
        << '\n';
  }
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "stack_sim_node_bench", ros::init_options::AnonymousName);
  std::vector<std::string> args;
  ros::removeROSArgs(argc, argv, args);
  Arguments arguments;
  if (!parseArguments(args, &arguments)) return 2;
  ros::AsyncSpinner spinner(1);
  spinner.start();
  client::SimClient sim;
  if (const client::CallResult up = sim.waitForNode(30.0); !up.ok) {
    std::fprintf(stderr, "stack_sim_node_bench: no node %s (start it with sim.launch): %s\n",
                 kNode.c_str(), up.message.c_str());
    return 1;
  }
  const int pid = nodePid();
  if (pid <= 0) {
    std::fprintf(stderr, "stack_sim_node_bench: could not ask %s for its pid\n", kNode.c_str());
    return 1;
  }
  char directory_template[] = "/tmp/stack_sim_node_bench_XXXXXX";
  const char* directory = mkdtemp(directory_template);
  if (!directory) return 1;

  std::vector<Case> cases;
  std::vector<int> subscriber_counts;
  planCases(arguments, &cases, &subscriber_counts);
  if (arguments.planner) cases.clear();
  std::vector<Row> rows;
  int failed = 0;
  // The planner case in both plans; not in the ~bricks delta pass.
  if (!arguments.delta && !node_bench::runPlanner(sim, directory, arguments.output)) ++failed;
  NodeBench bench(arguments.window, pid, std::move(sim));
  for (const Case& scene : cases)
    if (!bench.run(scene, writeScene(scene, directory), subscriber_counts, &rows)) ++failed;
  if (!arguments.planner) writeCsv(arguments.output, rows);
  spinner.stop();
  return failed == 0 ? 0 : 1;
}
