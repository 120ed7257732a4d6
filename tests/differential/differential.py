#!/usr/bin/env python3
"""Differential test of ncoffset against LinuxCNC's standalone rs274ngc interpreter (`rs274`).

Random closed contours of lines and arcs, in G17 and in G18, are written twice: as a LinuxCNC
.ngc and as a SINUMERIK .MPF. Both interpreters run; rs274's canonical trace and ncoffset's CSV
(`--coords wcs`) are parsed into the same segment list (end point, and for arcs centre and
sense).

Mode 1 (default): no cutter compensation (G40), contours of this script's own generator (arcs
beyond 180 degrees, centres on a Gaussian-integer lattice). The programmed paths must agree
segment by segment to 1e-4 mm (rs274 prints 4 decimals): an independent check of ncoffset's
circle handling (I/J/K centres, G2/G3 sense, arcs beyond 180 degrees) in G17 and G18.
Mode 2 (--compensated): the contours of the radius-compensation property test
(tests/support/random_contour.hpp, through ncoffset_random_contours --differential: tangent and
non-tangent joins, G41/G42, R 0.5..5 mm, coordinates with --decimals decimals), three laps with
G450 and MD20230 = 0; one full steady lap of each tool-centre path must lie within 1e-3 mm of the
other (sampled, both ways), away from the approach and the retract. Left out, as documented:
contours with an outside corner whose equidistants cross inside both elements.

rs274 is a test-time oracle only (installed by setup_rs274.sh into a cache directory); nothing
of LinuxCNC is linked with or shipped in ncoffset.

Exit status: 0 all agree; 1 a disagreement or an error; 77 skipped (rs274 cannot be had here).
"""

from __future__ import annotations

import argparse
import math
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field

SKIP = 77
HERE = os.path.dirname(os.path.abspath(__file__))
TOL = 1e-4          # mm: rs274 prints 4 decimals
EPS = 1e-9          # float noise on top of TOL
TICKS = 10000       # all generated coordinates are integers in units of 1e-4 mm (exact decimals)


# --------------------------------------------------------------------------------------------
# Segments: the common form both outputs are parsed into (work coordinates, mm)
# --------------------------------------------------------------------------------------------

@dataclass
class Segment:
    kind: str                      # 'G0' rapid, 'G1' line, 'ARC'
    end: tuple                     # (x, y, z)
    centre: tuple | None = None    # arcs: (x, y, z), in the plane of the arc's start point
    ccw: bool | None = None        # arcs: counter-clockwise seen from + of the plane's normal axis
    normal: str | None = None      # arcs: 'Z' (G17) or 'Y' (G18)
    feed: float | None = None      # G1/ARC feed rate (mm/min)
    src: str = ''                  # the raw row / trace line, for reports
    line: int | None = None        # ncoffset: source line of the block

    def describe(self) -> str:
        s = f"{self.kind} end=({_f(self.end)})"
        if self.kind == 'ARC':
            s += f" centre=({_f(self.centre)}) {'CCW' if self.ccw else 'CW'} about +{self.normal}"
        if self.feed is not None:
            s += f" F{self.feed:g}"
        return s


def _f(p) -> str:
    return ', '.join(f"{v:.4f}" for v in p)


def _close(p, q, tol=TOL) -> bool:
    return all(abs(a - b) <= tol + EPS for a, b in zip(p, q))


def compare_segments(got_nc: list[Segment], got_rs: list[Segment], check_feed=True) -> str | None:
    """None if equal within TOL, else a description of the first difference."""
    for k in range(min(len(got_nc), len(got_rs))):
        a, b = got_nc[k], got_rs[k]
        why = []
        if a.kind != b.kind:
            why.append('kind')
        if not _close(a.end, b.end):
            why.append('end point')
        if a.kind == 'ARC' and b.kind == 'ARC':
            if not _close(a.centre, b.centre):
                why.append('centre')
            if a.ccw != b.ccw:
                why.append('sense')
            if a.normal != b.normal:
                why.append('plane')
        if check_feed and a.kind != 'G0' and b.kind != 'G0' and a.feed is not None \
                and b.feed is not None and abs(a.feed - b.feed) > 1e-6 * max(1.0, abs(b.feed)):
            why.append('feed')
        if why:
            return (f"segment {k + 1}: {', '.join(why)} differ\n"
                    f"    ncoffset: {a.describe()}    [{a.src}]\n"
                    f"    rs274   : {b.describe()}    [{b.src}]")
    if len(got_nc) != len(got_rs):
        extra = got_nc[len(got_rs):] or got_rs[len(got_nc):]
        who = 'ncoffset' if len(got_nc) > len(got_rs) else 'rs274'
        return (f"segment count differs: ncoffset {len(got_nc)}, rs274 {len(got_rs)}; "
                f"first extra ({who}): {extra[0].describe()} [{extra[0].src}]")
    return None


# --------------------------------------------------------------------------------------------
# Parsers
# --------------------------------------------------------------------------------------------

_CANON = re.compile(r'\b(STRAIGHT_TRAVERSE|STRAIGHT_FEED|ARC_FEED|SET_FEED_RATE|SELECT_PLANE)'
                    r'\((.*)\)\s*$')


