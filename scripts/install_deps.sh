#!/usr/bin/env bash
# Installs the Debian packages the package needs, only those that are missing,
# so a second run costs a dpkg query.
# Usage: install_deps.sh [build|demo|test|sweep|cluster|gui|bench]
set -euo pipefail

build_packages=(
  build-essential cmake pkg-config
  catkin ros-base-dev ros-message-generation ros-message-runtime rosbash
  libroscpp-dev libroslib-dev librostest-dev python3-rostest python3-rosunit
  libstd-msgs-dev libstd-srvs-dev libgeometry-msgs-dev libvisualization-msgs-dev
  libros-rosgraph-msgs-dev libtf2-ros-dev
  python3-std-msgs python3-std-srvs python3-geometry-msgs python3-visualization-msgs
  libbullet-dev libeigen3-dev liburdfdom-dev libyaml-cpp-dev coinor-libclp-dev
  # brick shapes from URDF meshes (STL, OBJ, ...), read as their convex hull
  libassimp-dev
  googletest libgtest-dev
  libtf2-msgs-dev python3-rospkg python3-roslaunch
  # make test's convention checks: catkin_lint, and the install space driven
  # with rosrun, rospack, rosservice and rosparam (test/checks)
  catkin-lint rospack-tools python3-rosservice python3-rosparam
  # teleop: the RViz brick placer
  libinteractive-markers-dev
)
# RViz; scripts/screenshot_placer.sh also needs Xvfb, rostopic and ImageMagick.
gui_packages=(rviz xvfb imagemagick libgl1-mesa-dri python3-rostopic)
# plot_bench.py
bench_packages=(python3-matplotlib)
# stack_sim_sweep (docs/sweeps.md): it reads the sweep file with python3-yaml
# and runs a sweep on this machine through GNU parallel. make test runs a
# sweep too, so the test set has them.
sweep_packages=(python3-yaml parallel)
# A single-node Slurm (scripts/start_slurm.sh) for the cluster test, which
# make test runs where Slurm can start and reports skipped elsewhere.
cluster_packages=(slurm-wlm munge)

wanted=("${build_packages[@]}")
case "${1:-build}" in
  build|demo) ;;
  sweep) wanted+=("${sweep_packages[@]}") ;;
  test|cluster) wanted+=("${sweep_packages[@]}" "${cluster_packages[@]}") ;;
  gui) wanted+=("${gui_packages[@]}") ;;
  bench) wanted+=("${bench_packages[@]}") ;;
  *) echo "install_deps.sh: unknown set '$1' (build, demo, test, sweep, cluster, gui or bench)" >&2
     exit 2 ;;
esac

missing=()
for package in "${wanted[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$package" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$package")
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

echo "Installing Debian packages: ${missing[*]}"
sudo_cmd=()
[[ $(id -u) -eq 0 ]] || sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
# Without systemd (a container), a package's maintainer scripts may try to
# start its daemons (slurmd, munge) through init scripts and fail the
# install; a policy-rc.d that denies every start (exit 101) stops them for
# the install, as Docker's images do. scripts/start_slurm.sh starts its own.
policy=/usr/sbin/policy-rc.d
own_policy=0
if [[ ! -d /run/systemd/system && ! -e "${policy}" ]]; then
  printf '#!/bin/sh\n# written by install_deps.sh for one install\nexit 101\n' \
    | "${sudo_cmd[@]}" tee "${policy}" >/dev/null
  "${sudo_cmd[@]}" chmod 755 "${policy}"
  own_policy=1
  trap '"${sudo_cmd[@]}" rm -f "${policy}"' EXIT
fi
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
if ((own_policy)); then "${sudo_cmd[@]}" rm -f "${policy}"; trap - EXIT; fi
