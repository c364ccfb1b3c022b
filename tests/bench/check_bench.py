#!/usr/bin/env python3
"""Whole-process runs of `rapid check` side by side: wall time, CPU time
and peak memory of several binaries on the same inputs, alternating.

    python3 tests/bench/check_bench.py [--runs 7] [--floor PARSE_COST] \
        NAME=BINARY... -- DIR...

Each DIR is checked by each binary (`rapid check DIR --format concise
--exit-zero`, output thrown away) `--runs` times, the binaries taking turns
within each round so that load changes hit all of them alike. With
`--floor`, the `parse_cost` example (`cargo build --release -p rapid-tests
--example parse_cost`) runs in the same rounds as `floor`: reading and a
raw single-thread tree-sitter parse of the same modules. Prints a Markdown
table: per DIR and binary the median wall time, median CPU time (user +
system), median peak resident memory, each binary's ratio to the first
binary and to the floor, and the modules' bytes with the peak memory as a
multiple of them.
"""

import argparse
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

MODULE_EXT = {".mod", ".modx", ".sys", ".sysx", ".prg"}


def code_bytes(folder):
    total = 0
    for root, _, files in os.walk(folder):
        for f in files:
            if os.path.splitext(f)[1].lower() in MODULE_EXT:
                total += os.path.getsize(os.path.join(root, f))
    return total


def run_once(cmd):
    """Wall seconds, CPU seconds and peak RSS (bytes) of one run."""
    start = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - start
    if os.waitstatus_to_exitcode(status) not in (0, 1):
        sys.exit(f"{' '.join(cmd)} failed with {status}")
    return wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss * 1024


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=7)
    ap.add_argument("--floor", help="the parse_cost example binary")
    ap.add_argument("--args", default="", help="more arguments for rapid check")
    ap.add_argument("items", nargs="+", help="NAME=BINARY... -- DIR...")
    args = ap.parse_args()
    if "--" in args.items:
        split = args.items.index("--")
        bins, dirs = args.items[:split], args.items[split + 1:]
    else:
        bins = [i for i in args.items if "=" in i]
        dirs = [i for i in args.items if "=" not in i]
    binaries = [tuple(b.split("=", 1)) for b in bins]
    extra = args.args.split()
    print(f"load average at start: {os.getloadavg()[0]:.1f}", file=sys.stderr)
    rows = []
    for d in dirs:
        cmds = [(name, [path, "check", d, "--format", "concise", "--exit-zero", *extra])
                for name, path in binaries]
        if args.floor:
            cmds.append(("floor", [args.floor, "raw", d]))
        results = {name: [] for name, _ in cmds}
        for r in range(args.runs):
            for name, cmd in cmds:
                results[name].append(run_once(cmd))
            print(f"{d}: round {r + 1}/{args.runs}", file=sys.stderr)
        size = code_bytes(d)
        med = {name: [statistics.median(x[i] for x in res) for i in range(3)]
               for name, res in results.items()}
        first = binaries[0][0]
        for name, _ in cmds:
            wall, cpu, rss = med[name]
            rows.append((Path(d).name, name, wall, cpu, rss, size,
                         wall / med[first][0], wall / med["floor"][0] if args.floor else None))
    print(f"load average at end: {os.getloadavg()[0]:.1f}", file=sys.stderr)
    print("| input | binary | wall (median) | CPU | peak RSS | RSS / code | wall vs "
          f"{binaries[0][0]} | wall vs floor |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- |")
    for d, name, wall, cpu, rss, size, ratio, floor in rows:
        fl = f"{floor:.2f}x" if floor is not None else ""
        print(f"| {d} ({size / 1e6:.1f} MB) | {name} | {wall:.3f} s | {cpu:.3f} s | "
              f"{rss / 1e6:.0f} MB | {rss / size:.1f}x | {ratio:.2f}x | {fl} |")


if __name__ == "__main__":
    main()
