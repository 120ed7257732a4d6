#!/usr/bin/env python3
"""Only regular files are read (issue 14, finding 4): a FIFO, a device or a directory as the
program or an init file is a file error (exit 1) and a FIFO as a subprogram is alarm 14011,
all without blocking. Every run has a timeout, so a hang fails the test instead of stalling it."""
import os, subprocess, sys, tempfile

binary = os.path.abspath(sys.argv[1])
d = tempfile.mkdtemp(prefix="ncoffset-inputs-")
fails = []


def check(name, cond, detail=""):
    print(("ok   " if cond else "FAIL ") + name + ("" if cond else f"  [{detail}]"))
    if not cond:
        fails.append(name)


def run(*args):
    try:
        return subprocess.run([binary, *args], cwd=d, capture_output=True, text=True, timeout=2)
    except subprocess.TimeoutExpired:
        return None


os.mkfifo(os.path.join(d, "FIFO.MPF"))
os.mkfifo(os.path.join(d, "PIPESUB.SPF"))
os.mkdir(os.path.join(d, "DIR.MPF"))
with open(os.path.join(d, "CALL.MPF"), "w") as f:
    f.write("G90 G1 X1 F100\nPIPESUB\nM30\n")
with open(os.path.join(d, "OK.MPF"), "w") as f:
    f.write("G90 G1 X1 F100\nM30\n")

for what, args, reason in [
        ("FIFO as the program", ["FIFO.MPF"], "FIFO"),
        ("FIFO as an init file", ["--init", "FIFO.MPF", "OK.MPF"], "FIFO"),
        ("device as the program", ["/dev/zero"], "device"),
        ("directory as the program", ["DIR.MPF"], "directory")]:
    p = run(*args)
    check(f"{what}: finishes", p is not None)
    if p is not None:
        check(f"{what}: exit 1", p.returncode == 1, p.returncode)
        check(f"{what}: says why", "cannot read" in p.stderr and reason in p.stderr, p.stderr)

p = run("CALL.MPF")
check("FIFO as a subprogram: finishes", p is not None)
if p is not None:
    check("FIFO as a subprogram: exit 2", p.returncode == 2, p.returncode)
    check("FIFO as a subprogram: alarm 14011", "CALL.MPF:2: alarm 14011:" in p.stderr, p.stderr)
    check("FIFO as a subprogram: the row before it", p.stdout.count("\n") == 2, p.stdout)

print("all input checks hold" if not fails else f"{len(fails)} input checks fail")
sys.exit(1 if fails else 0)
