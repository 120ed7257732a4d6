#!/usr/bin/env python3
"""The CLI's two sink paths give the same output (tools/ncoffset/message_sinks.hpp,
docs/performance.md §28): where stderr is not a terminal (or with -q) each segment goes straight
to the writer, which prints MSG texts and warnings itself; where stderr is a terminal a
ProgressForwarder counts the segments for the progress line and passes everything on. For every
format, a program with MSG texts, warnings 10763, events and an alarm at the end is run both ways;
the output files and the stderr lines must be the same byte for byte (the run is shorter than the
second after which a progress line shows)."""
import os, subprocess, sys, tempfile

import terminal_stderr

binary = os.path.abspath(sys.argv[1])
d = tempfile.mkdtemp(prefix="ncoffset-sinks-")
fails = []


def check(name, cond, detail=""):
    print(("ok   " if cond else "FAIL ") + name + ("" if cond else f"  [{detail!r}]"))
    if not cond:
        fails.append(name)


# A G41 CDON contour with a bottleneck (two blocks omitted: warnings 10763 at lines 13 and 14),
# MSG texts before, inside and after it, tool, M, dwell, spindle and feed events, and alarm 14080
# (jump target missing) at the end.
PROGRAM = """$TC_DP1[1,1]=120
$TC_DP6[1,1]=5
T1 D1 M6
S1000 M3
MSG("start of the contour")
$MC_CUTCOM_MAXNUM_CHECK_BLOCKS=3
G17 G90 G0 X-10 Y10 Z0
G41 CDON G1 X0 Y0 F100
N10 X40
MSG("in the contour")
N20 Y-4
N30 X44
N40 Y20
G4 F0.5
N50 G40 X30 Y30 F200
MSG("after the contour")
G2 X50 Y30 CR=10
GOTOF NOWHERE
M30
"""
with open(os.path.join(d, "SINKS.MPF"), "w") as f:
    f.write(PROGRAM)


def run(fmt, extra, terminal):
    out = os.path.join(d, f"out_{fmt}_{len(extra)}_{int(terminal)}")
    args = [binary, "--format", fmt, *extra, "-o", out, "SINKS.MPF"]
    if terminal:  # stderr a terminal: the progress line's path
        status, err = terminal_stderr.run_with_terminal_stderr(args, d, timeout=60)
        err = err.replace(b"\r\n", b"\n")  # the terminal's line discipline
    else:
        r = subprocess.run(args, cwd=d, stderr=subprocess.PIPE, stdout=subprocess.DEVNULL,
                           timeout=60)
        status, err = r.returncode, r.stderr
    with open(out, "rb") as f:
        return status, err, f.read()


for fmt, extra in [("csv", []), ("csv", ["--decimals", "3"]), ("jsonl", []), ("svg", []),
                   ("html", []), ("mpf", [])]:
    name = " ".join([fmt, *extra])
    direct = run(fmt, extra, False)
    forwarded = run(fmt, extra, True)
    quiet = run(fmt, extra + ["-q"], True)
    check(f"{name}: exit 2 (the alarm)", direct[0] == 2, direct[0])
    check(f"{name}: the messages and warnings on stderr",
          direct[1].count(b": message: ") == 3 and direct[1].count(b": warning 10763: ") == 2
          and b"alarm 14080" in direct[1], direct[1])
    check(f"{name}: stderr the same on both paths", direct[1] == forwarded[1] == quiet[1],
          (direct[1], forwarded[1]))
    check(f"{name}: the output the same on both paths", direct[2] == forwarded[2] == quiet[2])
    check(f"{name}: an output was written", len(direct[2]) > 0)

sys.exit(1 if fails else 0)
