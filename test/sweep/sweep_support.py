"""What the sweep tests share: a junit result with skipped cases, the
program as a module, and running it (docs/testing.md, "The sweep tests")."""
import argparse
import contextlib
import csv
import importlib.machinery
import importlib.util
import io
import os
import subprocess
import sys
import time
import traceback
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
SOURCE_PROGRAM = os.path.join(REPO, "src", "tools", "stack_sim_sweep")


class Skip(Exception):
    """Raised by a case that cannot run here; its message is the reason."""


class Suite:
    """Runs cases (functions that raise AssertionError to fail, Skip to be
    skipped) and writes them as one junit testsuite."""

    def __init__(self, name):
        self.name = name
        self.cases = []

    def run(self, name, function, *args):
        started = time.monotonic()
        output = io.StringIO()
        outcome, message = "passed", ""
        try:
            with contextlib.redirect_stdout(output):
                function(*args)
        except Skip as skip:
            outcome, message = "skipped", str(skip)
        except Exception as error:  # noqa: BLE001: every error fails its case, not the suite
            outcome = "failed"
            message = "%s: %s" % (type(error).__name__, error)
            output.write(traceback.format_exc())
        seconds = time.monotonic() - started
        self.cases.append((name, outcome, message, output.getvalue(), seconds))
        print("[%s] %s.%s (%.1f s)%s" % (outcome.upper(), self.name, name, seconds,
                                          ": " + message if message else ""))
        if output.getvalue():
            print(output.getvalue().rstrip())
        return outcome == "passed"

    def write(self, path):
        failures = sum(1 for case in self.cases if case[1] == "failed")
        skipped = sum(1 for case in self.cases if case[1] == "skipped")
        root = ET.Element("testsuite", name=self.name, tests=str(len(self.cases)),
                          failures=str(failures), errors="0", skipped=str(skipped))
        for name, outcome, message, output, seconds in self.cases:
            case = ET.SubElement(root, "testcase", classname=self.name, name=name,
                                 time="%.3f" % seconds)
            if outcome == "failed":
                ET.SubElement(case, "failure", message=message).text = output
            elif outcome == "skipped":
                ET.SubElement(case, "skipped", message=message)
            if output:
                ET.SubElement(case, "system-out").text = output
        os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
        ET.ElementTree(root).write(path, encoding="utf-8", xml_declaration=True)
        return failures


def load_program(path=SOURCE_PROGRAM):
    """stack_sim_sweep as a module (it has no .py suffix)."""
    loader = importlib.machinery.SourceFileLoader("stack_sim_sweep", path)
    spec = importlib.util.spec_from_loader("stack_sim_sweep", loader)
    module = importlib.util.module_from_spec(spec)
    loader.exec_module(module)
    return module


def run_program(program, args, timeout=600, env=None):
    """Runs the program with Debian's python3 (its relay in the devel space
    is a script too); returns (exit status, stdout, stderr)."""
    command = [sys.executable, program] + list(args)
    result = subprocess.run(command, capture_output=True, text=True, timeout=timeout,
                            env=env)
    print("$ %s\n%s%s[exit %d]" % (" ".join(command), result.stdout, result.stderr,
                                   result.returncode))
    return result.returncode, result.stdout, result.stderr


def read_rows(path):
    with open(path, newline="") as stream:
        return list(csv.DictReader(stream))


def without_wall_time(path):
    """The lines of a results.csv with the wall_time column cut out."""
    with open(path, newline="") as stream:
        rows = list(csv.reader(stream))
    column = rows[0].index("wall_time")
    return [row[:column] + row[column + 1:] for row in rows]


def standard_args(description):
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--junit", required=True, help="the junit result to write")
    parser.add_argument("--program", default=SOURCE_PROGRAM,
                        help="stack_sim_sweep (the devel space's, beside stack_sim_run)")
    parser.add_argument("--keep", action="store_true", help="keep the sweep folders")
    return parser
