#!/usr/bin/env python3
"""JSON Lines event records (docs/architecture.md "Events"): each with a "type", in order with the
segments; CSV without them. Expected values by hand from the program:
  T1 D1 M6 (TOOLS: length 100 along Z, radius 4): tool events T, M6, D with radius 4, length
  [0,0,100]; S1200 M3 M8: m 3, m 8, then spindle 1200 (S is decided once the block's words are
  known: speed, not a G4 revolution count); G4 F2: dwell 2 s; G1 X10 F300: feed 300 before its
  segment; M0 after the segment of X20 on the same line; M5 before the last segment; M30: none."""
import json, os, subprocess, sys, tempfile

binary = sys.argv[1]
d = tempfile.mkdtemp(prefix="ncoffset-events-")
open(os.path.join(d, "TOOLS.INI"), "w").write("$TC_DP1[1,1]=120\n$TC_DP3[1,1]=100\n$TC_DP6[1,1]=4\nM17\n")
prog = os.path.join(d, "E.MPF")
open(prog, "w").write("T1 D1 M6\nS1200 M3 M8\nG4 F2\nG1 X10 F300\nX20 M0\nM5 X30\nM30\n")
fails = []


def check(name, cond, detail=""):
    print(("ok   " if cond else "FAIL ") + name + ("" if cond else f"  [{detail}]"))
    if not cond:
        fails.append(name)


p = subprocess.run([binary, "--init", os.path.join(d, "TOOLS.INI"), "--coords", "wcs", "--format",
                    "jsonl", prog], capture_output=True, text=True)
check("exit 0", p.returncode == 0, p.stderr)
recs = [json.loads(l) for l in p.stdout.splitlines()]
kinds = [r.get("type", "seg") for r in recs]
check("order", kinds == ["tool", "tool", "tool", "m", "m", "spindle", "dwell", "feed", "seg", "seg",
                         "m", "m", "seg"], kinds)
t = recs[0]
check("tool T", t["word"] == "T" and t["tool"] == 1 and t["edge"] == 1 and t["radius"] == 4
      and t["length"] == [0, 0, 100] and t["line"] == 1 and t["file"].endswith("E.MPF"), t)
check("M6 then D", recs[1]["word"] == "M6" and recs[2]["word"] == "D", recs[1:3])
check("M3 M8", [recs[3]["number"], recs[4]["number"]] == [3, 8], recs[3:5])
check("spindle", recs[5]["speed"] == 1200 and recs[5]["spindle"] == 0, recs[5])
check("dwell", recs[6]["seconds"] == 2 and recs[6]["revolutions"] == 0, recs[6])
check("feed", recs[7]["feed"] == 300 and recs[7]["line"] == 4, recs[7])
check("M0 after X20", recs[10]["number"] == 0 and recs[9]["x"] == 20, recs[9:11])
check("M5 before X30", recs[11]["number"] == 5 and recs[12]["x"] == 30, recs[11:13])
c = subprocess.run([binary, "--init", os.path.join(d, "TOOLS.INI"), prog], capture_output=True,
                   text=True)
check("csv: header and the three segments only", len(c.stdout.splitlines()) == 4, c.stdout)

# Frame events: G54 (from $P_UIFR[1]: X100 Y50) and TRANS Z-10 change the frame, G54 again with
# the same values and a SUPA block do not. By hand: the frame record of line 2 has offset
# [100,50,0] and the unit matrix; the one of line 4 offset [100,50,-10]; each comes before its
# block's segment (G1 F100 adds its feed event).
open(os.path.join(d, "FR.INI"), "w").write("$P_UIFR[1,X,TR]=100\n$P_UIFR[1,Y,TR]=50\nM17\n")
fr = os.path.join(d, "FR.MPF")
open(fr, "w").write("G0 X0 Y0 Z20\nG54 G0 X10\nG54\nTRANS Z-10\nG1 Z0 F100\nG0 SUPA Z5\nM30\n")
p = subprocess.run([binary, "--init", os.path.join(d, "FR.INI"), "--format", "jsonl", fr],
                   capture_output=True, text=True)
recs = [json.loads(l) for l in p.stdout.splitlines()]
kinds = [r.get("type", "seg") for r in recs]
check("frame: exit 0, records in order", p.returncode == 0 and
      kinds == ["seg", "frame", "seg", "frame", "feed", "seg", "seg"], (p.stderr, kinds))
if len(recs) == 7:
    f1, f2 = recs[1], recs[3]
    unit = [[1, 0, 0], [0, 1, 0], [0, 0, 1]]
    check("frame G54", f1["line"] == 2 and f1["offset"] == [100, 50, 0] and f1["linear"] == unit, f1)
    check("frame TRANS", f2["line"] == 4 and f2["offset"] == [100, 50, -10] and f2["linear"] == unit,
          f2)
sys.exit(1 if fails else 0)
