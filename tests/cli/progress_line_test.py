#!/usr/bin/env python3
"""The progress line on long runs (issues 14 and 21, tools/ncoffset/progress_line.hpp): where
stderr is a terminal, a run longer than a second shows `ncoffset: FILE:LINE: B M blocks (R M
blocks/s), N M segments[, P % of the file], T s` rewritten in place (\\r, erase to end of line;
the percentage in a file larger than 4 MiB) and erases it before an alarm line and at the end;
where stderr is not a terminal, or with -q, nothing but the alarm is written."""
import os, subprocess, sys, tempfile

import terminal_stderr

binary = os.path.abspath(sys.argv[1])
# Passes of the loop: enough for a run of several seconds (the line shows after one); the
# sanitizer build (about 15 times slower) passes fewer, so that each run stays well within the
# timeouts.
passes = int(sys.argv[2]) if len(sys.argv) > 2 else 3000000
d = tempfile.mkdtemp(prefix="ncoffset-progress-")
fails = []


def check(name, cond, detail=""):
    print(("ok   " if cond else "FAIL ") + name + ("" if cond else f"  [{detail!r}]"))
    if not cond:
        fails.append(name)


# About 6 M segments (a few seconds), then alarm 14080 (jump target missing) at line 9.
prog = os.path.join(d, "LONG.MPF")
with open(prog, "w") as f:
    f.write(f"R1=0\nWHILE R1<{passes}\nG1 X10 Y0 F1000\nG1 X0 Y0\nR1=R1+1\nENDWHILE\n"
            "G0 X5\nR2=1\nGOTOF NOWHERE\nM30\n")


# The loop is a long program, not an endless one: it runs more blocks than the automatic
# --max-blocks of so short a text allows (docs/limits.md), so the limit is given.
LIMIT = ["--max-blocks", "1000000000"]


def run_with_terminal_stderr(*args, program="LONG.MPF"):
    return terminal_stderr.run_with_terminal_stderr([binary, *LIMIT, *args, "-o", os.devnull,
                                                     program], d)


status, err = run_with_terminal_stderr()
check("terminal: exit 2 (the alarm)", status == 2, status)
check("terminal: a progress line", b"\r\x1b[Kncoffset: LONG.MPF:" in err and b"M segments" in err
      and b" M blocks (" in err and b" M blocks/s)" in err, err[:300])
check("terminal: no percentage for a small file", b"% of the file" not in err, err[:300])
alarm_at = err.find(b"LONG.MPF:9: alarm 14080")  # the file as named on the command line
check("terminal: the alarm line", alarm_at > 0, err[-300:])
check("terminal: the line is erased before the alarm", err[:alarm_at].endswith(b"\r\x1b[K"), err[max(0, alarm_at - 80):alarm_at + 40])

p = subprocess.run([binary, *LIMIT, "-o", os.devnull, "LONG.MPF"], cwd=d, capture_output=True, timeout=120)
check("pipe: exit 2", p.returncode == 2, p.returncode)
check("pipe: no progress line", b"segments" not in p.stderr and b"\r" not in p.stderr, p.stderr[:300])

status, err = run_with_terminal_stderr("-q")
check("-q: exit 2", status == 2, status)
check("-q: no progress line, the alarm stays", b"segments" not in err and b"\x1b[K" not in err
      and b"LONG.MPF:9: alarm 14080" in err, err[:300])

# A program larger than 4 MiB: the same loop, then 5 MiB of comment lines.
big = os.path.join(d, "BIG.MPF")
with open(big, "w") as f:
    f.write(f"R1=0\nWHILE R1<{passes}\nG1 X10 Y0 F1000\nG1 X0 Y0\nR1=R1+1\nENDWHILE\n")
    f.write(("; " + "x" * 98 + "\n") * 52000)
    f.write("M30\n")
status, err = run_with_terminal_stderr(program="BIG.MPF")
check("large file: exit 0", status == 0, status)
check("large file: how far through the file", b"% of the file" in err, err[:300])

print("all progress checks hold" if not fails else f"{len(fails)} progress checks fail")
sys.exit(1 if fails else 0)