def parse_rs274(text: str) -> list[Segment]:
    """rs274's canonical trace -> segments.

    STRAIGHT_TRAVERSE/STRAIGHT_FEED(x, y, z, a, b, c).
    ARC_FEED(first_end, second_end, first_centre, second_centre, rotation, axis_end, a, b, c),
    where (first, second, axis) is (X, Y, Z) in G17 and (Z, X, Y) in G18 (CANON_PLANE_XZ).
    Orientation: the rotation is counted in the (first, second) frame, positive = from +first
    towards +second. (X, Y, Z) and (Z, X, Y) are both cyclic, i.e. right-handed, so
    first x second = +axis: rotation > 0 is counter-clockwise seen from +Z in G17 and from +Y in
    G18, the same sense SINUMERIK's G3 has in both planes (and ncoffset's CSV motion G3: sense
    seen from the + end of the axis the arc turns about). Hand example (checked by
    hand_check() on every run): G18, from X20 Z0, `G3 X30 Z-10 I0 K-10` -> centre X20 Z-10;
    the radius vector turns from +Z (0 deg in the Z,X frame) to +X (90 deg): a quarter turn
    about +Y, counter-clockwise seen from +Y; rs274 prints ARC_FEED(-10.0000, 30.0000, -10.0000,
    20.0000, 1, 0.0000, ...) = Z end, X end, Z centre, X centre, +1.
    Feed rates come from SET_FEED_RATE (units/min with G21 G94).
    """
    segs: list[Segment] = []
    pos = [0.0, 0.0, 0.0]
    plane = 'XY'
    feed = None
    for line in text.splitlines():
        m = _CANON.search(line)
        if not m:
            continue
        name, args = m.group(1), m.group(2)
        if name == 'SELECT_PLANE':
            plane = {'CANON_PLANE_XY': 'XY', 'CANON_PLANE_XZ': 'XZ',
                     'CANON_PLANE_YZ': 'YZ'}[args.strip()]
            continue
        v = [float(s) for s in args.split(',')]
        if name == 'SET_FEED_RATE':
            feed = v[0]
            continue
        raw = line.strip()
        if name in ('STRAIGHT_TRAVERSE', 'STRAIGHT_FEED'):
            end = (v[0], v[1], v[2])
            kind = 'G0' if name == 'STRAIGHT_TRAVERSE' else 'G1'
            segs.append(Segment(kind, end, feed=None if kind == 'G0' else feed, src=raw))
        else:
            fe, se, fc, sc, rot, ae = v[0], v[1], v[2], v[3], int(v[4]), v[5]
            if abs(rot) != 1:
                raise ValueError(f"rs274 arc with {rot} turns (generator makes none): {raw}")
            if plane == 'XY':
                end, centre, normal = (fe, se, ae), (fc, sc, pos[2]), 'Z'
            elif plane == 'XZ':   # first = Z, second = X, axis = Y
                end, centre, normal = (se, ae, fe), (sc, pos[1], fc), 'Y'
            else:
                raise ValueError(f"plane {plane} is not compared: {raw}")
            segs.append(Segment('ARC', end, centre, rot > 0, normal, feed, raw))
        pos = list(segs[-1].end)
    return segs


def parse_ncoffset(text: str, plane_of_line) -> list[Segment]:
    """ncoffset's CSV `line,motion,x,y,z,cx,cy,cz,feed` -> segments (motion G2/G3: sense seen
    from + of the axis the arc turns about; with --coords wcs no mirroring frame applies)."""
    segs: list[Segment] = []
    lines = text.splitlines()
    if not lines or lines[0].strip() != 'line,motion,x,y,z,cx,cy,cz,feed':
        raise ValueError(f"unexpected ncoffset CSV header: {lines[:1]}")
    for row in lines[1:]:
        if not row.strip():
            continue
        c = row.split(',')
        line_no, motion = int(c[0]), c[1]
        end = (float(c[2]), float(c[3]), float(c[4]))
        feed = float(c[8]) if c[8] else None
        if motion == 'G0':
            segs.append(Segment('G0', end, src=row))
        elif motion == 'G1':
            segs.append(Segment('G1', end, feed=feed, src=row))
        elif motion in ('G2', 'G3'):
            centre = (float(c[5]), float(c[6]), float(c[7]))
            segs.append(Segment('ARC', end, centre, motion == 'G3',
                                plane_of_line(line_no), feed, row))
        else:
            raise ValueError(f"unexpected ncoffset motion {motion!r}: {row}")
        segs[-1].line = line_no
    return segs


# --------------------------------------------------------------------------------------------
# Contour generation (plane coordinates: a = abscissa, o = ordinate; integers in 1e-4 mm)
# --------------------------------------------------------------------------------------------

@dataclass
class Element:
    kind: str                        # 'line' or 'arc'
    end: tuple                       # (a, o) ticks
    centre: tuple | None = None      # (a, o) ticks, absolute
    ccw: bool = False                # counter-clockwise in the (a, o) frame
    feed: int | None = None          # F word on this block, if any


@dataclass
class Contour:
    index: int
    plane: str                       # 'G17' or 'G18'
    ccw: bool                        # traversal sense of the contour
    level: int                       # applicate (Z in G17, Y in G18), ticks
    start: tuple                     # contour start point P0 (a, o)
    approach_from: tuple             # A: outside, where the approach line starts
    elements: list = field(default_factory=list)
    feed: int = 500
    convex: int = 0
    concave: int = 0
    arcs_over_180: int = 0


def _unit(x, y):
    n = math.hypot(x, y)
    return x / n, y / n


def _tangent_at(el_start, el: Element, at_end: bool):
    if el.kind == 'line':
        return _unit(el.end[0] - el_start[0], el.end[1] - el_start[1])
    p = el.end if at_end else el_start
    rx, ry = p[0] - el.centre[0], p[1] - el.centre[1]
    return _unit(-ry, rx) if el.ccw else _unit(ry, -rx)


