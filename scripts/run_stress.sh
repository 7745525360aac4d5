#!/usr/bin/env bash
# The long stress runs (make test runs short versions of each):
# - batch runs of stack_sim_run: each must end with nonfinite = 0, no brick lost or
#   missing, no crash, and the short ones must give bit-identical reports
#   when run twice;
# - the node's service fuzzer with three seeds of 10 000 requests, an hour of
#   sim time of placing and removing (memory measured), and the concurrent
#   clients with more rounds: each must pass its gtests.
set -eo pipefail
source "$(dirname "$0")/env.sh"
bash "${repo_root}/scripts/build.sh" tests
run="${workspace}/devel/lib/brick_stack_sim/stack_sim_run"
out="${workspace}/stress"
mkdir -p "${out}"
failed=0 passed=0

check() {  # check NAME REPORT [REPORT_OF_SECOND_RUN]
  if /usr/bin/python3 - "$@" <<'PY'
import json, re, sys
name, first = sys.argv[1], json.load(open(sys.argv[2]))
problems = []
if first["nonfinite"] != 0: problems.append(f"nonfinite {first['nonfinite']}")
if first["lost"] != 0: problems.append(f"lost {first['lost']}")
if first["missing"] != 0: problems.append(f"missing {first['missing']}")
if len(sys.argv) > 3:
    strip = lambda t: re.sub(r'"(wall_time|stage_seconds|bullet_stages)": (\{[^}]*\}|[^,]*),', "", t)
    if strip(open(sys.argv[2]).read()) != strip(open(sys.argv[3]).read()):
        problems.append("second run differs")
print(f"{name}: {first['sim_time']:.0f} s simulated, {len(first['bricks'])} bricks, "
      f"blow-ups repaired {first['blowups']}, largest displacement "
      f"{1000 * first['max_displacement']:.2f} mm" + (" -- " + "; ".join(problems) if problems else ""))
sys.exit(1 if problems else 0)
PY
  then passed=$((passed + 1)); else failed=$((failed + 1)); fi
}

stress() {  # stress NAME TWICE ARGS...
  local name=$1 twice=$2; shift 2
  if ! "${run}" "$@" --report "${out}/${name}.json" 2>"${out}/${name}.log"; then
    echo "${name}: stack_sim_run failed: $(tail -1 "${out}/${name}.log")"; failed=$((failed + 1)); return
  fi
  if [[ "${twice}" == twice ]]; then
    "${run}" "$@" --report "${out}/${name}.again.json" 2>/dev/null
    check "${name}" "${out}/${name}.json" "${out}/${name}.again.json"
  else
    check "${name}" "${out}/${name}.json"
  fi
}

scenes="${repo_root}/scenes/stress"
stress tower133_com twice --scene "${scenes}/tower133.yaml" --mode com --duration 30
stress tower133_none once --scene "${scenes}/tower133.yaml" --mode none --duration 30
stress mass_ratio_none twice --scene "${scenes}/mass_ratio.yaml" --mode none --duration 10
stress mass_ratio_com twice --scene "${scenes}/mass_ratio.yaml" --mode com --duration 10
stress pile2000_com once --scene "${scenes}/pile2000.yaml" --mode com --duration 4
for step in 0.001 0.004 0.0167 0.033 0.066 0.1; do
  stress "sweep_dt_${step}" once --scene tower10 --mode none --no-sleep --time-step "${step}" \
    --iterations 5 --duration 20
done
# A million steps of a scene that never sleeps.
stress busy50_million_steps once --scene "${scenes}/busy50.yaml" --mode none --no-sleep \
  --duration 1000

rostest_run() {  # rostest_run NAME TEST_FILE TEST_NAME ARGS...
  local name=$1 file=$2 test_name=$3; shift 3
  local log="${out}/${name}.log"
  # rostest --text shows the test's output but no longer judges it: the
  # gtest result file it asks for does.
  local result="${ROS_HOME:-${HOME}/.ros}/test_results/brick_stack_sim/rosunit-${test_name}.xml"
  rm -f "${result}"
  (
    cd "${workspace}"
    # shellcheck disable=SC1091
    source devel/setup.bash
    rostest --text brick_stack_sim "${file}" "$@"
  ) >"${log}" 2>&1 || true
  # The test's own lines (its counts and measurements).
  grep -h -E '^(fuzz|soak|  [a-z_]+( \(topic\))?:|[0-9]+ clients)' "${log}" || true
  if /usr/bin/python3 - "${result}" <<'PY'
import sys, xml.etree.ElementTree as ET
try:
    root = ET.parse(sys.argv[1]).getroot()
except (OSError, ET.ParseError):
    sys.exit(1)  # no result: the test crashed or never ran
cases = list(root.iter("testcase"))
bad = [c for c in cases if c.find("failure") is not None or c.find("error") is not None]
sys.exit(0 if cases and not bad else 1)
PY
  then
    echo "${name}: passed"; passed=$((passed + 1))
  else
    echo "${name}: FAILED (${log})"; failed=$((failed + 1))
  fi
}
rostest_run fuzz_seed1_soak_hour service_fuzz.test service_fuzz requests:=10000 seed:=1 \
  soak_sim_seconds:=3600 time_limit:=3600
for seed in 2 3; do
  rostest_run "fuzz_seed${seed}" service_fuzz.test service_fuzz requests:=10000 "seed:=${seed}" \
    soak_sim_seconds:=60 time_limit:=1800
done
rostest_run concurrent_clients_40_rounds concurrent_clients.test concurrent_clients rounds:=40
echo "stress: ${passed} passed, ${failed} failed"
[[ ${failed} -eq 0 ]]
