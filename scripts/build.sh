#!/usr/bin/env bash
# Builds the package in the git-ignored workspace .catkin_ws, whose src/ holds
# a link to the repository root. Extra arguments go to catkin_make.
set -eo pipefail
source "$(dirname "$0")/env.sh"
mkdir -p "${workspace}/src"
# The workspace's view of the package: a directory of links to the
# repository's entries, all but the workspace itself. One link to the whole
# repository put the workspace inside its own source space, and rosrun's
# `find -L` reported a file-system loop on every call.
package_view="${workspace}/src/brick_stack_sim"
if [[ -L "${package_view}" ]]; then rm "${package_view}"; fi
mkdir -p "${package_view}"
for link in "${package_view}"/* "${package_view}"/.[!.]*; do
  if [[ -L "${link}" && ! -e "${link}" ]]; then rm "${link}"; fi  # its entry is gone
done
for entry in "${repo_root}"/* "${repo_root}"/.[!.]*; do
  name="$(basename "${entry}")"
  case "${name}" in .catkin_ws | .catkin_ws_* | .git) continue ;; esac
  if [[ -e "${entry}" ]]; then ln -sfn "${entry}" "${package_view}/${name}"; fi
done
cd "${workspace}"
log="${workspace}/build.log"
echo "Building in ${workspace} (log: ${log})"
if ! catkin_make -DPYTHON_EXECUTABLE=/usr/bin/python3 -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -j"$(nproc)" "$@" >"${log}" 2>&1; then
  grep -E -B2 -A12 'error|Error|CMake Error' "${log}" | head -150 >&2 || tail -80 "${log}" >&2
  echo "catkin_make failed; full log: ${log}" >&2
  exit 1
fi
grep -E 'warning:' "${log}" | sort -u | head -40 || true
