#!/usr/bin/env bash
# Builds, runs every gtest and rostest of the package and the convention
# checks (launch args and files, catkin_lint -W1, the install space), and
# prints one closing line "N passed, N failed"; exits non-zero when anything
# failed.
#   run_tests.sh [--tests-only] [catkin_make arguments...]
# --tests-only leaves out the convention checks (make sanitize: they are
# about the sources, not the build); the other arguments go to the build.
set -eo pipefail
source "$(dirname "$0")/env.sh"
checks=1
if [[ "${1:-}" == --tests-only ]]; then checks=0; shift; fi
bash "${repo_root}/scripts/build.sh" tests "$@"
cd "${workspace}"
results="${workspace}/build/test_results/brick_stack_sim"
rm -rf "${results}"
set +e
# shellcheck disable=SC1091
source devel/setup.bash
catkin_make -DPYTHON_EXECUTABLE=/usr/bin/python3 run_tests -j1 >"${workspace}/test.log" 2>&1
run_status=$?
mkdir -p "${results}"
install_written=1
if ((checks)); then
# The package stays catkin_lint -W1 clean: one more test in the count.
lint_output="$(cd "${repo_root}" && catkin_lint -W1 . 2>&1)" && lint_status=0 || lint_status=$?
/usr/bin/python3 - "${results}/catkin_lint.xml" "${lint_status}" "${lint_output}" <<'PY'
import sys
from xml.sax.saxutils import escape
path, status, output = sys.argv[1], int(sys.argv[2]), sys.argv[3]
problems = [line for line in output.splitlines() if ": warning: " in line or ": error: " in line]
failure = ""
if status != 0 or problems:
    failure = '<failure message="catkin_lint -W1 found problems">%s</failure>' % escape(output)
with open(path, "w") as xml:
    xml.write('<testsuite name="catkin_lint" tests="1"><testcase classname="catkin_lint" '
              'name="W1_clean">%s</testcase></testsuite>\n' % failure)
PY
# The package from an install space alone (about 20 s once built); after
# run_tests, which empties the results directory, and outside it, since it
# runs catkin_make install in the same build tree. Its junit result is
# counted below like the others.
/usr/bin/python3 "${repo_root}/test/checks/check_install_space.py" --workspace "${workspace}" \
  --junit "${results}/install_space.xml" 2>&1 | tee -a "${workspace}/test.log"
[[ -s "${results}/install_space.xml" ]] || install_written=0
fi
set -e
# The per-test lines of every suite, for the reader of the CI log.
grep -h -E '^\[ +(OK|FAILED) +\]|^\[ROSTEST\]|^ *\* |FAILURE|ERROR' "${workspace}/test.log" \
  | grep -v -E 'FAILED TESTS?$' || true
/usr/bin/python3 - "${results}" "${run_status}" "${install_written}" <<'PY'
import sys, glob, xml.etree.ElementTree as ET
results_dir, run_status, install_written = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
passed = failed = skipped = 0
files = sorted(glob.glob(results_dir + "/**/*.xml", recursive=True))
for path in files:
    try:
        root = ET.parse(path).getroot()
    except ET.ParseError as error:
        print(f"unreadable result {path}: {error}"); failed += 1; continue
    for case in root.iter("testcase"):
        bad = case.find("failure") is not None or case.find("error") is not None
        skip = case.find("skipped") is not None
        name = f"{case.get('classname')}.{case.get('name')}"
        if bad:
            failed += 1
            print(f"FAILED: {name}")
        elif skip:
            skipped += 1
        else:
            passed += 1
if not files:
    print("no test results were written")
    failed += 1
if not install_written:
    print("the install space check wrote no result (see .catkin_ws/test.log)")
    failed += 1
if run_status != 0 and failed == 0:
    print(f"catkin_make run_tests exited {run_status} (see .catkin_ws/test.log)")
    failed += 1
print(f"{passed} passed, {failed} failed" + (f", {skipped} skipped" if skipped else ""))
sys.exit(1 if failed else 0)
PY
