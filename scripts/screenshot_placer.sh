#!/usr/bin/env bash
# Writes docs/images/placer.png, the README's picture of the brick placer:
# teleop.launch on the tower10 scene under Xvfb with Mesa's software GL, the
# ghost brick beside the tower, captured with ImageMagick once RViz has drawn
# it. Its own ROS master port and X display keep it off anything running.
# Usage: bash scripts/screenshot_placer.sh [output.png]
set -eo pipefail
source "$(dirname "$0")/env.sh"
bash "${repo_root}/scripts/install_deps.sh" gui
bash "${repo_root}/scripts/build.sh" brick_stack_sim_node brick_placer
output="$(realpath -m "${1:-${repo_root}/docs/images/placer.png}")"
mkdir -p "$(dirname "${output}")"

# shellcheck source=scripts/screenshot_session.sh
source "${repo_root}/scripts/screenshot_session.sh" 11431

# The tower is 10 layers (7.8 cm); the ghost starts where teleop.launch puts
# it by default: on the table top beside the tower, hiding none of it.
roslaunch brick_stack_sim teleop.launch scene:=tower10 output:=log >/dev/null 2>&1 &
pids+=($!)

# RViz is ready when it listens to the placer; software GL then needs a few
# seconds for the first frames.
# (Not "rostopic | grep -q": with pipefail, grep's early exit fails the pipe.)
rviz_listens() { [[ "$(rostopic info /brick_placer/update 2>/dev/null)" == *"/rviz"* ]]; }
for _ in $(seq 120); do rviz_listens && break; sleep 0.5; done
rviz_listens || { echo "RViz never subscribed to /brick_placer/update (see ${ROS_LOG_DIR})" >&2; exit 1; }
sleep "${SCREENSHOT_RENDER_WAIT:-10}"
import -window root "${output}"
echo "wrote ${output}"