def exact_arc(p, centre_wanted, sweep_signed):
    """An arc from the lattice point p turning sweep_signed (radians, > 0 counter-clockwise)
    about roughly centre_wanted, whose centre C and end point Q are lattice points with
    |p - C| == |Q - C| EXACTLY (integer ticks). Start and end radii that differ by even 1e-4 mm
    shift a compensated corner by more than the tolerance (the two interpreters may take either
    radius), so they must be equal. Gaussian integers: with s = w1*w2 and e = w1*conj(w2)*i^k,
    |s| = |e| = |w1||w2| and arg(e) - arg(s) = k*90deg - 2*arg(w2); pick w2 (small) for
    the sweep, then w1 for the start direction and radius; C = p - s, Q = C + e. Q lands within
    about 0.2 mm of the wanted end point (the shape only needs to be roughly as wanted)."""
    sx, sy = p[0] - centre_wanted[0], p[1] - centre_wanted[1]
    radius, alpha = math.hypot(sx, sy), math.atan2(sy, sx)

    # arg(w2) = -sweep/2 modulo 45 degrees (the rest is i^k and symmetry): a w2 in the first
    # octant, m >= k >= 0, m <= 300.
    target = (-sweep_signed / 2) % (math.pi / 4)
    m, k = min(((mm, round(mm * math.tan(target))) for mm in range(1, 301)),
               key=lambda w: abs(math.atan2(w[1], w[0]) - target))
    arg2 = math.atan2(k, m)
    quarter = round((sweep_signed + 2 * arg2) / (math.pi / 2)) % 4
    mod1 = radius / math.hypot(m, k)
    w1 = (round(mod1 * math.cos(alpha - arg2)), round(mod1 * math.sin(alpha - arg2)))
    s = (w1[0] * m - w1[1] * k, w1[0] * k + w1[1] * m)           # w1 * w2
    e = (w1[0] * m + w1[1] * k, -w1[0] * k + w1[1] * m)          # w1 * conj(w2)
    for _ in range(quarter):                                      # * i^quarter
        e = (-e[1], e[0])
    c = (p[0] - s[0], p[1] - s[1])
    q = (c[0] + e[0], c[1] + e[1])
    assert (p[0] - c[0]) ** 2 + (p[1] - c[1]) ** 2 == (q[0] - c[0]) ** 2 + (q[1] - c[1]) ** 2
    return c, q


# Corner turning angles (degrees) the contours keep clear of: there the two interpreters
# differ by design, not by error. SINUMERIK G450 computes the intersection instead of a
# transition circle at outside corners turning less than MD20230 CUTCOM_CURVE_INSERT_LIMIT
# (10 deg); rs274 treats corners turning less than its TOLERANCE_CONCAVE_CORNER (0.05 rad,
# 2.9 deg) as tangent (no arc outside, no intersection inside: a few micrometres of jump).
MIN_CONVEX_TURN = 15.0
MIN_CONCAVE_TURN = 5.0
# Near-reversals are left out too: a notch narrower than the tool is no test of corner
# handling (rs274 even takes a 177 deg inside turn for an outside corner).
MAX_CONVEX_TURN = 150.0
MAX_CONCAVE_TURN = 120.0


def generate(index: int, seed: int) -> Contour:
    rng = random.Random(seed * 100003 + index)
    plane = 'G17' if index % 2 == 0 else 'G18'
    ccw = rng.random() < 0.5
    while True:
        c = _try_generate(rng, index, plane, ccw)
        if c is not None:
            return c


def _try_generate(rng, index, plane, ccw) -> Contour | None:
    while True:
        n = rng.randint(4, 8)
        ca, co = rng.uniform(-30, 30), rng.uniform(-30, 30)
        th0 = rng.uniform(0, 2 * math.pi)
        step = 2 * math.pi / n
        pts = []
        for i in range(n):
            th = th0 + i * step + rng.uniform(-0.3, 0.3) * step
            r = rng.uniform(22, 60)
            pts.append((round((ca + r * math.cos(th)) * TICKS), round((co + r * math.sin(th)) * TICKS)))
        if not ccw:
            pts.reverse()
        if min(math.dist(pts[i], pts[(i + 1) % n]) for i in range(n)) >= 12 * TICKS:
            break
    elements = []
    starts = []
    big_used = False
    cur = pts[0]
    for i in range(n):
        p, q = cur, pts[(i + 1) % n]
        starts.append(p)
        dx, dy = q[0] - p[0], q[1] - p[1]
        length = math.hypot(dx, dy)
        left = (-dy / length, dx / length)
        inward = left if ccw else (-left[0], -left[1])     # towards the contour's interior
        u = rng.random()
        if u < 0.40 or i == n - 1:                # the closing element is a line: exact closure
            elements.append(Element('line', q))
            cur = q
            continue
        if u < 0.72:
            kind, sweep = 'out', math.radians(rng.uniform(30, 150))
        elif u < 0.92 or big_used:
            kind, sweep = 'in', math.radians(rng.uniform(20, 80))
        else:
            kind, sweep, big_used = 'out', math.radians(rng.uniform(200, 250)), True
        radius = length / (2 * math.sin(sweep / 2))
        h = radius * math.cos(sweep / 2)          # < 0 beyond 180 degrees: centre outside
        side = 1 if kind == 'out' else -1         # outward bulge: centre on the interior side
        centre = ((p[0] + q[0]) / 2 + side * h * inward[0],
                  (p[1] + q[1]) / 2 + side * h * inward[1])
        arc_ccw = ccw if kind == 'out' else not ccw
        centre, cur = exact_arc(p, centre, sweep if arc_ccw else -sweep)
        elements.append(Element('arc', cur, centre, arc_ccw))
    for el in elements:
        if rng.random() < 0.25:
            el.feed = rng.choice([300, 400, 600, 800, 1000])
    c = Contour(index, plane, ccw, -rng.randint(0, 50000), pts[0], (0, 0), elements,
                feed=rng.choice([200, 500, 750]))
    if elements[0].feed is None:      # the same feed in every lap (mode 2 compares lap 2)
        elements[0].feed = c.feed
    # Corners: turning towards the interior is convex (an outside tool goes round it on an arc).
    for i in range(n):
        t1 = _tangent_at(starts[i], elements[i], True)
        j = (i + 1) % n
        t2 = _tangent_at(starts[j], elements[j], False)
        cross = t1[0] * t2[1] - t1[1] * t2[0]
        turn = abs(math.degrees(math.atan2(cross, t1[0] * t2[0] + t1[1] * t2[1])))
        if (cross > 0) == ccw:
            c.convex += 1
            if not MIN_CONVEX_TURN <= turn <= MAX_CONVEX_TURN:
                return None
        else:
            c.concave += 1
            if not MIN_CONCAVE_TURN <= turn <= MAX_CONCAVE_TURN:
                return None
    for i, el in enumerate(elements):
        if el.kind == 'arc':
            p = starts[i]
            cross = (p[0] - el.centre[0]) * (el.end[1] - el.centre[1]) - \
                    (p[1] - el.centre[1]) * (el.end[0] - el.centre[0])
            if (cross > 0) != el.ccw:
                c.arcs_over_180 += 1
    # Approach from outside the contour: 12 mm out from P0 along the first element's outward
    # normal, 4 mm back along its tangent.
    t = _tangent_at(pts[0], elements[0], False)
    left = (-t[1], t[0])
    out = (-left[0], -left[1]) if ccw else left
    c.approach_from = (round(pts[0][0] + (12 * out[0] - 4 * t[0]) * TICKS),
                       round(pts[0][1] + (12 * out[1] - 4 * t[1]) * TICKS))
    return c


