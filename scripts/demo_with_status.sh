#!/usr/bin/env bash
# Runs a demo launch and exits with its builders' status, which roslaunch
# does not pass on (it exits 0 whatever its nodes did): 0 when the structure
# did what the scene expects, 1 when not, 2 when a builder could not run or
# wrote no status (docs/ros_interface.md, "Launch files").
#   bash scripts/demo_with_status.sh [demo.launch|compare.launch] [arg:=value ...]
# The launch file defaults to demo.launch; compare.launch ends by itself only
# with gui:=false, and its status is the worse of its two builders'. It builds
# nothing: source a workspace first (devel or install); scripts/run_demo.sh
# builds and then runs this.
set -u
launch=demo.launch
if [[ "${1:-}" == *.launch ]]; then
  launch="$1"
  shift
fi
case "${launch}" in
  demo.launch) builders=(status) ;;
  compare.launch) builders=(status.left status.right) ;;
  *)
    echo "demo_with_status.sh: ${launch} is no demo launch (demo.launch or compare.launch)" >&2
    exit 2
    ;;
esac
status_dir="$(mktemp -d)"
trap 'rm -rf "${status_dir}"' EXIT
roslaunch brick_stack_sim "${launch}" "$@" status_file:="${status_dir}/status"
launch_status=$?
status=0
for builder in "${builders[@]}"; do
  read -r builder_status 2>/dev/null <"${status_dir}/${builder}" || builder_status=""
  if [[ ! "${builder_status}" =~ ^[0-9]+$ ]]; then
    echo "demo_with_status.sh: no exit status from the builder (${builder}); roslaunch exited ${launch_status}" >&2
    builder_status=2
  fi
  ((builder_status > status)) && status=${builder_status}
done
exit "${status}"
