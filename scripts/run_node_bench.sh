#!/usr/bin/env bash
# The node benchmark (docs/benchmarks.md, "The node's cost"): starts brick_sim through sim.launch on a
# master of its own, pinned to one core, and measures it from a C++ client on
# the other (stack_sim_node_bench): node CPU, publish rates and sizes, and
# service latency for settled scenes of 100 to 10 000 bricks. Then the plots
# and the table of targets.
# Usage: run_node_bench.sh quick|full   (quick: 100 and 2000 bricks)
set -eo pipefail
source "$(dirname "$0")/env.sh"
plan="${1:-quick}"
case "${plan}" in quick|full) ;; *) echo "run_node_bench.sh: quick or full" >&2; exit 2 ;; esac
bash "${repo_root}/scripts/build.sh"
results="${repo_root}/bench/results"
mkdir -p "${results}"
csv="${results}/node_bench_${plan}.csv"
# shellcheck disable=SC1091
source "${workspace}/devel/setup.bash"
# A master of its own, on a port of its own: a running roscore is left alone.
export ROS_MASTER_URI="http://localhost:11391"
node_core=() client_core=()
if command -v taskset >/dev/null && [[ $(nproc) -ge 2 ]]; then
  node_core=(taskset -c 0) client_core=(taskset -c 1)
fi
log="${workspace}/node_bench_launch.log"
launch_pid=""
trap 'if [[ -n "${launch_pid}" ]]; then kill -INT ${launch_pid} 2>/dev/null; wait ${launch_pid} 2>/dev/null || true; fi' EXIT
# One pass: a node started with the launch args `$1`, measured by the bench
# with the rest of the arguments.
run_pass() {
  local launch_args="$1"
  shift
  # shellcheck disable=SC2086
  "${node_core[@]}" roslaunch --port 11391 brick_stack_sim sim.launch mode:=com ${launch_args} >>"${log}" 2>&1 &
  launch_pid=$!
  "${client_core[@]}" "${workspace}/devel/lib/brick_stack_sim/stack_sim_node_bench" "$@"
  kill -INT "${launch_pid}" 2>/dev/null
  wait "${launch_pid}" 2>/dev/null || true
  launch_pid=""
}
: >"${log}"
plan_args=()
[[ "${plan}" == quick ]] && plan_args+=(--quick --window 3)
echo "Node benchmark (${plan}) into ${csv}"
run_pass "" "${csv}" "${plan_args[@]}"
# ~bricks as deltas: the same busy scenes, one subscriber.
run_pass "bricks_delta:=true" "${csv%.csv}_delta.csv" "${plan_args[@]}" --delta
/usr/bin/python3 "${repo_root}/bench/plot_node_bench.py" "${csv}" "${results}"
{ echo "machine: $(nproc --all) cores (node on one, client on another), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)";
  echo "date: $(date -u +%Y-%m-%d)"; } > "${results}/node_bench_${plan}_machine.txt"
