// The memo of cold statics solves hands back an answer only for a problem
// identical to one it solved, bit for bit; any other problem is solved. The
// answers themselves are checked against statics with exact answers: a
// plank stands while its centre of mass is over its contact patch on the
// table, and cannot once it is beyond the patch's edge.

#include <cmath>

#include <gtest/gtest.h>

#include "physics/body_handle.h"
#include "stability/statics_memo.h"
#include "support/kapla.h"

namespace brick_stack_sim {
namespace {

/// Half the side of the square patch a plank rests on [m].
constexpr double kPatchHalf = 0.01;

/// A plank on the table on a square patch around the origin, its centre of
/// mass `offset` [m] along x from the patch's centre.
StaticsAssembly plankOnTable(double offset) {
  StaticsAssembly assembly{StabilityOptions()};
  const int plank = assembly.addFree(1, test::kKaplaMass,
                                     Eigen::Vector3d(offset, 0.0, 0.5 * test::kKaplaThickness));
  SupportPatch patch;
  patch.supporter = kTableHandle;
  patch.friction = 0.5;
  for (double x : {-kPatchHalf, kPatchHalf})
    for (double y : {-kPatchHalf, kPatchHalf}) {
      patch.points.emplace_back(x, y, 0.0);
      patch.normals.push_back(Eigen::Vector3d::UnitZ());
    }
  assembly.addPatches(plank, {patch});
  return assembly;
}

void expectSameAnswer(const StaticsSolution& kept, const StaticsSolution& solved) {
  EXPECT_EQ(kept.solved, solved.solved);
  EXPECT_EQ(kept.feasible, solved.feasible);
  EXPECT_EQ(kept.imbalance, solved.imbalance);
  EXPECT_EQ(kept.moves, solved.moves);
  ASSERT_EQ(kept.forces.size(), solved.forces.size());
  for (std::size_t i = 0; i < kept.forces.size(); ++i) EXPECT_EQ(kept.forces[i], solved.forces[i]);
}

TEST(StaticsMemo, HandsBackTheAnswerToTheSameProblem) {
  StaticsMemo memo;
  const StaticsAssembly over_patch = plankOnTable(0.5 * kPatchHalf);
  const StaticsSolution first = memo.solve(over_patch);
  ASSERT_TRUE(first.solved) << first.message;
  EXPECT_TRUE(first.feasible);  // its weight passes inside the patch
  const StaticsSolution again = memo.solve(plankOnTable(0.5 * kPatchHalf));
  EXPECT_EQ(memo.solves(), 1u);
  EXPECT_EQ(memo.hits(), 1u);
  expectSameAnswer(again, over_patch.solve());
  // The contact forces carry the plank's weight [N].
  double vertical = 0.0;
  for (const Eigen::Vector3d& force : again.forces) vertical += force.z();
  EXPECT_NEAR(vertical, test::kKaplaMass * StaticsOptions().gravity, 1e-9);
}

TEST(StaticsMemo, SolvesAProblemThatDiffersInAnyBit) {
  StaticsMemo memo;
  ASSERT_TRUE(memo.solve(plankOnTable(0.5 * kPatchHalf)).feasible);
  // Beyond the patch's edge: no contact force can hold it up.
  const StaticsSolution beyond = memo.solve(plankOnTable(1.5 * kPatchHalf));
  ASSERT_TRUE(beyond.solved) << beyond.message;
  EXPECT_FALSE(beyond.feasible);
  EXPECT_EQ(memo.solves(), 2u);
  EXPECT_EQ(memo.hits(), 0u);
  // The smallest step of the centre of mass is another problem.
  const double half = 0.5 * kPatchHalf;
  memo.solve(plankOnTable(std::nextafter(half, 1.0)));
  EXPECT_EQ(memo.solves(), 3u);
  EXPECT_EQ(memo.hits(), 0u);
}

TEST(StaticsMemo, KeepsOnlyTheLatestProblems) {
  StaticsMemo memo(1);
  memo.solve(plankOnTable(0.0));
  memo.solve(plankOnTable(1.5 * kPatchHalf));
  const StaticsSolution first_again = memo.solve(plankOnTable(0.0));
  EXPECT_EQ(memo.solves(), 3u);  // pushed out by the second
  EXPECT_TRUE(first_again.feasible);
  memo.solve(plankOnTable(0.0));
  EXPECT_EQ(memo.hits(), 1u);
}

}  // namespace
}  // namespace brick_stack_sim
