#!/usr/bin/python3
"""stack_sim_sweep on Slurm: the 50 runs of towers50.yaml as a job array on
the single-node Slurm of scripts/start_slurm.sh give the same rows as the
same sweep run here with GNU parallel (every column but wall_time), every
run ok; --status tells it; a run whose report is deleted is run again by
--rerun as an array of one; submitted again, only the runs without a report
are.

usage: test_sweep_cluster.py --junit RESULT.xml [--program stack_sim_sweep]
                             [--require] [--timeout S]

It starts the single-node Slurm when none of the script's is up, and stops
it again at the end. Where Slurm cannot be started (not installed, or its
daemons fail) the cases are reported skipped with the reason; --require
(make test-cluster) makes that a failure.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sweep_support import (HERE, REPO, Skip, Suite, read_rows, run_program,  # noqa: E402
                           standard_args, without_wall_time)

SWEEP = os.path.join(HERE, "towers50.yaml")
START = os.path.join(REPO, "scripts", "start_slurm.sh")


class Cluster:
    """The single-node Slurm: started here unless it was up already."""

    def __init__(self, require):
        self.require = require
        self.started = False
        self.reason = None
        self.env = None

    def start(self):
        up = subprocess.run(["bash", START, "status"], capture_output=True, text=True)
        try:
            result = subprocess.run(["bash", START, "start"], capture_output=True, text=True,
                                    timeout=180)
        except subprocess.TimeoutExpired:
            self.reason = "Slurm could not be started here: start_slurm.sh took over 180 s"
            subprocess.run(["bash", START, "stop"], timeout=120)
            return False
        print(result.stdout + result.stderr)
        if result.returncode != 0:
            what = "not installed" if result.returncode == 3 else "could not be started"
            self.reason = "Slurm %s here: %s" % (what, (result.stderr.strip().splitlines()
                                                         or ["no message"])[0])
            return False
        self.started = up.returncode != 0
        conf = re.search(r"SLURM_CONF=(\S+)", result.stdout).group(1)
        self.env = dict(os.environ, SLURM_CONF=conf)
        return True

    def stop(self):
        if self.started:
            subprocess.run(["bash", START, "stop"], timeout=120)

    def check(self):
        if self.reason:
            if self.require:
                raise AssertionError(self.reason)
            raise Skip(self.reason)


class Fixture:
    def __init__(self, program, timeout):
        self.program = program
        self.timeout = timeout
        self.tmp = tempfile.mkdtemp(prefix="test_sweep_cluster_")
        self.local = os.path.join(self.tmp, "local")
        self.slurm = os.path.join(self.tmp, "slurm")
        self.seconds = {}


def cancel(env, out):
    try:
        with open(os.path.join(out, "slurm_jobs.txt")) as stream:
            jobs = [line.split("\t")[0] for line in stream if line.strip()]
    except OSError:
        return
    if jobs:
        subprocess.run(["scancel"] + jobs, env=env)


def on_slurm(f, cluster, args):
    started = time.monotonic()
    try:
        result = run_program(f.program, args, timeout=f.timeout, env=cluster.env)
    except subprocess.TimeoutExpired:
        cancel(cluster.env, f.slurm)
        raise AssertionError("the job did not end within %d s; cancelled" % f.timeout)
    return result + (time.monotonic() - started,)


def check_same_as_local(f, cluster):
    cluster.check()
    started = time.monotonic()
    status, _, _ = run_program(f.program, [SWEEP, "--out", f.local, "--jobs", "2"])
    f.seconds["local"] = time.monotonic() - started
    assert status == 0, status
    status, out, _, f.seconds["slurm"] = on_slurm(
        f, cluster, [SWEEP, "--out", f.slurm, "--slurm", "--submit", "--wait", "--jobs", "2"])
    assert status == 0 and "submitted job" in out, (status, out)
    with open(os.path.join(f.slurm, "sweep.sbatch")) as stream:
        assert "#SBATCH --array=0-49%2" in stream.read()
    local = without_wall_time(os.path.join(f.local, "results.csv"))
    slurm = without_wall_time(os.path.join(f.slurm, "results.csv"))
    assert len(slurm) == 51
    for a, b in zip(local, slurm):
        assert a == b, (a, b)
    rows = read_rows(os.path.join(f.slurm, "results.csv"))
    assert all(r["status"] == "ok" for r in rows)
    print("50 runs, 2 at a time: GNU parallel %.1f s, Slurm %.1f s (submit to merged)"
          % (f.seconds["local"], f.seconds["slurm"]))


def check_status_and_rerun(f, cluster):
    cluster.check()
    assert os.path.exists(os.path.join(f.slurm, "results.csv")), "no Slurm sweep to look at"
    status, text, _ = run_program(f.program, ["--out", f.slurm, "--status"], env=cluster.env)
    assert status == 0 and re.search(r"ok +50$", text, re.M) and "slurm jobs:" in text, text
    before = without_wall_time(os.path.join(f.slurm, "results.csv"))
    os.remove(os.path.join(f.slurm, "reports", "run_000017.json"))
    status, text, _ = run_program(f.program, ["--out", f.slurm, "--status"], env=cluster.env)
    assert status == 1 and re.search(r"missing +1: 17$", text, re.M), text
    status, out, _, _ = on_slurm(f, cluster, ["--out", f.slurm, "--rerun", "17", "--slurm",
                                              "--wait"])
    assert status == 0 and "--array=17%100" in out, (status, out)
    assert without_wall_time(os.path.join(f.slurm, "results.csv")) == before
    with open(os.path.join(f.slurm, "slurm_jobs.txt")) as stream:
        assert [line.split("\t")[1].strip() for line in stream] == ["all", "17%100"]


def check_resubmit(f, cluster):
    cluster.check()
    assert os.path.exists(os.path.join(f.slurm, "results.csv")), "no Slurm sweep to look at"
    before = without_wall_time(os.path.join(f.slurm, "results.csv"))
    for run in (3, 30, 31):
        os.remove(os.path.join(f.slurm, "reports", "run_%06d.json" % run))
    status, out, _, _ = on_slurm(f, cluster, [SWEEP, "--out", f.slurm, "--slurm", "--submit",
                                              "--wait", "--jobs", "2"])
    assert status == 0 and "--array=3,30-31%2" in out, (status, out)
    assert without_wall_time(os.path.join(f.slurm, "results.csv")) == before


def main():
    parser = standard_args(__doc__)
    parser.add_argument("--require", action="store_true",
                        help="fail, rather than skip, where Slurm cannot be started")
    parser.add_argument("--timeout", type=float, default=600,
                        help="seconds a job may take before it is cancelled (default 600)")
    args = parser.parse_args()
    fixture = Fixture(args.program, args.timeout)
    cluster = Cluster(args.require)
    suite = Suite("sweep_cluster")
    try:
        cluster.start()
        suite.run("same_as_local", check_same_as_local, fixture, cluster)
        suite.run("status_and_rerun", check_status_and_rerun, fixture, cluster)
        suite.run("resubmit_resumes", check_resubmit, fixture, cluster)
    finally:
        cluster.stop()
    failures = suite.write(args.junit)
    if not args.keep and not failures:
        shutil.rmtree(fixture.tmp, ignore_errors=True)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
