#!/usr/bin/env python3
"""ncoffset against LinuxCNC's rs274 on the G41/G42 contour of issue 22 (docs/performance.md §24).

  compare_rs274.py --ncoffset build/ncoffset [--rs274 PATH/bin/rs274] [--blocks 100000]
                   [--runs 5] [--instructions] [--variants integral,decimals] [--arcs cr|ij]

For each variant (integral coordinates, decimals in every coordinate) it writes the program in
both dialects (bench/trc_contour.py: TRC.MPF with TOOLS.INI, trc.ngc with tool.tbl), then runs

  ncoffset -q -o out.csv TRC.MPF --init TOOLS.INI
  HOME=TMP rs274 -g -t tool.tbl -v params.var trc.ngc out.txt

alternately (A, B, A, B, ...) RUNS times each, both writing their path to a file, and prints
the median wall time, the median CPU time (user + sys), blocks per second (blocks / median wall)
and the ratio. With --instructions each runs once more under `valgrind --tool=callgrind` (the
whole process: start-up, reading the files, writing the output) and the instructions per block
and their ratio are printed. Both must make the same number of moves: the CSV rows of ncoffset
and rs274's STRAIGHT_TRAVERSE / STRAIGHT_FEED / ARC_FEED calls are counted and compared with
the number the generator wrote; a difference fails the run (exit 1).

Without --rs274 only ncoffset runs (the smoke mode of ctest `bench_compare_rs274`);
`--rs274 setup` installs it with tests/differential/setup_rs274.sh (exit 77 where it cannot be
had: ctest `bench_compare_rs274_peer` is then skipped). rs274 is found in its unpacked package
(`dpkg -x linuxcnc-uspace_*.deb DIR`: DIR/usr/bin/rs274, its libraries in DIR/usr/lib) or in
the cache of setup_rs274.sh (bin/ and lib/): LD_LIBRARY_PATH is the `lib` directory beside the
binary's directory unless --rs274-lib is given. Nothing of LinuxCNC is part of ncoffset.
"""
import argparse
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import trc_contour  # noqa: E402  (bench/trc_contour.py, beside this script)

# Issue 22's targets against rs274 on this contour.
TARGET_INSTRUCTION_RATIO = 25.0
TARGET_INSTRUCTIONS_PER_BLOCK = 1200
TARGET_SPEED_RATIO = 25.0
SKIP = 77  # ctest's SKIP_RETURN_CODE
MOVE_RE = re.compile(rb"STRAIGHT_TRAVERSE\(|STRAIGHT_FEED\(|ARC_FEED\(")


class Tool:
    """One interpreter: how to run it on a program and how to count the moves it wrote."""

    def __init__(self, name, argv, output, env=None, count=None):
        self.name, self.argv, self.output, self.env, self.count = name, argv, output, env, count
        self.walls, self.cpus = [], []
        self.instructions = None

    def run(self, prefix=()):
        """Runs once; returns (wall s, CPU s, stderr text). Raises on a non-zero exit."""
        err_path = self.output + ".stderr"
        with open(err_path, "wb") as err:
            t0 = time.perf_counter()
            p = subprocess.Popen(list(prefix) + self.argv, stdin=subprocess.DEVNULL,
                                 stdout=subprocess.DEVNULL, stderr=err, env=self.env)
            _, status, usage = os.wait4(p.pid, 0)
            wall = time.perf_counter() - t0
        p.returncode = os.waitstatus_to_exitcode(status)
        text = open(err_path, encoding="utf-8", errors="replace").read()
        if p.returncode != 0:
            raise SystemExit(f"{self.name} failed (exit {p.returncode}): {' '.join(self.argv)}\n"
                             f"{text[-2000:]}")
        return wall, usage.ru_utime + usage.ru_stime, text

    def timed(self):
        wall, cpu, _ = self.run()
        self.walls.append(wall)
        self.cpus.append(cpu)

    def callgrind(self, workdir):
        out = os.path.join(workdir, f"callgrind.{self.name}.out")
        _, _, text = self.run(("valgrind", "--tool=callgrind", f"--callgrind-out-file={out}"))
        m = re.search(r"Collected : (\d+)", text)
        if not m:
            raise SystemExit(f"no callgrind total for {self.name}:\n{text[-2000:]}")
        self.instructions = int(m.group(1))


def count_csv_rows(path):
    with open(path, "rb") as f:
        return sum(1 for _ in f) - 1  # the header


def count_rs274_moves(path):
    with open(path, "rb") as f:
        return sum(1 for line in f if MOVE_RE.search(line))


def make_tools(args, progs, workdir):
    tools = [Tool("ncoffset", [args.ncoffset, "-q", "-o", os.path.join(workdir, "out.csv"),
                               progs["mpf"], "--init", progs["init"]],
                  os.path.join(workdir, "out.csv"), count=count_csv_rows)]
    if args.rs274:
        home = os.path.join(workdir, "rs274-home")  # rs274 truncates $HOME/.tool.mmap
        os.makedirs(home, exist_ok=True)
        lib = args.rs274_lib or os.path.join(os.path.dirname(os.path.dirname(
            os.path.abspath(args.rs274))), "lib")
        env = dict(os.environ, HOME=home, LD_LIBRARY_PATH=lib)
        out = os.path.join(workdir, "out.txt")
        tools.append(Tool("rs274", [args.rs274, "-g", "-t", progs["tbl"], "-v",
                                    os.path.join(home, "params.var"), progs["ngc"], out],
                          out, env=env, count=count_rs274_moves))
    return tools


def fmt_int(n):
    return f"{n:,}"


