#!/usr/bin/env bash
# Builds the package, installs it with catkin_make install into
# .catkin_ws/install and runs it from there alone: stack_sim_run, roslaunch
# --ros-args and the node through sim.launch (test/checks/check_install_space.py;
# make test runs the same check). Arguments go to the check (--keep keeps the
# install space).
set -eo pipefail
source "$(dirname "$0")/env.sh"
bash "${repo_root}/scripts/build.sh"
exec /usr/bin/python3 "${repo_root}/test/checks/check_install_space.py" --workspace "${workspace}" "$@"
