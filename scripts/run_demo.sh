#!/usr/bin/env bash
# Builds the package and runs launch/demo.launch: a demo scene (default: the
# 25-layer 4-stack) is built brick by brick through ~place_brick by
# blueprint_builder, which prints a summary; the launch ends by itself.
# Arguments are passed to roslaunch (e.g. gui:=true scene:=card_house mode:=none).
# Exits with the builder's status (scripts/demo_with_status.sh): 0 when the
# structure did what the scene expects, 1 when not, 2 when it could not run.
set -eo pipefail
source "$(dirname "$0")/env.sh"
bash "${repo_root}/scripts/build.sh"
cd "${workspace}"
# shellcheck disable=SC1091
source devel/setup.bash
export ROS_LOG_DIR="${workspace}/log"
# A private master port keeps the demo off any master already running here.
export ROS_MASTER_URI="http://localhost:${DEMO_MASTER_PORT:-11411}"
exec bash "${repo_root}/scripts/demo_with_status.sh" demo.launch "$@"
