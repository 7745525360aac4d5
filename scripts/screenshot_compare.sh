#!/usr/bin/env bash
# Writes docs/images/compare.png, the picture of compare.launch: one scene in
# two stability modes side by side in one RViz window (config/compare.rviz),
# each table titled with its mode, captured once both builders have printed
# their summaries. Under Xvfb with Mesa's software GL, on a ROS master port
# and X display of its own, so nothing running is disturbed.
#
# Usage: bash scripts/screenshot_compare.sh [OUTPUT.png] [SCENE] [LEFT] [RIGHT]
#   defaults: docs/images/compare.png, tower, com, none
# Environment: SCREENSHOT_MASTER_PORT (default 11433), SCREENSHOT_RENDER_WAIT
# (wall seconds RViz gets to draw the final state, default 10).
#
# The two simulators run on wall time (docs/ros_interface.md, "Launch
# files"), so unlike scripts/screenshot_demo.sh the instant captured is the
# end of the builds, not an exact sim time.
set -eo pipefail
source "$(dirname "$0")/env.sh"
output="$(realpath -m "${1:-${repo_root}/docs/images/compare.png}")"
scene="${2:-tower}"
left="${3:-com}"
right="${4:-none}"
bash "${repo_root}/scripts/install_deps.sh" gui
bash "${repo_root}/scripts/build.sh" brick_stack_sim_node blueprint_builder frame_offset
mkdir -p "$(dirname "${output}")" "${workspace}/log"

# shellcheck source=scripts/screenshot_session.sh
source "${repo_root}/scripts/screenshot_session.sh" 11433

launch_log="${ROS_LOG_DIR}/screenshot_compare.out"
roslaunch brick_stack_sim compare.launch scene:="${scene}" left:="${left}" right:="${right}" \
  >"${launch_log}" 2>&1 &
pids+=($!)

# RViz is ready when it listens to both simulators' markers.
# (Not "rostopic | grep -q": with pipefail, grep's early exit fails the pipe.)
rviz_listens() {
  [[ "$(rostopic info /left/brick_sim/markers 2>/dev/null)" == *"/rviz"* &&
    "$(rostopic info /right/brick_sim/markers 2>/dev/null)" == *"/rviz"* ]]
}
for _ in $(seq 120); do rviz_listens && break; sleep 0.5; done
rviz_listens || { echo "RViz never subscribed to both markers (see ${launch_log})" >&2; exit 1; }
# Both builds are over when both builders have printed their summary line.
summaries() { grep -c "demo summary" "${launch_log}" 2>/dev/null || true; }
for _ in $(seq 600); do (($(summaries) >= 2)) && break; sleep 0.5; done
(($(summaries) >= 2)) || { echo "the builds did not end within 300 s (see ${launch_log})" >&2; exit 1; }
grep -E "demo summary|result|FAILED" "${launch_log}" || true
sleep "${SCREENSHOT_RENDER_WAIT:-10}"
import -window root "${output}"
echo "wrote ${output} (${scene}: left ${left}, right ${right})"
