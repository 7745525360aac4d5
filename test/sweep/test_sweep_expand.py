#!/usr/bin/python3
"""stack_sim_sweep's expansion, without running a simulation: how many runs,
in what order, --count, draws that are the same on every machine and in every
process, grid times samples, the files it writes, and bad sweep files refused
with the key named before anything is written.

usage: test_sweep_expand.py --junit RESULT.xml [--program stack_sim_sweep]

Runs that would start stack_sim_run go to a stand-in runner that does
nothing (the preflight and --help included).
"""
import os
import shutil
import sys
import tempfile

import yaml

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sweep_support import REPO, Suite, load_program, run_program, standard_args  # noqa: E402

DATASET = os.path.join(REPO, "scenes", "sweeps", "block_towers.yaml")
# Draws of the dataset's sweep, pinned: they depend on (seed, sample, key)
# alone, through Python's Mersenne Twister seeded with a string, and must
# not change with the machine or the Python release.
PINNED = [
    ((1, 0, "generator.criticality", {"uniform": [0.8, 1.2]}), 1.1953805845956054),
    ((1, 9999, "generator.bricks", {"integers": [2, 6]}), 6),
    ((1, 42, "generator.type", {"choice": ["cube", "kapla"]}), "cube"),
    ((1, 42, "generator.seed", {"integers": [0, 1000000000]}), 87593674),
]
SMALL = """name: small
scene: {generator: {name: block_tower, bricks: 3, type: cube, criticality: 0.9, seed: 0}}
duration: 2.0
samples: 4
seed: 5
grid:
  mode: [com, none]
  iterations: [10, 20, 30]
draw:
  generator.bricks: {integers: [2, 6]}
  generator.criticality: {uniform: [0.8, 1.2]}
  pose_noise.position: {uniform: [0, 0.0005]}
"""
FAKE_RUNNER = """#!/bin/sh
# A stand-in for stack_sim_run: it says it has --statics, and runs nothing.
case "$*" in *--help*) echo "  --statics           add statics"; esac
exit 0
"""


class Fixture:
    def __init__(self, program):
        self.program = program
        self.module = load_program()  # the source: the devel relay only execs it
        self.tmp = tempfile.mkdtemp(prefix="test_sweep_expand_")
        self.runner = os.path.join(self.tmp, "fake_stack_sim_run")
        with open(self.runner, "w") as stream:
            stream.write(FAKE_RUNNER)
        os.chmod(self.runner, 0o755)

    def sweep_file(self, name, text):
        path = os.path.join(self.tmp, name)
        with open(path, "w") as stream:
            stream.write(text)
        return path

    def load(self, text, name="sweep.yaml"):
        return self.module.load_sweep(self.sweep_file(name, text))

    def write(self, sweep_path, out, *extra, env=None):
        return run_program(self.program, [sweep_path, "--out", out, "--write-only",
                                          "--runner", self.runner] + list(extra), env=env)


def check_counts_and_order(f):
    sweep = f.module.load_sweep(DATASET)
    assert sweep.samples == 10000 and len(sweep.points) == 3, (sweep.samples, sweep.points)
    assert sweep.runs == 30000, sweep.runs
    runs = f.module.expand(sweep)
    assert [r[0] for r in runs] == list(range(30000))
    # Sample-major: run = sample * 3 + point, the modes in the order listed.
    for run, sample, parameters in runs[:300]:
        assert sample == run // 3, (run, sample)
        assert parameters["mode"] == ["none", "com", "equilibrium"][run % 3], (run, parameters)
    # One draw per sample, the same at each of its grid points.
    for first in range(0, 300, 3):
        drawn = [{k: v for k, v in runs[first + i][2].items() if k != "mode"} for i in range(3)]
        assert drawn[0] == drawn[1] == drawn[2], drawn
    assert runs[0][2] != runs[3][2]


def check_grid_times_samples(f):
    sweep = f.load(SMALL)
    runs = f.module.expand(sweep)
    assert len(runs) == 4 * 2 * 3, len(runs)
    # The last grid key varies fastest.
    expected = [(m, i) for m in ("com", "none") for i in (10, 20, 30)]
    for sample in range(4):
        points = [(p["mode"], p["iterations"]) for _, s, p in runs if s == sample]
        assert points == expected, (sample, points)
    assert sweep.parameters == ["mode", "iterations", "generator.bricks",
                                "generator.criticality", "pose_noise.position"], sweep.parameters


