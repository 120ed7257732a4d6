#!/usr/bin/env python3
"""Draws the cutting edge position pictures docs/pictures/sl1.svg ... sl9.svg.

Every picture is ncoffset's own output (JSON Lines, --coords wcs) for docs/pictures/slN.MPF
with docs/pictures/sl.INI, run three times:
  * the contour: the same program with the nose radius 0 and SL 9 (S = P = the contour);
  * the path of S, the cutting edge centre: radius R and SL 9 (P = S, so the WCS output is S);
  * the path of P, the theoretical tip: radius R and SL N, what `--coords wcs` writes.
The tool nose circle (radius R about S, with S and P marked) is drawn at the middle of every
block the program marks with the comment `; NOSE`, an arrowhead on the last contour element
shows the direction of travel. G18 view: Z to the right, X (radius) up.

  scripts/turning-pictures.py build/ncoffset           writes the SVGs
  scripts/turning-pictures.py --check build/ncoffset   fails if a committed SVG differs
Python standard library only.
"""
import argparse
import json
import math
import os
import re
import subprocess
import sys
import tempfile

PICTURES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "docs", "pictures")
POSITIONS = range(1, 10)
SCALE = 8.0  # pixels per mm
MARGIN = 14.0
TITLE_H = 40.0
LEGEND_H = 58.0
WIDTH = 340.0
TIP_TEXT = {1: "(+R, +R)", 2: "(+R, \u2212R)", 3: "(\u2212R, \u2212R)", 4: "(\u2212R, +R)",
            5: "(0, +R)", 6: "(+R, 0)", 7: "(0, \u2212R)", 8: "(\u2212R, 0)", 9: "(0, 0)"}
STYLE = (".c{fill:none;stroke:#444;stroke-width:2}"
         ".m{fill:#e4e4e4;stroke:none}"
         ".s{fill:none;stroke:#1f5fbf;stroke-width:1.3;stroke-dasharray:5 3}"
         ".p{fill:none;stroke:#d62728;stroke-width:1.6}"
         ".n{fill:#1f5fbf;fill-opacity:.08;stroke:#1f5fbf;stroke-width:1}"
         ".a{fill:none;stroke:#333;stroke-width:1.2}"
         "text{font-family:sans-serif;font-size:11px;fill:#222}"
         ".t{font-size:14px;font-weight:bold}"
         ".l{font-size:12px;font-weight:bold;paint-order:stroke;stroke:#fff;stroke-width:3px}")


def run(ncoffset, position, override):
    """Runs ncoffset on slN.MPF with sl.INI and the override lines; returns the rows."""
    program = os.path.join(PICTURES, "sl%d.MPF" % position)
    with tempfile.TemporaryDirectory() as tmp:
        extra = os.path.join(tmp, "override.INI")
        with open(extra, "w") as f:
            f.write("".join("$TC_DP%s[%d,1]=%s\n" % (k, position, v) for k, v in override))
        out = subprocess.run([ncoffset, "--init", os.path.join(PICTURES, "sl.INI"), "--init",
                              extra, "--coords", "wcs", "--format", "jsonl", program],
                             capture_output=True, text=True, check=False)
    if out.returncode != 0:
        sys.exit("ncoffset failed on %s:\n%s" % (program, out.stderr))
    return [json.loads(line) for line in out.stdout.splitlines() if line.strip()]


def nose_lines(position):
    with open(os.path.join(PICTURES, "sl%d.MPF" % position)) as f:
        return {i + 1 for i, text in enumerate(f)
                if "; NOSE" in text and not text.lstrip().startswith(";")}


def segments(rows):
    """(motion, start, end, centre, line) in (z, x); G0 rows only move the start."""
    result, at = [], None
    for r in rows:
        if "type" in r or "motion" not in r:
            continue  # event, message or warning records (docs/output-formats.md)
        end = (r["z"], r["x"])
        centre = (r["cz"], r["cx"]) if "cx" in r else None
        if r["motion"] != "G0" and at is not None:
            result.append((r["motion"], at, end, centre, r["line"]))
        at = end
    return result


class View:
    """Model (z, x) to pixels: Z to the right, X up."""

    def __init__(self, points):
        self.z0 = min(p[0] for p in points)
        self.x1 = max(p[1] for p in points)
        z1 = max(p[0] for p in points)
        x0 = min(p[1] for p in points)
        self.dx = (WIDTH - 2 * MARGIN - (z1 - self.z0) * SCALE) / 2 + MARGIN
        self.height = TITLE_H + (self.x1 - x0) * SCALE + 2 * MARGIN + LEGEND_H
        self.bottom = self.height - LEGEND_H

    def __call__(self, p):
        return (self.dx + (p[0] - self.z0) * SCALE, TITLE_H + MARGIN + (self.x1 - p[1]) * SCALE)


