// The node in mode com, driven through its services: a three-layer tower
// freezes brick by brick with the support graph the geometry gives, removing
// a middle brick wakes exactly the bricks it carried, ~markers shows the
// stability layer, and a brick past the table edge is never called stable.
// Each test pauses the node and advances it with ~step, so sim time is exact.
#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <ros/ros.h>
#include <visualization_msgs/MarkerArray.h>

#include "brick_stack_sim/core/types/world_options.h"
#include "node_fixture.h"
#include "support/kapla.h"
#include "support/marker_viewer.h"

namespace {

using namespace brick_stack_sim;
using test::kKaplaThickness;
using visualization_msgs::Marker;
using visualization_msgs::MarkerArray;

constexpr double kTableHalfX = 0.6;  ///< The default 1.2 x 0.8 m table, centred [m].

std::vector<std::string> sorted(std::vector<std::string> ids) {
  std::sort(ids.begin(), ids.end());
  return ids;
}

class StabilityNode : public test::NodeFixture {
 protected:
  void SetUp() override {
    NodeFixture::SetUp();
    if (HasFatalFailure()) return;
    events_sub_ = sim_->subscribeEvents(
        [this](const StabilityEvent::ConstPtr& msg) {
          std::lock_guard<std::mutex> lock(mutex_);
          events_.push_back(*msg);
        },
        1000);
    ASSERT_TRUE(waitFor([&] { return events_sub_.getNumPublishers() > 0; }, 10.0));
    // Every test starts from a paused node and an empty table.
    ASSERT_TRUE(setPaused(true));
    const client::Reply<ResetScene::Response> reset = sim_->reset();
    ASSERT_TRUE(reset.ok) << reset.message;
    ros::WallDuration(0.2).sleep();  // the reset's removed events
    clearEvents();
  }

  void TearDown() override {
    // No callback runs after shutdown() returns; taking the lock once more
    // makes the callbacks' writes visible to this thread (and to TSan).
    events_sub_.shutdown();
    std::lock_guard<std::mutex> lock(mutex_);
    events_.clear();
  }

  // place, step and bricks hide the base's: here a refused placement or step
  // is a failure, and bricks come by id.

  bool place(const std::string& id, double x, double y, double z, double yaw) {
    const PlaceBrick::Response placed = NodeFixture::place(id, x, y, z, yaw);
    EXPECT_TRUE(placed.success) << id << ": " << placed.message;
    return placed.success;
  }

  /// Brick `slot` (0 or 1) of `layer` of the core's tower generator.
  bool placeTowerBrick(const std::string& id, int layer, int slot) {
    const test::TowerSlot s = test::towerSlot(layer, slot);
    return place(id, s.x, s.y, s.z, s.yaw);
  }

  void step(unsigned steps) {
    const StepSimulation::Response stepped = NodeFixture::step(steps);
    ASSERT_TRUE(stepped.success) << stepped.message;
  }

  std::map<std::string, Brick> bricks() {
    std::map<std::string, Brick> by_id;
    for (const Brick& b : NodeFixture::bricks()) by_id[b.id] = b;
    return by_id;
  }

  std::set<std::string> eventIds(uint8_t kind) {
    std::lock_guard<std::mutex> lock(mutex_);
    std::set<std::string> ids;
    for (const StabilityEvent& e : events_)
      if (e.kind == kind) ids.insert(e.brick_id);
    return ids;
  }

  std::optional<StabilityEvent> event(const std::string& id, uint8_t kind) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const StabilityEvent& e : events_)
      if (e.brick_id == id && e.kind == kind) return e;
    return std::nullopt;
  }

  void clearEvents() {
    std::lock_guard<std::mutex> lock(mutex_);
    events_.clear();
  }

  std::mutex mutex_;
  std::vector<StabilityEvent> events_;
  // Last: destroyed first, so that no callback runs into the members above
  // while they are destroyed.
  ros::Subscriber events_sub_;
};

TEST_F(StabilityNode, StabilityYamlHoldsTheBuiltInDefaults) {
  // sim.launch loads config/stability.yaml; its values must be the ones the
  // node would use without it, as its header says.
  const StabilityOptions defaults;
  const std::map<std::string, double> expected = {
      {"rest_linear_speed", defaults.rest_linear_speed},
      {"rest_angular_speed", defaults.rest_angular_speed},
      {"rest_time", defaults.rest_time},
      {"impact_speed", defaults.impact_speed},
      {"support_normal_tolerance", defaults.support_normal_tolerance},
      {"flush_angle", defaults.flush_angle},
      {"contact_distance", defaults.contact_distance},
      {"min_margin", defaults.min_margin}};
  for (const auto& [name, value] : expected) {
    double loaded = -1.0;
    EXPECT_TRUE(nh_.getParam(sim_->resolve("stability/" + name), loaded)) << name << " not loaded";
    EXPECT_EQ(loaded, value) << name;
  }
  std::string mode;
  EXPECT_TRUE(nh_.getParam(sim_->resolve("stability/mode"), mode));
  EXPECT_EQ(mode, "com");
}