def check_count(f):
    path = f.sweep_file("small.yaml", SMALL)
    out = os.path.join(f.tmp, "count")
    status, _, _ = f.write(path, out, "--count", "7")
    assert status == 0, status
    with open(os.path.join(out, "tasks.txt")) as stream:
        assert len(stream.readlines()) == 7
    assert sorted(os.listdir(os.path.join(out, "scenes"))) == [
        "run_%06d.yaml" % r for r in range(7)]
    with open(os.path.join(out, "runs.csv")) as stream:
        lines = stream.read().splitlines()
    assert len(lines) == 8 and lines[0].startswith("run,sample,seed,mode,iterations,"), lines[:2]
    full = f.module.expand(f.module.load_sweep(path))
    assert f.module.expand(f.module.load_sweep(path), 7) == full[:7]


def check_reproducible(f):
    for (args, value) in PINNED:
        drawn = f.module.draw_value(*args)
        assert drawn == value and type(drawn) is type(value), (args, drawn, value)
    sweep = f.module.load_sweep(DATASET)
    assert f.module.expand(sweep, 3000) == f.module.expand(f.module.load_sweep(DATASET), 3000)
    # Two processes, each with its own hash seed, write the same files.
    outs = []
    for hash_seed in ("1", "2"):
        out = os.path.join(f.tmp, "reproduce_%s" % hash_seed)
        env = dict(os.environ, PYTHONHASHSEED=hash_seed)
        status, _, _ = f.write(DATASET, out, "--count", "600", env=env)
        assert status == 0, status
        outs.append(out)
    for name in ["runs.csv", "sweep.yaml"] + ["scenes/run_%06d.yaml" % r for r in range(600)]:
        texts = []
        for out in outs:
            with open(os.path.join(out, name), "rb") as stream:
                texts.append(stream.read())
        assert texts[0] == texts[1], name
    tasks = []
    for out in outs:
        with open(os.path.join(out, "tasks.txt")) as stream:
            tasks.append(stream.read().replace(out, "DIR"))
    assert tasks[0] == tasks[1]


def check_draws(f):
    spec = {"integers": [2, 6]}
    values = [f.module.draw_value(3, k, "n", spec) for k in range(2000)]
    assert set(values) == {2, 3, 4, 5, 6}, sorted(set(values))  # both ends included
    spec = {"uniform": [0.8, 1.2]}
    values = [f.module.draw_value(3, k, "c", spec) for k in range(2000)]
    assert all(0.8 <= v <= 1.2 for v in values) and len(set(values)) == 2000
    assert 0.79 < min(values) < 0.81 and 1.19 < max(values) < 1.21
    # A key's draws do not depend on the other keys: adding one changes nothing.
    base = f.load(SMALL)
    more = f.load(SMALL.replace("draw:\n", "draw:\n  table.friction: {uniform: [0.3, 0.9]}\n"),
                  "more.yaml")
    for (_, _, a), (_, _, b) in zip(f.module.expand(base), f.module.expand(more)):
        assert {k: v for k, v in b.items() if k != "table.friction"} == a, (a, b)
    # Another seed, other draws.
    other = f.load(SMALL.replace("seed: 5", "seed: 6"), "other.yaml")
    assert f.module.expand(other)[0][2] != f.module.expand(base)[0][2]


def check_files(f):
    out = os.path.join(f.tmp, "files")
    path = f.sweep_file("small.yaml", SMALL.replace("duration: 2.0", "duration: 2.0\n"
                                                     "sleeping: false"))
    status, _, _ = f.write(path, out)
    assert status == 0, status
    with open(os.path.join(out, "tasks.txt")) as stream:
        first = stream.readline().split()
    assert first[0] == f.runner, first
    assert first[1:3] == ["--scene", os.path.join(out, "scenes", "run_000000.yaml")], first
    for flag, value in (("--mode", "com"), ("--iterations", "10"), ("--duration", "2.0"),
                        ("--report", os.path.join(out, "reports", "run_000000.json"))):
        assert first[first.index(flag) + 1] == value, (flag, first)
    assert "--statics" in first and "--no-sleep" in first, first
    sweep = f.module.load_sweep(path)
    _, _, parameters = f.module.expand(sweep)[0]
    with open(os.path.join(out, "scenes", "run_000000.yaml")) as stream:
        scene = yaml.safe_load(stream)
    assert scene["generator"]["bricks"] == parameters["generator.bricks"], scene
    assert scene["generator"]["criticality"] == parameters["generator.criticality"], scene
    assert scene["pose_noise"] == {"position": parameters["pose_noise.position"]}, scene
    with open(os.path.join(out, "sweep.yaml")) as stream:
        assert stream.read() == sweep.text
    # A generator list: an element by its index.
    listed = f.load("scene: {generator: [{name: column, count: 2}, {name: slant_tower, "
                    "layers: 3, offset: 0.01}]}\ndraw:\n  generator.1.offset: {uniform: [0, 1]}\n",
                    "listed.yaml")
    scene = f.module.scene_of(listed, f.module.expand(listed)[0][2])
    assert scene["generator"][0] == {"name": "column", "count": 2}, scene
    assert 0 <= scene["generator"][1]["offset"] <= 1, scene
    # The package's sweep by its name.
    out = os.path.join(f.tmp, "by_name")
    status, _, _ = f.write("block_towers", out, "--count", "2")
    assert status == 0, status
    with open(os.path.join(out, "sweep.yaml")) as a, open(DATASET) as b:
        assert a.read() == b.read()
    # A scene by name: passed on as it is, no scene files.
    named = f.sweep_file("named.yaml", "scene: tower10\ngrid: {mode: [com, none]}\n")
    out = os.path.join(f.tmp, "named")
    status, _, _ = f.write(named, out)
    assert status == 0 and os.listdir(os.path.join(out, "scenes")) == []
    with open(os.path.join(out, "tasks.txt")) as stream:
        assert stream.readline().split()[1:3] == ["--scene", "tower10"]