# --------------------------------------------------------------------------------------------
# Program writers. Plane mapping: G17 (a, o, applicate) = (X, Y, Z), centre words I J;
# G18 (a, o, applicate) = (Z, X, Y), centre words K (for a = Z) and I (for o = X). In both,
# G3 is counter-clockwise in the (a, o) frame seen from +applicate (Z x X = +Y).
# --------------------------------------------------------------------------------------------

def num(t: int) -> str:
    sign = '-' if t < 0 else ''
    t = abs(t)
    return f"{sign}{t // TICKS}.{t % TICKS:04d}"


AXES = {'G17': ('X', 'Y', 'Z', 'I', 'J'), 'G18': ('Z', 'X', 'Y', 'K', 'I')}


def blocks(c: Contour, dialect: str):
    """The program as a list of (text, role) lines, role = None or ('el', lap, k)."""
    A, O, APP, CA, CO = AXES[c.plane]
    a0, o0 = c.approach_from
    out = []
    if dialect == 'ngc':
        out.append((f"(ncoffset differential contour {c.index} {c.plane})", None))
        out.append((f"G21 G90 G94 G40 G49 {c.plane}", None))
    else:
        out.append((f"; ncoffset differential contour {c.index} {c.plane}", None))
        out.append((f"G71 G90 G94 G40 {c.plane}", None))
    out.append((f"G0 {A}{num(a0)} {O}{num(o0)} {APP}5", None))
    out.append((f"G1 {APP}{num(c.level)} F{c.feed}", None))
    out.append((f"G1 {A}{num(c.start[0])} {O}{num(c.start[1])}", None))
    prev = c.start
    for k, el in enumerate(c.elements):
        f = f" F{el.feed}" if el.feed else ''
        if el.kind == 'line':
            text = f"G1 {A}{num(el.end[0])} {O}{num(el.end[1])}{f}"
        else:
            g = 'G3' if el.ccw else 'G2'
            text = (f"{g} {A}{num(el.end[0])} {O}{num(el.end[1])} "
                    f"{CA}{num(el.centre[0] - prev[0])} {CO}{num(el.centre[1] - prev[1])}{f}")
        out.append((text, ('el', 0, k)))
        prev = el.end
    out.append((f"G1 {A}{num(a0)} {O}{num(o0)}", None))
    out.append((f"G0 {APP}5", None))
    out.append(("M2" if dialect == 'ngc' else "M30", None))
    return out


# --------------------------------------------------------------------------------------------
# Running the two interpreters
# --------------------------------------------------------------------------------------------

class Runner:
    def __init__(self, ncoffset: str, rs274: str, workdir: str):
        self.ncoffset, self.rs274, self.workdir = ncoffset, rs274, workdir
        self.rs_home = os.path.join(workdir, 'rs274-home')     # rs274 truncates $HOME/.tool.mmap
        os.makedirs(self.rs_home, exist_ok=True)
        self.tool_table = os.path.join(workdir, 'empty.tbl')   # tools come from G41.1 D (diameter)
        open(self.tool_table, 'w').close()
        self.env = dict(os.environ, HOME=self.rs_home,
                        LD_LIBRARY_PATH=os.path.join(os.path.dirname(os.path.dirname(rs274)), 'lib'))

    def run_rs274(self, ngc_path: str) -> tuple[int, str, str]:
        out = ngc_path + '.canon'
        p = subprocess.run([self.rs274, '-g', '-t', self.tool_table, '-v',
                            os.path.join(self.rs_home, 'params.var'), ngc_path, out],
                           env=self.env, stdin=subprocess.DEVNULL, capture_output=True, text=True,
                           timeout=60)
        text = open(out).read() if os.path.exists(out) else ''
        # rs274 -g exits 0 even after some errors; its error text is on stderr ("executing" and
        # the var-file notice are always there).
        err = '\n'.join(l for l in p.stderr.splitlines()
                        if l.strip() and l.strip() != 'executing'
                        and not l.startswith('link (updating variable file)'))
        return p.returncode, text, err

    def run_ncoffset(self, mpf_path: str) -> tuple[int, str, str]:
        p = subprocess.run([self.ncoffset, '--coords', 'wcs', mpf_path], stdin=subprocess.DEVNULL,
                           capture_output=True, text=True, timeout=60)
        return p.returncode, p.stdout, p.stderr


def write_programs(workdir: str, name: str, ngc_lines, mpf_lines):
    ngc = os.path.join(workdir, name + '.ngc')
    mpf = os.path.join(workdir, name.upper() + '.MPF')
    with open(ngc, 'w') as f:
        f.write('\n'.join(t for t, _ in ngc_lines) + '\n')
    with open(mpf, 'w') as f:
        f.write('\n'.join(t for t, _ in mpf_lines) + '\n')
    return ngc, mpf


def plane_lookup(mpf_lines):
    """CSV line number -> normal axis of the plane active there (plane is set once per program)."""
    plane = 'Z'
    for t, _ in mpf_lines:
        if 'G18' in t.split():
            plane = 'Y'
    return lambda _line: plane


# --------------------------------------------------------------------------------------------
# Hand check: the field mapping of both parsers against values derived by hand
# --------------------------------------------------------------------------------------------

