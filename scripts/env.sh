# Sourced by the project's scripts: Debian's python3 must come before any
# pyenv build on PATH, because catkin and rostest need the ROS modules.
export PATH="/usr/bin:/bin:${PATH}"
export PYTHONNOUSERSITE=1
unset PYTHONHOME PYTHONPATH
# ROS nodes advertise themselves by host name; where that name does not
# resolve (containers, chroots, fresh VMs) every rostest fails to reach its
# own nodes. Loopback always works for a single machine.
export ROS_HOSTNAME="${ROS_HOSTNAME:-localhost}"
repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# make sanitize builds in workspaces of its own (.catkin_ws_asan, ...).
workspace="${BRICK_WORKSPACE:-${repo_root}/.catkin_ws}"
