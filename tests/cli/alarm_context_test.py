#!/usr/bin/env python3
"""Under an alarm the CLI shows the offending source line and a caret under the column of the
statement (or the block's first word for an alarm of the block as a whole), the way compilers
do; the first line stays `FILE:LINE: alarm NUMBER: TEXT` and JSON Lines carry `column`."""
import json, os, subprocess, sys, tempfile

binary = os.path.abspath(sys.argv[1])
d = tempfile.mkdtemp(prefix="ncoffset-context-")
fails = []


def check(name, cond, detail=""):
    print(("ok   " if cond else "FAIL ") + name + ("" if cond else f"  [{detail!r}]"))
    if not cond:
        fails.append(name)


def run(name, text, *args):
    with open(os.path.join(d, name), "w") as f:
        f.write(text)
    return subprocess.run([binary, *args, name], cwd=d, capture_output=True, text=True, timeout=20)


# An address that is not modelled, the fourth word of line 2: column 13.
p = run("Q.MPF", "G1 X10 F100\nG1 X10 F100 Q5\nM30\n")
lines = p.stderr.splitlines()
check("exit 2", p.returncode == 2, p.returncode)
check("first line unchanged", lines[0].startswith("Q.MPF:2: alarm 99010: address Q"), lines)
check("source line", len(lines) > 1 and lines[1] == " 2 | G1 X10 F100 Q5", lines)
check("caret under Q", len(lines) > 2 and lines[2] == "   |             ^", lines)

# An alarm of the block as a whole (circle end point) points at its first word.
p = run("C.MPF", "G1 X10 F100\nN20 G2 X20 Y5 CR=2\n")
lines = p.stderr.splitlines()
check("circle: caret under the first word", len(lines) > 2 and lines[2] == "   |     ^", lines)

# A structure error found when the file is loaded names its own line, without a caret.
p = run("S.MPF", "G1 X1 F1\nIF 1\nG1 X2\n")
lines = p.stderr.splitlines()
check("structure: the IF line", len(lines) == 2 and lines[1] == " 2 | IF 1", lines)

# JSON Lines: the alarm record has the column.
p = run("J.MPF", "G1 X10 F100\nG1 X10 F100 Q5\n", "--format", "jsonl")
records = [json.loads(l) for l in p.stdout.splitlines() if l.startswith("{")]
alarm = [r for r in records if "alarm" in r]
check("jsonl: column", alarm and alarm[0].get("column") == 13 and alarm[0].get("line") == 2, alarm)

print(f"{len(fails)} failed" if fails else "all passed")
sys.exit(1 if fails else 0)
