#!/usr/bin/env python3
"""The drawing and program formats from the command line: `-o x.svg` / `.html` / `.MPF` choose
the format, --view picks the plane, the SVG parses as XML with a viewBox around the path, the
HTML page is one self-contained document, and a run that ends in an alarm still writes a whole
drawing with the alarm marked (exit 2). usage: drawing_formats_test.py NCOFFSET EXAMPLES_DIR"""
import os, subprocess, sys, tempfile
import xml.etree.ElementTree as ET

binary = os.path.abspath(sys.argv[1])
examples = os.path.abspath(sys.argv[2])
d = tempfile.mkdtemp(prefix="ncoffset-draw-")
fails = []
NS = "{http://www.w3.org/2000/svg}"

def check(name, cond, detail=""):
    print(("ok   " if cond else "FAIL ") + name + ("" if cond else f"  [{detail}]"))
    if not cond:
        fails.append(name)

def run(*args):
    return subprocess.run([binary, *args], capture_output=True, text=True, cwd=d, timeout=60)

def svg_root(path):
    try:
        return ET.parse(path).getroot()
    except (ET.ParseError, OSError) as e:
        return str(e)

frames = os.path.join(examples, "frames.MPF")
# The golden check: an example to SVG by extension.
out = os.path.join(d, "x.svg")
p = run(frames, "-o", out)
check("svg: exit 0", p.returncode == 0, p.stderr)
root = svg_root(out)
check("svg: parses as XML, root <svg>", not isinstance(root, str) and root.tag == NS + "svg", root)
if not isinstance(root, str):
    vb = [float(v) for v in root.get("viewBox", "0 0 0 0").split()]
    check("svg: viewBox has an area", vb[2] > 0 and vb[3] > 0, vb)
    paths = root.findall(f".//{NS}path")
    check("svg: path elements, all non-scaling strokes", len(paths) > 3 and all(
        p.get("vector-effect") == "non-scaling-stroke" for p in paths), len(paths))
    check("svg: programmed and compensated path", root.find(f".//{NS}g[@id='programmed']/{NS}path")
          is not None and root.find(f".//{NS}g[@id='path']/{NS}path") is not None)
    check("svg: an SVG arc for the G17 arcs", any("A" in p.get("d", "") for p in paths))

for view, label in (("zx", "view ZX (G18)"), ("yz", "view YZ (G19)")):
    out = os.path.join(d, f"{view}.svg")
    p = run("--view", view, "-o", out, frames)
    check(f"--view {view}: exit 0 and labelled", p.returncode == 0 and label in open(out).read(),
          p.stderr)
p = run("--view", "xz", "-o", os.path.join(d, "bad.svg"), frames)
check("--view xz rejected with exit 1", p.returncode == 1, p.returncode)
p = run("--format", "svg", frames)
check("--format svg to stdout", p.returncode == 0 and p.stdout.rstrip().endswith("</svg>"), p.stdout[-60:])

out = os.path.join(d, "r.html")
p = run("--init", os.path.join(examples, "frames.INI"), "-o", out, frames)
html = open(out).read() if os.path.exists(out) else ""
check("html: exit 0", p.returncode == 0, p.stderr)
check("html: one document with the drawing's svg", html.startswith("<!DOCTYPE html>")
      and html.rstrip().endswith("</html>") and html.count('<svg id="nco-svg"') == 1, html[:80])
check("html: self-contained (inline data and script only)",
      html.count("<script") == 2 and not any(s in html for s in ("<link", " src=", "href=", "url(")))
check("html: summary, the data and the program text",
      "<h2>Summary</h2>" in html and 'id="nco-data"' in html and "frames.MPF" in html)

out = os.path.join(d, "c.MPF")
p = run("-o", out, frames)
text = open(out).read() if os.path.exists(out) else ""
check("mpf: chosen by the .MPF extension", p.returncode == 0 and
      text.startswith("; ncoffset compensated path (coords mcs)"), text[:80])

# An alarm: the drawing is whole, the alarm marked where the path stopped.
prog = os.path.join(d, "A.MPF")
with open(prog, "w") as f:
    f.write("G17 G90 G1 X10 Y5 Z0 F100\nG2 X20 Y0 I3 J0\nM30\n")
out = os.path.join(d, "a.svg")
p = run("-o", out, prog)
check("alarm: exit 2", p.returncode == 2, p.returncode)
root = svg_root(out)
check("alarm: the SVG parses", not isinstance(root, str), root)
if not isinstance(root, str):
    mark = root.find(f".//{NS}g[@id='alarm']/{NS}circle")
    check("alarm: marked at the last end point", mark is not None and mark.get("cx") == "10"
          and mark.get("cy") == "-5", None if mark is None else mark.attrib)
    title = mark.find(f"{NS}title").text if mark is not None else ""
    check("alarm: title names it", title.startswith("alarm 14040 at ") and "A.MPF:2:" in title, title)

# The time estimate: G0 X100 at MD32000 10000 mm/min (166.67 mm/s) with MD32300 1 m/s2:
# 0.6 s + 0.1667 s; G1 X200 F6000 (100 mm/s): 1 s + 0.1 s; 1.867 s in all. With
# $MA_MAX_AX_VELO[X]=6000 and $MA_MAX_AX_ACCEL[X]=2 from an init file: 1 s + 0.05 s twice.
# --start 0,0,0: the machine stands at its zero, so the first move is real and is counted
# (without --start it is from an assumed position and left out: docs/output-formats.md).
prog = os.path.join(d, "T.MPF")
with open(prog, "w") as f:
    f.write("G0 X100\nG1 X200 F6000\nM30\n")