HAND = {
    # G17: from X20 Y0, G3 X30 Y10 I0 J10: centre X20 Y10; radius vector -Y -> +X: CCW about +Z.
    #      then G2 X40 Y0 I0 J-10: centre X30 Y0; +Y -> +X: clockwise about +Z.
    'G17': (["G0 X10 Y0 Z0", "G1 X20 F100", "G3 X30 Y10 I0 J10", "G2 X40 Y0 I0 J-10"],
            [Segment('G0', (10, 0, 0)), Segment('G1', (20, 0, 0), feed=100),
             Segment('ARC', (30, 10, 0), (20, 10, 0), True, 'Z', 100),
             Segment('ARC', (40, 0, 0), (30, 0, 0), False, 'Z', 100)]),
    # G18: from X20 Z0, G3 X30 Z-10 I0 K-10: centre X20 Z-10; radius vector +Z -> +X, a quarter
    #      turn about +Y (Z x X = Y): CCW seen from +Y. Then G2 X20 Z-20 I-10 K0: centre X20
    #      Z-10; +X -> -Z the long way round (270 degrees), clockwise seen from +Y.
    'G18': (["G0 X10 Y3 Z0", "G1 X20 F100", "G3 X30 Z-10 I0 K-10", "G2 X20 Z-20 I-10 K0"],
            [Segment('G0', (10, 3, 0)), Segment('G1', (20, 3, 0), feed=100),
             Segment('ARC', (30, 3, -10), (20, 3, -10), True, 'Y', 100),
             Segment('ARC', (20, 3, -20), (20, 3, -10), False, 'Y', 100)]),
}


def hand_check(runner: Runner) -> list[str]:
    problems = []
    for plane, (body, expected) in HAND.items():
        ngc_lines = [(f"G21 G90 G94 G40 G49 {plane}", None)] + [(b, None) for b in body] + [("M2", None)]
        mpf_lines = [(f"G71 G90 G94 {plane}", None)] + [(b, None) for b in body] + [("M30", None)]
        ngc, mpf = write_programs(runner.workdir, f"hand_{plane}", ngc_lines, mpf_lines)
        rc, text, err = runner.run_rs274(ngc)
        if rc != 0 or err:
            problems.append(f"hand check {plane}: rs274 failed ({rc}): {err}")
            continue
        diff = compare_segments(parse_rs274(text), expected)
        if diff:
            problems.append(f"hand check {plane}: rs274 trace parsed against the hand values "
                            f"(left = parsed rs274, right = hand):\n  {diff}")
        rc, text, err = runner.run_ncoffset(mpf)
        if rc != 0:
            problems.append(f"hand check {plane}: ncoffset failed ({rc}): {err.strip()}")
            continue
        diff = compare_segments(parse_ncoffset(text, plane_lookup(mpf_lines)), expected)
        if diff:
            problems.append(f"hand check {plane}: ncoffset CSV against the hand values "
                            f"(left = ncoffset, right = hand):\n  {diff}")
    return problems


# --------------------------------------------------------------------------------------------
# Mode 2: one steady lap of the compensated path
# --------------------------------------------------------------------------------------------

def steady_lap(segs: list[Segment], marker: tuple) -> list[Segment] | None:
    """Segments after the first arrival at `marker` up to and including the second one."""
    hits = [i for i, s in enumerate(segs) if _close(s.end, marker, 2 * TOL)]
    if len(hits) < 2:
        return None
    return segs[hits[0] + 1:hits[1] + 1]



# --------------------------------------------------------------------------------------------
# Mode 2: the contours of tests/support/random_contour.hpp (the property test's generator)
# --------------------------------------------------------------------------------------------

COMP_TOL = 1e-3     # mm: the compensated paths agree within this (rs274 prints 4 decimals)
LAPS = 3


@dataclass
class SharedContour:
    index: int
    plane: str                       # 'G17' or 'G18'
    side: str                        # 'G41' or 'G42'
    radius: float
    decimals: int
    start: tuple
    approach: tuple
    elements: list = field(default_factory=list)   # (kind, end, centre, ccw), plane coordinates


def shared_contours(generator: str, seed: int, count: int, decimals: int) -> list:
    """The contours of ncoffset_random_contours --differential (random_contour.hpp), parsed."""
    p = subprocess.run([generator, '--differential', str(seed), '0', str(count), str(decimals)],
                       capture_output=True, text=True, check=True, timeout=120)
    out, cur = [], None
    for line in p.stdout.splitlines():
        w = line.split()
        if not w:
            continue
        if w[0] == 'contour':
            cur = SharedContour(int(w[1]), w[2], w[3], float(w[4]), int(w[5]), (0, 0), (0, 0))
        elif w[0] == 'start':
            cur.start = (w[1], w[2])
        elif w[0] == 'approach':
            cur.approach = (w[1], w[2])
        elif w[0] == 'line':
            cur.elements.append(('line', (w[1], w[2]), None, False))
        elif w[0] == 'arc':
            cur.elements.append(('arc', (w[1], w[2]), (w[3], w[4]), w[5] == 'ccw'))
        elif w[0] == 'end':
            out.append(cur)
    return out


