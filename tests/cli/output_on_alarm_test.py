#!/usr/bin/env python3
"""Output never lies (issue Robustness 4): when a run ends in an alarm, the CSV and JSON Lines
written so far hold every segment before the alarm, whole lines only, the JSON Lines end with
the alarm record, and the exit status is 2. Uses enough segments to pass the write buffer."""
import json, os, subprocess, sys, tempfile

binary = sys.argv[1]
d = tempfile.mkdtemp(prefix="ncoffset-alarm-")
segments = 20000
prog = os.path.join(d, "P.MPF")
with open(prog, "w") as f:
    f.write("G17 G90 G1 F100\n")
    for i in range(segments):
        f.write(f"X{(i % 97) + 1} Y{i % 13}\n")
    f.write("R1=1/0\nM30\n")
alarm_line = segments + 2
fails = []

def check(name, cond, detail=""):
    print(("ok   " if cond else "FAIL ") + name + ("" if cond else f"  [{detail}]"))
    if not cond:
        fails.append(name)

for fmt in ("csv", "jsonl"):
    out = os.path.join(d, "out." + fmt)
    p = subprocess.run([binary, "--format", fmt, "-o", out, prog], capture_output=True, text=True)
    check(f"{fmt}: exit status 2", p.returncode == 2, p.returncode)
    check(f"{fmt}: alarm line on stderr", f"P.MPF:{alarm_line}: alarm 14051:" in p.stderr, p.stderr)
    data = open(out).read()
    check(f"{fmt}: ends with a whole line", data.endswith("\n"), data[-40:])
    lines = data.splitlines()
    if fmt == "csv":
        check("csv: header and every segment", len(lines) == segments + 1, len(lines))
        check("csv: last row is the last block", lines[-1].startswith(f"{segments + 1},G1,"), lines[-1])
    else:
        # Event records (a "type" field: here the feed of line 1) are not segments.
        recs = [r for r in (json.loads(l) for l in lines) if "type" not in r]
        check("jsonl: every segment and the alarm", len(recs) == segments + 1, len(recs))
        last = recs[-1]
        check("jsonl: alarm record last", last.get("alarm") == 14051 and last.get("line") == alarm_line, last)
        check("jsonl: segments before it", all("motion" in r for r in recs[:-1]))

print("all output checks hold" if not fails else f"{len(fails)} output checks fail")
sys.exit(1 if fails else 0)
