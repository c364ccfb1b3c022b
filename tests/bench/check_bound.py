#!/usr/bin/env python3
"""A gate on the memory and time of one `rapid check` run (issue 27): fails
when the run's peak resident memory is over `--rss` times the bytes of the
modules it checks, or its CPU time over `--cpu` times that of a raw
single-thread tree-sitter parse of the same modules (the `parse_cost`
example, when `--floor` names it).

    python3 tests/bench/check_bound.py [--rss 15] [--floor PARSE_COST] \
        [--cpu 8] BINARY DIR

CI runs it on 2,000 damaged copies of corpus modules in one folder
(`tests/bench/layouts.py OUT damaged 2000`), the layout that once took
5.7 GB and 40 s. Memory and CPU time are what a run costs on any machine
within a few percent; the bounds are several times today's figures
(BENCHMARKS.md), so that only a blow-up fails: this is not a benchmark.
"""

import argparse
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from check_bench import code_bytes, run_once  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rss", type=float, default=15.0,
                    help="most peak memory, as a multiple of the modules' bytes")
    ap.add_argument("--floor", help="the parse_cost example binary")
    ap.add_argument("--cpu", type=float, default=8.0,
                    help="most CPU time, as a multiple of the floor's")
    ap.add_argument("binary")
    ap.add_argument("dir")
    args = ap.parse_args()
    size = code_bytes(args.dir)
    if size == 0:
        sys.exit(f"no modules in {args.dir}")
    wall, cpu, rss = run_once([args.binary, "check", args.dir, "--format", "concise",
                               "--exit-zero"])
    print(f"rapid check {args.dir}: {size / 1e6:.1f} MB of modules; {wall:.2f} s wall, "
          f"{cpu:.2f} s CPU, peak {rss / 1e6:.0f} MB ({rss / size:.1f}x the modules)")
    failed = []
    if rss > args.rss * size:
        failed.append(f"peak memory {rss / size:.1f}x the modules (bound {args.rss}x)")
    if args.floor:
        _, floor_cpu, _ = run_once([args.floor, "raw", args.dir])
        ratio = cpu / max(floor_cpu, 1e-3)
        print(f"raw parse: {floor_cpu:.2f} s CPU; the check {ratio:.1f}x")
        if ratio > args.cpu:
            failed.append(f"CPU time {ratio:.1f}x a raw parse (bound {args.cpu}x)")
    if failed:
        print("error: " + "; ".join(failed), file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
