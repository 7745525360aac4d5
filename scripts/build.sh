#!/usr/bin/env bash
# Builds the package in the git-ignored workspace .catkin_ws, whose src/ holds
# a link to the repository root. Extra arguments go to catkin_make.
set -eo pipefail
source "$(dirname "$0")/env.sh"
mkdir -p "${workspace}/src"
ln -sfn "${repo_root}" "${workspace}/src/brick_stack_sim"
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
