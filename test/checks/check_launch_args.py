#!/usr/bin/python3
"""Every launch file of the package lists each of its args with a doc, and an
arg with a default is not listed as required.

usage: check_launch_args.py --junit RESULT.xml LAUNCH_DIR

`roslaunch --ros-args <file>` is what a user reads: it prints "undocumented"
for an arg without doc= and lists an arg whose default is empty under
"Required Arguments", as if it had none. One testcase per launch file.
"""
import argparse
import glob
import os
import subprocess
import sys

from roslaunch.arg_dump import get_args

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from junit_result import write_junit  # noqa: E402


def listed_args(launch_file):
    """(required, optional, problems) as `roslaunch --ros-args` prints them:
    name -> doc."""
    run = subprocess.run(["roslaunch", "--ros-args", launch_file], capture_output=True,
                         text=True, timeout=60)
    if run.returncode != 0:
        return {}, {}, ["roslaunch --ros-args failed: " + (run.stderr or run.stdout).strip()]
    required, optional, section = {}, {}, None
    for line in run.stdout.splitlines():
        if line == "Required Arguments:":
            section = required
        elif line == "Optional Arguments:":
            section = optional
        elif line.startswith("  ") and section is not None:
            head, _, doc = line.strip().partition(": ")
            section[head.split(" (default ")[0]] = doc
    return required, optional, []


def check(launch_file):
    required, optional, problems = listed_args(launch_file)
    if problems:
        return problems
    for name, doc in sorted({**required, **optional}.items()):
        if doc == "undocumented":
            problems.append(f"arg '{name}' has no doc=")
    # roslaunch's own reading: default None is a real required arg, '' a
    # default it lists as required anyway.
    for name, (_, default) in sorted(get_args([launch_file]).items()):
        if default is not None and name in required:
            problems.append(f"arg '{name}' has a default ('{default}') but is listed as "
                            "required: roslaunch lists an empty default so")
    return problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--junit", required=True)
    parser.add_argument("launch_dir")
    args = parser.parse_args()
    files = sorted(glob.glob(os.path.join(args.launch_dir, "*.launch")))
    cases = [(os.path.basename(f), check(f)) for f in files]
    if not cases:
        cases = [("launch_files", [f"no *.launch in {args.launch_dir}"])]
    for name, problems in cases:
        print(f"{name}: " + ("; ".join(problems) if problems else "every arg documented"))
    return 1 if write_junit(args.junit, "launch_args", cases) else 0


if __name__ == "__main__":
    sys.exit(main())