def report_variant(label, progs, tools, args):
    """Prints the variant's table; returns False when a move count differs."""
    blocks = progs["blocks"]
    print(f"\n{label}: {fmt_int(blocks)} blocks ({fmt_int(progs['laps'])} laps of "
          f"{trc_contour.BLOCKS_PER_LAP}, G41/G42 alternating, arcs {args.arcs.upper()}), "
          f"{fmt_int(progs['moves'])} moves written")
    ok = True
    counts = []
    for t in tools:
        n = t.count(t.output)
        counts.append(f"{t.name} {fmt_int(n)}")
        ok = ok and n == progs["moves"]
    print("  moves made: " + ", ".join(counts) +
          (" -- the same number of moves" if ok else " -- MOVE COUNTS DIFFER"))
    print(f"  {len(tools[0].walls)} runs (alternated)  wall median (min)     CPU median   "
          "blocks/s (median wall)")
    for t in tools:
        wall, cpu = statistics.median(t.walls), statistics.median(t.cpus)
        print(f"  {t.name:<22} {wall:8.3f} s ({min(t.walls):.3f})  {cpu:8.3f} s   "
              f"{blocks / wall / 1e6:8.3f} M")
    if len(tools) == 2:
        nco, rs = tools
        speed = statistics.median(rs.walls) / statistics.median(nco.walls)
        cpu = statistics.median(rs.cpus) / statistics.median(nco.cpus)
        verdict = "met" if speed >= TARGET_SPEED_RATIO else "not met"
        print(f"  ratio rs274 / ncoffset: wall {speed:.1f}x, CPU {cpu:.1f}x "
              f"(target >= {TARGET_SPEED_RATIO:.0f}x blocks/s: {verdict})")
    if tools[0].instructions is not None:
        print("  instructions (callgrind, whole process):")
        for t in tools:
            print(f"  {t.name:<22} {fmt_int(t.instructions):>16}  "
                  f"{t.instructions / blocks:10,.0f} per block")
        per_block = tools[0].instructions / blocks
        verdict = "met" if per_block <= TARGET_INSTRUCTIONS_PER_BLOCK else "not met"
        print(f"  target <= {TARGET_INSTRUCTIONS_PER_BLOCK:,} per block: {verdict}")
        if len(tools) == 2:
            ratio = tools[1].instructions / tools[0].instructions
            verdict = "met" if ratio >= TARGET_INSTRUCTION_RATIO else "not met"
            print(f"  ratio rs274 / ncoffset: {ratio:.1f}x "
                  f"(target >= {TARGET_INSTRUCTION_RATIO:.0f}x fewer instructions: {verdict})")
    return ok


def run_variant(args, label, decimals, workdir):
    progs = trc_contour.write(workdir, args.blocks, decimals, args.arcs)
    tools = make_tools(args, progs, workdir)
    for t in tools:  # one untimed run each: page cache warm, output files exist
        t.run()
    for _ in range(args.runs):
        for t in tools:
            t.timed()
    if args.instructions:
        for t in tools:
            t.callgrind(workdir)
    return report_variant(label, progs, tools, args)


def setup_rs274():
    """The binary installed by tests/differential/setup_rs274.sh, or None (cannot be had)."""
    here = os.path.dirname(os.path.abspath(__file__))
    sys.path.insert(0, os.path.join(here, os.pardir, "tests", "differential"))
    from differential import find_rs274  # the differential tests' installer call

    return find_rs274(argparse.Namespace(rs274=None, rs274_cache=None))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--ncoffset", required=True, help="the ncoffset binary")
    ap.add_argument("--rs274", help="LinuxCNC's rs274 binary, or 'setup' (setup_rs274.sh); "
                                    "without it only ncoffset runs")
    ap.add_argument("--rs274-lib", help="its LD_LIBRARY_PATH (default: ../lib beside its bin/)")
    ap.add_argument("--blocks", type=int, default=100000, help="about this many blocks (100000)")
    ap.add_argument("--runs", type=int, default=5, help="timed runs of each, alternated (5)")
    ap.add_argument("--instructions", action="store_true",
                    help="also run each once under valgrind --tool=callgrind")
    ap.add_argument("--variants", default="integral,decimals",
                    help="integral, decimals or both (default: both)")
    ap.add_argument("--arcs", choices=("cr", "ij"), default="cr",
                    help="arcs by radius (CR= / R) or by centre (I J), default cr")
    ap.add_argument("--keep", help="write the programs and outputs here and keep them")
    args = ap.parse_args()
    if args.runs < 1 or args.blocks < 1:
        ap.error("--runs and --blocks must be at least 1")
    args.ncoffset = os.path.abspath(args.ncoffset)
    if args.rs274 == "setup":
        args.rs274 = setup_rs274()
        if args.rs274 is None:
            print("compare_rs274: SKIP: LinuxCNC's rs274 is not available")
            return SKIP
    if args.instructions and not shutil.which("valgrind"):
        ap.error("--instructions needs valgrind on PATH")
    variants = [v.strip() for v in args.variants.split(",") if v.strip()]
    if not variants or any(v not in ("integral", "decimals") for v in variants):
        ap.error("--variants: integral, decimals or both")
    base = args.keep or tempfile.mkdtemp(prefix="ncoffset-compare-")
    print(f"ncoffset: {args.ncoffset}\nrs274:    {args.rs274 or '(not given: ncoffset only)'}")
    # Wall times on a loaded machine mostly measure the queue: say how loaded it was.
    print("load average: %.2f %.2f %.2f (%d CPUs)" % (*os.getloadavg(), os.cpu_count() or 0))
    ok = True
    try:
        for v in variants:
            label = ("TRC contour, integral coordinates" if v == "integral"
                     else "TRC contour, decimals in every coordinate")
            ok = run_variant(args, label, v == "decimals", os.path.join(base, v)) and ok
    finally:
        if not args.keep:
            shutil.rmtree(base, ignore_errors=True)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
