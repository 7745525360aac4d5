#!/usr/bin/python3
"""Plots a stack_sim_bench CSV and writes the table of the benchmark targets.

usage: plot_bench.py RESULTS.csv OUTPUT_DIR

For each case: run time against error for every mode and setting (the Pareto
picture), for the piles also against the time they settle; for the settled
towers: cost against number of bricks. The targets
are checked on ratios measured side by side in the same CSV. The motions with
an answer from mechanics get a table of their own (*_motion.md): measured,
expected and error per mode, at the default setting.
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

DEFAULT = (0.001, 20)
COLOURS = {"none_nosleep": "tab:red", "none_sleep": "tab:orange", "com": "tab:green"}
# Modes the benchmark takes from the core's registry but this script does not
# know yet still get a colour of their own, in the order they first appear.
SPARE_COLOURS = ["tab:blue", "tab:purple", "tab:brown", "tab:pink", "tab:olive", "tab:cyan"]


def colours_for(rows):
    """Every mode of `rows` with its colour: the known ones first, then the rest."""
    modes = list(COLOURS)
    for r in rows:
        if r["mode"] not in modes:
            modes.append(r["mode"])
    spare = iter(SPARE_COLOURS)
    return {m: COLOURS.get(m) or next(spare, "tab:gray") for m in modes}
ERROR_OF = {  # case kind -> (column, axis label)
    "drift_mm": "drift over the run [mm]",
    "threshold_error_pct": "harmonic threshold error [% of f]",
    "collapse_layer_error": "|collapse layer error| [layers]",
    "penetration_mm": "deepest penetration [mm]",
    "motion_error_pct": "error against mechanics [%]",
    "settle_time": "settled from (98 % of bricks at rest to the end) [s]; never: at the end",
}
# Measured by Jolt on pile1000 for 10 s at 1 ms: what the stability layer is held to.
JOLT_PILE1000_WALL_S = 46.0
JOLT_PILE1000_PENETRATION_MM = 0.7
# What each motion case measures, and the reference its error is against.
MOTION_QUANTITY = {
    "slide": ("stopping distance from 1 m/s [mm]", 1000.0, "v^2 / (2 mu g)"),
    "incline": ("acceleration down 35 degrees [m/s^2]", 1.0, "g (sin a - mu cos a)"),
    "topple": ("time to tip to 45 degrees [ms]", 1000.0, "rigid pendulum about the edge"),
    "free_flight": ("height gained in 0.3 s [mm]", 1000.0, "v t - g t^2 / 2"),
    "domino": ("toppling wave speed [m/s]", 1.0, "plain Bullet at 1/4000 s, 100 it."),
}


def load(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for key in ("time_step", "wall_ms_per_sim_s", "bricks", "iterations"):
            r[key] = float(r[key])
        for key in ("motion_measured", "motion_expected", "motion_error_pct", "settle_time",
                    "at_rest_pct", "fell_off", "settled_cost_pct"):
            r.setdefault(key, "")  # a CSV from before the motions or the piles
    return rows


def error_column(rows):
    for column in ("drift_mm", "threshold_error_pct", "collapse_layer_error", "motion_error_pct"):
        if all(r[column] != "" for r in rows):
            return column
    return "penetration_mm"


def error_value(row, column):
    if column == "settle_time" and row[column] == "":
        return float(row["sim_time"])  # never settled: as late as the run shows
    value = float(row[column])
    return abs(value)


def is_pile(row):
    """A pile case's row: it measures how the pile came to rest."""
    return row["at_rest_pct"] != ""


def is_default(row):
    return abs(row["time_step"] - DEFAULT[0]) < 1e-9 and int(row["iterations"]) == DEFAULT[1]