init = os.path.join(d, "axes.INI")
with open(init, "w") as f:
    f.write("$MA_MAX_AX_VELO[X]=6000\n$MA_MAX_AX_ACCEL[X]=2\nM17\n")
for args, want in ((("--start", "0,0,0"), "0:00:01.9 (without acceleration 0:00:01.6; rapid 0:00:00.8"),
                   (("--start", "0,0,0", "--init", init), "0:00:02.1 (without acceleration 0:00:02.0; rapid 0:00:01.1")):
    out = os.path.join(d, "t.html")
    p = run(*args, "-o", out, prog)
    page = open(out).read() if os.path.exists(out) else ""
    check(f"html time estimate {args}", p.returncode == 0 and f'id="nco-time">{want}' in page,
          (p.stderr, page[page.find('nco-time'):page.find('nco-time') + 90]))

# The lathe example (docs/turning.md) as an HTML report in the ZX plane; --diameter is refused
# for drawings (a doubled axis would make its circles ellipses).
lathe = [os.path.join(examples, n) for n in ("lathe.INI", "lathe_tools.INI", "lathe.MPF")]
out = os.path.join(d, "lathe.html")
p = run("--init", lathe[0], "--init", lathe[1], "--view", "zx", "-o", out, lathe[2])
check("lathe: html report", p.returncode == 0 and '"view":"zx"' in open(out).read(), p.stderr)
p = run("--init", lathe[0], "--init", lathe[1], "--diameter", "-o", os.path.join(d, "l.svg"),
        lathe[2])
check("lathe: --diameter refused for svg", p.returncode == 1 and "--diameter" in p.stderr,
      (p.returncode, p.stderr))

# A continuous path (docs/output-formats.md "Start position"): the tool changes of the lathe
# example and the length take-up of the lentoax example draw without a jump, every <path> of
# the output layer beginning where the one before ended; without --start the drawing begins at
# the first segment's end (the move from the assumed start is left out), with --start at the
# start position.
import re
def path_points(svg_file):
    """The (start, end) of each <path> of the output layer, in SVG coordinates."""
    root = svg_root(svg_file)
    if isinstance(root, str):
        return []
    runs = []
    for e in root.findall(f".//{NS}g[@id='path']/{NS}path"):
        tokens = re.findall(r"[MLA]|[-+0-9.eE]+", e.get("d", ""))
        pts, cmd, nums = [], None, []
        for t in tokens + ["M"]:
            if t in "MLA":
                if cmd:
                    k = 7 if cmd == "A" else 2
                    for j in range(0, len(nums), k):
                        pts.append((float(nums[j + k - 2]), float(nums[j + k - 1])))
                cmd, nums = t, []
            else:
                nums.append(t)
        runs.append((pts[0], pts[-1]))
    return runs

def jumps(runs):
    return [(a[1], b[0]) for a, b in zip(runs, runs[1:])
            if max(abs(a[1][0] - b[0][0]), abs(a[1][1] - b[0][1])) > 1e-6]

drawn = {
    "lentoax": (["--init", os.path.join(examples, "tools.INI")], "lentoax.MPF", "xy"),
    "lathe": (["--init", lathe[0], "--init", lathe[1]], "lathe.MPF", "zx"),
}
for name, (inits, prog, view) in drawn.items():
    for view_name in sorted({view, "zx"}):
        out = os.path.join(d, f"cont_{name}_{view_name}.svg")
        p = run(*inits, "--view", view_name, "-o", out, os.path.join(examples, prog))
        runs = path_points(out)
        check(f"{name} --view {view_name}: drawn without a jump", p.returncode == 0 and runs
              and not jumps(runs), (p.stderr, jumps(runs)))
out = os.path.join(d, "cont_start.svg")
p = run("--init", os.path.join(examples, "tools.INI"), "--view", "zx", "--start", "0,0,500",
        "-o", out, os.path.join(examples, "lentoax.MPF"))
runs = path_points(out)
# lentoax.MPF: G0 X0 Y0 Z50 first; in the ZX view (Z right, X up, y = -X) from (Z500, X0).
check("--start 0,0,500: the first move is drawn from the start position",
      p.returncode == 0 and runs and runs[0][0] == (500.0, 0.0), (p.stderr, runs[:1]))
out = os.path.join(d, "cont_nostart.svg")
p = run("--init", os.path.join(examples, "tools.INI"), "--view", "zx", "-o", out,
        os.path.join(examples, "lentoax.MPF"))
runs = path_points(out)
check("without --start the drawing begins at the first segment's end (Z50, X0)",
      p.returncode == 0 and runs and runs[0][0] == (50.0, 0.0), (p.stderr, runs[:1]))
for bad in ("1,2", "1,2,3,4", "a,b,c", "0x10,0,0", "inf,0,0", "1,,2", "2e9,0,0"):
    p = run("--start", bad, os.path.join(examples, "lentoax.MPF"))
    check(f"--start {bad} refused with exit 1", p.returncode == 1 and "--start" in p.stderr,
          (p.returncode, p.stderr))

print("all format checks hold" if not fails else f"{len(fails)} format checks fail")
sys.exit(1 if fails else 0)
