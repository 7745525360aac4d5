#!/usr/bin/python3
"""Plots a stack_sim_node_bench CSV and writes the table of the node's targets.

usage: plot_node_bench.py NODE_RESULTS.csv OUTPUT_DIR

Node CPU and ~get_bricks latency against the number of settled bricks, one
line per number of moving bricks and subscribers; the node's targets
(docs/benchmarks.md, "The node's cost") are checked on rows of the same CSV
(one run, one machine). NODE_RESULTS_delta.csv,
when it lies beside it, adds what bricks_delta saves a ~bricks subscriber.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

SUBSCRIBERS = {0: "no subscriber", 1: "~bricks", 3: "~bricks, ~markers, /tf"}
PUBLISH_RATE = 30.0  # [Hz], config/sim.yaml publish_rate, which run_node_bench.sh keeps


def load(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for key in r:
            r[key] = float(r[key])
    return rows


def find(rows, bricks, moving, subscribers):
    for r in rows:
        if (r["bricks"], r["moving"], r["subscribers"]) == (bricks, moving, subscribers):
            return r
    return None


def plot(rows, column, label, path, scale=1.0):
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for moving in sorted({r["moving"] for r in rows}):
        for subscribers, name in SUBSCRIBERS.items():
            line = sorted((r["bricks"], scale * r[column]) for r in rows
                          if r["moving"] == moving and r["subscribers"] == subscribers
                          and r["bricks"] > 0)
            if not line:
                continue
            ax.plot([x for x, _ in line], [y for _, y in line], marker="o",
                    linestyle="-" if moving == 0 else "--",
                    label=f"{int(moving)} moving, {name}")
    ax.set_xscale("log")
    ax.set_xlabel("settled bricks")
    ax.set_ylabel(label)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def targets(rows, delta_rows):
    lines = ["| target | measured | met |", "|---|---|---|"]

    def add(name, value, ok):
        lines.append(f"| {name} | {value} | {'yes' if ok else 'no'} |")

    settled = find(rows, 2000, 0, 0)
    if settled:
        add("settled 2000 bricks, no subscriber: node CPU <= 2 % of a core",
            f"{100 * settled['node_cpu']:.2f} %", settled["node_cpu"] <= 0.02)
    alone, busy = find(rows, 0, 10, 3), find(rows, 2000, 10, 3)
    if alone and busy and alone["node_cpu"] > 0:
        ratio = busy["node_cpu"] / alone["node_cpu"]
        add("2000 settled + 10 moving, RViz's 3 subscribers: <= 3 x the 10 moving alone",
            f"{ratio:.2f} x ({100 * busy['node_cpu']:.1f} % / {100 * alone['node_cpu']:.1f} %)",
            ratio <= 3.0)
    at2000 = [r for r in rows if r["bricks"] == 2000]
    if at2000:
        worst = max(r["get_bricks_p99_ms"] for r in at2000)
        add("~get_bricks p99 < 20 ms at 2000 bricks", f"{worst:.1f} ms (worst case)", worst < 20)
    largest = max(r["bricks"] for r in rows)
    subscribed = [r for r in rows if r["bricks"] == largest and r["subscribers"] >= 1]
    if subscribed:
        # Too fast is as far off as too slow: a client sized for 30 Hz gets more.
        rates = [r["bricks_hz"] for r in subscribed]
        worst = max(rates, key=lambda rate: abs(rate - PUBLISH_RATE))
        add(f"~bricks within 5 % of publish_rate ({PUBLISH_RATE:.0f} Hz) at {int(largest)} bricks",
            f"{min(rates):.1f} to {max(rates):.1f} Hz",
            abs(worst - PUBLISH_RATE) <= 0.05 * PUBLISH_RATE)
    # Not a target: what bricks_delta saves a planner on the busy scenes.
    for row in delta_rows:
        full = find(rows, row["bricks"], row["moving"], 1)
        if not full:
            continue
        lines.append(
            f"| (bricks_delta) {int(row['bricks'])} settled + {int(row['moving'])} moving, one "
            f"~bricks subscriber | {row['bricks_bytes'] / 1000:.1f} kB a message at "
            f"{row['bricks_hz']:.1f} Hz, node {100 * row['node_cpu']:.1f} % (every brick: "
            f"{full['bricks_bytes'] / 1000:.0f} kB, {100 * full['node_cpu']:.1f} %) | - |")
    return "\n".join(lines) + "\n"


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    rows = load(sys.argv[1])
    out = sys.argv[2]
    stem = os.path.splitext(os.path.basename(sys.argv[1]))[0]
    plot(rows, "node_cpu", "node CPU [% of a core]", os.path.join(out, f"{stem}_cpu.png"), 100)
    plot(rows, "get_bricks_p99_ms", "~get_bricks p99 [ms]",
         os.path.join(out, f"{stem}_get_bricks.png"))
    delta_path = os.path.splitext(sys.argv[1])[0] + "_delta.csv"
    delta_rows = load(delta_path) if os.path.exists(delta_path) else []
    table = targets(rows, delta_rows)
    with open(os.path.join(out, f"{stem}_targets.md"), "w") as f:
        f.write(table)
    print(table, end="")


if __name__ == "__main__":
    main()
