#!/usr/bin/env bash
# Installs the Debian packages the package needs, only those that are missing,
# so a second run costs a dpkg query. Usage: install_deps.sh [build|demo|gui|bench]
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

wanted=("${build_packages[@]}")
case "${1:-build}" in
  build|demo) ;;
  gui) wanted+=("${gui_packages[@]}") ;;
  bench) wanted+=("${bench_packages[@]}") ;;
  *) echo "install_deps.sh: unknown set '$1' (build, demo, gui or bench)" >&2; exit 2 ;;
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
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