def plot_pareto(case, rows, out_dir, stem, column=None, suffix=""):
    column = column or error_column(rows)
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for mode, colour in colours_for(rows).items():
        points = [r for r in rows if r["mode"] == mode]
        if not points:
            continue
        ax.scatter([error_value(r, column) for r in points],
                   [max(r["wall_ms_per_sim_s"], 1e-3) for r in points],
                   color=colour, label=mode, s=36)
        for r in points:
            never = " never" if column == "settle_time" and r[column] == "" else ""
            ax.annotate(f"1/{round(1 / r['time_step'])}s,{int(r['iterations'])}it{never}",
                        (error_value(r, column), max(r["wall_ms_per_sim_s"], 1e-3)),
                        fontsize=6, xytext=(3, 2), textcoords="offset points")
    ax.set_yscale("log")
    if column != "settle_time":  # seconds read best on a linear axis
        ax.set_xscale("symlog", linthresh=0.01)
    ax.set_xlim(left=0.0)
    ax.set_xlabel(ERROR_OF[column])
    ax.set_ylabel("wall time per simulated second [ms]")
    against = "settling" if column == "settle_time" else "error"
    ax.set_title(f"{case}: run time against {against} (lower left is better)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, f"{stem}_pareto_{case}{suffix}.png"), dpi=110)
    plt.close(fig)


def plot_scaling(rows, out_dir, stem):
    towers = [r for r in rows if r["case"].startswith("tower") and is_default(r)]
    if not towers:
        return
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for mode, colour in colours_for(rows).items():
        points = sorted((r["bricks"], max(r["wall_ms_per_sim_s"], 1e-3))
                        for r in towers if r["mode"] == mode)
        if points:
            ax.plot(*zip(*points), "o-", color=colour, label=mode)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("bricks in a settled tower")
    ax.set_ylabel("wall time per simulated second [ms]")
    ax.set_title("cost against size of a settled scene (dt 1 ms, 20 iterations)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, f"{stem}_scaling_settled.png"), dpi=110)
    plt.close(fig)


def ratio(a, b):
    return a / b if b > 0 else math.inf


def pile_targets(case, by):
    """A pile left to settle: com against plain Bullet with sleeping, how soon
    it comes to rest and what it costs then; pile1000 also against Jolt."""
    com, none = by.get((case, "com")), by.get((case, "none_sleep"))
    if not com:
        return []
    lines = []
    if none:
        r = ratio(none["wall_ms_per_sim_s"], com["wall_ms_per_sim_s"])
        lines.append(f"| {case}: com >= 10x faster than none | {r:.1f}x | "
                     f"{'yes' if r >= 10 else 'no'} |")
    rest = float(com["at_rest_pct"])
    settle = float(com["settle_time"]) if com["settle_time"] != "" else math.inf
    lines.append(f"| {case} (com): >= 98 % of bricks at rest, settled by 5 s | {rest:.1f} % at "
                 f"rest, settled {'never' if settle == math.inf else f'at {settle:.2f} s'} | "
                 f"{'yes' if rest >= 98 and settle <= 5.0 else 'no'} |")
    cost = float(com["settled_cost_pct"])
    lines.append(f"| {case} (com): settled pile costs < 2 % of real time | {cost:.3f} % | "
                 f"{'yes' if cost < 2.0 else 'no'} |")
    if case == "pile1000":
        wall = com["wall_ms_per_sim_s"] * 10.0 / 1000.0  # for 10 s, as Jolt's
        lines.append(f"| {case} (com): wall time within Jolt's {JOLT_PILE1000_WALL_S:.0f} s at 1 ms "
                     f"(10 s simulated) | {wall:.1f} s | "
                     f"{'yes' if wall <= JOLT_PILE1000_WALL_S else 'no'} |")
        depth = float(com["penetration_mm"])
        lines.append(f"| {case} (com): penetration no worse than Jolt's "
                     f"{JOLT_PILE1000_PENETRATION_MM} mm | {depth:.2f} mm | "
                     f"{'yes' if depth <= JOLT_PILE1000_PENETRATION_MM else 'no'} |")
    return lines


def targets(rows):
    lines = ["| target | measured (same run) | met |", "|---|---|---|"]
    by = {(r["case"], r["mode"]): r for r in rows if is_default(r)}
    settled = sorted({r["case"] for r in rows if r["drift_mm"] != "" and is_default(r)})
    for case in settled:
        com = by.get((case, "com"))
        nosleep = by.get((case, "none_nosleep"))
        sleep = by.get((case, "none_sleep"))
        if not (com and nosleep and sleep):
            continue
        r1 = ratio(nosleep["wall_ms_per_sim_s"], com["wall_ms_per_sim_s"])
        r2 = ratio(sleep["wall_ms_per_sim_s"], com["wall_ms_per_sim_s"])
        drift_ok = float(com["drift_mm"]) < min(float(nosleep["drift_mm"]), float(sleep["drift_mm"]))
        lines.append(f"| {case}: com >= 20x faster than none without sleeping | {r1:.0f}x | "
                     f"{'yes' if r1 >= 20 else 'no'} |")
        lines.append(f"| {case}: com >= 5x faster than none with sleeping | {r2:.0f}x | "
                     f"{'yes' if r2 >= 5 else 'no'} |")
        lines.append(f"| {case}: at lower drift | com {float(com['drift_mm']):.4f} mm, none "
                     f"{float(nosleep['drift_mm']):.3f} / {float(sleep['drift_mm']):.3f} mm | "
                     f"{'yes' if drift_ok else 'no'} |")
    big, small = by.get(("settled2000_moving10", "com")), by.get(("moving10", "com"))
    if big and small:
        r = ratio(big["wall_ms_per_sim_s"], small["wall_ms_per_sim_s"])
        lines.append(f"| 2000 settled + 10 moving <= 1.5x the 10 alone (com) | {r:.2f}x | "
                     f"{'yes' if r <= 1.5 else 'no'} |")
    for case in sorted({r["case"] for r in rows
                        if r["case"].startswith("pile") or r["case"].startswith("freefall")}):
        com, none = by.get((case, "com")), by.get((case, "none_sleep"))
        if com and is_pile(com):
            lines.extend(pile_targets(case, by))
        elif com and none:
            r = ratio(com["wall_ms_per_sim_s"], none["wall_ms_per_sim_s"])
            lines.append(f"| {case} drop: com <= 1.10x none | {r:.2f}x | "
                         f"{'yes' if r <= 1.10 else 'no'} |")
    motions = [r for r in rows if r["motion_error_pct"] != "" and is_default(r)]
    for mode in ("com", "equilibrium"):
        closed = [r for r in motions if r["mode"] == mode and r["case"] != "domino"]
        if closed:
            worst = max(closed, key=lambda r: float(r["motion_error_pct"]))
            lines.append(f"| motions with a closed form within 2 % ({mode}) | worst "
                         f"{float(worst['motion_error_pct']):.2f} % ({worst['case']}) | "
                         f"{'yes' if float(worst['motion_error_pct']) <= 2.0 else 'no'} |")
    for case in sorted({r["case"] for r in rows}):
        points = [r for r in rows if r["case"] == case]
        column = error_column(points)
        nones = [r for r in points if r["mode"].startswith("none")]
        coms = [r for r in points if r["mode"] == "com"]
        # Motions measure accuracy: the layer has nothing to skip there.
        if not nones or not coms or column in ("penetration_mm", "motion_error_pct"):
            continue
        beaten = sum(
            1 for n in nones
            if any(error_value(c, column) <= error_value(n, column)
                   and c["wall_ms_per_sim_s"] < n["wall_ms_per_sim_s"] for c in coms))
        lines.append(f"| {case}: for each error level com is faster | com beats {beaten} of "
                     f"{len(nones)} none settings at equal or lower error | "
                     f"{'yes' if beaten == len(nones) else 'no'} |")
    return "\n".join(lines) + "\n"


def motion_table(rows):
    """Each motion at the default setting, every mode side by side."""
    motions = [r for r in rows if r["motion_error_pct"] != "" and is_default(r)]
    modes = [m for m in colours_for(motions) if any(r["mode"] == m for r in motions)]
    header = "| motion | quantity | reference | " + " | ".join(
        f"{m}: measured, error, ms per sim s" for m in modes) + " |"
    lines = [header, "|" + "---|" * (3 + len(modes))]
    for case, (quantity, scale, reference) in MOTION_QUANTITY.items():
        by_mode = {r["mode"]: r for r in motions if r["case"] == case}
        if not by_mode:
            continue
        expected = next(iter(by_mode.values()))["motion_expected"]
        cells = [case, quantity, f"{reference}: {float(expected) * scale:.4g}"]
        for m in modes:
            r = by_mode.get(m)
            if r is None or r["motion_measured"] == "":
                cells.append("-")
                continue
            cells.append(f"{float(r['motion_measured']) * scale:.4g}, "
                         f"{float(r['motion_error_pct']):.2f} %, {r['wall_ms_per_sim_s']:.3g}")
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n" if len(lines) > 2 else ""


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    rows = load(sys.argv[1])
    out_dir = sys.argv[2]
    os.makedirs(out_dir, exist_ok=True)
    stem = os.path.splitext(os.path.basename(sys.argv[1]))[0]
    for case in sorted({r["case"] for r in rows}):
        points = [r for r in rows if r["case"] == case]
        plot_pareto(case, points, out_dir, stem)
        if all(is_pile(r) for r in points):
            plot_pareto(case, points, out_dir, stem, "settle_time", "_settle")
    plot_scaling(rows, out_dir, stem)
    table = targets(rows)
    with open(os.path.join(out_dir, f"{stem}_targets.md"), "w") as f:
        f.write(table)
    print(table)
    motions = motion_table(rows)
    if motions:
        with open(os.path.join(out_dir, f"{stem}_motion.md"), "w") as f:
            f.write(motions)
        print(motions)


if __name__ == "__main__":
    main()
