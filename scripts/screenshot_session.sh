# Sourced by the screenshot scripts: the workspace's environment on a ROS
# master port of their own (SCREENSHOT_MASTER_PORT, else $1), and an Xvfb
# display with Mesa's software GL (Xvfb has no GPU) that RViz can draw on.
# Processes appended to `pids` are killed on exit, last started first; a
# script may set `extra_cleanup` to a command run after them.
cd "${workspace}"
# shellcheck disable=SC1091
source devel/setup.bash
export ROS_LOG_DIR="${workspace}/log"
export ROS_MASTER_URI="http://localhost:${SCREENSHOT_MASTER_PORT:-$1}"
export LIBGL_ALWAYS_SOFTWARE=1

pids=()
extra_cleanup=""
cleanup() {
  for ((i = ${#pids[@]} - 1; i >= 0; i--)); do kill "${pids[i]}" 2>/dev/null || true; done
  wait 2>/dev/null || true
  if [[ -n "${extra_cleanup}" ]]; then eval "${extra_cleanup}"; fi
}
trap cleanup EXIT

# -displayfd: Xvfb picks a free display and tells us which.
display_file="$(mktemp)"
Xvfb -displayfd 3 -screen 0 1200x800x24 -nolisten tcp 3>"${display_file}" 2>/dev/null &
pids+=($!)
for _ in $(seq 50); do [[ -s "${display_file}" ]] && break; sleep 0.1; done
[[ -s "${display_file}" ]] || { echo "Xvfb did not start" >&2; exit 1; }
export DISPLAY=":$(head -n1 "${display_file}")"
rm -f "${display_file}"