def num(v):
    text = "%.1f" % v
    return "0" if text in ("0.0", "-0.0") else text.rstrip("0").rstrip(".")


def xy(p):
    return "%s %s" % (num(p[0]), num(p[1]))


def path_d(segs, view):
    d, at = [], None
    for motion, start, end, centre, _ in segs:
        if at is None or math.dist(at, start) > 1e-6:
            d.append("M" + xy(view(start)))
        if motion == "G1":
            d.append("L" + xy(view(end)))
        else:
            d.append(arc(motion, start, end, centre, view))
        at = end
    return "".join(d)


def arc(motion, start, end, centre, view):
    """G2 is clockwise in this view (seen from +Y, PM-NC "circular interpolation")."""
    r = math.dist(centre, end) * SCALE
    a0 = math.atan2(start[1] - centre[1], start[0] - centre[0])
    a1 = math.atan2(end[1] - centre[1], end[0] - centre[0])
    sweep = (a0 - a1) if motion == "G2" else (a1 - a0)
    sweep %= 2 * math.pi
    large = 1 if sweep > math.pi else 0
    flag = 1 if motion == "G2" else 0
    return "A%s %s 0 %d %d %s" % (num(r), num(r), large, flag, xy(view(end)))


def middle(seg):
    motion, start, end, centre, _ = seg
    if motion == "G1":
        return ((start[0] + end[0]) / 2, (start[1] + end[1]) / 2)
    r = math.dist(centre, end)
    a0 = math.atan2(start[1] - centre[1], start[0] - centre[0])
    a1 = math.atan2(end[1] - centre[1], end[0] - centre[0])
    if motion == "G2":
        a = a0 - ((a0 - a1) % (2 * math.pi)) / 2
    else:
        a = a0 + ((a1 - a0) % (2 * math.pi)) / 2
    return (centre[0] + r * math.cos(a), centre[1] + r * math.sin(a))


def material(contour, view, bounds):
    """The workpiece: the contour closed on the side away from the tool (X low for an OD)."""
    first, last = contour[0][1], contour[-1][2]
    x = bounds[0] if last[1] > first[1] else bounds[1]
    return path_d(contour, view) + "L%sL%sZ" % (xy(view((last[0], x))), xy(view((first[0], x))))


def nose(s_point, p_point, radius, view):
    """The nose circle about S, S and P marked and labelled (P beyond the tip, S opposite)."""
    s_px, p_px = view(s_point), view(p_point)
    out = ['<circle class="n" cx="%s" cy="%s" r="%s"/>' % (num(s_px[0]), num(s_px[1]),
                                                           num(radius * SCALE))]
    gap = math.dist(s_px, p_px)
    if gap < 1e-6:
        out.append(dot(s_px, "#d62728", 3.2))
        corner = radius * SCALE * 0.72
        out.append(label((s_px[0] + corner + 2, s_px[1] - corner - 2), "S = P", "start"))
        return out
    u = ((p_px[0] - s_px[0]) / gap, (p_px[1] - s_px[1]) / gap)
    out.append('<path class="a" stroke-dasharray="2 2" d="M%sL%s"/>' % (xy(s_px), xy(p_px)))
    out.append(dot(s_px, "#1f5fbf", 2.8))
    out.append(dot(p_px, "#d62728", 3.2))
    out.append(placed(s_px, (-u[0], -u[1]), "S"))
    out.append(placed(p_px, u, "P"))
    return out


def dot(p, colour, r):
    return '<circle cx="%s" cy="%s" r="%s" fill="%s"/>' % (num(p[0]), num(p[1]), num(r), colour)


def label(p, text, anchor):
    return '<text class="l" x="%s" y="%s" text-anchor="%s">%s</text>' % (num(p[0]), num(p[1]),
                                                                          anchor, text)


def placed(p, u, text):
    """A label 9 px from p in the direction u."""
    anchor = "start" if u[0] > 0.3 else "end" if u[0] < -0.3 else "middle"
    return label((p[0] + 9 * u[0], p[1] + 9 * u[1] + 4), text, anchor)


def legend(view):
    y = view.bottom + 4
    rows = [("c", "", "programmed contour (\u25b8 direction of travel)"),
            ("s", "", "S, cutting edge centre: the equidistant at R"),
            ("p", "", "P, theoretical tip: ncoffset --coords wcs")]
    out = []
    for i, (cls, _, text) in enumerate(rows):
        yy = y + 12 + i * 15
        out.append('<path class="%s" d="M14 %sh22"/>' % (cls, num(yy - 4)))
        out.append('<text x="42" y="%s">%s</text>' % (num(yy), text))
    ox, oy = WIDTH - 50, 34
    out.append('<path class="a" d="M%s %sh26m-5 -3l5 3l-5 3M%s %sv-26m-3 5l3 -5l3 5"/>' %
               (num(ox), num(oy), num(ox), num(oy)))
    out.append('<text x="%s" y="%s">+Z</text>' % (num(ox + 30), num(oy + 4)))
    out.append('<text x="%s" y="%s">+X</text>' % (num(ox + 6), num(oy - 18)))
    return out


