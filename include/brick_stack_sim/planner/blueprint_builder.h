#pragma once
// blueprint_builder: the reference of how a planner uses the simulator. It
// reads a scene, places its bricks through ~place_brick at their times,
// watches each come to rest through ~get_bricks, and tells whether the
// structure did what the scene expects (BuildLedger).

#include <cstdio>
#include <string>
#include <vector>

#include <ros/node_handle.h>

#include "brick_stack_sim/client/sim_client.h"
#include "brick_stack_sim/core/scene/scene.h"
#include "brick_stack_sim/core/status.h"
#include "brick_stack_sim/planner/build_ledger.h"
#include "brick_stack_sim/ros/interface_names.h"

namespace brick_stack_sim {
namespace planner {

/// The builder's private parameters (docs/ros_interface.md, "blueprint_builder").
struct BuilderOptions {
  std::string scene;  ///< A name in `scene_dirs` or a path.
  std::vector<std::string> scene_dirs;
  /// Namespace of the simulator's services.
  std::string sim = ros_adapter::kDefaultNamespace;
  std::string types_urdf;  ///< Brick types; must be the simulator's.
  std::string materials_yaml;
  /// Put in brackets at the start of every progress and summary line
  /// ("[left com] placed b0 (1/50)"), so that two builders writing to one
  /// console (compare.launch) can be told apart; empty: no tag.
  std::string label;
  /// How long past its placement a brick may take to come to rest [s] (sim
  /// time) before the builder goes on without it and says so.
  double settle_timeout = 3.0;
  double final_wait = 3.0;   ///< Watched after the last placement [s] (sim time).
  double poll_period = 0.1;  ///< Between two looks at ~get_bricks [s] (sim time).
  /// For the simulator's services to come up [s] (wall time), at the start
  /// and whenever a connection to one has to be made again.
  double service_wait = 60.0;
  LedgerOptions ledger;
};

/// Reads and checks the parameters of `private_nh` over the defaults; data
/// paths left empty come from `package_dir`. A bad value is refused with a
/// message naming it and `*options` is left unchanged.
Status readBuilderOptions(const ros::NodeHandle& private_nh, const std::string& package_dir,
                          BuilderOptions* options);

/// "[<label>] " for a label, "" for none: what starts each line of output.
std::string linePrefix(const BuilderOptions& options);

/// What a build came to.
struct BuildOutcome {
  BuildSummary summary;
  bool met = false;     ///< The structure did what the scene expects.
  std::string verdict;  ///< Why, naming the brick that fell.
  std::string summary_line;
};

class BlueprintBuilder {
 public:
  /// Progress goes to `progress` (one line per event). The simulator is
  /// reached through `nh` with persistent connections.
  BlueprintBuilder(ros::NodeHandle nh, BuilderOptions options, std::FILE* progress = stdout);

  /// Loads options.scene with the options' brick types.
  Status loadScene(Scene* scene) const;

  /// Builds `scene` on the simulator, which should hold nothing of it yet.
  /// Fails only when the simulator cannot be reached or ROS shuts down; a
  /// structure that falls is a successful run with `met` false.
  Status build(const Scene& scene, BuildOutcome* outcome);

  const BuildLedger& ledger() const { return ledger_; }

 private:
  /// Places bricks [first, last) of the scene at once (paused in between, so
  /// that two leaning bricks arrive together); appends to `structure` the ids
  /// the simulator gave those it accepted that were not thrown (an empty id
  /// in the scene becomes brick_<n>).
  /// A scene that defines brick types of its own (an arch's voussoir) has
  /// them in a scene of types alone, which the simulator loads through
  /// ~reset: it knows them for ~place_brick then, on an empty table. The
  /// file is shared by path, so the simulator must run on this machine.
  Status handOverTypes(const Scene& scene);
  Status placeGroup(const std::vector<ScheduledBrick>& bricks, std::size_t first, std::size_t last,
                    std::vector<std::string>* structure);
  /// Looks at ~get_bricks and reports what fell.
  Status observe();
  /// Watches until `until` (sim time) and, when `group` is not empty, until
  /// its bricks have come to rest or `settle_until` has passed.
  Status watch(const ros::Time& until, const std::vector<std::string>& group,
               const ros::Time& settle_until);
  bool restedAll(const std::vector<std::string>& ids) const;
  /// Seconds of `t` since epoch_: what progress lines and the summary show.
  double clock(const ros::Time& t) const;
  void say(const char* format, ...) const __attribute__((format(printf, 2, 3)));

  BuilderOptions options_;
  std::FILE* progress_;
  BuildLedger ledger_;
  client::SimClient sim_;
  ros::Time next_observation_;
  ros::Time epoch_;  ///< 0 on sim time; the build's start on wall time.
};

}  // namespace planner
}  // namespace brick_stack_sim
