#!/usr/bin/env bash
# make sanitize: builds the package and every test with AddressSanitizer and
# UndefinedBehaviorSanitizer, and separately with ThreadSanitizer, each in a
# workspace of its own (.catkin_ws_asan, .catkin_ws_tsan; the first build of
# each takes about ten minutes on two cores), and runs all the tests in each.
# A variant passes when every test passes and no sanitizer wrote a report:
# nodes started by rostest report into files, not into a test's result, so
# the reports are counted from those files.
#   run_sanitize.sh [address|thread]...   (default: both)
set -eo pipefail
source "$(dirname "$0")/env.sh"
variants=("$@")
[[ ${#variants[@]} -gt 0 ]] || variants=(address thread)
suppressions="${repo_root}/test/sanitize"
failed_variants=()

for variant in "${variants[@]}"; do
  case "${variant}" in
    address) sanitizers="address;undefined" workspace_name=.catkin_ws_asan ;;
    thread) sanitizers="thread" workspace_name=.catkin_ws_tsan ;;
    *) echo "unknown variant '${variant}': expected address or thread" >&2; exit 2 ;;
  esac
  export BRICK_WORKSPACE="${repo_root}/${workspace_name}"
  reports="${BRICK_WORKSPACE}/sanitizer_reports"
  rm -rf "${reports}"
  mkdir -p "${reports}"
  # Each process writes <kind>.<pid> into reports/ when it finds something.
  common="log_path=${reports}/report:print_stacktrace=1"
  export ASAN_OPTIONS="${common}:detect_leaks=1:strict_string_checks=1"
  export LSAN_OPTIONS="${common}:suppressions=${suppressions}/lsan.supp"
  export UBSAN_OPTIONS="${common}:halt_on_error=1:suppressions=${suppressions}/ubsan.supp"
  export TSAN_OPTIONS="${common}:halt_on_error=0:second_deadlock_stack=1"
  TSAN_OPTIONS+=":suppressions=${suppressions}/tsan.supp"
  echo "== ${variant}: -fsanitize=${sanitizers/;/,} in ${BRICK_WORKSPACE}"
  set +e
  bash "${repo_root}/scripts/run_tests.sh" --tests-only \
    "-DBRICK_STACK_SIM_SANITIZE=${sanitizers}" | tee "${BRICK_WORKSPACE}/summary.txt"
  tests_status=${PIPESTATUS[0]}
  set -e
  count=$(find "${reports}" -type f | wc -l)
  if ((count > 0)); then
    echo "${variant}: ${count} sanitizer report(s) in ${reports}; the first:"
    head -40 "$(find "${reports}" -type f | sort | head -1)"
  fi
  echo "${variant}: $(tail -1 "${BRICK_WORKSPACE}/summary.txt"); ${count} sanitizer reports"
  if ((tests_status != 0 || count > 0)); then failed_variants+=("${variant}"); fi
done

if ((${#failed_variants[@]} > 0)); then
  echo "sanitize: failed: ${failed_variants[*]}"
  exit 1
fi
echo "sanitize: ${variants[*]} clean"
