#!/usr/bin/env python3
"""The compensated program (--format mpf) reproduces the path: run once to CSV and once to MPF,
run the MPF again, and the CSV end points, arc centres and feeds agree to 1e-6 (the MPF has six
decimals). A WCS case with tool radius compensation (G41, NORM approach), arcs in G17/G18/G19, a
helix with TURN= and a full circle; an MCS case with a rotated frame and a tool length; and a run
that ends in an alarm (the MPF ends with the alarm comment, M0 and M30). The header: comment
lines, then the reset block starting with G90."""
import csv, os, subprocess, sys, tempfile

binary = os.path.abspath(sys.argv[1])
d = tempfile.mkdtemp(prefix="ncoffset-mpf-")
fails = []

def check(name, cond, detail=""):
    print(("ok   " if cond else "FAIL ") + name + ("" if cond else f"  [{detail}]"))
    if not cond:
        fails.append(name)

def write(name, text):
    p = os.path.join(d, name)
    with open(p, "w") as f:
        f.write(text)
    return p

def run(*args):
    return subprocess.run([binary, *args], capture_output=True, text=True, cwd=d, timeout=60)

def rows(path):
    return list(csv.DictReader(open(path)))

def same(a, b):
    if a == "" or b == "":
        return a == b
    return abs(float(a) - float(b)) <= 1e-6

TOOL = "$TC_DP1[1,1]=120\n$TC_DP3[1,1]=100\n$TC_DP6[1,1]=4\n"
cases = {
    "wcs": TOOL + """T1 D1
G17 G90 G0 X-20 Y-20 Z5
G1 Z-1 F200
G41 G450 G1 X0 Y0
G1 X40 F300
G3 X50 Y10 CR=10
G1 Y30
G3 X40 Y40 I-10 J0
G1 X0
G1 Y0
G40 G1 X-20 Y-20
G0 Z5
G18 G1 X0 Y0 Z0
G2 Z20 X0 K10 I0 F150
G3 Z0 X0 Y5 K-10 I0 TURN=1
G19 G1 Y0 Z0
G2 Y10 Z10 J10 K0
G17 G1 X0 Y0 Z0
G2 X0 Y0 I5 J0
G3 X10 Y0 Z-3 I5 J0 TURN=2
MSG("done")
M30
""",
    "mcs": TOOL + """T1 D1
G17 G90 G0 X0 Y0 Z50
ROT Z30
G0 X10 Y0 Z5
G1 Z-2 F100
G42 G1 X20 Y0
G2 X40 Y0 I10 J0
G1 Y-20
G40 G1 X50 Y-30
ROT
G0 Z50
M30
""",
}
for coords, text in cases.items():
    prog = write(f"{coords.upper()}.MPF", text)
    a_csv, mpf, b_csv = (os.path.join(d, f"{coords}.{ext}") for ext in ("csv", "mpf", "back.csv"))
    p = run("--coords", coords, "-o", a_csv, prog)
    check(f"{coords}: original runs", p.returncode == 0, p.stderr)
    p = run("--coords", coords, "-o", mpf, prog)
    check(f"{coords}: MPF written", p.returncode == 0, p.stderr)
    text = open(mpf).read()
    head = text.split("\n")
    first_block = next(l for l in head if not l.startswith(";"))
    check(f"{coords}: header", text.startswith(f"; ncoffset compensated path (coords {coords})\n")
          and first_block.startswith("G90"), text[:80])
    check(f"{coords}: ends with M30", text.endswith("M30\n"), text[-40:])
    p = run("--coords", coords, "-o", b_csv, mpf)
    check(f"{coords}: the MPF runs", p.returncode == 0, p.stderr)
    a, b = rows(a_csv), rows(b_csv)
    check(f"{coords}: as many segments", len(a) == len(b) and len(a) > 5, (len(a), len(b)))
    bad = [(ra, rb) for ra, rb in zip(a, b)
           if ra["motion"] != rb["motion"]
           or not all(same(ra[k], rb[k]) for k in ("x", "y", "z", "cx", "cy", "cz", "feed"))]
    check(f"{coords}: same motions, end points, centres and feeds to 1e-6", not bad, bad[:3])
    if coords == "wcs":
        check("wcs: arcs in all three planes and TURN=",
              all(s in text for s in ("G17\n", "G18\n", "G19\n", "TURN=1", "TURN=2", "K=AC(")), text)
        check("wcs: MSG as a comment", "; MSG: done" in text, text)

