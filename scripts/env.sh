# Sourced by the project's scripts: Debian's python3 must come before any
# pyenv build on PATH, because catkin and rostest need the ROS modules.
export PATH="/usr/bin:/bin:${PATH}"
export PYTHONNOUSERSITE=1
unset PYTHONHOME PYTHONPATH
repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
workspace="${repo_root}/.catkin_ws"