def shared_blocks(c: SharedContour, dialect: str):
    """The program as (text, role) lines: the contour three times with G41/G42 (LinuxCNC:
    G41.1/G42.1 D<diameter>), approach from and retraction to c.approach, G450 and MD20230 = 0
    (an arc at every convex corner, as LinuxCNC)."""
    A, O, APP, CA, CO = AXES[c.plane]
    out = []
    if dialect == 'ngc':
        out.append((f"(ncoffset differential contour {c.index} {c.plane})", None))
        out.append((f"G21 G90 G94 G40 G49 {c.plane}", None))
    else:
        out.append((f"; ncoffset differential contour {c.index} {c.plane}", None))
        out.append((f"G71 G90 G94 G40 {c.plane}", None))
        out.append((f"$TC_DP1[1,1]=120 $TC_DP6[1,1]={c.radius:.3f}", None))
        out.append(("$MC_CUTCOM_CURVE_INSERT_LIMIT=0", None))
        out.append(("T1 D1", None))
        out.append(("G450 CDOF", None))
    out.append((f"G0 {A}{c.approach[0]} {O}{c.approach[1]} {APP}0", None))
    comp = f"{c.side}.1 D{2 * c.radius:.3f} " if dialect == 'ngc' else f"{c.side} "
    out.append((f"{comp}G1 {A}{c.start[0]} {O}{c.start[1]} F500", None))
    for lap in range(LAPS):
        prev = tuple(float(v) for v in c.start)
        for k, (kind, end, centre, ccw) in enumerate(c.elements):
            if kind == 'line':
                text = f"G1 {A}{end[0]} {O}{end[1]}"
            else:
                # Incremental centre words with the contour's own number of decimals.
                ia = f"{float(centre[0]) - prev[0]:.{c.decimals}f}"
                io = f"{float(centre[1]) - prev[1]:.{c.decimals}f}"
                text = f"{'G3' if ccw else 'G2'} {A}{end[0]} {O}{end[1]} {CA}{ia} {CO}{io}"
            out.append((text, ('el', lap, k)))
            prev = (float(end[0]), float(end[1]))
    out.append((f"G40 G1 {A}{c.approach[0]} {O}{c.approach[1]}", None))
    out.append(("M2" if dialect == 'ngc' else "M30", None))
    return out


def _plane(p: tuple, plane: str) -> tuple:
    """(x, y, z) -> plane coordinates (a, o): G17 (X, Y), G18 (Z, X)."""
    return (p[2], p[0]) if plane == 'G18' else (p[0], p[1])


def _pieces(segs: list, plane: str) -> list:
    """Segments -> plane pieces (start, end, centre or None, ccw)."""
    out = []
    for i in range(1, len(segs)):
        a, b = segs[i - 1], segs[i]
        s, e = _plane(a.end, plane), _plane(b.end, plane)
        if b.kind == 'ARC':
            out.append((s, e, _plane(b.centre, plane), b.ccw))
        elif math.dist(s, e) > 0:
            out.append((s, e, None, False))
    return out


def _sweep(c, s, e, ccw):
    a0, a1 = math.atan2(s[1] - c[1], s[0] - c[0]), math.atan2(e[1] - c[1], e[0] - c[0])
    d = (a1 - a0) if ccw else (a0 - a1)
    d %= 2 * math.pi
    return d if d > 1e-12 else 2 * math.pi


def _sample(piece, n=12):
    s, e, c, ccw = piece
    if c is None:
        return [(s[0] + (e[0] - s[0]) * j / n, s[1] + (e[1] - s[1]) * j / n) for j in range(n + 1)]
    r0, r1 = math.dist(s, c), math.dist(e, c)
    a0, sw = math.atan2(s[1] - c[1], s[0] - c[0]), _sweep(c, s, e, ccw)
    pts = []
    for j in range(n + 1):
        a = a0 + (1 if ccw else -1) * sw * j / n
        r = r0 + (r1 - r0) * j / n
        pts.append((c[0] + r * math.cos(a), c[1] + r * math.sin(a)))
    return pts


def _distance(q, piece) -> float:
    s, e, c, ccw = piece
    if c is None:
        dx, dy = e[0] - s[0], e[1] - s[1]
        t = max(0.0, min(1.0, ((q[0] - s[0]) * dx + (q[1] - s[1]) * dy) / (dx * dx + dy * dy)))
        return math.hypot(q[0] - s[0] - t * dx, q[1] - s[1] - t * dy)
    sw = _sweep(c, s, e, ccw)
    aq = math.atan2(q[1] - c[1], q[0] - c[0])
    d = ((aq - math.atan2(s[1] - c[1], s[0] - c[0])) if ccw
         else (math.atan2(s[1] - c[1], s[0] - c[0]) - aq)) % (2 * math.pi)
    if d <= sw:
        r = math.dist(s, c) + (math.dist(e, c) - math.dist(s, c)) * d / sw
        return abs(math.dist(q, c) - r)
    return min(math.dist(q, s), math.dist(q, e))


def path_distance(a: list, b: list) -> tuple:
    """The largest distance of a sampled point of path a from path b, and the point."""
    worst, at = 0.0, None
    for piece in a:
        for q in _sample(piece):
            d = min(_distance(q, other) for other in b)
            if d > worst:
                worst, at = d, q
    return worst, at


