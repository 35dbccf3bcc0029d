#!/usr/bin/env python3
"""The best static setting of SINS's schema parameters on a tuning sequence (docs/sins.md).

Writes an `amp bench` experiment with one `static` row per setting of the grid obstacle_gain
{0, 0.25, 0.5, 1} x goal_gain {0.25, 0.5, 1} x noise_gain {0.5, 0.75, 1} x noise_persistence
{2, 5, 10, 20} (144 settings), runs it on one sequence of a tuning seed that no report uses, and
prints the settings by solved share (ties: fewer steps). Any extra arguments after `--` become
params of every row (e.g. `-- min_radius=0.5 max_radius=2 step_limit=1000` with the classic arena).

Usage: scripts/sins-static-grid.py [--amp build/bin/amp] [--arena problems/sins-arena.yaml]
                                   [--seed 99] [--worlds 200] [--top 10] --out DIR [-- name=value ...]
"""
import argparse
import csv
import itertools
import os
import subprocess
import sys

GRID = {
    "obstacle_gain": [0, 0.25, 0.5, 1],
    "goal_gain": [0.25, 0.5, 1],
    "noise_gain": [0.5, 0.75, 1],
    "noise_persistence": [2, 5, 10, 20],
}


def main():
    argv = sys.argv[1:]
    extra = argv[argv.index("--") + 1:] if "--" in argv else []
    argv = argv[: argv.index("--")] if "--" in argv else argv
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--amp", default="build/bin/amp")
    ap.add_argument("--arena", default="problems/sins-arena.yaml")
    ap.add_argument("--seed", type=int, default=99)
    ap.add_argument("--worlds", type=int, default=200)
    ap.add_argument("--clutter", type=float, default=0.25)
    ap.add_argument("--top", type=int, default=10)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--out", required=True)
    a = ap.parse_args(argv)
    params = {}
    for item in extra:
        name, sep, value = item.partition("=")
        if not sep:
            sys.exit(f"sins-static-grid: expected name=value after --, got '{item}'")
        params[name] = value
    if os.path.exists(a.out):
        sys.exit(f"sins-static-grid: '{a.out}' exists; choose a new folder")
    os.makedirs(a.out)
    rows = []
    for values in itertools.product(*GRID.values()):
        setting = dict(zip(GRID.keys(), values))
        name = "o{}-g{}-n{}-p{}".format(*values)
        row = {"worlds": a.worlds, "clutter": a.clutter, **setting, **params}
        body = ", ".join(f"{k}: {v}" for k, v in row.items())
        rows.append(f"  - {{name: {name}, planner: static, params: {{{body}}}}}")
    experiment = os.path.join(a.out, "grid.yaml")
    with open(experiment, "w") as f:
        f.write(f"name: sins-static-grid\nseed: {a.seed}\nruns: 1\ntime_limit: 600\ncommon_seeds: true\n"
                f"cost: solved_fraction\nproblems:\n  - {os.path.abspath(a.arena)}\nplanners:\n")
        f.write("\n".join(rows) + "\n")
    subprocess.run([a.amp, "bench", experiment, "-j", str(a.jobs), "--out", os.path.join(a.out, "bench")], check=True)
    results = []
    with open(os.path.join(a.out, "bench", "runs.csv")) as f:
        for r in csv.DictReader(f):
            extra_fields = dict(kv.split("=") for kv in r["extra"].split(";") if kv)
            results.append((float(extra_fields["solved_fraction"]), float(extra_fields["steps_mean"]), r["planner"]))
    results.sort(key=lambda t: (-t[0], t[1]))
    print("setting (obstacle, goal, noise gains, persistence)  solved %  steps")
    for solved, steps, name in results[: a.top]:
        print(f"{name:<52} {100 * solved:6.1f}  {steps:6.1f}")


if __name__ == "__main__":
    main()