TEST_F(StabilityNode, TowerFreezesAndRemovalWakesExactlyTheBricksAbove) {
  const std::vector<std::string> ids = {"l0a", "l0b", "l1a", "l1b", "l2a", "l2b"};
  for (int i = 0; i < 6; ++i) ASSERT_TRUE(placeTowerBrick(ids[i], i / 2, i % 2));
  step(100);  // 0.1 s: longer than rest_time, for any brick not frozen at placement

  const std::set<std::string> all(ids.begin(), ids.end());
  EXPECT_TRUE(waitFor([&] { return eventIds(StabilityEvent::FROZEN) == all; }, 10.0))
      << "frozen events for " << eventIds(StabilityEvent::FROZEN).size() << " of 6 bricks";
  EXPECT_TRUE(eventIds(StabilityEvent::WOKEN).empty()) << "a resting tower woke up";

  std::map<std::string, Brick> tower = bricks();
  ASSERT_EQ(tower.size(), 6u);
  const std::map<std::string, std::vector<std::string>> supporters = {
      {"l0a", {"table"}},      {"l0b", {"table"}},      {"l1a", {"l0a", "l0b"}},
      {"l1b", {"l0a", "l0b"}}, {"l2a", {"l1a", "l1b"}}, {"l2b", {"l1a", "l1b"}}};
  for (const auto& [id, expected] : supporters) {
    const Brick& b = tower[id];
    EXPECT_EQ(b.state, Brick::STABLE) << id;
    EXPECT_EQ(sorted(b.supported_by), expected) << id;
    EXPECT_GT(b.margin, 0.0) << id;
    EXPECT_GE(b.mass_above, b.mass) << id;
    EXPECT_FALSE(b.fell_off) << id;
  }
  // The load runs down the tower: the bottom carries everything above it.
  EXPECT_NEAR(tower["l0a"].mass_above + tower["l0b"].mass_above, 6 * tower["l0a"].mass, 1e-9);
  EXPECT_NEAR(tower["l2a"].mass_above, tower["l2a"].mass, 1e-9);

  // Removing a layer-1 brick takes the support from under both layer-2 bricks
  // and from nothing else. Paused, so no fall can wake anything afterwards.
  clearEvents();
  const client::Reply<RemoveBrick::Response> remove = sim_->removeBrick("l1a");
  ASSERT_TRUE(remove.reached) << remove.message;
  ASSERT_TRUE(remove.response.success) << remove.response.message;
  const std::set<std::string> above = {"l2a", "l2b"};
  EXPECT_TRUE(waitFor([&] { return eventIds(StabilityEvent::WOKEN) == above; }, 10.0));
  ros::WallDuration(0.5).sleep();  // anything else would have arrived by now
  EXPECT_EQ(eventIds(StabilityEvent::WOKEN), above);
  const std::optional<StabilityEvent> woken = event("l2a", StabilityEvent::WOKEN);
  ASSERT_TRUE(woken);
  EXPECT_NE(woken->reason.find("l1a"), std::string::npos) << woken->reason;

  tower = bricks();
  EXPECT_EQ(tower.count("l1a"), 0u);
  for (const char* id : {"l0a", "l0b", "l1b"}) EXPECT_EQ(tower[id].state, Brick::STABLE) << id;
  for (const std::string& id : above) EXPECT_EQ(tower[id].state, Brick::DYNAMIC) << id;
}

TEST_F(StabilityNode, BottomBrickComAboveIsTheCentreOfMassOfEverythingItCarries) {
  // Thesis figure 5: the COM-above of a brick is the centre of mass of it and
  // all it carries, in 3D. A symmetric 4-layer tower splits every load evenly
  // between the two bricks under it, so each bottom brick's COM-above is at
  // the height of the whole tower's centre of mass: the mean of its layers'.
  const int layers = 4;
  double centre_height = 0.0;
  for (int i = 0; i < 2 * layers; ++i) {
    ASSERT_TRUE(placeTowerBrick("c" + std::to_string(i), i / 2, i % 2));
    centre_height += test::towerSlot(i / 2, i % 2).z / (2 * layers);
  }
  step(10);
  std::map<std::string, Brick> tower = bricks();
  for (const char* bottom : {"c0", "c1"}) {
    EXPECT_EQ(tower[bottom].state, Brick::STABLE) << bottom;
    EXPECT_NEAR(tower[bottom].com_above.z, centre_height, 1e-9) << bottom;
    EXPECT_NEAR(tower[bottom].mass_above, layers * tower[bottom].mass, 1e-9) << bottom;
  }
  // A top brick carries only itself: its COM-above is its own centre.
  EXPECT_NEAR(tower["c7"].com_above.z, tower["c7"].pose.position.z, 1e-9);
}