def picture(ncoffset, position):
    radius = 2.4
    contour = segments(run(ncoffset, position, [(6, 0), (2, 9)]))[1:-1]
    s_path = segments(run(ncoffset, position, [(2, 9)]))
    p_path = segments(run(ncoffset, position, []))
    if [g[4] for g in s_path] != [g[4] for g in p_path]:
        sys.exit("sl%d: the S and P runs differ in their blocks" % position)
    noses = []
    for line in sorted(nose_lines(position)):
        index = max((i for i, g in enumerate(s_path) if g[4] == line),
                    key=lambda i: math.dist(s_path[i][1], s_path[i][2]))
        noses.append((middle(s_path[index]), middle(p_path[index])))
    points = [q for seg in contour + s_path + p_path for q in seg[1:3]]
    x_low, x_high = min(q[1] for q in points), max(q[1] for q in points)
    view = View(points + [(q[0] + d, q[1] + d) for q in points for d in (-1, 1)] +
                [(q[0][0] + d, q[0][1] + d) for q in noses for d in (-radius - 1, radius + 1)])
    side = "G42" if "G42" in open(os.path.join(PICTURES, "sl%d.MPF" % position)).read() else "G41"
    title = "SL %d · %s · P − S = %s" % (position, side, TIP_TEXT[position])
    body = ['<rect width="100%" height="100%" fill="#fff"/>',
            '<text class="t" x="14" y="20">%s</text>' % title,
            '<text x="14" y="35">in (X, Z); R = %s mm; G18, X as a radius</text>' % num(radius),
            '<path class="m" d="%s"/>' % material(contour, view, (x_low, x_high)),
            '<path class="c" d="%s"/>' % path_d(contour, view),
            '<path class="p" d="%s"/>' % path_d(p_path, view),
            '<path class="s" d="%s"/>' % path_d(s_path, view), travel(contour, view)]
    for s_point, p_point in noses:
        body += nose(s_point, p_point, radius, view)
    body += legend(view)
    head = ('<svg xmlns="http://www.w3.org/2000/svg" width="%s" height="%s" viewBox="0 0 %s %s">'
            % (num(WIDTH), num(view.height), num(WIDTH), num(view.height)))
    return "\n".join([head, "<title>Cutting edge position SL %d</title>" % position,
                       "<style>%s</style>" % STYLE] + body + ["</svg>"]) + "\n"


def same(committed, drawn):
    """Equal but for numbers within 0.15 px: another compiler may round the last bit of a
    coordinate differently, which must not fail the check."""
    number = re.compile(r"-?[0-9]+(?:\.[0-9]+)?")
    if number.sub("#", committed) != number.sub("#", drawn):
        return False
    pairs = zip(number.findall(committed), number.findall(drawn))
    return all(abs(float(a) - float(b)) <= 0.15 for a, b in pairs)


def travel(contour, view):
    """An arrowhead on the contour's last element: the direction of travel (G41/G42 side)."""
    motion, start, end, _, _ = contour[-1]
    a, b = view(start), view(end)
    length = math.dist(a, b)
    u = ((b[0] - a[0]) / length, (b[1] - a[1]) / length)
    tip = ((a[0] + b[0]) / 2 + 5 * u[0], (a[1] + b[1]) / 2 + 5 * u[1])
    back = (tip[0] - 10 * u[0], tip[1] - 10 * u[1])
    left = (back[0] - 4 * u[1], back[1] + 4 * u[0])
    right = (back[0] + 4 * u[1], back[1] - 4 * u[0])
    return '<path fill="#444" d="M%sL%sL%sZ"/>' % (xy(tip), xy(left), xy(right))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("ncoffset")
    parser.add_argument("--check", action="store_true", help="compare, do not write")
    args = parser.parse_args()
    stale = []
    for position in POSITIONS:
        svg = picture(args.ncoffset, position)
        target = os.path.join(PICTURES, "sl%d.svg" % position)
        if args.check:
            with open(target, encoding="utf-8") as f:
                if not same(f.read(), svg):
                    stale.append(target)
        else:
            with open(target, "w", encoding="utf-8") as f:
                f.write(svg)
    if stale:
        sys.exit("out of date (run scripts/doc-pictures.sh): " + ", ".join(stale))


if __name__ == "__main__":
    main()
