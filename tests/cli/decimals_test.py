#!/usr/bin/env python3
"""--decimals N (0..17) rounds the numbers written in csv, jsonl, mpf, svg (the path) and html
(the table and ranges): at most N decimals, no exponent, never "-0"; without it CSV keeps the
shortest round-trip text. And the mpf output's header (what the positions assume, then the
reset block; SUPA in every MCS motion block) and its end after an alarm (; ALARM, M0, M30)."""
import csv, io, json, os, re, subprocess, sys, tempfile
import xml.etree.ElementTree as ET

binary = os.path.abspath(sys.argv[1])
d = tempfile.mkdtemp(prefix="ncoffset-decimals-")
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


# ROT Z45 puts 1e-16-sized noise into the coordinates on its diagonals, 0.1 + 0.2 is
# 0.30000000000000004, ROT Z-30 gives numbers with many decimals and -9.999999999999998.
prog = write("NOISE.MPF", """G17 G90 G0 X0 Y0 Z5
ROT Z45
G1 X10 Y10 F100
G1 X-3 Y3
G1 X3 Y-3
ROT
G1 X=0.1+0.2 Y-1 Z=-0.1-0.2
ROT Z-30
G1 X20 Y0
G2 X0 Y0 I-10 J0
ROT
G1 X0 Y0 Z0
M30
""")

NUMBER = re.compile(r"-?\d+(\.\d+)?([eE][-+]?\d+)?")


def bad_numbers(fields, decimals):
    """The fields that are no plain number with at most `decimals` decimals, or are -0."""
    bad = []
    for f in fields:
        if f == "":
            continue
        m = re.fullmatch(r"-?\d+(\.(\d+))?", f)
        if not m or (m.group(2) and len(m.group(2)) > decimals) or float(f) == 0 and f != "0" \
                or (m.group(2) or "x").endswith("0"):
            bad.append(f)
    return bad


p = run(prog)
check("csv default: exit 0", p.returncode == 0, p.stderr)
plain = list(csv.reader(io.StringIO(p.stdout)))
check("csv default: the shortest round-trip text as before",
      "0.30000000000000004" in p.stdout and "-9.999999999999998" in p.stdout
      and re.search(r"\de-1[5-7]", p.stdout), p.stdout)
for n in (0, 3, 17):
    p = run("--decimals", str(n), prog)
    check(f"csv --decimals {n}: exit 0", p.returncode == 0, p.stderr)
    rows = list(csv.reader(io.StringIO(p.stdout)))
    fields = [f for r in rows[1:] for f in r[2:]]
    check(f"csv --decimals {n}: plain numbers, at most {n} decimals, no -0",
          not bad_numbers(fields, n), bad_numbers(fields, n))
    check(f"csv --decimals {n}: as many rows, same lines and motions",
          [r[:2] for r in rows] == [r[:2] for r in plain], rows)
    worst = max(abs(float(a) - float(b)) for ra, rb in zip(rows[1:], plain[1:])
                for a, b in zip(ra[2:], rb[2:]) if a != "")
    check(f"csv --decimals {n}: within half a unit of the last decimal", worst <= 0.5 * 10**-n + 1e-12,
          worst)
p = run("--decimals", "3", prog)
check("csv --decimals 3: the noise of ROT Z45 is 0, 0.1 + 0.2 is 0.3, -9.999999999999998 is -10",
      "3,G1,0,14.142,5,,,,100" in p.stdout and "4,G1,-4.243,0,5,,,,100" in p.stdout
      and ",0.3,-1,-0.3," in p.stdout and ",-10," in p.stdout, p.stdout)
for value in ("18", "-1", "1.5", "0x3", "", "03x", "99999999999999999999"):
    p = run("--decimals", value, prog)
    check(f"--decimals {value!r}: usage error naming the range", p.returncode == 1
          and p.stderr.startswith("--decimals: ") and "0..17" in p.stderr and p.stdout == "",
          (p.returncode, p.stderr))

p = run("--decimals", "2", "--format", "jsonl", prog)
recs = [json.loads(l) for l in p.stdout.splitlines()]
nums = re.findall(r'(?<=[:\[,])-?[\d.eE+-]+(?=[,\]}])', p.stdout)
check("jsonl --decimals 2: records parse, numbers have at most 2 decimals",
      p.returncode == 0 and len(recs) >= 5 and not bad_numbers(nums, 2), bad_numbers(nums, 2))