TEST_F(StabilityNode, MarkersShowBricksComRaysAndContactMeshes) {
  // Applied in order, as RViz does: the first array holds everything, the
  // later ones what changed.
  std::mutex mutex;
  test::MarkerViewer viewer;
  std::optional<bool> first_clears;
  ros::Subscriber sub = sim_->subscribeMarkers(
      [&](const MarkerArray::ConstPtr& msg) {
        std::lock_guard<std::mutex> lock(mutex);
        if (!first_clears)
          first_clears = !msg->markers.empty() && msg->markers.front().action == Marker::DELETEALL;
        viewer.apply(*msg);
      },
      10);
  ASSERT_TRUE(waitFor([&] { return sub.getNumPublishers() > 0; }, 10.0));
  for (int i = 0; i < 4; ++i) ASSERT_TRUE(placeTowerBrick("m" + std::to_string(i), i / 2, i % 2));
  step(100);

  auto count = [&](const std::string& ns) {
    int n = 0;
    for (const auto& [key, marker] : viewer.shown()) n += key.first == ns;
    return n;
  };
  ASSERT_TRUE(waitFor(
      [&] {
        std::lock_guard<std::mutex> lock(mutex);
        return count("bricks") == 4 && count("com_above") == 4 && count("contact_mesh") == 8;
      },
      15.0))
      << "the viewer never showed 4 bricks, 4 com_above rays and 8 contact meshes";
  std::lock_guard<std::mutex> lock(mutex);
  EXPECT_EQ(first_clears, std::optional<bool>(true)) << "the first array does not start afresh";
  std::set<int> ray_ids;
  for (const auto& [key, m] : viewer.shown()) {
    for (const geometry_msgs::Point& p : m.points)
      EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) << m.ns;
    if (m.ns != "com_above") continue;
    ray_ids.insert(m.id);
    ASSERT_GE(m.points.size(), 2u);
    EXPECT_GT(m.color.g, m.color.r) << "a stable brick's ray is not green";
    EXPECT_GT(m.points[0].z, m.points[1].z);  // pointing down
  }
  EXPECT_EQ(ray_ids.size(), 4u) << "ray ids are not one per brick";
}

TEST_F(StabilityNode, BrickPastTheTableEdgeIsNeverStableThereAndFallsOff) {
  // Along x with its centre 5 mm past the +x edge: statics says it tips off.
  // The control, 5 mm inside the edge, must stay: the test tells them apart.
  ASSERT_TRUE(place("over", kTableHalfX + 0.005, 0.0, kKaplaThickness / 2, 0.0));
  ASSERT_TRUE(place("inside", kTableHalfX - 0.005, 0.3, kKaplaThickness / 2, 0.0));
  auto stableOnTable = [](const Brick& b) {
    const auto& s = b.supported_by;
    return b.state == Brick::STABLE && std::find(s.begin(), s.end(), "table") != s.end();
  };
  EXPECT_FALSE(stableOnTable(bricks()["over"])) << "frozen on the table at placement";

  const unsigned kChunk = 50;       // 50 ms of sim time between looks
  const unsigned kMaxSteps = 5000;  // 5 s
  unsigned stepped = 0;
  while (stepped < kMaxSteps && !event("over", StabilityEvent::FELL_OFF)) {
    step(kChunk);
    stepped += kChunk;
    const Brick over = bricks()["over"];
    ASSERT_FALSE(stableOnTable(over)) << "STABLE on the table after " << stepped << " ms";
    if (over.fell_off)
      waitFor([&] { return event("over", StabilityEvent::FELL_OFF).has_value(); }, 5.0);
  }
  EXPECT_TRUE(event("over", StabilityEvent::FELL_OFF))
      << "no fell_off event within " << stepped << " ms of sim time";
  EXPECT_TRUE(bricks()["over"].fell_off);

  const Brick inside = bricks()["inside"];
  EXPECT_TRUE(stableOnTable(inside));
  EXPECT_FALSE(inside.fell_off);
  EXPECT_NEAR(inside.margin, 0.005, 1e-4) << "the margin is the distance to the edge";
  EXPECT_NEAR(inside.pose.position.x, kTableHalfX - 0.005, 1e-5) << "the control moved";
}

}  // namespace

int main(int argc, char** argv) {
  return brick_stack_sim::test::runNodeTests(argc, argv, "test_stability_node");
}