def curved_outside_crossing(c: SharedContour) -> bool:
    """A documented exception: an outside corner (for the tool) at which the two equidistants
    still cross inside both elements (an arc bending back over its neighbour): ncoffset trims the
    corner there, LinuxCNC goes round it on its arc."""
    n = len(c.elements)
    side = 1 if c.side == 'G41' else -1
    pts = [tuple(float(v) for v in c.start)] + [tuple(float(v) for v in el[1]) for el in c.elements]

    def el(k):
        kind, end, centre, ccw = c.elements[k]
        return (pts[k], pts[k + 1], None if kind == 'line' else tuple(float(v) for v in centre), ccw)

    def tangent(piece, at_end):
        s, e, cc, ccw = piece
        if cc is None:
            d = math.dist(s, e)
            return ((e[0] - s[0]) / d, (e[1] - s[1]) / d)
        q = e if at_end else s
        r = math.dist(q, cc)
        rx, ry = (q[0] - cc[0]) / r, (q[1] - cc[1]) / r
        return (-ry, rx) if ccw else (ry, -rx)

    def offset(piece):
        s, e, cc, ccw = piece
        if cc is None:
            t = tangent(piece, False)
            nx, ny = -side * t[1] * c.radius, side * t[0] * c.radius
            return ((s[0] + nx, s[1] + ny), (e[0] + nx, e[1] + ny), None, False)
        k = -1 if (ccw == (side > 0)) else 1       # the left side of a ccw arc is its inside
        r0, r1 = math.dist(s, cc) + k * c.radius, math.dist(e, cc) + k * c.radius
        if r0 <= 0 or r1 <= 0:
            return None
        f0, f1 = r0 / math.dist(s, cc), r1 / math.dist(e, cc)
        return ((cc[0] + f0 * (s[0] - cc[0]), cc[1] + f0 * (s[1] - cc[1])),
                (cc[0] + f1 * (e[0] - cc[0]), cc[1] + f1 * (e[1] - cc[1])), cc, ccw)

    def crossings(p, q):
        if p[2] is None and q[2] is None:
            return []
        if p[2] is None or q[2] is None:
            l, ci = (p, q) if p[2] is None else (q, p)
            (x0, y0), (x1, y1), cc, r = l[0], l[1], ci[2], math.dist(ci[0], ci[2])
            dx, dy = x1 - x0, y1 - y0
            fx, fy = x0 - cc[0], y0 - cc[1]
            A, B, C = dx * dx + dy * dy, 2 * (fx * dx + fy * dy), fx * fx + fy * fy - r * r
            disc = B * B - 4 * A * C
            if disc < 0:
                return []
            return [(x0 + t * dx, y0 + t * dy) for t in ((-B - math.sqrt(disc)) / (2 * A),
                                                        (-B + math.sqrt(disc)) / (2 * A))]
        c1, r1, c2, r2 = p[2], math.dist(p[0], p[2]), q[2], math.dist(q[0], q[2])
        d = math.dist(c1, c2)
        if d < 1e-12:
            return []
        a = (r1 * r1 - r2 * r2 + d * d) / (2 * d)
        h2 = r1 * r1 - a * a
        if h2 < 0:
            return []
        h, ux, uy = math.sqrt(h2), (c2[0] - c1[0]) / d, (c2[1] - c1[1]) / d
        mx, my = c1[0] + a * ux, c1[1] + a * uy
        return [(mx - h * uy, my + h * ux), (mx + h * uy, my - h * ux)]

    def inside(piece, x, margin=1e-6):
        s, e, cc, ccw = piece
        if cc is None:
            dx, dy = e[0] - s[0], e[1] - s[1]
            L = math.hypot(dx, dy)
            t = ((x[0] - s[0]) * dx + (x[1] - s[1]) * dy) / L
            return margin < t < L - margin
        sw = _sweep(cc, s, e, ccw)
        a0 = math.atan2(s[1] - cc[1], s[0] - cc[0])
        ax = math.atan2(x[1] - cc[1], x[0] - cc[0])
        d = ((ax - a0) if ccw else (a0 - ax)) % (2 * math.pi)
        r = math.dist(s, cc)
        return margin < d * r < sw * r - margin

    for k in range(n):
        p, q = el((k - 1) % n), el(k)
        if p[2] is None and q[2] is None:
            continue
        t1, t2 = tangent(p, True), tangent(q, False)
        if side * (t1[0] * t2[1] - t1[1] * t2[0]) >= 0:
            continue                                  # not an outside corner for the tool
        op, oq = offset(p), offset(q)
        if op is None or oq is None:
            continue
        if any(inside(op, x) and inside(oq, x) for x in crossings(op, oq)):
            return True
    return False


def run_compensated(args, runner, t_start) -> tuple:
    """Mode 2: (failures, summary line)."""
    generator = args.generator or os.path.join(os.path.dirname(os.path.abspath(args.ncoffset)),
                                               'tests', 'ncoffset_random_contours')
    contours = shared_contours(generator, args.seed, args.count, args.decimals)
    failures, agree, exceptions, g17, g18, worst_all, arcs = [], 0, 0, 0, 0, 0.0, 0
    for c in contours:
        name = f"s{c.index:04d}_{c.plane}"
        if curved_outside_crossing(c):
            exceptions += 1
            if args.verbose:
                print(f"{name}: skipped (an outside corner whose equidistants cross)")
            continue
        ngc_lines, mpf_lines = shared_blocks(c, 'ngc'), shared_blocks(c, 'mpf')
        ngc, mpf = write_programs(runner.workdir, name, ngc_lines, mpf_lines)
        rc, rs_text, rs_err = runner.run_rs274(ngc)
        if rc != 0 or rs_err:
            failures.append(f"{name}: rs274 refused the program ({rc}): {rs_err}\n    {ngc}")
            continue
        rc, nc_text, nc_err = runner.run_ncoffset(mpf)
        if rc != 0:
            failures.append(f"{name}: ncoffset failed ({rc}): {nc_err.strip()}\n    {mpf}")
            continue
        rs = parse_rs274(rs_text)
        nc = parse_ncoffset(nc_text, plane_lookup(mpf_lines))
        # One full steady lap of each: between two passes through a point of ncoffset's lap 2
        # that rs274's path contains too (a sharp corner's point is the same in both).
        lap2 = {1 + k for k, (_, role) in enumerate(mpf_lines) if role and role[1] == 1}
        laps = None
        for cand in (sg for sg in nc if sg.line in lap2):
            nc_lap, rs_lap = steady_lap(nc, cand.end), steady_lap(rs, cand.end)
            if nc_lap is not None and rs_lap is not None:
                laps = ([cand] + nc_lap, [cand] + rs_lap)
                break
        if laps is None:
            failures.append(f"{name}: no point of ncoffset's lap 2 recurs in rs274's path\n"
                            f"    {ngc}\n    {mpf}")
            continue
        a, b = _pieces(laps[0], c.plane), _pieces(laps[1], c.plane)
        d1, at1 = path_distance(a, b)
        d2, at2 = path_distance(b, a)
        worst = max(d1, d2)
        worst_all = max(worst_all, worst)
        if worst > COMP_TOL:
            at = at1 if d1 >= d2 else at2
            failures.append(f"{name} ({c.plane}, {c.side}, R {c.radius}): the tool-centre paths "
                            f"differ by {worst:.6f} mm at ({at[0]:.4f}, {at[1]:.4f}) "
                            f"(plane coordinates)\n    {ngc}\n    {mpf}")
            continue
        agree += 1
        g17 += c.plane == 'G17'
        g18 += c.plane == 'G18'
        arcs += sum(1 for e in c.elements if e[0] == 'arc')
        if args.verbose:
            print(f"{name}: agree within {worst:.2e} mm")
    elapsed = time.monotonic() - t_start
    summary = (f"differential_rs274 [compensated, random_contour.hpp contours with {args.decimals} "
               f"decimals, seed {args.seed}]: {agree} of {len(contours)} contours agree within "
               f"{COMP_TOL} mm ({g17} G17, {g18} G18, {arcs} arcs; largest difference "
               f"{worst_all:.2e} mm), {exceptions} left out (outside corners whose equidistants "
               f"cross), {len(failures)} disagree, in {elapsed:.1f} s")
    return failures, summary

