// stack_sim_bench: run time against error, side by side on one core, as CSV.
#include <cstring>
#include <fstream>
#include <iostream>

#include "brick_stack_sim/core/simulation/simulation_config.h"
#include "brick_stack_sim/tools/benchmark.h"
#include "brick_stack_sim/tools/package_data.h"

using namespace brick_stack_sim;

int main(int argc, char** argv) {
  const bool full = argc > 1 && std::strcmp(argv[1], "--full") == 0;
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  // Optional third argument: the cases to run, comma-separated (to redo some).
  if ((!full && !quick) || argc < 3 || argc > 4) {
    std::cerr << "usage: stack_sim_bench --quick|--full OUTPUT.csv [CASE,CASE...]\n";
    return 2;
  }
  const std::string only = argc == 4 ? "," + std::string(argv[3]) + "," : "";
  BenchContext context;
  DataOptions data;
  fillPackageData(packageDataDir(BRICK_STACK_SIM_DATA_DIR), &data);
  context.scene_dirs = data.scene_dirs;
  if (Status loaded = BrickTypeLibrary::load(data.types_urdf, data.materials_yaml, &context.types);
      !loaded) {
    std::cerr << "stack_sim_bench: " << loaded.message << "\n";
    return 1;
  }
  std::ofstream csv(argv[2]);
  if (!csv) {
    std::cerr << "stack_sim_bench: cannot write " << argv[2] << "\n";
    return 1;
  }
  csv << benchCsvHeader();
  const BenchPlan plan = full ? fullBenchPlan() : quickBenchPlan();
  for (const BenchCase& bench_case : plan.cases) {
    if (!only.empty() && only.find("," + bench_case.label + ",") == std::string::npos) continue;
    for (const BenchSetting& setting : bench_case.settings) {
      BenchRow row;
      if (Status ran = runBenchCase(bench_case, setting, context, plan.divergence, &row); !ran) {
        std::cerr << "stack_sim_bench: " << bench_case.label << ": " << ran.message << "\n";
        return 1;
      }
      const std::string line = toCsv(row);
      csv << line << std::flush;
      std::cerr << line;
    }
  }
  return 0;
}
