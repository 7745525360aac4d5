#!/usr/bin/python3
"""No include runs up the layers: a file may include headers of its own
folder and of folders on lower layers, never of a higher layer or of a peer
on its own layer.

usage: check_layers.py [--junit RESULT.xml] REPO_ROOT

The layers are the table below, bottom first; docs/design.md, "Layers" says
what each holds. A folder that is in no layer fails too, so that a new folder
is placed on purpose. Public core headers are under
include/brick_stack_sim/core/<folder>/, private ones under src/core/<folder>/
and included relative to src/core; both belong to <folder>'s layer.
"""
import argparse
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from junit_result import write_junit  # noqa: E402

# Bottom first; folders on one line are peers.
LAYERS = [
    ["core/base"],  # core/status.h and util/
    ["core/options", "core/geometry"],
    ["core/types"],
    ["core/physics"],
    ["core/bullet", "core/stability"],
    ["core/world", "core/scene"],
    ["core/simulation"],
    ["core/io"],
    ["tools", "ros"],
    ["client"],
    ["planner", "teleop"],
    ["nodes"],
]
RANK = {folder: rank for rank, peers in enumerate(LAYERS) for folder in peers}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def folder_of(path):
    """The layer folder of a repository path, or None when it is not code of
    a layer (tests, say)."""
    parts = path.split("/")
    if parts[:3] == ["include", "brick_stack_sim", "core"] or parts[:2] == ["src", "core"]:
        rest = parts[3:] if parts[0] == "include" else parts[2:]
        if len(rest) == 1 or rest[0] == "util":
            return "core/base"
        return "core/" + rest[0]
    if parts[:2] == ["include", "brick_stack_sim"] and len(parts) > 3:
        return parts[2]
    if parts[0] == "src" and len(parts) > 2:
        return parts[1]
    return None


def resolve(root, including, name):
    """The repository path an include names, or None for a header that is
    not the package's (a system or ROS one)."""
    for candidate in (os.path.join(os.path.dirname(including), name),
                      os.path.join("include", name), os.path.join("src/core", name)):
        if os.path.isfile(os.path.join(root, candidate)):
            return os.path.normpath(candidate)
    return None


def upward_includes(root):
    """(folder, problems) for every layer folder, plus unplaced folders."""
    problems = {}
    for top in ("src", "include"):
        for directory, _, files in os.walk(os.path.join(root, top)):
            for name in sorted(files):
                if not name.endswith((".h", ".cpp")):
                    continue
                path = os.path.relpath(os.path.join(directory, name), root)
                folder = folder_of(path)
                if folder is None:
                    continue
                found = problems.setdefault(folder, [])
                if folder not in RANK:
                    found.append(f"{path}: folder {folder} is in no layer of check_layers.py")
                    continue
                with open(os.path.join(root, path), encoding="utf-8") as source:
                    for number, line in enumerate(source, 1):
                        match = INCLUDE.match(line)
                        target = match and resolve(root, path, match.group(1))
                        if not target:
                            continue
                        target_folder = folder_of(target)
                        if target_folder in (None, folder):
                            continue
                        if RANK.get(target_folder, len(LAYERS)) >= RANK[folder]:
                            found.append(f"{path}:{number}: {folder} includes {match.group(1)} "
                                         f"of {target_folder}, which is not below it")
    return problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--junit", help="write a junit result here")
    parser.add_argument("root")
    args = parser.parse_args()
    problems = upward_includes(os.path.abspath(args.root))
    for folder in sorted(problems):
        for problem in problems[folder]:
            print(problem)
    if args.junit:
        write_junit(args.junit, "layers",
                    [(folder.replace("/", "_"), problems[folder]) for folder in sorted(problems)])
    return 1 if any(problems.values()) else 0


if __name__ == "__main__":
    sys.exit(main())
