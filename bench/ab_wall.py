#!/usr/bin/env python3
"""Two builds of ncoffset on the same arguments, alternated, for a wall-time A/B.

Runs A and B N times each (ABBA order, so neither always follows the other) and prints the
median and the minimum wall time and the median CPU time (user + system, from getrusage of the
children) of each, and B's change against A. Two copies of one binary come out about 1.5 %
apart on the project's 2-vCPU VM (docs/performance.md §53): smaller differences are noise.

  python3 bench/ab_wall.py --runs 400 A/ncoffset B/ncoffset -- -q -o /tmp/out.csv TRC.MPF \
      --init TOOLS.INI
"""
import argparse
import resource
import statistics
import subprocess
import time


def timed_run(command):
    """Wall and CPU seconds of one run of `command`."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run(command, check=True)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime + after.ru_stime) - (before.ru_utime + before.ru_stime)
    return wall, cpu


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--runs", type=int, default=200, help="runs of each binary (200)")
    parser.add_argument("a", help="the first binary (the baseline)")
    parser.add_argument("b", help="the second binary")
    parser.add_argument("args", nargs=argparse.REMAINDER, help="-- then ncoffset's arguments")
    opts = parser.parse_args()
    args = opts.args[1:] if opts.args[:1] == ["--"] else opts.args
    times = {opts.a: [], opts.b: []}
    for i in range(opts.runs):
        order = (opts.a, opts.b) if i % 2 == 0 else (opts.b, opts.a)
        for binary in order:
            times[binary].append(timed_run([binary] + args))
    medians = {}
    for binary in (opts.a, opts.b):
        walls = [w for w, _ in times[binary]]
        cpus = [c for _, c in times[binary]]
        medians[binary] = statistics.median(walls)
        print(f"{binary}: wall median {medians[binary] * 1e3:.3f} ms, min {min(walls) * 1e3:.3f} ms,"
              f" CPU median {statistics.median(cpus) * 1e3:.3f} ms")
    change = medians[opts.b] / medians[opts.a] - 1
    print(f"B against A: {change * 100:+.1f} % wall (median of {opts.runs})")


if __name__ == "__main__":
    main()