REFUSALS = [
    ("sampels: 3\nscene: tower10\n", "unknown key 'sampels'"),
    ("scene: tower10\ngrid: {mode: []}\n", "grid key 'mode' needs a non-empty list"),
    ("scene: tower10\ngrid: {mode: com}\n", "grid key 'mode' needs a non-empty list"),
    ("scene: {generator: {name: tower}}\ndraw: {generator.layers: {integer: [1, 3]}}\n",
     "draw key 'generator.layers'"),
    ("scene: {generator: {name: tower}}\ndraw: {generator.layers: {integers: [3, 1]}}\n",
     "draw key 'generator.layers': integers needs two integers lo <= hi"),
    ("scene: {generator: {name: tower}}\ndraw: {friction: {uniform: [0.5]}}\n",
     "draw key 'friction': uniform needs [lo, hi]"),
    ("scene: {generator: {name: tower}}\ndraw: {friction: {choice: []}}\n",
     "draw key 'friction': choice needs a non-empty list"),
    ("scene: tower10\nsamples: 0\n", "samples must be an integer >= 1"),
    ("scene: tower10\ndraw: {generator.layers: {integers: [1, 3]}}\n",
     "draw key 'generator.layers' is a path into the scene, but the scene is a name"),
    ("scene: {generator: [{name: tower}, {name: column}]}\n"
     "draw: {generator.layers: {integers: [1, 3]}}\n",
     "draw key 'generator.layers': generator is a list of 2; address an element by its index"),
    ("scene: {generator: {name: tower}}\ngrid: {mode: [com]}\ndraw: {mode: {choice: [none]}}\n",
     "key 'mode' is in both grid and draw"),
    ("scene: tower10\ndraw: {mode: {uniform: [0, 1]}}\n", "draw key 'mode': mode is drawn with"),
    ("scene: tower10\ngrid: {time_step: [0.001, -1]}\n", "grid key 'time_step': -1 is not"),
    ("scene: {name: x, generator: {name: tower}}\ndraw: {name.first: {uniform: [0, 1]}}\n",
     "draw key 'name.first': name is 'x', not a mapping"),
    ("duration: 4\n", "the key 'scene' is missing"),
    ("scene: [tower10]\n", "scene must be a mapping"),
    ("- just a list\n", "expected a mapping"),
]


def check_refusals(f):
    for number, (text, expected) in enumerate(REFUSALS):
        try:
            f.load(text, "bad_%d.yaml" % number)
        except f.module.SweepError as error:
            assert expected in str(error), (text, str(error), expected)
        else:
            raise AssertionError("accepted: %r (expected %r)" % (text, expected))
    # From the command line: exit 2, the key named, nothing written.
    path = f.sweep_file("bad.yaml", REFUSALS[1][0])
    out = os.path.join(f.tmp, "refused")
    status, _, stderr = f.write(path, out)
    assert status == 2 and "grid key 'mode'" in stderr, (status, stderr)
    assert not os.path.exists(out), os.listdir(out)


def main():
    args = standard_args(__doc__).parse_args()
    fixture = Fixture(args.program)
    suite = Suite("sweep_expand")
    for name, case in (("counts_and_order", check_counts_and_order),
                       ("grid_times_samples", check_grid_times_samples),
                       ("count", check_count), ("reproducible", check_reproducible),
                       ("draws", check_draws), ("files", check_files),
                       ("refusals", check_refusals)):
        suite.run(name, case, fixture)
    failures = suite.write(args.junit)
    if not args.keep:
        shutil.rmtree(fixture.tmp, ignore_errors=True)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