for fmt_ in ("svg", "html"):
    out = os.path.join(d, f"p.{fmt_}")
    p = run("--decimals", "1", "-o", out, prog)
    text = open(out).read()
    if fmt_ == "svg":
        paths = re.findall(r' d="([^"]*)"', text[text.index('<g id="programmed">'):])
        nums = [n for dd in paths for n in re.findall(r"-?\d[\d.eE+-]*", dd)]
    else:  # the report's data: the coordinates, centres and feeds of both paths
        data = json.loads(re.search(r'<script type="application/json" id="nco-data">(.*?)</script>',
                                    text, re.S).group(1))
        nums = [str(v) for path in (data["out"], data["prog"]) for col in "XYZ" for v in path[col]]
        nums += [str(v) for path in (data["out"], data["prog"]) for a in path["A"] for v in a[1:7]]
    check(f"{fmt_} --decimals 1: the path's numbers (not the legend's) have at most 1 decimal",
          p.returncode == 0 and nums and not bad_numbers(nums, 1), bad_numbers(nums, 1)[:5])
    if fmt_ == "svg":
        ET.fromstring(text)  # still well-formed
    else:
        ranges = re.findall(r'<th>[XYZ] range</th><td class="n">([^<]*)</td>', text)
        cells = [c for r in ranges for c in r.split(" &#8230; ")]
        check("html --decimals 1: the X/Y/Z ranges have at most 1 decimal",
              cells and not bad_numbers(cells, 1), bad_numbers(cells, 1)[:5])

# The mpf header and blocks, MCS and WCS; the rounded MPF runs again to the rounded path.
for coords in ("mcs", "wcs"):
    mpf = os.path.join(d, f"p-{coords}.mpf")
    p = run("--coords", coords, "--decimals", "2", "-o", mpf, prog)
    lines = open(mpf).read().splitlines()
    head = [l for l in lines[:next(i for i, l in enumerate(lines) if not l.startswith(";"))]]
    reset = lines[len(head)]
    check(f"mpf {coords}: a header comment, then the reset block",
          p.returncode == 0 and len(head) >= 5 and head[0] == f"; ncoffset compensated path (coords {coords})"
          and reset.startswith("G90 G71 G94 G40 G17" + (" D0" if coords == "mcs" else "")), lines[:10])
    check(f"mpf {coords}: the header says what the positions are",
          any(f"({coords.upper()})" in l for l in head) and any("radius compensation" in l for l in head),
          head)
    blocks = [l for l in lines if re.match(r"N\d+ ", l)]
    check(f"mpf {coords}: SUPA in every motion block" if coords == "mcs" else "mpf wcs: no SUPA",
          blocks and all((" SUPA " in b) == (coords == "mcs") for b in blocks), blocks[:3])
    words = [w[1:] for b in blocks for w in b.split(" ;")[0].split()[2:] if w[0] in "XYZF"]
    check(f"mpf {coords} --decimals 2: numbers with at most 2 decimals",
          not bad_numbers(words, 2), bad_numbers(words, 2))
    check(f"mpf {coords}: ends with M30", lines[-1] == "M30", lines[-3:])
    back = os.path.join(d, f"back-{coords}.csv")
    p = run("--coords", coords, "-o", back, mpf)
    rounded = list(csv.reader(io.StringIO(run("--coords", coords, "--decimals", "2", prog).stdout)))
    again = list(csv.reader(open(back)))
    check(f"mpf {coords}: runs again to the rounded path", p.returncode == 0 and
          [r[1:] for r in again] == [r[1:] for r in rounded], (p.stderr, again[:3], rounded[:3]))

alarm = write("ALARM.MPF", "G17 G90 G1 X10 Y0 Z0 F100\nG2 X20 Y0 I3 J0\nM30\n")
out = os.path.join(d, "alarm.mpf")
p = run("-o", out, alarm)
lines = open(out).read().splitlines()
check("mpf after an alarm: exit 2, ; ALARM, then M0 and M30",
      p.returncode == 2 and lines[-3].startswith("; ALARM 14040 at ") and lines[-2].startswith("M0 ;")
      and lines[-1] == "M30", lines[-3:])

print("all --decimals and mpf checks hold" if not fails else f"{len(fails)} checks fail")
sys.exit(1 if fails else 0)
