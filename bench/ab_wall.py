#!/usr/bin/env python3
"""Two builds of ncoffset on the same arguments, alternated, for a wall-time A/B.

Runs A and B N times each (ABBA order, so neither always follows the other) and prints the
median and the minimum wall time and the median CPU time (user + system of the run itself) of
each, and B's change against A. Each run is timed as compare_rs274.py times its runs (its Tool).
Two copies of one binary come out about 1.5 % apart on the project's 2-vCPU VM
(docs/performance.md §53): smaller differences are noise.

  python3 bench/ab_wall.py --runs 400 A/ncoffset B/ncoffset -- -q -o /tmp/out.csv TRC.MPF \
      --init TOOLS.INI
"""
import argparse
import os
import statistics
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from compare_rs274 import Tool  # noqa: E402  (bench/compare_rs274.py, beside this script)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--runs", type=int, default=200, help="runs of each binary (200)")
    parser.add_argument("a", help="the first binary (the baseline)")
    parser.add_argument("b", help="the second binary")
    parser.add_argument("args", nargs=argparse.REMAINDER, help="-- then ncoffset's arguments")
    opts = parser.parse_args()
    args = opts.args[1:] if opts.args[:1] == ["--"] else opts.args
    with tempfile.TemporaryDirectory(prefix="ab_wall.") as workdir:
        # (The output path names only the runs' stderr file: ncoffset's own output is in args.)
        a, b = (Tool(binary, [binary] + args, os.path.join(workdir, name))
                for name, binary in (("a", opts.a), ("b", opts.b)))
        for i in range(opts.runs):
            for tool in (a, b) if i % 2 == 0 else (b, a):
                tool.timed()
    for tool in (a, b):
        print(f"{tool.name}: wall median {statistics.median(tool.walls) * 1e3:.3f} ms, "
              f"min {min(tool.walls) * 1e3:.3f} ms, "
              f"CPU median {statistics.median(tool.cpus) * 1e3:.3f} ms")
    change = statistics.median(b.walls) / statistics.median(a.walls) - 1
    print(f"B against A: {change * 100:+.1f} % wall (median of {opts.runs})")


if __name__ == "__main__":
    main()
