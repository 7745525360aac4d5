#!/usr/bin/env bash
# Builds the package and runs launch/demo.launch: a tower is built brick by
# brick through ~place_brick and a summary is printed; the launch ends by itself.
# Arguments are passed to roslaunch (e.g. gui:=true layers:=12 mode:=none).
set -eo pipefail
source "$(dirname "$0")/env.sh"
"${repo_root}/scripts/build.sh"
cd "${workspace}"
# shellcheck disable=SC1091
source devel/setup.bash
export ROS_LOG_DIR="${workspace}/log"
# A private master port keeps the demo off any master already running here.
export ROS_MASTER_URI="http://localhost:${DEMO_MASTER_PORT:-11411}"
exec roslaunch brick_stack_sim demo.launch "$@"
