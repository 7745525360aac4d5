#!/usr/bin/python3
"""The package runs from an install space alone.

usage: check_install_space.py --workspace WS [--junit RESULT.xml] [--keep]

Installs the package with `catkin_make install` from the workspace WS
(scripts/build.sh's .catkin_ws, already built) into WS/install, emptied
first, then, in an environment that has sourced WS/install/setup.bash and
nothing else (no devel space, no source tree on any path):

  layout        every program, plot_bench.py, stack_sim_sweep, the launch, config, urdf,
                scenes, msg and srv files and the headers are installed, and
                rospack finds the package there
  stack_sim_run `rosrun brick_stack_sim stack_sim_run --scene tower10 --mode
                com --duration 1 --report ...` reads the install space's
                scenes and writes its report
  ros_args      `roslaunch --ros-args brick_stack_sim sim.launch` resolves
                $(find brick_stack_sim) to the install space
  node          `roslaunch brick_stack_sim sim.launch scene:=tower10` on a
                master of its own: the node answers ~get_bricks with the
                scene's 20 bricks

Each is a testcase of the junit result; the install space is removed at the
end unless --keep.
"""
import argparse
import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from junit_result import write_junit  # noqa: E402

PACKAGE = "brick_stack_sim"
PROGRAMS = ["brick_stack_sim_node", "stack_sim_run", "stack_sim_bench", "stack_sim_lp_bench",
            "stack_sim_held_bench", "blueprint_builder", "brick_placer", "keyboard_teleop",
            "plot_bench.py", "stack_sim_sweep"]
SHARED = ["package.xml", "launch/sim.launch", "launch/teleop.launch", "launch/demo.launch",
          "config/sim.yaml", "config/stability.yaml", "config/bricks.yaml", "urdf/bricks.urdf",
          "scenes/tower10.yaml", "scenes/empty.yaml", "scenes/sweeps/block_towers.yaml",
          "msg/Brick.msg", "srv/PlaceBrick.srv"]
HEADERS = ["include/brick_stack_sim/ros/node.h", "include/brick_stack_sim/core/status.h",
           "include/brick_stack_sim/Brick.h"]


class InstallSpace:
    def __init__(self, workspace, scratch):
        self.workspace = os.path.realpath(workspace)
        self.prefix = os.path.join(self.workspace, "install")
        self.share = os.path.join(self.prefix, "share", PACKAGE)
        self.scratch = scratch
        # Nothing from the caller's shell: only what setup.bash adds.
        self.env = {"HOME": os.environ.get("HOME", "/root"), "PATH": "/usr/bin:/bin",
                    "LANG": "C.UTF-8", "ROS_HOSTNAME": "localhost",
                    "ROS_HOME": os.path.join(scratch, "ros_home"),
                    "ROS_LOG_DIR": os.path.join(scratch, "log")}

    def install(self):
        cache = os.path.join(self.workspace, "build", "CMakeCache.txt")
        if not os.path.isfile(cache):
            return [f"{self.workspace} is not built: run scripts/build.sh first"]
        with open(cache) as text:
            prefix = next((line.split("=", 1)[1].strip() for line in text
                           if line.startswith("CMAKE_INSTALL_PREFIX:")), "")
        if os.path.realpath(prefix) != self.prefix:
            return [f"the workspace installs into {prefix}, not {self.prefix}"]
        shutil.rmtree(self.prefix, ignore_errors=True)
        # The arguments of scripts/build.sh, so that CMake is not run again.
        run = subprocess.run(
            ["catkin_make", "-DPYTHON_EXECUTABLE=/usr/bin/python3",
             "-DCMAKE_BUILD_TYPE=RelWithDebInfo", f"-j{os.cpu_count() or 1}", "install"],
            cwd=self.workspace, env=dict(self.env), capture_output=True, text=True)
        if run.returncode != 0:
            return ["catkin_make install failed:"] + (run.stdout + run.stderr).splitlines()[-30:]
        return []

    def run(self, command, timeout=120, **kwargs):
        """`command` (a shell line) with the install space sourced, and only it."""
        line = f"source {self.prefix}/setup.bash && {command}"
        return subprocess.run(["bash", "-c", line], env=dict(self.env), capture_output=True,
                              text=True, timeout=timeout, **kwargs)

    def foreign_paths(self, text):
        """Entries of `text` (colon-separated paths) in the devel space or the
        source tree: what must not be reached from an install space."""
        forbidden = [os.path.join(self.workspace, "devel"), os.path.join(self.workspace, "src"),
                     os.path.dirname(self.workspace)]
        return [entry for entry in text.split(":") if entry and entry != self.prefix
                and not entry.startswith(self.prefix + "/")
                and any(entry == f or entry.startswith(f + "/") for f in forbidden)]


