#!/usr/bin/env bash
# Builds the package and runs the benchmark: run time against error, every
# mode side by side on one core, then the plots and the table of targets.
# Usage: run_bench.sh quick|full   (quick: a subset in under three minutes)
set -eo pipefail
source "$(dirname "$0")/env.sh"
plan="${1:-quick}"
case "${plan}" in quick|full) ;; *) echo "run_bench.sh: quick or full" >&2; exit 2 ;; esac
bash "${repo_root}/scripts/build.sh"
results="${repo_root}/bench/results"
mkdir -p "${results}"
csv="${results}/bench_${plan}.csv"
echo "Running the ${plan} benchmark into ${csv} (one row per case and setting)"
# taskset: one core, so the two modes of a row compete for nothing.
runner=("${workspace}/devel/lib/brick_stack_sim/stack_sim_bench" "--${plan}" "${csv}")
if command -v taskset >/dev/null; then runner=(taskset -c 0 "${runner[@]}"); fi
"${runner[@]}"
# The statics LP alone: time per solve against component size, cold and warm.
lp_runner=("${workspace}/devel/lib/brick_stack_sim/stack_sim_lp_bench" "${results}/statics_lp.csv")
if command -v taskset >/dev/null; then lp_runner=(taskset -c 0 "${lp_runner[@]}"); fi
echo "Statics LP per solve into ${results}/statics_lp.csv"
"${lp_runner[@]}"
# A held brick over 500 frozen bricks: the real-time factor.
held_runner=("${workspace}/devel/lib/brick_stack_sim/stack_sim_held_bench" "${results}/held_bench.csv")
if command -v taskset >/dev/null; then held_runner=(taskset -c 0 "${held_runner[@]}"); fi
echo "Held brick over 500 frozen bricks into ${results}/held_bench.csv"
"${held_runner[@]}"
/usr/bin/python3 "${repo_root}/bench/plot_bench.py" "${csv}" "${results}"
{ echo "machine: $(nproc --all) cores (the benchmark pinned to one), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)";
  echo "date: $(date -u +%Y-%m-%d)"; } > "${results}/bench_${plan}_machine.txt"
# The node as a ROS client sees it: CPU, publish rates, service latency for
# settled scenes of 100 to 10 000 bricks.
bash "${repo_root}/scripts/run_node_bench.sh" "${plan}"
