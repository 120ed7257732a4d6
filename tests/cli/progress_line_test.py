#!/usr/bin/env python3
"""The progress line on long runs (issue 14, tools/ncoffset/progress_line.hpp): where stderr is a
terminal, a run longer than a second shows `ncoffset: FILE:LINE: N M segments, T s` rewritten in
place (\\r, erase to end of line) and erases it before an alarm line and at the end; where stderr
is not a terminal, nothing but the alarm is written."""
import os, pty, subprocess, sys, tempfile

binary = os.path.abspath(sys.argv[1])
d = tempfile.mkdtemp(prefix="ncoffset-progress-")
fails = []


def check(name, cond, detail=""):
    print(("ok   " if cond else "FAIL ") + name + ("" if cond else f"  [{detail!r}]"))
    if not cond:
        fails.append(name)


# About 6 M segments (a few seconds), then alarm 14080 (jump target missing) at line 9.
prog = os.path.join(d, "LONG.MPF")
with open(prog, "w") as f:
    f.write("R1=0\nWHILE R1<3000000\nG1 X10 Y0 F1000\nG1 X0 Y0\nR1=R1+1\nENDWHILE\n"
            "G0 X5\nR2=1\nGOTOF NOWHERE\nM30\n")


def run_with_terminal_stderr():
    master, slave = pty.openpty()
    p = subprocess.Popen([binary, "-o", os.devnull, "LONG.MPF"], cwd=d, stderr=slave,
                         stdout=subprocess.DEVNULL)
    os.close(slave)
    out = b""
    while True:
        try:
            chunk = os.read(master, 65536)
        except OSError:  # EIO: the child closed the terminal
            break
        if not chunk:
            break
        out += chunk
    p.wait(timeout=120)
    os.close(master)
    return p.returncode, out


status, err = run_with_terminal_stderr()
check("terminal: exit 2 (the alarm)", status == 2, status)
check("terminal: a progress line", b"\r\x1b[Kncoffset: LONG.MPF:" in err and b"M segments" in err, err[:300])
alarm_at = err.find(b"LONG.MPF:9: alarm 14080")  # the file as named on the command line
check("terminal: the alarm line", alarm_at > 0, err[-300:])
check("terminal: the line is erased before the alarm", err[:alarm_at].endswith(b"\r\x1b[K"), err[max(0, alarm_at - 80):alarm_at + 40])

p = subprocess.run([binary, "-o", os.devnull, "LONG.MPF"], cwd=d, capture_output=True, timeout=120)
check("pipe: exit 2", p.returncode == 2, p.returncode)
check("pipe: no progress line", b"segments" not in p.stderr and b"\r" not in p.stderr, p.stderr[:300])

print("all progress checks hold" if not fails else f"{len(fails)} progress checks fail")
sys.exit(1 if fails else 0)