def check_layout(space):
    problems = []
    for program in PROGRAMS:
        path = os.path.join(space.prefix, "lib", PACKAGE, program)
        if not os.access(path, os.X_OK):
            problems.append(f"not installed: lib/{PACKAGE}/{program}")
    for name in SHARED:
        if not os.path.isfile(os.path.join(space.share, name)):
            problems.append(f"not installed: share/{PACKAGE}/{name}")
    for name in HEADERS:
        if not os.path.isfile(os.path.join(space.prefix, name)):
            problems.append(f"not installed: {name}")
    run = space.run(f"rospack find {PACKAGE}; echo \"$ROS_PACKAGE_PATH:$CMAKE_PREFIX_PATH:"
                    "$LD_LIBRARY_PATH:$PYTHONPATH:$PATH\"")
    lines = run.stdout.splitlines()
    if run.returncode != 0 or len(lines) < 2:
        return problems + [f"sourcing {space.prefix}/setup.bash failed: {run.stderr.strip()}"]
    if lines[0] != space.share:
        problems.append(f"rospack finds {PACKAGE} in {lines[0]}, not {space.share}")
    problems += [f"the install space's environment reaches {p}"
                 for p in space.foreign_paths(lines[1])]
    return problems


def check_stack_sim_run(space):
    problems = []
    usage = space.run(f"rosrun {PACKAGE} stack_sim_run --help")
    if f"scenes/: {space.share}" not in usage.stdout:
        problems.append(f"stack_sim_run --help does not name {space.share} as its data: "
                        + (usage.stdout + usage.stderr).strip().splitlines()[-1:][0])
    report = os.path.join(space.scratch, "x.json")
    run = space.run(f"rosrun {PACKAGE} stack_sim_run --scene tower10 --mode com --duration 1 "
                    f"--report {report}")
    if run.returncode != 0:
        return problems + [f"stack_sim_run exited {run.returncode}: {run.stderr.strip()}"]
    with open(report) as text:
        result = json.load(text)
    if len(result["bricks"]) != 20 or result["nonfinite"] != 0 or result["mode"] != "com":
        problems.append(f"unexpected report: {len(result['bricks'])} bricks, mode "
                        f"{result['mode']}, nonfinite {result['nonfinite']}")
    return problems


def check_ros_args(space):
    run = space.run(f"roslaunch --ros-args {PACKAGE} sim.launch")
    if run.returncode != 0:
        return [f"roslaunch --ros-args failed: {run.stderr.strip()}"]
    problems = [f"undocumented: {line.strip()}" for line in run.stdout.splitlines()
                if line.endswith(": undocumented")]
    for name in ("urdf/bricks.urdf", "config/bricks.yaml", "scenes"):
        if f'(default "{space.share}/{name}")' not in run.stdout:
            problems.append(f"sim.launch does not take {name} from {space.share}")
    return problems


def free_port():
    with socket.socket() as probe:
        probe.bind(("localhost", 0))
        return probe.getsockname()[1]


def check_node(space):
    port = free_port()
    space.env["ROS_MASTER_URI"] = f"http://localhost:{port}"
    log = open(os.path.join(space.scratch, "roslaunch.log"), "w")
    # Its own session, so that the master and the node stop with it.
    launch = subprocess.Popen(
        ["bash", "-c", f"source {space.prefix}/setup.bash && exec roslaunch -p {port} "
         f"{PACKAGE} sim.launch scene:=tower10"],
        env=dict(space.env), stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
    problems, answer = [], None
    try:
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline and launch.poll() is None:
            run = space.run("rosservice call /brick_sim/get_bricks '{}'", timeout=30)
            if run.returncode == 0:
                answer = run.stdout
                break
            time.sleep(1)
        if answer is None:
            problems.append("the node did not answer ~get_bricks within 60 s (log: "
                            f"{log.name})")
        else:
            bricks = answer.count("type: \"kapla\"")
            if bricks != 20:
                problems.append(f"~get_bricks answered {bricks} kapla bricks, tower10 has 20")
            urdf = space.run("rosparam get /brick_sim/types_urdf").stdout.strip()
            if not urdf.startswith(space.share):
                problems.append(f"the node read its brick types from {urdf}")
    finally:
        if launch.poll() is None:
            os.killpg(launch.pid, signal.SIGINT)
            try:
                launch.wait(timeout=30)
            except subprocess.TimeoutExpired:
                os.killpg(launch.pid, signal.SIGKILL)
                launch.wait()
        log.close()
    return problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--workspace", required=True)
    parser.add_argument("--junit")
    parser.add_argument("--keep", action="store_true", help="keep WS/install afterwards")
    args = parser.parse_args()
    scratch = tempfile.mkdtemp(prefix="brick_stack_sim_install_")
    space = InstallSpace(args.workspace, scratch)
    started = time.monotonic()
    cases = [("install", space.install())]
    checks = [("layout", check_layout), ("stack_sim_run", check_stack_sim_run),
              ("ros_args", check_ros_args), ("node", check_node)]
    for name, check in checks:
        if cases[0][1]:
            cases.append((name, ["not run: the install failed"]))
            continue
        try:
            cases.append((name, check(space)))
        except Exception as error:  # a crash of one check is its failure, not the run's
            cases.append((name, [f"{type(error).__name__}: {error}"]))
    for name, problems in cases:
        print(f"install space {name}: " + ("; ".join(problems) if problems else "ok"))
    print(f"install space: {space.prefix}, checked in {time.monotonic() - started:.0f} s")
    failures = sum(1 for _, problems in cases if problems)
    if args.junit:
        write_junit(args.junit, "install_space", cases)
    if not args.keep:
        shutil.rmtree(space.prefix, ignore_errors=True)
    if not failures:
        shutil.rmtree(scratch, ignore_errors=True)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
