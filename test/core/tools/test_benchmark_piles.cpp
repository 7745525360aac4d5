// The benchmark's pile cases: when a pile counts as settled, the plans that
// run the piles long enough to settle, and the CSV columns that report it,
// on a one-brick drop that settles within the second.

#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "brick_stack_sim/tools/benchmark.h"
#include "support/kapla.h"

namespace brick_stack_sim {
namespace {

/// Commas in `line`: one fewer than its columns.
long commas(const std::string& line) { return std::count(line.begin(), line.end(), ','); }

TEST(BenchmarkPiles, SettledFromTheFirstLookAfterWhichEveryLookWasSettled) {
  PileRest rest;
  EXPECT_TRUE(std::isnan(rest.settleTime()));
  rest.sample(1.0, 196, 200);  // 98 %: settled
  rest.sample(2.0, 195, 200);  // one brick short: not
  EXPECT_TRUE(std::isnan(rest.settleTime()));
  rest.sample(3.0, 200, 200);
  rest.sample(4.0, 197, 200);
  EXPECT_EQ(rest.settleTime(), 3.0);
  rest.sample(5.0, 0, 0);  // nothing left: nothing settled
  EXPECT_TRUE(std::isnan(rest.settleTime()));
}

TEST(BenchmarkPiles, BothPlansLetThePilesSettleInTheModesThatSleep) {
  for (const BenchPlan& plan : {quickBenchPlan(), fullBenchPlan()}) {
    int piles = 0;
    for (const BenchCase& c : plan.cases) {
      if (c.label.rfind("pile", 0) != 0) continue;
      ++piles;
      EXPECT_EQ(c.metric, BenchMetric::kPile) << c.label;
      EXPECT_EQ(c.duration, 10.0) << c.label;
      int carried_over = 0;
      for (const BenchSetting& s : c.settings) {
        EXPECT_TRUE(s.sleeping) << c.label << " " << s.mode_label;
        EXPECT_EQ(s.time_step, 1e-3);
        EXPECT_EQ(s.iterations, 20);
        // Plain Bullet and com once more with their impulses carried over
        // whole: the pile's other points of wall time against error.
        EXPECT_EQ(s.full_warm_start, s.mode_label == "none_full" || s.mode_label == "com_full")
            << c.label;
        if (s.full_warm_start) {
          ++carried_over;
          EXPECT_EQ(s.mode, s.mode_label == "none_full" ? "none" : "com");
        }
      }
      EXPECT_EQ(carried_over, 2) << c.label;
    }
    EXPECT_GE(piles, 1);
  }
}

TEST(BenchmarkPiles, OneDroppedPlankSettlesAndItsRowFillsThePileColumns) {
  BenchContext context;
  context.types = test::packageTypes();
  context.scene_dirs = {test::dataPath("scenes")};
  BenchCase drop;
  drop.label = "single_drop";
  drop.scene = "single_drop";
  drop.metric = BenchMetric::kPile;
  drop.duration = 2.0;
  BenchSetting com;
  com.mode_label = com.mode = "com";
  BenchRow row;
  const Status ran = runBenchCase(drop, com, context, false, &row);
  ASSERT_TRUE(ran.ok) << ran.message;
  // Dropped from 5 cm, it lands within 0.1 s and freezes soon after.
  ASSERT_FALSE(std::isnan(row.settle_time));
  EXPECT_GT(row.settle_time, 0.0);
  EXPECT_LT(row.settle_time, 1.0);
  EXPECT_EQ(row.at_rest_pct, 100.0);
  EXPECT_EQ(row.fell_off, 0);
  // The last second is part of the stepping time, and the frozen plank costs
  // less than a second of wall time in it.
  EXPECT_GE(row.settled_cost_pct, 0.0);
  EXPECT_LE(row.settled_cost_pct / 100.0, row.wall_time + 1e-12);
  EXPECT_LT(row.settled_cost_pct, 100.0);
  const std::string line = toCsv(row);
  EXPECT_EQ(commas(line), commas(benchCsvHeader()));
  EXPECT_NE(line.find(",100,0,"), std::string::npos) << line;
}

TEST(BenchmarkPiles, OtherCasesLeaveThePileColumnsEmpty) {
  BenchRow row;
  row.label = row.scene = "tower25";
  row.setting.mode_label = "com";
  const std::string line = toCsv(row);
  EXPECT_EQ(commas(line), commas(benchCsvHeader()));
  EXPECT_EQ(line.substr(line.size() - 5), ",,,,\n");
}

}  // namespace
}  // namespace brick_stack_sim
