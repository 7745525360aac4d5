// The support graph every freezing model shares: links, changed components,
// the order in which loads flow down, cycles, and taking a brick out with
// what it carries.
#include <gtest/gtest.h>

#include "stability/support_graph.h"

namespace brick_stack_sim {
namespace {

SupportPatch on(BodyHandle supporter) {
  SupportPatch patch;
  patch.supporter = supporter;
  return patch;
}

/// b0 on the table, b1 and b2 on b0, b3 on b1 and b2; b10 alone on the table.
SupportGraph twoStacks() {
  SupportGraph graph;
  graph.add(0, Eigen::Vector3d::Zero(), 1.0, {on(kTableHandle)});
  graph.add(1, Eigen::Vector3d::Zero(), 1.0, {on(0)});
  graph.add(2, Eigen::Vector3d::Zero(), 1.0, {on(0)});
  graph.add(3, Eigen::Vector3d::Zero(), 1.0, {on(1), on(2)});
  graph.add(10, Eigen::Vector3d::Zero(), 1.0, {on(kTableHandle)});
  return graph;
}

TEST(SupportGraph, LinksEachBrickUnderItsFrozenSupporters) {
  const SupportGraph graph = twoStacks();
  EXPECT_EQ(graph.find(0)->carries, (std::set<BodyHandle>{1, 2}));
  EXPECT_EQ(graph.find(1)->carries, (std::set<BodyHandle>{3}));
  EXPECT_TRUE(graph.find(3)->carries.empty());
  EXPECT_TRUE(graph.canSupport(kTableHandle));
  EXPECT_TRUE(graph.canSupport(kFloorHandle));
  EXPECT_TRUE(graph.canSupport(2));
  EXPECT_FALSE(graph.canSupport(4));  // not frozen: a stack cannot start on it
}

TEST(SupportGraph, EraseAndUnlinkLeavesTheLoadInPlaceWithoutItsContacts) {
  // b1 slid by an impact: b3 stays frozen, rests on b2 alone until b1 is
  // put back, and is judged again; b0 no longer carries b1.
  SupportGraph graph = twoStacks();
  graph.takeChangedComponents();
  EXPECT_EQ(graph.eraseAndUnlink(1), (std::set<BodyHandle>{3}));
  EXPECT_FALSE(graph.contains(1));
  ASSERT_TRUE(graph.contains(3));
  ASSERT_EQ(graph.find(3)->supports.size(), 1u);
  EXPECT_EQ(graph.find(3)->supports.front().supporter, 2u);
  EXPECT_EQ(graph.find(0)->carries, (std::set<BodyHandle>{2}));
  EXPECT_TRUE(graph.hasChanges());
  const std::vector<std::vector<BodyHandle>> changed = graph.takeChangedComponents();
  ASSERT_EQ(changed.size(), 1u);
  EXPECT_EQ(changed.front(), (std::vector<BodyHandle>{0, 2, 3}));
}

TEST(SupportGraph, ChangedComponentsAreTakenOnce) {
  SupportGraph graph = twoStacks();
  ASSERT_TRUE(graph.hasChanges());
  const auto components = graph.takeChangedComponents();
  ASSERT_EQ(components.size(), 2u);
  EXPECT_EQ(components[0], (std::vector<BodyHandle>{0, 1, 2, 3}));
  EXPECT_EQ(components[1], (std::vector<BodyHandle>{10}));
  EXPECT_FALSE(graph.hasChanges());
  EXPECT_TRUE(graph.takeChangedComponents().empty());
}

const SupportGraph::LeaningTest kAnySideContact = [](const SupportPatch&) { return true; };

TEST(SupportGraph, LoadsFlowFromTheTopDown) {
  SupportGraph graph = twoStacks();
  const auto groups = graph.loadOrder({0, 1, 2, 3}, kAnySideContact);
  ASSERT_EQ(groups.size(), 4u);
  std::vector<BodyHandle> order;
  for (const auto& group : groups) {
    ASSERT_EQ(group.size(), 1u);
    order.push_back(group[0]);
  }
  auto position = [&](BodyHandle h) { return std::find(order.begin(), order.end(), h); };
  // Every brick after everything it carries.
  EXPECT_LT(position(3), position(1));
  EXPECT_LT(position(3), position(2));
  EXPECT_LT(position(1), position(0));
  EXPECT_LT(position(2), position(0));
}

TEST(SupportGraph, BricksOnACycleShareAGroupAndWhatIsBelowStillGetsAnOrder) {
  // Contacts can say b5 rests on b6 and b6 on b5 (two bricks leaning on
  // each other seen as support): they pass load to each other, one group.
  SupportGraph graph;
  graph.add(4, Eigen::Vector3d::Zero(), 1.0, {on(kTableHandle)});
  graph.add(5, Eigen::Vector3d::Zero(), 1.0, {on(4)});
  graph.add(6, Eigen::Vector3d::Zero(), 1.0, {on(5)});
  graph.find(5)->supports.push_back(on(6));
  graph.find(6)->carries.insert(5);
  graph.add(7, Eigen::Vector3d::Zero(), 1.0, {on(6)});
  const auto groups = graph.loadOrder({4, 5, 6, 7}, kAnySideContact);
  EXPECT_EQ(groups, (std::vector<std::vector<BodyHandle>>{{7}, {5, 6}, {4}}));
}

TEST(SupportGraph, LeaningBricksPassLoadToWhatTheyLeanOnOthersDoNot) {
  // A V (b1, b2 leaning on each other on the table), a flat plank b3 on its
  // apex, and b4 standing beside b5 touching it (stable, not leaning).
  SupportGraph graph;
  graph.add(1, Eigen::Vector3d::Zero(), 1.0, {on(kTableHandle)}, {on(2)}, /*leaning=*/true);
  graph.add(2, Eigen::Vector3d::Zero(), 1.0, {on(kTableHandle)}, {on(1)}, /*leaning=*/true);
  graph.add(3, Eigen::Vector3d::Zero(), 1.0, {on(1), on(2)});
  graph.add(5, Eigen::Vector3d::Zero(), 1.0, {on(kTableHandle)});
  graph.add(4, Eigen::Vector3d::Zero(), 1.0, {on(kTableHandle)}, {on(5)});
  // The plank on the V shares its group: statics splits its load.
  EXPECT_EQ(graph.loadOrder({1, 2, 3}, kAnySideContact),
            (std::vector<std::vector<BodyHandle>>{{1, 2, 3}}));
  EXPECT_EQ(graph.loadOrder({4, 5}, kAnySideContact),
            (std::vector<std::vector<BodyHandle>>{{4}, {5}}));
  // Side contacts the test rejects (from above) pass nothing: only the
  // plank ties the V's planks together.
  const SupportGraph::LeaningTest none = [](const SupportPatch&) { return false; };
  EXPECT_EQ(graph.loadOrder({1, 2, 3}, none), (std::vector<std::vector<BodyHandle>>{{1, 2, 3}}));
  // Not leaning, the planks take the plank's load as supporters do.
  graph.find(1)->leaning = graph.find(2)->leaning = false;
  EXPECT_EQ(graph.loadOrder({1, 2, 3}, kAnySideContact),
            (std::vector<std::vector<BodyHandle>>{{3}, {1}, {2}}));
}

TEST(SupportGraph, DetachingTakesEverythingCarriedOnceInBreadthFirstOrder) {
  SupportGraph graph = twoStacks();
  graph.takeChangedComponents();
  const auto detached = graph.detachWithLoad(0);
  ASSERT_EQ(detached.size(), 4u);
  EXPECT_EQ(detached[0].brick, 0u);
  EXPECT_EQ(detached[1].brick, 1u);
  EXPECT_EQ(detached[1].carried_by, 0u);
  EXPECT_EQ(detached[2].brick, 2u);
  // b3 rests on b1 and b2: it leaves once, with the first brick that carried it.
  EXPECT_EQ(detached[3].brick, 3u);
  EXPECT_EQ(detached[3].carried_by, 1u);
  EXPECT_EQ(graph.size(), 1u);       // b10 stays
  EXPECT_FALSE(graph.hasChanges());  // nothing left in that component
  EXPECT_TRUE(graph.detachWithLoad(0).empty());
}

TEST(SupportGraph, DetachingAnUpperBrickChangesItsSupporters) {
  SupportGraph graph = twoStacks();
  graph.takeChangedComponents();
  graph.detachWithLoad(3);
  EXPECT_TRUE(graph.find(1)->carries.empty());
  EXPECT_TRUE(graph.find(2)->carries.empty());
  const auto components = graph.takeChangedComponents();
  ASSERT_EQ(components.size(), 1u);
  EXPECT_EQ(components[0], (std::vector<BodyHandle>{0, 1, 2}));
}

TEST(SupportGraph, ErasingABrickLeavesWhatItCarriedForTheModelToWake) {
  SupportGraph graph = twoStacks();
  graph.takeChangedComponents();
  EXPECT_EQ(graph.erase(1), (std::set<BodyHandle>{3}));
  EXPECT_FALSE(graph.contains(1));
  EXPECT_TRUE(graph.contains(3));
  EXPECT_EQ(graph.find(0)->carries, (std::set<BodyHandle>{2}));
  EXPECT_TRUE(graph.erase(1).empty());
}

TEST(SupportGraph, AWhatIfCopyHoldsOnlyTheComponentsItCanTouch) {
  SupportGraph graph = twoStacks();
  graph.takeChangedComponents();
  const SupportGraph copy = graph.componentsOf({kTableHandle, 2});
  EXPECT_EQ(copy.size(), 4u);
  EXPECT_FALSE(copy.contains(10));
  EXPECT_FALSE(copy.hasChanges());
  EXPECT_EQ(copy.find(0)->carries, graph.find(0)->carries);
}

}  // namespace
}  // namespace brick_stack_sim
