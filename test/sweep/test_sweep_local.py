#!/usr/bin/python3
"""stack_sim_sweep on this machine through GNU parallel: the 50 runs of
towers50.yaml with --jobs 1 and with --jobs 2 give the same rows (every
column but wall_time), every run ok, and the rows agree with statics; a
resumed sweep runs only what has no report; a failed run is named, its
output kept, and run again with --rerun; a scene key stack_sim_run does not
know stops the sweep before anything runs; a report without the keys of the
merged columns leaves those cells empty.

usage: test_sweep_local.py --junit RESULT.xml [--program stack_sim_sweep]

Ground truth (docs/testing.md, "Ground truth"): a block tower stands by
statics exactly when its criticality is below 1 (the generator offsets each
brick by criticality times the overhang that puts the centre of mass above
it on the edge below); with a margin of 5 % either way the simulation must
agree: below 0.95 no brick falls in any mode, and a tower of cubes above
1.05 loses at least one brick within the 1.5 s (a KAPLA plank that tips
over the one below drops less than the fall distance and is not counted).
"""
import json
import os
import re
import shutil
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sweep_support import (HERE, Suite, load_program, read_rows, run_program,  # noqa: E402
                           standard_args, without_wall_time)

SWEEP = os.path.join(HERE, "towers50.yaml")
FAILING_RUNNER = """#!/bin/sh
# stack_sim_run, but run 3 fails while the file FLAG exists.
case "$*" in
  *run_000003.json*) if [ -e 'FLAG' ]; then echo "failing on purpose" >&2; exit 1; fi ;;
esac
exec 'REAL' "$@"
"""


class Fixture:
    def __init__(self, program):
        self.program = program
        self.module = load_program()  # the source: the devel relay only execs it
        saved, sys.argv[0] = sys.argv[0], program  # found beside the program
        try:
            self.runner = self.module.find_runner(None)
        finally:
            sys.argv[0] = saved
        self.tmp = tempfile.mkdtemp(prefix="test_sweep_local_")
        self.one = os.path.join(self.tmp, "jobs1")
        self.two = os.path.join(self.tmp, "jobs2")
        self.seconds = {}

    def sweep(self, out, *args):
        started = time.monotonic()
        result = run_program(self.program, [SWEEP, "--out", out] + list(args))
        return result + (time.monotonic() - started,)


def check_jobs_equal(f):
    status_one, _, _, f.seconds[1] = f.sweep(f.one, "--jobs", "1")
    status_two, _, _, f.seconds[2] = f.sweep(f.two, "--jobs", "2")
    assert status_one == 0 and status_two == 0, (status_one, status_two)
    one = without_wall_time(os.path.join(f.one, "results.csv"))
    two = without_wall_time(os.path.join(f.two, "results.csv"))
    assert len(one) == 51, len(one)
    for a, b in zip(one, two):
        assert a == b, (a, b)
    rows = [[json.loads(line) for line in open(os.path.join(d, "results.jsonl"))]
            for d in (f.one, f.two)]
    for a, b in zip(*rows):
        a.pop("wall_time"), b.pop("wall_time")
        assert a == b, (a, b)
    print("50 runs: --jobs 1 %.2f s, --jobs 2 %.2f s; throughput 2 jobs / 1 job: %.2f"
          % (f.seconds[1], f.seconds[2], f.seconds[1] / f.seconds[2]))


def check_every_run_ok(f):
    rows = read_rows(os.path.join(f.one, "results.csv"))
    assert [int(r["run"]) for r in rows] == list(range(50))
    assert all(r["status"] == "ok" for r in rows), [r["run"] for r in rows if r["status"] != "ok"]
    assert {r["mode"] for r in rows} == {"com", "none"}
    for r in rows:
        assert r["fallen"] != "" and r["statics_stands"] != "", r
        placed = int(r["standing"]) + int(r["fallen"]) + int(r["lost"])
        assert placed == int(r["generator.bricks"]), r
        assert (r["first_fall"] == "") == (int(r["fallen"]) == 0), r
        assert int(r["steps"]) == 1500, r


def check_statics(f):
    rows = read_rows(os.path.join(f.one, "results.csv"))
    sides = {True: 0, False: 0}
    for r in rows:
        below = float(r["generator.criticality"]) < 1.0
        assert (r["statics_stands"] == "true") == below, r
        assert (float(r["statics_margin"]) > 0) == below, r
        sides[below] += 1
    assert sides[True] >= 10 and sides[False] >= 10, sides


def check_physics(f):
    rows = read_rows(os.path.join(f.one, "results.csv"))
    stands = falls = 0
    for r in rows:
        criticality = float(r["generator.criticality"])
        if criticality < 0.95:
            assert int(r["fallen"]) == 0, r
            stands += 1
        elif criticality > 1.05 and r["generator.type"] == "cube":
            assert int(r["fallen"]) >= 1 and r["first_fall"], r
            falls += 1
    assert stands >= 10 and falls >= 4, (stands, falls)