# --------------------------------------------------------------------------------------------

def find_rs274(args) -> str | None:
    if args.rs274:
        return args.rs274
    setup = os.path.join(HERE, 'setup_rs274.sh')
    cmd = ['bash', setup] + ([args.rs274_cache] if args.rs274_cache else [])
    p = subprocess.run(cmd, stdin=subprocess.DEVNULL, capture_output=True, text=True)
    if p.returncode == SKIP:
        print(p.stderr.strip() or "setup_rs274.sh: rs274 cannot be had here", file=sys.stderr)
        return None
    if p.returncode != 0:
        raise SystemExit(f"setup_rs274.sh failed ({p.returncode}):\n{p.stderr}")
    return p.stdout.strip().splitlines()[-1]


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    ap.add_argument('--ncoffset', required=True, help='path of the ncoffset binary')
    ap.add_argument('--rs274', help='path of rs274 (default: installed by setup_rs274.sh)')
    ap.add_argument('--rs274-cache', help='cache directory handed to setup_rs274.sh')
    ap.add_argument('-n', '--count', type=int, default=40, help='number of contours (default 40)')
    ap.add_argument('--seed', type=int, default=1, help='generator seed (default 1)')
    ap.add_argument('--compensated', action='store_true',
                    help='mode 2: the contours of tests/support/random_contour.hpp with G41/G42 '
                         'and G450, compare one steady lap of the tool-centre paths')
    ap.add_argument('--generator', help='mode 2: ncoffset_random_contours (default: '
                                        'tests/ncoffset_random_contours beside --ncoffset)')
    ap.add_argument('--decimals', type=int, default=4,
                    help='mode 2: decimals of the coordinates (3, 4 or 6; default 4)')
    ap.add_argument('--keep', help='write the programs and outputs here (kept afterwards)')
    ap.add_argument('-v', '--verbose', action='store_true')
    args = ap.parse_args()

    t_start = time.monotonic()
    rs274 = find_rs274(args)
    if rs274 is None:
        print("differential_rs274: SKIP: LinuxCNC's rs274 is not available")
        return SKIP
    workdir = args.keep or tempfile.mkdtemp(prefix='ncoffset-differential-')
    os.makedirs(workdir, exist_ok=True)
    runner = Runner(os.path.abspath(args.ncoffset), rs274, workdir)
    failures = []
    keep = bool(args.keep)
    try:
        problems = hand_check(runner)
        if problems:
            print('\n'.join(problems))
            print("differential_rs274: FAIL: the hand check of the trace/CSV field mapping failed")
            keep = True
            return 1

        if args.compensated:
            failures, summary = run_compensated(args, runner, t_start)
            for f in failures:
                print(f"DISAGREEMENT {f}")
            print(summary)
            print(f"differential: {args.count - len(failures)} passed or left out, "
                  f"{len(failures)} failed")
            return 1 if failures else 0
        mode = 'programmed path (G40)'
        totals = dict(contours=0, segments=0, contour_segments=0, arcs=0, over180=0, convex=0,
                      concave=0, g17=0, g18=0)
        for i in range(args.count):
            c = generate(i, args.seed)
            ngc_lines = blocks(c, 'ngc')
            mpf_lines = blocks(c, 'mpf')
            name = f"c{i:03d}_{c.plane}"
            ngc, mpf = write_programs(workdir, name, ngc_lines, mpf_lines)
            rc, rs_text, rs_err = runner.run_rs274(ngc)
            if rc != 0 or rs_err:
                failures.append(f"{name}: rs274 refused the program ({rc}): {rs_err}\n    {ngc}")
                continue
            rc, nc_text, nc_err = runner.run_ncoffset(mpf)
            if rc != 0:
                failures.append(f"{name}: ncoffset failed ({rc}): {nc_err.strip()}\n    {mpf}")
                continue
            with open(os.path.join(workdir, name + '.csv'), 'w') as f:
                f.write(nc_text)
            rs = parse_rs274(rs_text)
            nc = parse_ncoffset(nc_text, plane_lookup(mpf_lines))
            diff = compare_segments(nc, rs)
            if diff:
                failures.append(f"{name} ({c.plane}, {'CCW' if c.ccw else 'CW'} contour): {diff}\n"
                                f"    {ngc}\n    {mpf}")
                continue
            totals['contours'] += 1
            totals[c.plane.lower()] += 1
            totals['segments'] += len(nc)
            totals['contour_segments'] += len(c.elements)
            totals['arcs'] += sum(1 for e in c.elements if e.kind == 'arc')
            totals['over180'] += c.arcs_over_180
            totals['convex'] += c.convex
            totals['concave'] += c.concave
            if args.verbose:
                print(f"{name}: {len(nc)} segments agree")
        elapsed = time.monotonic() - t_start
        for f in failures:
            print(f"DISAGREEMENT {f}")
        t = totals
        print(f"differential_rs274 [{mode}, seed {args.seed}]: {t['contours']} of {args.count} contours "
              f"agree ({t['g17']} G17, {t['g18']} G18): {t['segments']} segments compared, "
              f"{t['contour_segments']} contour elements ({t['arcs']} arcs, {t['over180']} over 180 deg; "
              f"{t['convex']} convex and {t['concave']} concave corners) in {elapsed:.1f} s")
        print(f"differential: {t['contours']} passed, {len(failures)} failed")
        return 1 if failures else 0
    finally:
        if failures or keep:
            print(f"programs kept in {workdir}")
        else:
            shutil.rmtree(workdir, ignore_errors=True)


if __name__ == '__main__':
    sys.exit(main())
