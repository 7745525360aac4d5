// stack_sim_bench: run time against error, side by side on one core, as CSV.
#include <algorithm>
#include <cstring>
#include <fstream>
#include <iostream>
#include <string>

#include "brick_stack_sim/core/simulation/simulation_config.h"
#include "brick_stack_sim/tools/benchmark.h"
#include "brick_stack_sim/tools/package_data.h"

using namespace brick_stack_sim;

namespace {

/// "a, b, c": the labels of a plan's cases.
std::string caseNames(const BenchPlan& plan) {
  std::string names;
  for (const BenchCase& bench_case : plan.cases)
    names += (names.empty() ? "" : ", ") + bench_case.label;
  return names;
}

std::string usage() {
  return "usage: stack_sim_bench --quick|--full OUTPUT.csv [CASE,CASE...]\n"
         "Runs the benchmark's cases and writes one CSV row per setting (docs/benchmarks.md);\n"
         "CASE,CASE... runs only the cases named (to redo some).\n"
         "  --quick cases: " +
         caseNames(quickBenchPlan()) +
         "\n"
         "  --full cases:  " +
         caseNames(fullBenchPlan()) + "\n";
}

/// The first name of `only` (comma-separated) that is no case of `plan`, or "".
std::string unknownCase(const std::string& only, const BenchPlan& plan) {
  std::string name;
  for (std::size_t start = 0; start <= only.size();) {
    const std::size_t comma = std::min(only.find(',', start), only.size());
    name = only.substr(start, comma - start);
    bool known = false;
    for (const BenchCase& bench_case : plan.cases) known = known || bench_case.label == name;
    if (!known) return name.empty() ? "(an empty name)" : name;
    start = comma + 1;
  }
  return "";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0)) {
    std::cout << usage();
    return 0;
  }
  const bool full = argc > 1 && std::strcmp(argv[1], "--full") == 0;
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  // Optional third argument: the cases to run, comma-separated (to redo some).
  if ((!full && !quick) || argc < 3 || argc > 4) {
    std::cerr << usage();
    return 2;
  }
  const BenchPlan plan = full ? fullBenchPlan() : quickBenchPlan();
  if (argc == 4) {
    if (const std::string unknown = unknownCase(argv[3], plan); !unknown.empty()) {
      std::cerr << "stack_sim_bench: no case " << unknown << " in --" << (full ? "full" : "quick")
                << " (its cases: " << caseNames(plan) << ")\n";
      return 2;
    }
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
