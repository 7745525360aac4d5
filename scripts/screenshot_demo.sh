#!/usr/bin/env bash
# Writes a screenshot of RViz (config/demo.rviz) showing a scene after SECONDS
# of sim time: the README's pictures of what RViz shows. The simulator and
# RViz run under Xvfb with Mesa's software GL, on their own ROS master port
# and X display, so nothing running is disturbed.
#
# Usage: bash scripts/screenshot_demo.sh SCENE MODE OUTPUT.png [SECONDS]
#   SCENE    a scene name (scenes/<name>.yaml) or path, e.g. tower25
#   MODE     stability/mode: com, equilibrium or none
#   SECONDS  sim time the scene runs before the capture [s], default 3
# Environment: SCREENSHOT_MASTER_PORT (default 11432), SCREENSHOT_RENDER_WAIT
# (wall seconds RViz gets to draw the final state, default 10),
# SCREENSHOT_HIDE (marker namespaces to untick in RViz, e.g. "bricks" for the
# view inside the stack; default none), SCREENSHOT_VIEW (the camera's distance
# and focal height [m], e.g. "1.5 0.2" for a large scene; default demo.rviz's).
#
# Sim time is exact and independent of the machine: once RViz listens, the
# script pauses the simulator, restarts the scene (~reset) and advances it
# SECONDS through ~step, so a collapse is captured at the same instant on
# any machine, however slowly software GL starts.
set -eo pipefail
if [[ $# -lt 3 || $# -gt 4 ]]; then
  echo "usage: $0 SCENE MODE OUTPUT.png [SECONDS]" >&2
  exit 2
fi
scene="$1"
mode="$2"
seconds="${4:-3}"
source "$(dirname "$0")/env.sh"
output="$(realpath -m "$3")"
[[ "${seconds}" =~ ^[0-9]+([.][0-9]+)?$ ]] || { echo "SECONDS must be a number: ${seconds}" >&2; exit 2; }
bash "${repo_root}/scripts/install_deps.sh" gui
bash "${repo_root}/scripts/build.sh" brick_stack_sim_node
mkdir -p "$(dirname "${output}")" "${workspace}/log"

# shellcheck source=scripts/screenshot_session.sh
source "${repo_root}/scripts/screenshot_session.sh" 11432

# config/demo.rviz, or a copy of it with SCREENSHOT_HIDE's namespaces unticked
# and the camera SCREENSHOT_VIEW ("DISTANCE FOCAL_Z" [m]) away.
rviz_config=()
if [[ -n "${SCREENSHOT_HIDE:-}" || -n "${SCREENSHOT_VIEW:-}" ]]; then
  hidden_config="$(mktemp --suffix=.rviz)"
  extra_cleanup='rm -f "${hidden_config}"'
  cp "${repo_root}/config/demo.rviz" "${hidden_config}"
  for namespace in ${SCREENSHOT_HIDE:-}; do
    sed -i "s/^\( *\)${namespace}: true\$/\1${namespace}: false/" "${hidden_config}"
  done
  if [[ -n "${SCREENSHOT_VIEW:-}" ]]; then
    read -r view_distance view_z <<<"${SCREENSHOT_VIEW}"
    sed -i "s/^\( *\)Distance: .*/\1Distance: ${view_distance}/" "${hidden_config}"
    sed -i "/Focal Point:/,/Z:/ s/^\( *\)Z: .*/\1Z: ${view_z}/" "${hidden_config}"
  fi
  rviz_config=(rviz_config:="${hidden_config}")
fi

# The one launch line: the simulator (node /brick_sim) with RViz.
roslaunch brick_stack_sim sim.launch scene:="${scene}" mode:="${mode}" gui:=true \
  "${rviz_config[@]}" >"${ROS_LOG_DIR}/screenshot_demo.out" 2>&1 &
pids+=($!)

# RViz is ready when it listens to the markers; the simulator when it serves
# ~step (advertised after ~pause and ~reset).
# (Not "rostopic | grep -q": with pipefail, grep's early exit fails the pipe.)
rviz_listens() { [[ "$(rostopic info /brick_sim/markers 2>/dev/null)" == *"/rviz"* ]]; }
for _ in $(seq 120); do rviz_listens && break; sleep 0.5; done
rviz_listens || { echo "RViz never subscribed to /brick_sim/markers (see ${ROS_LOG_DIR})" >&2; exit 1; }
serves_step() { rosservice type /brick_sim/step >/dev/null 2>&1; }
for _ in $(seq 60); do serves_step && break; sleep 0.5; done
serves_step || { echo "no /brick_sim/step (see ${ROS_LOG_DIR})" >&2; exit 1; }

call() {  # service, request; fails with the simulator's message
  local answer
  answer="$(rosservice call "$1" "$2")" || { echo "$1 failed: ${answer}" >&2; exit 1; }
  [[ "${answer}" == *"success: True"* ]] || { echo "$1 refused: ${answer}" >&2; exit 1; }
}
time_step="$(rosparam get /brick_sim/time_step)"
steps="$(awk -v s="${seconds}" -v dt="${time_step}" 'BEGIN { printf "%d", s / dt + 0.5 }')"
call /brick_sim/pause "{data: true}"
call /brick_sim/reset "{scene: '${scene}'}"
if ((steps > 0)); then call /brick_sim/step "{steps: ${steps}}"; fi

# RViz got every marker when it subscribed and the changes since; software GL
# needs a few seconds to draw them.
sleep "${SCREENSHOT_RENDER_WAIT:-10}"
import -window root "${output}"
echo "wrote ${output} (${scene}, mode ${mode}, ${seconds} s of sim time)"