def check_resume(f):
    before = without_wall_time(os.path.join(f.two, "results.csv"))
    reports = os.path.join(f.two, "reports")
    times = {name: os.stat(os.path.join(reports, name)).st_mtime_ns
             for name in os.listdir(reports)}
    os.remove(os.path.join(reports, "run_000017.json"))
    status, out, _, _ = f.sweep(f.two, "--jobs", "2")
    assert status == 0 and "running the other 1" in out, (status, out)
    with open(os.path.join(f.two, "joblog.tsv")) as stream:
        jobs = stream.read().splitlines()[1:]
    assert len(jobs) == 1 and jobs[0].split("\t")[-1].endswith("run_task.sh 17"), jobs
    for name, stamp in times.items():
        if name != "run_000017.json":
            assert os.stat(os.path.join(reports, name)).st_mtime_ns == stamp, name
    assert without_wall_time(os.path.join(f.two, "results.csv")) == before


def check_failed_run(f):
    runner = os.path.join(f.tmp, "failing_runner")
    flag = os.path.join(f.tmp, "fail_run_3")
    with open(runner, "w") as stream:
        stream.write(FAILING_RUNNER.replace("FLAG", flag).replace("REAL", f.runner))
    os.chmod(runner, 0o755)
    open(flag, "w").close()
    out = os.path.join(f.tmp, "failing")
    status, _, stderr, _ = f.sweep(out, "--count", "6", "--jobs", "2", "--runner", runner)
    assert status == 1 and "run 3 failed (exit status 1)" in stderr, (status, stderr)
    with open(os.path.join(out, "logs", "run_000003.log")) as stream:
        assert "failing on purpose" in stream.read()
    rows = read_rows(os.path.join(out, "results.csv"))
    assert [r["status"] for r in rows] == ["ok", "ok", "ok", "failed", "ok", "ok"], rows
    assert rows[3]["fallen"] == "" and rows[3]["mode"] == "none", rows[3]
    status, text, _ = run_program(f.program, ["--out", out, "--status"])
    assert status == 1 and re.search(r"failed +1: 3$", text, re.M), text
    os.remove(flag)
    status, _, _ = run_program(f.program, ["--out", out, "--rerun", "failed"])
    assert status == 0, status
    rows = read_rows(os.path.join(out, "results.csv"))
    assert all(r["status"] == "ok" for r in rows), rows
    assert not os.path.exists(os.path.join(out, "logs", "run_000003.log"))
    reference = without_wall_time(os.path.join(f.one, "results.csv"))[:7]
    assert without_wall_time(os.path.join(out, "results.csv")) == reference


def check_preflight(f):
    bad = os.path.join(f.tmp, "typo.yaml")
    with open(SWEEP) as stream:
        text = stream.read().replace("generator.bricks:", "generator.brikcs:")
    with open(bad, "w") as stream:
        stream.write(text)
    out = os.path.join(f.tmp, "typo")
    status, _, stderr = run_program(f.program, [bad, "--out", out])
    assert status == 2 and "unknown key 'brikcs'" in stderr, (status, stderr)
    assert not os.path.exists(out)


def check_absent_keys(f):
    out = os.path.join(f.tmp, "absent")
    shutil.copytree(f.one, out)
    path = os.path.join(out, "reports", "run_000000.json")
    with open(path) as stream:
        report = json.load(stream)
    for key in ("statics", "fallen", "standing", "first_fall", "first_fall_t", "cost"):
        report.pop(key)
    with open(path, "w") as stream:
        json.dump(report, stream)
    os.remove(os.path.join(out, "reports", "run_000001.json"))
    status, _, _ = run_program(f.program, ["--out", out, "--merge-only"])
    assert status == 1, status  # one run missing
    rows = read_rows(os.path.join(out, "results.csv"))
    for key in ("statics_stands", "statics_margin", "fallen", "standing", "first_fall",
                "bullet_steps"):
        assert rows[0][key] == "", (key, rows[0])
    assert rows[0]["status"] == "ok" and rows[0]["steps"] == "1500", rows[0]
    assert rows[1]["status"] == "missing" and rows[1]["steps"] == "", rows[1]
    assert rows[1]["mode"] == "none", rows[1]


def main():
    args = standard_args(__doc__).parse_args()
    fixture = Fixture(args.program)
    suite = Suite("sweep_local")
    if suite.run("jobs_1_and_2_equal", check_jobs_equal, fixture):
        for name, case in (("every_run_ok", check_every_run_ok),
                           ("statics_ground_truth", check_statics),
                           ("physics_ground_truth", check_physics),
                           ("resume", check_resume), ("failed_run", check_failed_run),
                           ("absent_keys", check_absent_keys)):
            suite.run(name, case, fixture)
    suite.run("preflight_refuses", check_preflight, fixture)
    failures = suite.write(args.junit)
    if not args.keep and not failures:
        shutil.rmtree(fixture.tmp, ignore_errors=True)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