# A lathe (docs/turning.md): DIAMON, G95 with G94 in between, arcs in G18, a turning tool; once
# with radius values, once with --diameter (the MPF then says DIAMON and needs MD20100 as the
# source had it). The MPF writes G95/G94 where the feed unit changes.
lathe_ini = write("LATHE.INI", '$MC_DIAMETER_AX_DEF="X"\n$MC_GCODE_RESET_VALUES[5]=2\nM17\n')
axis_ini = write("AXIS.INI", '$MC_DIAMETER_AX_DEF="X"\nM17\n')
lathe = write("LATHE.MPF", """$TC_DP1[1,1]=500 $TC_DP2[1,1]=3 $TC_DP3[1,1]=20 $TC_DP4[1,1]=40
T1 D1 DIAMON G95
G0 X40 Z2
G1 Z0 F0.2
G3 X60 Z-10 I0 K-10
G94 G1 X70 F300
G95 G2 X90 Z-20 I=AC(90) K=AC(-10) F0.1
G0 X120 Z50
M30
""")
for extra in ([], ["--diameter"]):
    tag = "lathe" + ("-diameter" if extra else "")
    a_csv, mpf, b_csv = (os.path.join(d, f"{tag}.{ext}") for ext in ("csv", "mpf", "back.csv"))
    p = run("--init", lathe_ini, *extra, "-o", a_csv, lathe)
    check(f"{tag}: original runs", p.returncode == 0, p.stderr)
    p = run("--init", lathe_ini, *extra, "-o", mpf, lathe)
    check(f"{tag}: MPF written", p.returncode == 0, p.stderr)
    text = open(mpf).read()
    check(f"{tag}: G95 before the first feed per revolution, G94 where it changes",
          "G95 ; feed in mm/rev\nN2 G1" in text and "G94 ; feed in mm/min\n" in text, text)
    check(f"{tag}: DIAMON only with --diameter", ("\nDIAMON ;" in text) == bool(extra), text)
    p = run("--init", axis_ini, *extra, "-o", b_csv, mpf)
    check(f"{tag}: the MPF runs", p.returncode == 0, p.stderr)
    a, b = rows(a_csv), rows(b_csv)
    bad = [(ra, rb) for ra, rb in zip(a, b)
           if ra["motion"] != rb["motion"]
           or not all(same(ra[k], rb[k]) for k in ("x", "y", "z", "cx", "cy", "cz", "feed"))]
    check(f"{tag}: same path", len(a) == len(b) == 6 and not bad, (len(a), len(b), bad[:3]))

# An alarm ends the program with the alarm, M0 and M30; the path before it is there.
prog = write("ALARM.MPF", "G17 G90 G1 X10 Y0 Z0 F100\nG2 X20 Y0 I3 J0\nM30\n")
out = os.path.join(d, "alarm.mpf")
p = run("-o", out, prog)
check("alarm: exit 2", p.returncode == 2, p.returncode)
lines = open(out).read().splitlines()
check("alarm: the block before it (MCS: with SUPA)",
      any(l.startswith("N1 G1 SUPA X10 Y0 Z0 F100") for l in lines), lines)
check("alarm: comment then M0 and M30", len(lines) >= 3 and lines[-3].startswith("; ALARM 14040 at ")
      and "ALARM.MPF:2: " in lines[-3] and lines[-2].split(" ;")[0] == "M0" and lines[-1] == "M30",
      lines[-3:])

print("all round-trip checks hold" if not fails else f"{len(fails)} round-trip checks fail")
sys.exit(1 if fails else 0)
