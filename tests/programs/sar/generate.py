#!/usr/bin/env python3
"""Writes the pending smooth approach and retraction (SAR, G147...G348) golden cases of this
folder: NAME.MPF (header comment with the hand derivation + program) and NAME.expected, and the
case table of README.md (between the '<!-- cases -->' markers).

Nothing here implements SAR: every case states its inputs and its construction (tangent t, left
normal n_L, side u = sigma*n_L, contour radius r, centre M, points P1..P4, compensated points
C1/C3/C4, the feed of every sub-block and why) in the MPF header, and this script only does the
arithmetic of those formulas, the line numbering and the mapping of plane coordinates
(a, o, applicate) onto X, Y, Z. The formulas are the ones of README.md ('Construction'); the
manual examples S-1 and S-2 are written out with literal numbers.

Run: python3 tests/programs/sar/generate.py   (deterministic)
"""
import math
import os
import re
import textwrap

HERE = os.path.dirname(os.path.abspath(__file__))
CASES = []
EPS = 1e-9

# ------------------------------------------------------------------------------------------
# formatting helpers (same conventions as tests/programs-pending/trc/generate.py)

LETTERS = {17: ("X", "Y", "Z"), 18: ("Z", "X", "Y"), 19: ("Y", "Z", "X")}
PLANE_TXT = {17: "G17: a=X, o=Y, applicate Z",
             18: "G18: a=Z, o=X, applicate Y (CSV columns x=o, y=app, z=a)",
             19: "G19: a=Y, o=Z, applicate X (CSV columns x=app, y=a, z=o)"}
CONV = ("Conventions (README.md): plane coords (a,o,app); t = unit tangent; n_L = (-t_o, t_a); "
        "G41 centre = P + R*n_L, G42 centre = P - R*n_L; G2/G3 = sense in (a,o) seen from +app.")


def xyz(plane, p):
    a, o, n = p
    if plane == 17:
        return (a, o, n)
    if plane == 18:
        return (o, n, a)
    return (n, a, o)


def num(v):
    if abs(v) < 5e-10:
        v = 0.0
    s = f"{v:.9f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def f6(v):
    if abs(v) < 5e-7:
        v = 0.0
    s = f"{v:.6f}".rstrip("0").rstrip(".")
    return "0" if s == "-0" else s


def P(p):
    return "(" + ",".join(f6(c) for c in p) + ")"


def words(plane, a=None, o=None, n=None):
    L = LETTERS[plane]
    return " ".join(f"{L[k]}{num(v)}" for k, v in enumerate((a, o, n)) if v is not None)


def add(name, plane, header, body, rows, status=0, errs=(), meta=None):
    """body: list of strings; '@lab text' gives the line a label.
    rows: (label, motion, (a,o,app), centre (a,o,app) or None, feed or None)
    errs: (label, kind, number).  meta: (checks, spec, readings) for the README table."""
    CASES.append((name, plane, header, body, rows, status, errs, meta))


def write_all():
    names = set()
    for name, plane, header, body, rows, status, errs, meta in CASES:
        assert name not in names, name
        names.add(name)
        hdr = []
        for h in header:
            ind = len(h) - len(h.lstrip(" "))
            hdr += [("; " + w).rstrip() for w in textwrap.wrap(
                h, 98, initial_indent="", subsequent_indent=" " * (ind + 2),
                break_long_words=False, break_on_hyphens=False)] or [";"]
        labels = {}
        text = []
        for k, b in enumerate(body):
            if b.startswith("@"):
                lab, b = b[1:].split(" ", 1)
                assert lab not in labels, (name, lab)
                labels[lab] = len(hdr) + k + 1
            text.append(b)
        lines = hdr + text
        for l in lines:
            assert all(32 <= ord(c) < 127 for c in l), (name, l)
        with open(os.path.join(HERE, name + ".MPF"), "w", newline="\n") as f:
            f.write("\n".join(lines) + "\n")
        out = []
        if status:
            out.append(f"# status: {status}")
        for lab, kind, no in errs:
            out.append(f"# stderr: {name}.MPF:{labels[lab]}: {kind} {no}: *")
        out.append("line,motion,x,y,z,cx,cy,cz,feed")
        for lab, motion, p, c, feed in rows:
            x, y, z = xyz(plane, p)
            cs = ",," if c is None else ",".join(num(v) for v in xyz(plane, c))
            fs = "" if motion == "G0" else num(feed)
            out.append(f"{labels[lab]},{motion},{num(x)},{num(y)},{num(z)},{cs},{fs}")
        with open(os.path.join(HERE, name + ".expected"), "w", newline="\n") as f:
            f.write("\n".join(out) + "\n")
    write_readme_table()
    print(f"{len(CASES)} cases written")


def write_readme_table():
    path = os.path.join(HERE, "README.md")
    if not os.path.exists(path):
        return
    with open(path) as f:
        text = f.read()
    rows = ["| case | checks | spec | readings |", "|---|---|---|---|"]
    for name, plane, header, body, r, status, errs, meta in CASES:
        checks, spec, rd = meta
        rows.append(f"| {name} | {checks} | {spec} | {', '.join(rd)} |")
    table = "\n".join(rows)
    new = re.sub(r"<!-- cases -->.*<!-- /cases -->",
                 lambda m: "<!-- cases -->\n" + table + "\n<!-- /cases -->", text, flags=re.S)
    with open(path, "w", newline="\n") as f:
        f.write(new)


# ------------------------------------------------------------------------------------------
# plane vector helpers

def vadd(p, q):
    return (p[0] + q[0], p[1] + q[1])


def vsub(p, q):
    return (p[0] - q[0], p[1] - q[1])


def vmul(k, p):
    return (k * p[0], k * p[1])


def unit(v):
    d = math.hypot(v[0], v[1])
    return (v[0] / d, v[1] / d)


def nl(t):
    """left normal of t (t rotated +90 deg about +applicate)"""
    return (-t[1], t[0])


def rot_m90(v):
    return (v[1], -v[0])


def cross(u, v):
    return u[0] * v[1] - u[1] * v[0]


def same(p, q):
    return abs(p[0] - q[0]) < EPS and abs(p[1] - q[1]) < EPS


def sweep(m, a, b, sigma):
    """angle swept from a to b about m in the sense sigma (+1 CCW, -1 CW), in degrees 0..360"""
    aa = math.atan2(a[1] - m[1], a[0] - m[0])
    bb = math.atan2(b[1] - m[1], b[0] - m[0])
    d = math.degrees((bb - aa) * sigma) % 360.0
    return d


def arc_tangent(m, p, sigma):
    rv = unit(vsub(p, m))
    return nl(rv) if sigma > 0 else rot_m90(rv)


def tool(r):
    return ["$TC_DP1[1,1]=120", f"$TC_DP6[1,1]={num(r)}", "T1 D1"]


def param(name, v):
    """DISCL=3 / DISCL=AC(5) / FAD=PM(300) ..."""
    if v is None:
        return ""
    if isinstance(v, tuple):
        return f" {name}={v[0]}({num(v[1])})"
    return f" {name}={num(v)}"


def circle_roots(p, q, m, r):
    """parameters s of the points p + s*(q-p) on the circle (m, r)."""
    d = vsub(q, p)
    f = vsub(p, m)
    A = d[0] ** 2 + d[1] ** 2
    B = 2 * (f[0] * d[0] + f[1] * d[1])
    C = f[0] ** 2 + f[1] ** 2 - r * r
    disc = B * B - 4 * A * C
    if disc < -1e-9:
        return []
    disc = math.sqrt(max(disc, 0))
    return sorted([(-B - disc) / (2 * A), (-B + disc) / (2 * A)])


def app_target(base, v, what):
    """incremental value measured along +applicate from base, or AC(v) absolute."""
    if v is None:
        return None
    if isinstance(v, tuple):
        assert v[0] == "AC"
        return v[1], f"{what}=AC({num(v[1])}) -> absolute {f6(v[1])}"
    return base + v, f"{what}={num(v)} -> P4.app + {num(v)} = {f6(base + v)}"


def monotonic(seq):
    d = [b - a for a, b in zip(seq, seq[1:]) if abs(b - a) > EPS]
    return all(x > 0 for x in d) or all(x < 0 for x in d)


SIDE_TXT = {141: "G141: approach/retract from/to the left -> sigma = +1",
            142: "G142: from/to the right -> sigma = -1"}

# ------------------------------------------------------------------------------------------
# the construction shared by the approach cases (README 'Construction', readings V1..V4)


def side_of(side, s, p0p, p4p, t, retract=False):
    """returns (sigma, text)"""
    eff, txt = side, []
    if side == 140:
        if s == 0:
            eff = 143
            txt.append("G140 with G40 behaves like G143 (spec 6.1, FM 828D p1466)")
        else:
            eff = 141 if s > 0 else 142
            txt.append(f"G140 with G4{1 if s > 0 else 2}"
                       + (" (active before the SAR block, reading K2)" if retract else "")
                       + f" -> {'left' if s > 0 else 'right'}")
    if eff == 143:
        c = cross(t, vsub(p0p, p4p))
        assert abs(c) > 1e-6
        sigma = 1 if c > 0 else -1
        txt.append(f"G143: cross(t, P0-P4) = {f6(c)} {'> 0: P0 left' if c > 0 else '< 0: P0 right'}"
                   f" of the tangent line at P4 -> sigma = {sigma:+d}")
    elif eff in (141, 142):
        sigma = 1 if eff == 141 else -1
        if side != 140:
            txt.append(SIDE_TXT[eff])
        else:
            txt.append(f"-> sigma = {sigma:+d}")
    return sigma, "; ".join(txt)


def contour_radius(disr, R, s, sigma):
    if s == 0:
        return disr, f"G40: R counts as 0 -> contour radius r = DISR = {f6(disr)}"
    inside = (sigma == s)
    if inside:
        return disr + R, (f"tool on the inside of the arc (G4{1 if s > 0 else 2} and sense "
                          f"G{3 if sigma > 0 else 2}) -> r = DISR + R = {f6(disr + R)}")
    return disr - R, (f"tool on the outside of the arc (G4{1 if s > 0 else 2} and sense "
                      f"G{3 if sigma > 0 else 2}) -> r = DISR - R = {f6(disr - R)}")


def approach(name, plane, *, title, spec, readings, checks, R=5.0, trc=41, kind=2, g34=340,
             side=None, write_g34=True, disr, discl=None, disrp=None, fad=None, f_sar=None,
             prev=("G0", 300.0), p0, p4, cont_end, p4_src="sar", pre_dummies=(),
             post_dummies=(), setup=(), sar_words="", trailer=(), trailer_rows=(),
             extra_hdr=(), write_side=True, row_map=None):
    s = {41: 1, 42: -1, 40: 0}[trc]
    p0p, p4p = p0[:2], p4[:2]
    t = unit(vsub(cont_end, p4p))
    n = nl(t)
    hdr = [f"{name}: {title}", f"Spec: {spec}. Readings (README): {', '.join(readings)}.",
           CONV, PLANE_TXT[plane] + "."]
    hdr.append(f"Tool R = {f6(R)}, " + (f"G4{1 if s > 0 else 2} selected in the SAR block (the "
                                         "first sub-block with plane motion is the NORM selection "
                                         "block, spec 6.5)." if s else
                                         "G40: no compensation, rows = programmed SAR contour."))
    hdr.append(f"P0 = {P(p0)} (end of the previous block, {prev[0]}, modal F{num(prev[1])}).")
    src = {"sar": "programmed in the SAR block",
           "next": "from the next traversing block (the SAR block has no geometry axis)",
           "next_xy": "plane axes from the next traversing block, applicate from the SAR block"}
    hdr.append(f"P4 = {P(p4)} {src[p4_src]}. Tangent block ends at {P(cont_end)}: t = {P(t)}, "
               f"n_L = {P(n)}.")
    hdr += list(extra_hdr)
    # --- side, radius, P3 in the plane
    if kind == 1:
        L = (R if s and R > 0 else 0) + disr
        assert L > 0
        p3p = vsub(p4p, vmul(L, t))
        hdr.append(f"G147: line of length L = {'R + ' if s else ''}DISR = {f6(L)} ending in P4 along "
                   f"t -> P3 (plane) = P4 - L*t = {P(p3p)}.")
        motion, M, sigma = "G1", None, 0
        t3 = t
    else:
        sigma, stxt = side_of(side, s, p0p, p4p, t)
        r, rtxt = contour_radius(disr, R, s, sigma)
        assert r > 0
        M = vadd(p4p, vmul(r * sigma, n))
        hdr.append(f"Side: {stxt}; u = sigma*n_L = {P(vmul(sigma, n))}; sense "
                   f"G{3 if sigma > 0 else 2}.")
        hdr.append(f"Radius: {rtxt}. Centre M = P4 + r*u = {P(M)}.")
        if kind == 2:
            p3p = vsub(M, vmul(r, t))
            hdr.append(f"G247 quarter circle: P3 (plane) = M - r*t = {P(p3p)}.")
        else:
            p3p = vadd(p4p, vmul(2 * r * sigma, n))
            hdr.append(f"G347 semicircle: P3 (plane) = P4 + 2r*u = {P(p3p)}.")
        motion = "G3" if sigma > 0 else "G2"
        rv = unit(vsub(p3p, M))
        t3 = nl(rv) if sigma > 0 else rot_m90(rv)
        # independent checks: the arc ends in P4 tangent to t after 90 / 180 degrees
        assert same(arc_tangent(M, p4p, sigma), t)
        assert abs(sweep(M, p3p, p4p, sigma) - (90 if kind == 2 else 180)) < 1e-7
    # --- applicates
    app4 = p4[2]
    a2 = app_target(app4, discl, "DISCL")
    if a2 is None:
        app2, txt2 = app4, "DISCL not programmed -> read as DISCL=0 (reading Z2)"
    else:
        app2, txt2 = a2
    a1 = app_target(app4, disrp, "DISRP")
    if a1 is None:
        app1, txt1 = p0[2], f"no DISRP -> P1.app = P0.app = {f6(p0[2])}"
    else:
        app1, txt1 = a1
    app3 = app2 if g34 == 340 else app4
    seq = [p0[2], app1, app2, app3, app4]
    assert monotonic(seq), (name, seq)
    p1, p2, p3, p4_ = (*p3p, app1), (*p3p, app2), (*p3p, app3), p4
    hdr.append(f"Applicates: {txt1}; {txt2}; G{g34}: P3.app = "
               + ("P2.app" if g34 == 340 else "P4.app") + f" = {f6(app3)}. Sequence "
               + " -> ".join(f6(v) for v in seq) + " is monotonic (no reversal).")
    hdr.append(f"Points: P1 = {P(p1)}, P2 = {P(p2)}, P3 = {P(p3)}, P4 = {P(p4_)}"
               + (f"; helix (P3 not in the plane of P4)" if kind > 1 and abs(app3 - app4) > EPS
                  else "") + ".")
    # --- compensation
    comp = (lambda p, tan: vadd(p, vmul(s * R, nl(tan))))
    c1p, c4p = comp(p3p, t3), comp(p4p, t)
    cend = comp(cont_end, t)
    if s:
        hdr.append(f"TRC: curve start tangent t3 = {P(t3)} -> C1 = C3 = P3 {'+' if s > 0 else '-'} "
                   f"R*n_L(t3) = {P(c1p)} (NORM end of the selection sub-block); C4 = P4 "
                   f"{'+' if s > 0 else '-'} R*n_L(t) = {P(c4p)}; contour end {P(cend)}.")
        if M is not None:
            assert abs(math.dist(c1p, M) - disr) < 1e-9 and abs(math.dist(c4p, M) - disr) < 1e-9
            hdr.append(f"  Check: |C1-M| = |C4-M| = {f6(disr)} = DISR (centre path radius).")
    assert not same(p0p, c1p), "P0->P1 needs plane motion"
    if M is not None:
        roots = circle_roots(p0p, c1p, M, math.dist(c1p, M))
        others = [x for x in roots if abs(x - 1) > 1e-7]
        assert all(x > 1 - 1e-9 for x in others), (name, roots)
        hdr.append("  The line P0 -> C1 meets the centre-path circle first at C1 (other root "
                   + (f"s = {f6(others[0])} > 1" if others else "none") + "): nothing cut.")
    # --- feeds (readings V1..V4)
    fast, fprev = prev
    fslow = fad[1] if isinstance(fad, tuple) else fad
    if g34 == 341:
        f_c = fslow if fad is not None else (f_sar if f_sar is not None else fprev)
        f_d = f_sar if f_sar is not None else fprev
    else:
        f_c = None
        f_d = fslow if fad is not None else (f_sar if f_sar is not None else fprev)
    f_after = f_sar if f_sar is not None else fprev
    dline = "sar" if p4_src == "sar" else "p4"
    rows, tab = [], []
    pa = c1p if s else p3p
    rows.append(("sar", fast, (*pa, app1), None, fprev))
    tab.append(f"A  P0->P1 {fast}{'' if fast == 'G0' else ' F' + num(fprev)} to {P((*pa, app1))} "
               "(velocity of the block before the SAR block, V1)"
               + (" = TRC selection" if s else ""))
    if abs(app2 - app1) > EPS:
        rows.append(("sar", fast, (*pa, app2), None, fprev))
        tab.append(f"B  P1->P{'3' if g34 == 340 else '2'} {fast} to {P((*pa, app2))} (fast infeed, V1)")
    else:
        tab.append("B  P1->P2 zero length: no row")
    if g34 == 341:
        if abs(app3 - app2) > EPS:
            rows.append(("sar", "G1", (*pa, app3), None, f_c))
            tab.append(f"C  P2->P3 G1 F{num(f_c)} to {P((*pa, app3))} ("
                       + ("FAD" if fad is not None else "no FAD: F of the SAR block" if f_sar
                          is not None else "no FAD, no F: modal F") + ", V2)")
        else:
            tab.append("C  P2->P3 zero length: no row")
    ce = c4p if s else p4p
    if kind == 1:
        rows.append((dline, "G1", (*ce, app4), None, f_d))
    else:
        rows.append((dline, motion, (*ce, app4), (*M, app3), f_d))
    why = ("G341: F of the SAR block" if f_sar is not None else "G341: modal F") if g34 == 341 \
        else ("G340: FAD" if fad is not None else "G340 no FAD: F of the SAR block"
              if f_sar is not None else "G340 no FAD, no F: modal F")
    tab.append(f"D  P3->P4 {motion} F{num(f_d)} to {P((*ce, app4))}"
               + (f" centre {P((*M, app3))}" if M is not None else "") + f" ({why}, V2/V3)"
               + ("" if p4_src == "sar" else "; row of the P4 block (V5)"))
    cr = cend if s else cont_end
    rows.append(("tan", "G1", (*cr, app4), None, f_after))
    tab.append(f"Tangent block G1 to {P((*cr, app4))} F{num(f_after)} (F of the SAR block stays "
               "modal, FAD does not)" + (" - compensated, ends on its normal" if s else ""))
    hdr.append("Sub-blocks:")
    hdr += ["  " + x for x in tab]
    # --- body
    Lw = LETTERS[plane]
    sar = ("" if not s else f"G4{1 if s > 0 else 2} ") + f"G{kind}47"
    if write_g34:
        sar += f" G{g34}"
    if side is not None and write_side:
        sar += f" G{side}"
    if side is not None and not write_side:
        hdr.append(f"G{side} is the initial setting and is not written in the program.")
    sar += param("DISR", disr) + param("DISCL", discl) + param("DISRP", disrp) + param("FAD", fad)
    if p4_src == "sar":
        sar += " " + words(plane, *p4)
    elif p4_src == "next_xy":
        sar += " " + words(plane, None, None, p4[2])
    if f_sar is not None:
        sar += f" F{num(f_sar)}"
    sar += sar_words
    body = tool(R) + list(setup)
    body.append(f"@p0 G{plane} G90 {fast} {words(plane, *p0)} F{num(fprev)}")
    body.append("@sar " + sar)
    body += list(pre_dummies)
    if p4_src == "next":
        body.append("@p4 G1 " + words(plane, *p4))
    elif p4_src == "next_xy":
        body.append("@p4 G1 " + words(plane, *p4p))
    body += list(post_dummies)
    body.append("@tan G1 " + words(plane, *cont_end))
    body += list(trailer)
    body.append("M30")
    allrows = [("p0", fast, p0, None, fprev)] + rows
    if row_map is not None:
        allrows = [(lab, m, row_map(p), None if c is None else row_map(c), f)
                   for lab, m, p, c, f in allrows]
    allrows += list(trailer_rows)
    add(name, plane, hdr, body, allrows, meta=(checks, spec, readings))
    return dict(p3=p3, p4=p4_, c4=c4p, cend=cend, app4=app4, f_after=f_after)


# ------------------------------------------------------------------------------------------
# the construction shared by the retraction cases (reverse order P4 -> P3 -> P2 -> P1 -> P0)

def retraction(name, plane, *, title, spec, readings, checks, R=5.0, trc=41, kind=2, g34=340,
               side=None, disr, discl=None, disrp=None, fad=None, f_sar=None, sar_motion="G1",
               write_motion=False, start, sel=None, p4, p0, prev_f=400.0, extra_hdr=(),
               write_side=True):
    s = {41: 1, 42: -1, 40: 0}[trc]
    p0p, p4p = p0[:2], p4[:2]
    if sel is None:
        assert s == 0
        sel_pt = start[:2]
    else:
        sel_pt = sel
    t = unit(vsub(p4p, sel_pt))
    n = nl(t)
    app4 = p4[2]
    hdr = [f"{name}: {title}", f"Spec: {spec}. Readings (README): {', '.join(readings)}.",
           CONV, PLANE_TXT[plane] + "."]
    hdr.append(f"Tool R = {f6(R)}; " + (f"G4{1 if s > 0 else 2} active on the contour, G40 in the "
                                         "retraction block: its last sub-block with plane motion "
                                         "(P1->P0) is the NORM deselection block (reading K1)."
                                         if s else "G40: no compensation."))
    hdr.append(f"Contour: {P((*sel_pt, app4))} -> P4 = {P(p4)} (G1 F{num(prev_f)}), end tangent t = "
               f"{P(t)}, n_L = {P(n)}. P0 = {P(p0)} programmed in the SAR block (explicit).")
    hdr += list(extra_hdr)
    if kind == 1:
        L = (R if s and R > 0 else 0) + disr
        assert L > 0
        p3p = vadd(p4p, vmul(L, t))
        hdr.append(f"G148: line of length L = {'R + ' if s else ''}DISR = {f6(L)} leaving P4 along t "
                   f"-> P3 (plane) = P4 + L*t = {P(p3p)}.")
        motion, M = "G1", None
        t3 = t
    else:
        sigma, stxt = side_of(side, s, p0p, p4p, t, retract=True)
        r, rtxt = contour_radius(disr, R, s, sigma)
        assert r > 0
        M = vadd(p4p, vmul(r * sigma, n))
        hdr.append(f"Side: {stxt}; u = sigma*n_L = {P(vmul(sigma, n))}; the arc leaves P4 along t "
                   f"turning to u: sense G{3 if sigma > 0 else 2}.")
        hdr.append(f"Radius: {rtxt}. Centre M = P4 + r*u = {P(M)}.")
        if kind == 2:
            p3p = vadd(M, vmul(r, t))
            hdr.append(f"G248 quarter circle: P3 (plane) = M + r*t = {P(p3p)}.")
        else:
            p3p = vadd(p4p, vmul(2 * r * sigma, n))
            hdr.append(f"G348 semicircle: P3 (plane) = P4 + 2r*u = {P(p3p)}.")
        motion = "G3" if sigma > 0 else "G2"
        rv = unit(vsub(p3p, M))
        t3 = nl(rv) if sigma > 0 else rot_m90(rv)
        # independent checks: the arc leaves P4 along t and sweeps 90 / 180 degrees
        assert same(arc_tangent(M, p4p, sigma), t)
        assert abs(sweep(M, p4p, p3p, sigma) - (90 if kind == 2 else 180)) < 1e-7
    a2 = app_target(app4, discl, "DISCL")
    app2, txt2 = (app4, "no DISCL -> 0 (reading Z2)") if a2 is None else a2
    a1 = app_target(app4, disrp, "DISRP")
    app1, txt1 = (p0[2], f"no DISRP -> P1.app = P0.app = {f6(p0[2])}") if a1 is None else a1
    app3 = app2 if g34 == 340 else app4
    seq = [app4, app3, app2, app1, p0[2]]
    assert monotonic(seq), (name, seq)
    hdr.append(f"Applicates: {txt2}; G{g34}: P3.app = " + ("P2.app" if g34 == 340 else "P4.app")
               + f" = {f6(app3)}; {txt1}. Sequence P4..P0 " + " -> ".join(f6(v) for v in seq)
               + " is monotonic.")
    hdr.append(f"Points: P4 = {P(p4)}, P3 = {P((*p3p, app3))}, P2 = {P((*p3p, app2))}, "
               f"P1 = {P((*p3p, app1))}, P0 = {P(p0)}"
               + ("; helix" if kind > 1 and abs(app3 - app4) > EPS else "") + ".")
    comp = (lambda p, tan: vadd(p, vmul(s * R, nl(tan))))
    c3p, c4p, csel = comp(p3p, t3), comp(p4p, t), comp(sel_pt, t)
    if s:
        hdr.append(f"TRC: selection ends at {P(csel)}, contour at C4 = {P(c4p)}; curve end tangent "
                   f"at P3 = {P(t3)} -> C3 = {P(c3p)}; lifts run at C3; deselection C3 -> P0.")
        if M is not None:
            assert abs(math.dist(c3p, M) - disr) < 1e-9 and abs(math.dist(c4p, M) - disr) < 1e-9
            hdr.append(f"  Check: |C3-M| = |C4-M| = {f6(disr)} = DISR.")
    pc = c3p if s else p3p
    assert not same(pc, p0p)
    if M is not None:
        roots = circle_roots(pc, p0p, M, math.dist(pc, M))
        others = [x for x in roots if abs(x) > 1e-7]
        assert all(x < 1e-9 for x in others), (name, roots)
        hdr.append("  The line C3 -> P0 leaves the centre-path circle at C3 (other root "
                   + (f"s = {f6(others[0])} < 0" if others else "none") + "): nothing cut.")
    fslow = fad[1] if isinstance(fad, tuple) else fad
    f_new = f_sar if f_sar is not None else prev_f
    if g34 == 340:
        f_d = fslow if fad is not None else prev_f
        f_c = None
    else:
        f_d = prev_f
        f_c = fslow if fad is not None else prev_f
    rows, tab = [], []
    ce = c4p if s else p4p
    if kind == 1:
        rows.append(("sar", "G1", (*pc, app3), None, f_d))
    else:
        rows.append(("sar", motion, (*pc, app3), (*M, app4), f_d))
    tab.append(f"D' P4->P3 {motion} F{num(f_d)} to {P((*pc, app3))}"
               + (f" centre {P((*M, app4))}" if M is not None else "") + " ("
               + ("G340: FAD" if g34 == 340 and fad is not None else "old F") + ", K2)")
    if g34 == 341:
        if abs(app2 - app3) > EPS:
            rows.append(("sar", "G1", (*pc, app2), None, f_c))
            tab.append(f"C' P3->P2 G1 F{num(f_c)} to {P((*pc, app2))} ("
                       + ("FAD" if fad is not None else "no FAD: old F") + ", K2)")
        else:
            tab.append("C' P3->P2 zero length: no row")
    if abs(app1 - app2) > EPS:
        rows.append(("sar", sar_motion, (*pc, app1), None, f_new))
        tab.append(f"B' P{'3' if g34 == 340 else '2'}->P1 {sar_motion}"
                   + ("" if sar_motion == "G0" else f" F{num(f_new)}") + f" to {P((*pc, app1))} "
                   "(interpolation of the SAR block, new F, K2)")
    rows.append(("sar", sar_motion, p0, None, f_new))
    tab.append(f"A' P1->P0 {sar_motion}" + ("" if sar_motion == "G0" else f" F{num(f_new)}")
               + f" to {P(p0)}" + (" = NORM deselection" if s else "") + " (K2)")
    hdr.append("Sub-blocks:")
    hdr += ["  " + x for x in tab]
    sarw = ("G40 " if s else "") + (f"{sar_motion} " if write_motion else "") + f"G{kind}48 G{g34}"
    if side is not None and write_side:
        sarw += f" G{side}"
    if side is not None and not write_side:
        hdr.append(f"G{side} is the initial setting and is not written in the program.")
    sarw += param("DISR", disr) + param("DISCL", discl) + param("DISRP", disrp) + param("FAD", fad)
    sarw += " " + words(plane, *p0)
    if f_sar is not None:
        sarw += f" F{num(f_sar)}"
    body = tool(R) + [f"@g0 G{plane} G90 G0 {words(plane, *start)}"]
    allrows = [("g0", "G0", start, None, None)]
    if sel is not None:
        body.append(f"@sel {'G4%d ' % (1 if s > 0 else 2) if s else ''}G1 {words(plane, *sel)} "
                    f"F{num(prev_f)}")
        body.append(f"@c1 {words(plane, *p4p)}")
        allrows.append(("sel", "G1", (*csel, start[2]), None, prev_f))
    else:
        body.append(f"@c1 G1 {words(plane, *p4p)} F{num(prev_f)}")
    body += ["@sar " + sarw, "M30"]
    allrows += [("c1", "G1", (*ce, app4), None, prev_f)] + rows
    assert abs(start[2] - app4) < EPS
    add(name, plane, hdr, body, allrows, meta=(checks, spec, readings))
    return dict(p3=(*p3p, app3), p4=p4, c3=c3p, c4=c4p)


# ==========================================================================================
# 1. Manual examples S-1 and S-2 (spec 6.6), written out with literal numbers

S1_HDR = [
    "s1_pm_g247_g341: PM-NC 12/2019 p280 example (spec 6.6 S-1): G41 G341 G247, DISCL=AC(5),",
    "DISR=13, FAD=500, F200, R = 7.",
    "CHANGES to the printed program: 'FAD 500' written FAD=500 (reading S1); N30 gets G1 (the",
    "printed N30 X50 would inherit G0 from N10: the group-1 state after a SAR block is not",
    "documented, reading V6).",
    CONV, PLANE_TXT[17] + ".",
    "P0 = (0,0,20). P4 = (40,-10,0) from N20. Tangent block N30: t = (1,0), n_L = (0,1).",
    "G140 (default) with G41 -> approach from the left, sigma = +1, u = (0,1), sense G3.",
    "G41 on the left of a G3 arc = inside -> contour radius r = DISR + R = 20 (so that the centre",
    "  path has radius DISR = 13). M = P4 + 20*u = (40,10). G247: P3 = M - 20*t = (20,10).",
    "Applicates: no DISRP -> P1.app = 20; DISCL=AC(5) -> P2.app = 5; G341 -> P3.app = 0.",
    "P1 = (20,10,20), P2 = (20,10,5), P3 = (20,10,0), P4 = (40,-10,0).",
    "TRC: start tangent of the arc at P3 = (0,-1), n_L = (1,0) -> C1 = C3 = (27,10); C4 = (40,-3).",
    "  |C3-M| = |C4-M| = 13 = DISR. Line (0,0) -> (27,10) meets the circle (M,13) at s = 1 and",
    "  s = 1.8468 only: nothing cut (TRC NORM, details Q1).",
    "Sub-blocks (N20):",
    "  A P0->P1 G0 (27,10,20) = selection (velocity of N10 = G0, V1)",
    "  B P1->P2 G0 (27,10,5) (fast infeed, V1)",
    "  C P2->P3 G1 (27,10,0) F500 (FAD, G341, V2)",
    "  D P3->P4 G3 (40,-3,0) centre (40,10,0) F200 (F of the SAR block, V3)",
    "N30 G1 X50 -> (50,-3,0) F200; N40 X60 -> (60,-3,0) F200 (ends on its normal at M30).",
    "Spec 6.6 expectation (C3 = (27,10), CCW) confirmed."]
add("s1_pm_g247_g341", 17, S1_HDR,
    ["$TC_DP1[1,1]=120", "$TC_DP6[1,1]=7",
     "@n10 N10 G90 G0 X0 Y0 Z20 D1 T1",
     "@n20 N20 G41 G341 G247 DISCL=AC(5) DISR=13 FAD=500 X40 Y-10 Z=0 F200",
     "@n30 N30 G1 X50", "@n40 N40 X60", "M30"],
    [("n10", "G0", (0, 0, 20), None, None), ("n20", "G0", (27, 10, 20), None, None),
     ("n20", "G0", (27, 10, 5), None, None), ("n20", "G1", (27, 10, 0), None, 500),
     ("n20", "G3", (40, -3, 0), (40, 10, 0), 200), ("n30", "G1", (50, -3, 0), None, 200),
     ("n40", "G1", (60, -3, 0), None, 200)],
    meta=("manual example S-1: quadrant, G341, DISCL=AC, FAD, G140 default", "6.6 S-1, 6.2",
          ["V1", "V2", "V3", "V6", "S1"]))


def wrapped_len(header):
    return sum(max(1, len(textwrap.wrap("; " + h, 98, break_long_words=False,
                                        break_on_hyphens=False))) for h in header)


def s2(name, variant):
    hdr = [f"{name}: PM-NC 12/2019 p278 example (spec 6.6 S-2), form '{variant}': G41 G147,",
           "G340 (default), DISCL=3, DISR=13, F1000, R = 7. The three forms of the manual must give",
           "the same path; only the line of the curve row differs (reading V5: the curve belongs to",
           "the block that supplies P4). Line numbers are aligned between the three forms.",
           CONV, PLANE_TXT[17] + ".",
           "P0 = (10,0,30) (after N20). P4 = (40,-10,0). Tangent block N50: t = (1,0), n_L = (0,1).",
           "G147: line length R + DISR = 20 -> P3 (plane) = P4 - 20*t = (20,-10).",
           "Applicates: P1.app = P0.app = 30; DISCL=3 -> P2.app = P3.app = 0 + 3 = 3 (G340: P2 = P3).",
           "P1 = (20,-10,30), P3 = (20,-10,3), P4 = (40,-10,0); $P_APR would be (20,-10,3).",
           "TRC: C1 = C3 = (20,-10) + 7*(0,1) = (20,-3); C4 = (40,-3).",
           "Sub-blocks:",
           "  A P0->P1 G0 (20,-3,30) = selection (N20 is G0, V1)",
           "  B P1->P3 G0 (20,-3,3) (V1)",
           "  D P3->P4 G1 (40,-3,0) F1000 (G340, no FAD: F of the SAR block, V2) - a line in space",
           "N50 G1 X50 -> (50,-3,0) F1000."]
    if variant == "Z in the SAR block, X/Y in N40":
        body = ["@n30 N30 G41 G147 DISCL=3 DISR=13 Z=0 F1000", "@n40 N40 G1 X40 Y-10"]
        hdr.append("The SAR block programs only the applicate: P4 gets X/Y from N40, Z0 from N30 (V5).")
        dl = "n40"
    elif variant == "P4 in the SAR block":
        body = ["@n30 N30 G41 G147 DISCL=3 DISR=13 X40 Y-10 Z0 F1000", "; (N40 merged into N30)"]
        hdr.append("P4 in the SAR block: the curve row is N30's.")
        dl = "n30"
    else:
        body = ["@n30 N30 G41 G147 DISCL=3 DISR=13 F1000", "@n40 N40 G1 X40 Y-10 Z0"]
        hdr.append("No geometry axis in N30: P4 = end of N40; N30's empty last sub-block: no row.")
        dl = "n40"
    while wrapped_len(hdr) < 22:
        hdr.append("(padding: same line numbers in the three forms)")
    assert wrapped_len(hdr) == 22, wrapped_len(hdr)
    add(name, 17, hdr,
        ["$TC_DP1[1,1]=120", "$TC_DP6[1,1]=7", "@n10 N10 G90 G0 X0 Y0 Z30 D1 T1", "@n20 N20 X10"]
        + body + ["@n50 N50 G1 X50", "M30"],
        [("n10", "G0", (0, 0, 30), None, None), ("n20", "G0", (10, 0, 30), None, None),
         ("n30", "G0", (20, -3, 30), None, None), ("n30", "G0", (20, -3, 3), None, None),
         (dl, "G1", (40, -3, 0), None, 1000), ("n50", "G1", (50, -3, 0), None, 1000)],
        meta=(f"manual example S-2, form: {variant}", "6.6 S-2, 6.3", ["V1", "V2", "V5"]))


s2("s2_pm_g147_z_in_sar", "Z in the SAR block, X/Y in N40")
s2("s2_pm_g147_p4_in_sar", "P4 in the SAR block")
s2("s2_pm_g147_p4_next", "no axes in the SAR block, X/Y/Z in N40")

# ==========================================================================================
# 2. Approach: G147 / G247 / G347 x G340 / G341 x G140..G143, three planes, G41/G42/G40

approach("app_g147_g340_g17_g42", 17,
         title="straight-line approach G147 in space (G340) with G42, DISCL, FAD, F.",
         spec="6.1, 6.2, 6.5", readings=["V1", "V2", "D1"],
         checks="G147 G340 G42 G17: line in space from DISCL to P4, FAD on the line",
         trc=42, kind=1, g34=340, disr=8, discl=2, fad=100, f_sar=400,
         p0=(80, 30, 25), p4=(40, 0, -5), cont_end=(0, 0))

approach("app_g147_g341_g18_g41", 18,
         title="straight-line approach G147 in the plane (G341) with G41 in G18.",
         spec="6.1, 6.2, 6.5", readings=["V1", "V2", "V3", "D1"],
         checks="G147 G341 G41 G18: fast infeed to DISCL, FAD infeed, line in the plane at F",
         trc=41, kind=1, g34=341, disr=6, discl=3, fad=150, f_sar=500,
         p0=(30, 10, 20), p4=(0, 20, 0), cont_end=(-40, 20))

approach("app_g147_g40_g19_discl_ac", 19,
         title="G147 without TRC in G19: line length = DISR (R counts 0), DISCL=AC(7), no FAD.",
         spec="6.1 (DISR, DISCL=AC)", readings=["V1", "V2", "D1", "D2"],
         checks="G147 G40 G19: L = DISR; DISCL=AC; G340 without FAD runs the line at F",
         trc=40, kind=1, g34=340, disr=10, discl=("AC", 7), f_sar=250,
         p0=(-20, 20, 30), p4=(10, -5, 2), cont_end=(10, -40))

approach("app_g147_negative_disr", 17,
         title="G147 with negative DISR, |DISR| < R: line length R + DISR = 2 (PM-F 11/2006 p372).",
         spec="6.1 (DISR)", readings=["V1", "V2"],
         checks="G147 DISR=-3 with R=5: L = 2",
         trc=41, kind=1, g34=340, disr=-3, discl=1, f_sar=330,
         p0=(-20, -20, 10), p4=(0, 0, 0), cont_end=(0, 30))

approach("app_g247_g340_g17_g42_helix", 17,
         title="quadrant approach G247 in space (G340) with G42, G140: helix from DISCL to P4.",
         spec="6.1, 6.2 (helix)", readings=["V1", "V2", "D1", "H1"],
         checks="G247 G340 G140+G42 (right, G2, inside r=DISR+R) G17: helix, FAD",
         trc=42, kind=2, g34=340, side=140, disr=10, discl=4, fad=200, f_sar=600,
         p0=(60, -30, 30), p4=(20, 10, -2), cont_end=(20, 60))

approach("app_g247_g341_g18_g42_g141", 18,
         title="G247 in the plane (G341), G42 with G141 (approach from the LEFT): the tool runs on "
               "the outside of the arc, contour radius DISR - R.",
         spec="6.1 (G141, DISR for circles)", readings=["V1", "V2", "V3", "D1"],
         checks="G247 G341 G141+G42 G18: outside, r = DISR-R",
         trc=42, kind=2, g34=341, side=141, disr=12, discl=5, fad=100, f_sar=280,
         p0=(40, 10, 25), p4=(0, 30, 0), cont_end=(-50, 30))

approach("app_g247_g340_g19_g41_g142", 19,
         title="G247 in space (G340), G41 with G142 (from the right): outside, r = DISR - R; no FAD "
               "-> helix at the F of the SAR block.",
         spec="6.1 (G142), 6.2", readings=["V1", "V2", "D1", "H1"],
         checks="G247 G340 G142+G41 G19: outside arc, helix at F (no FAD)",
         trc=41, kind=2, g34=340, side=142, disr=9, discl=2, f_sar=350,
         p0=(-30, -30, 20), p4=(0, 0, 5), cont_end=(40, 0))

approach("app_g247_g40_g143_left", 17,
         title="G247 without TRC, G143: the side follows P0 (left of the tangent line at P4).",
         spec="6.1 (G143)", readings=["V1", "V2", "V3", "D3"],
         checks="G247 G341 G143 G40 G17: P0 left -> G3, r = DISR",
         trc=40, kind=2, g34=341, side=143, disr=6, discl=3, fad=80, f_sar=200,
         p0=(-20, 30, 15), p4=(10, 10, 0), cont_end=(50, 10))

approach("app_g247_g40_g140_right", 18,
         title="G247 without TRC and G140 (initial setting, not written): behaves like G143 (no "
               "alarm); P0 right of the tangent line -> G2; DISCL=AC(4) helix.",
         spec="6.1 (G140 with G40)", readings=["V1", "V2", "D2", "D3", "H1"],
         checks="G247 G340 G140->G143 G40 G18: P0 right -> G2 helix",
         trc=40, kind=2, g34=340, side=140, write_side=False, disr=8, discl=("AC", 4), f_sar=150,
         p0=(-10, -25, 12), p4=(0, 0, 0), cont_end=(30, 0))

approach("app_g347_g341_g17_g41", 17,
         title="semicircle approach G347 in the plane (G341), G41 + G140 (inside, r = DISR + R), "
               "FAD=PM(120).",
         spec="6.1 (FAD=PM)", readings=["V1", "V2", "V3", "F1"],
         checks="G347 G341 G140+G41 G17: semicircle, FAD=PM",
         trc=41, kind=3, g34=341, side=140, disr=6, discl=2, fad=("PM", 120), f_sar=450,
         p0=(40, 30, 20), p4=(0, 0, 0), cont_end=(0, -40))

approach("app_g347_g340_g18_g41_g143", 18,
         title="G347 in space (G340), G41 with G143: P0 right of the tangent -> G2, the tool runs "
               "outside (r = DISR - R); helix.",
         spec="6.1 (G143), 6.2", readings=["V1", "V2", "D3", "H1"],
         checks="G347 G340 G143+G41 G18: P0 right -> G2 outside, helix",
         trc=41, kind=3, g34=340, side=143, disr=10, discl=3, fad=90, f_sar=500,
         p0=(30, 40, 15), p4=(0, 20, 0), cont_end=(-40, 20))

approach("app_g347_g341_g19_g42_g142", 19,
         title="G347 in the plane (G341), G42 with G142 (inside, r = DISR + R).",
         spec="6.1 (G142)", readings=["V1", "V2", "V3"],
         checks="G347 G341 G142+G42 G19: inside semicircle",
         trc=42, kind=3, g34=341, side=142, disr=4, discl=2, fad=60, f_sar=200,
         p0=(40, 20, 30), p4=(10, 0, 0), cont_end=(10, 30))

approach("app_g347_g341_g18_g40_g141_no_fad", 18,
         title="G347 without TRC, G141, G341 without FAD: the slow infeed P2->P3 runs at the F of "
               "the SAR block.",
         spec="6.2 (velocities)", readings=["V1", "V2", "V3"],
         checks="G347 G341 G141 G40 G18: no FAD -> P2->P3 at F",
         trc=40, kind=3, g34=341, side=141, disr=5, discl=1, f_sar=220,
         p0=(-20, 20, 10), p4=(10, 0, 0), cont_end=(40, 0))

# DISRP / DISCL variants
approach("app_disrp_incremental", 17,
         title="DISRP=10: P1 lies 10 above the plane of P4, so P0->P1 is not parallel to the plane.",
         spec="6.1 (DISRP), 6.2", readings=["V1", "V2", "D1"],
         checks="DISRP incremental: slanted P0->P1",
         trc=41, kind=1, g34=340, disr=5, discl=2, disrp=10, fad=100, f_sar=320,
         p0=(-30, 20, 40), p4=(0, 0, 0), cont_end=(50, 0))

approach("app_disrp_ac_g341", 18,
         title="DISRP=AC(15) and DISCL=AC(6) with G341, G42 + G140 quadrant, P4 below 0.",
         spec="6.1 (DISRP=AC, DISCL=AC)", readings=["V1", "V2", "V3", "D1", "D2"],
         checks="DISRP=AC, DISCL=AC, G247 G341 G42 G18",
         trc=42, kind=2, g34=341, side=140, disr=5, discl=("AC", 6), disrp=("AC", 15), fad=50,
         f_sar=250, p0=(40, -20, 30), p4=(0, 10, -3), cont_end=(0, 50))

approach("app_discl0_p0_in_plane", 17,
         title="DISCL=0 with G340 and P0 in the plane of P4: P1 = P2 = P3, only two motions "
               "(PM-F 11/2006 p372); no reading needed because P0.app = P4.app.",
         spec="6.1 (DISCL=0)", readings=["V1", "V2"],
         checks="DISCL=0 G340, P0 in the plane: 2 sub-blocks",
         trc=41, kind=2, g34=340, side=140, disr=8, discl=0, fad=100, f_sar=310,
         p0=(-30, 30, 0), p4=(0, 0, 0), cont_end=(40, 0))

approach("app_discl0_g340_p0_above", 17,
         title="DISCL=0 with G340, P0 above the plane: convention (P0->P1 parallel, P1->P3 fast "
               "infeed to the plane of P4, then the line). FLAG: PM-F 11/2006 p372 says 'only two "
               "blocks (P1, P2 and P3 combined)' - see README reading Z1.",
         spec="6.1 (DISCL=0)", readings=["V1", "V2", "Z1"],
         checks="DISCL=0 G340 with P0 above: convention rows (flagged)",
         trc=40, kind=1, g34=340, disr=10, discl=0, fad=50, f_sar=200,
         p0=(20, -30, 10), p4=(0, 0, -5), cont_end=(0, 40))

approach("app_discl_missing_g340", 18,
         title="no DISCL with G340 (G41 G247 G140): read as DISCL=0 (reading Z2, flagged).",
         spec="6.1 (DISCL)", readings=["V1", "V2", "Z2"],
         checks="DISCL not programmed = 0: circle in the plane, not a helix",
         trc=41, kind=2, g34=340, side=140, disr=6, fad=70, f_sar=290,
         p0=(30, -30, 20), p4=(0, 0, 0), cont_end=(-30, 0))

approach("app_discl0_g341", 19,
         title="DISCL=0 with G341: P2 = P3, the FAD infeed has zero length (no row), the whole "
               "infeed runs at the fast velocity (reading Z3).",
         spec="6.1 (DISCL=0)", readings=["V1", "V3", "Z3"],
         checks="DISCL=0 G341 G147 G42 G19: no FAD row",
         trc=42, kind=1, g34=341, disr=2, discl=0, fad=40, f_sar=180,
         p0=(-20, 30, 15), p4=(5, 5, 0), cont_end=(5, -30))

# feeds
approach("app_fad_pr", 17,
         title="FAD=PR(0.2) under G94: the FAD sub-block gets feed 0.2 (mm/rev); the CSV shows the "
               "number only (reading F1).",
         spec="6.1 (FAD=PR)", readings=["V1", "V2", "V3", "F1"],
         checks="FAD=PR(..) value on the P2->P3 row",
         trc=41, kind=1, g34=341, disr=4, discl=2, fad=("PR", 0.2), f_sar=340,
         p0=(30, 20, 10), p4=(0, 0, 0), cont_end=(-40, 0))

approach("app_fad_pm_g95", 17,
         title="G95 active (F0.3, F0.1 per revolution), FAD=PM(400) as linear feed: FAD row 400, "
               "curve 0.1 (reading F1).",
         spec="6.1 (FAD=PM)", readings=["V1", "V2", "V3", "F1"],
         checks="FAD=PM(..) under G95; G247 G341 G42 G140",
         trc=42, kind=2, g34=341, side=140, disr=5, discl=3, fad=("PM", 400), f_sar=0.1,
         prev=("G0", 0.3), setup=["G95"],
         p0=(-30, -40, 20), p4=(0, 0, 0), cont_end=(40, 0))

approach("app_prev_g1_no_fad_no_f", 17,
         title="previous block in G1 F250, no FAD and no F in the SAR block: every sub-block runs "
               "G1 F250 (velocity of the previous block / modal F).",
         spec="6.2 (velocities)", readings=["V1", "V2", "V3"],
         checks="fast part inherits G1 + F; no FAD/F -> modal F everywhere",
         trc=41, kind=2, g34=341, side=140, disr=7, discl=2,
         prev=("G1", 250), p0=(0, -30, 15), p4=(50, 0, 0), cont_end=(50, 40))

# P4 from a later block, dummy blocks
approach("app_p4_later_dummy_within_limit", 17,
         title="P4 from a later block with two dummy blocks (M8, M9) in between, MD20202 = 2 "
               "(within the limit); G341: P2->P3 stays in the SAR block, the curve is the P4 "
               "block's row.",
         spec="6.3, 6.5 (MD20202)", readings=["V1", "V2", "V3", "V5", "M1"],
         checks="dummy blocks within MD20202; rows of the SAR block vs P4 block",
         trc=40, kind=2, g34=341, side=141, disr=5, discl=2, fad=100, f_sar=300,
         prev=("G0", 500), p0=(0, 0, 20), p4=(40, -10, 0), cont_end=(60, -10), p4_src="next",
         setup=["$MC_WAB_MAXNUM_DUMMY_BLOCKS=2"], pre_dummies=["M8", "M9"])

approach("app_p4_later_dummy_trc", 17,
         title="G41 G147 without axes, one dummy block before the P4 block and one before the "
               "tangent block: the dummies run at the point reached (no rows).",
         spec="6.3, 6.5", readings=["V1", "V2", "V5", "M1"],
         checks="P4 from a later block under TRC; dummy blocks on both sides",
         trc=41, kind=1, g34=340, disr=3, discl=1, f_sar=400,
         p0=(-10, -10, 10), p4=(20, 20, -1), cont_end=(20, 60), p4_src="next",
         setup=["$MC_CUTCOM_MAXNUM_DUMMY_BLOCKS=5"], pre_dummies=["M8"], post_dummies=["M9"],
         extra_hdr=["MD20250 is raised to 5 so that the TRC limit on blocks without plane motion "
                    "(P1->P3, the empty last SAR sub-block, M8) cannot interfere (reading M1)."])

# other NC words in the SAR block, R parameter read back later
approach("app_other_words_in_sar_block", 17,
         title="other NC words in the SAR block (M3 S1000 R1=35) run with its first sub-block; "
               "R1 is read back by a later G0 Z=R1.",
         spec="6.5 (other NC commands)", readings=["V1", "V2", "V3", "W1"],
         checks="M/S/R words in the SAR block do not change the path; R1 set",
         trc=42, kind=1, g34=341, disr=4, discl=2, fad=90, f_sar=270, sar_words=" M3 S1000 R1=35",
         p0=(-30, -20, 10), p4=(0, 0, 0), cont_end=(30, 0),
         trailer=["@ret G40 G1 X40 Y-20", "@up G0 Z=R1"],
         trailer_rows=[("ret", "G1", (40, -20, 0), None, 270), ("up", "G0", (40, -20, 35), None, None)],
         extra_hdr=["After the contour: G40 G1 X40 Y-20 = NORM retraction from (30,-5) to "
                    "(40,-20) F270; G0 Z=R1 -> (40,-20,35)."])

# ------------------------------------------------------------------------------------------
# $P_APR / $P_AEP / $P_APDV, frames

approach("app_sysvars_papr_paep", 17,
         title="$P_APR = P3 (uncompensated, WCS), $P_AEP = P4, $P_APDV = 1, written into the path "
               "by G0 moves after the contour (spec 6.4; details 4.1).",
         spec="6.4", readings=["V1", "V2", "H1", "P1"],
         checks="$P_APR/$P_AEP values (uncompensated) and $P_APDV",
         trc=41, kind=2, g34=340, side=140, disr=8, discl=3, fad=100, f_sar=350,
         p0=(0, 20, 20), p4=(40, -10, 0), cont_end=(70, -10),
         trailer=["@ret G40 G1 X80 Y-30", "@up G0 Z50", "@apr G0 X=$P_APR[X] Y=$P_APR[Y] Z=$P_APR[Z]",
                  "@aep G0 X=$P_AEP[X] Y=$P_AEP[Y] Z=$P_AEP[Z]", "IF $P_APDV==1", "@dv G0 Z77",
                  "ENDIF"],
         trailer_rows=[("ret", "G1", (80, -30, 0), None, 350), ("up", "G0", (80, -30, 50), None, None),
                       ("apr", "G0", (27, 3, 3), None, None), ("aep", "G0", (40, -10, 0), None, None),
                       ("dv", "G0", (40, -10, 77), None, None)],
         extra_hdr=["Trailer: G40 G1 X80 Y-30 (NORM retraction F350), G0 Z50, then G0 to $P_APR = "
                    "P3 = (27,3,3) (the compensated C3 would be (32,3,3)), G0 to $P_AEP = P4 = "
                    "(40,-10,0), and G0 Z77 because $P_APDV == 1."])

approach("app_frame_trans_paep", 17,
         title="SAR under TRANS X100 (MCS = WCS + (100,0,0)); after TRANS X0 the stored $P_APR / "
               "$P_AEP keep their old WCS values (FM-W1 11/2006 p70).",
         spec="6.4, 6.2 (frames)", readings=["V1", "V2", "P1"],
         checks="SAR in the WCS under a frame; $P_AEP unaffected by a later WCS change",
         trc=40, kind=1, g34=340, disr=10, discl=2, f_sar=260,
         p0=(-30, 20, 10), p4=(0, 0, 0), cont_end=(30, 0), setup=["TRANS X100"],
         row_map=lambda p: (p[0] + 100, p[1], p[2]),
         trailer=["TRANS X0", "@apr G0 X=$P_APR[X] Y=$P_APR[Y] Z=$P_APR[Z]",
                  "@aep G0 X=$P_AEP[X] Y=$P_AEP[Y] Z=$P_AEP[Z]"],
         trailer_rows=[("apr", "G0", (-10, 0, 2), None, None), ("aep", "G0", (0, 0, 0), None, None)],
         extra_hdr=["All points below are WCS; the CSV (MCS) rows of the SAR part are shifted by "
                    "+100 in X (see the .expected). After TRANS X0 (frame = 0): G0 to $P_APR = "
                    "(-10,0,2) and to $P_AEP = (0,0,0) in the MCS."])
approach("app_frame_rot_z90", 17,
         title="SAR under ROT Z90: the construction runs in the WCS; MCS (x,y) = (-y_w, x_w).",
         spec="6.2 (rotating frames), 6.5", readings=["V1", "V2", "V3"],
         checks="SAR with a rotating frame",
         trc=41, kind=2, g34=341, side=140, disr=10, discl=("AC", 5), fad=200, f_sar=100,
         p0=(0, 0, 20), p4=(40, -10, 0), cont_end=(60, -10), setup=["ROT Z90"],
         row_map=lambda p: (-p[1], p[0], p[2]),
         extra_hdr=["All points below are WCS; the .expected holds them rotated into the MCS."])

# ==========================================================================================
# 3. Retraction: G148 / G248 / G348

retraction("ret_g148_g340_g17_g41", 17,
           title="straight-line retraction G148 in space (G340), G41 deselected in the SAR block, "
                 "FAD on the line, new F from P3 on.",
           spec="6.1, 6.2 (retraction)", readings=["K1", "K2"],
           checks="G148 G340 G41 G17: FAD on the retraction line, F1000 from P3",
           trc=41, kind=1, g34=340, disr=5, discl=3, fad=150, f_sar=1000,
           start=(-10, -10, 0), sel=(0, 0), p4=(40, 0, 0), p0=(70, 20, 10))

retraction("ret_g248_g341_g18_g42", 18,
           title="quadrant retraction G248 in the plane (G341), G42 + G140 -> retract to the right "
                 "(G2, inside r = DISR + R), no F: the old F everywhere except FAD.",
           spec="6.1, 6.2", readings=["K1", "K2", "K3"],
           checks="G248 G341 G140+G42 G18: G2 inside; FAD on P3->P2",
           trc=42, kind=2, g34=341, side=140, disr=6, discl=4, fad=80,
           start=(10, 30, 0), sel=(0, 20), p4=(-40, 20, 0), p0=(-70, 40, 12))

retraction("ret_g348_g340_g19_g41_g142", 19,
           title="semicircle retraction G348 in space (G340) with G41 + G142 (outside, r = DISR - R)"
                 ", G0 in the SAR block: helix at the old F, then G0.",
           spec="6.1, 6.2", readings=["K1", "K2", "H1"],
           checks="G348 G340 G142+G41 G19: helix up, G0 from P3 on",
           trc=41, kind=3, g34=340, side=142, disr=8, discl=5, sar_motion="G0", write_motion=True,
           start=(-10, -10, 0), sel=(0, 0), p4=(0, 30, 0), p0=(40, 40, 25))

retraction("ret_g248_g40_g143_left", 17,
           title="G248 without TRC, G143 with an explicit end point left of the end tangent -> G3; "
                 "G340 helix at FAD, F800 from P3.",
           spec="6.1 (G143 on retraction)", readings=["K2", "D3", "H1"],
           checks="G248 G340 G143 G40 G17: explicit end point allowed",
           trc=40, kind=2, g34=340, side=143, disr=10, discl=2, fad=120, f_sar=800,
           start=(-10, 0, 0), p4=(30, 0, 0), p0=(50, 40, 15))

retraction("ret_g348_g341_g17_g42_g141", 17,
           title="G348 in the plane (G341), G42 with G141 (retract to the left: outside, r = DISR - "
                 "R).",
           spec="6.1 (G141)", readings=["K1", "K2"],
           checks="G348 G341 G141+G42 G17: outside semicircle",
           trc=42, kind=3, g34=341, side=141, disr=9, discl=3, fad=100, f_sar=900,
           start=(-10, 10, 0), sel=(0, 0), p4=(0, -40, 0), p0=(40, -20, 20))

retraction("ret_g148_g18_disrp_g0", 18,
           title="G148 with DISRP=10 and G0 in the SAR block: FAD line, G0 lift to DISRP, slanted "
                 "G0 to P0.",
           spec="6.1 (DISRP)", readings=["K1", "K2", "D1"],
           checks="G148 G340 DISRP on retraction, G0 from P3",
           trc=41, kind=1, g34=340, disr=4, discl=2, disrp=10, fad=60, sar_motion="G0",
           write_motion=True, start=(-10, -10, 0), sel=(0, 0), p4=(0, 30, 0), p0=(20, 50, 25))

retraction("ret_g248_g19_g40_g140_fallback", 19,
           title="G248 without TRC and G140 (initial setting): like G143, explicit end point right "
                 "of the end tangent -> G2; G341 without FAD and F: old F everywhere.",
           spec="6.1 (G140 with G40)", readings=["K2", "D3"],
           checks="G248 G341 G140->G143 G40 G19",
           trc=40, kind=2, g34=341, side=140, write_side=False, disr=6, discl=1, prev_f=300,
           start=(-10, 0, 0), p4=(30, 0, 0), p0=(50, -30, 20))

# ==========================================================================================
# 4. Alarms


def alarm(name, plane, hdr, body, rows, lab, no, checks, spec, readings):
    add(name, plane, [f"{name}: " + hdr[0]] + hdr[1:] + [CONV, PLANE_TXT[plane] + "."], body, rows,
        status=2, errs=[(lab, "alarm", no)], meta=(checks, spec, readings))


A_ROWS = "Rows: only the G0 to P0 (fixed before the SAR block); nothing of the SAR block (E1). Status 2."

alarm("alarm_disr_missing_g247", 17,
      ["G247 without DISR: alarm 10742 'WAB distance invalid or not programmed' on the SAR block",
       "(spec 6.1 DISR, 6.7 [M]).", A_ROWS],
      tool(5) + ["@p0 G17 G90 G0 X0 Y0 Z20 F500", "@sar G41 G247 G340 DISCL=2 X40 Y-10 Z0 F300",
                 "G1 X60", "M30"],
      [("p0", "G0", (0, 0, 20), None, None)], "sar", 10742,
      "G247 without DISR", "6.1, 6.7", ["E1", "E2"])

alarm("alarm_disr_zero_g347", 18,
      ["G347 with DISR=0: alarm 10742 (DISR <= 0 for circles, spec 6.1).", A_ROWS],
      tool(5) + ["@p0 G18 G90 G0 Z0 X0 Y20 F500",
                 "@sar G42 G347 G341 DISR=0 DISCL=2 Z-40 X10 Y0 F300", "G1 Z-60", "M30"],
      [("p0", "G0", (0, 0, 20), None, None)], "sar", 10742,
      "G347 with DISR=0", "6.1, 6.7", ["E1", "E2"])

alarm("alarm_disr_negative_g247", 19,
      ["G247 with DISR=-5: alarm 10742 (negative DISR only allowed for lines, spec 6.1).", A_ROWS],
      tool(5) + ["@p0 G19 G90 G0 Y0 Z0 X20 F500",
                 "@sar G41 G247 G340 DISR=-5 DISCL=2 Y40 Z-10 X0 F300", "G1 Y60", "M30"],
      [("p0", "G0", (0, 0, 20), None, None)], "sar", 10742,
      "G247 with DISR<0", "6.1, 6.7", ["E1", "E2"])

alarm("alarm_g147_disr_minus_r", 17,
      ["G147 with DISR=-5 and R=5: |DISR| >= R, line length R + DISR = 0 -> alarm 10742",
       "(PM-F 11/2006 p372: the resulting length must be positive).", A_ROWS],
      tool(5) + ["@p0 G17 G90 G0 X0 Y0 Z20 F500",
                 "@sar G41 G147 G340 DISR=-5 DISCL=2 X40 Y-10 Z0 F300", "G1 X60", "M30"],
      [("p0", "G0", (0, 0, 20), None, None)], "sar", 10742,
      "G147 with abs(DISR) >= R", "6.1, 6.7", ["E1", "E2"])

alarm("alarm_g147_g40_negative_disr", 17,
      ["G147 without TRC and DISR=-2: R counts 0 without TRC (and is only added when positive),",
       "so the line length is -2 -> alarm 10742.", A_ROWS],
      tool(5) + ["@p0 G17 G90 G0 X0 Y0 Z20 F500",
                 "@sar G147 G340 DISR=-2 DISCL=2 X40 Y-10 Z0 F300", "G1 X60", "M30"],
      [("p0", "G0", (0, 0, 20), None, None)], "sar", 10742,
      "G147 G40 with DISR<0", "6.1, 6.7", ["E1", "E2", "D1"])

alarm("alarm_g247_inner_radius_zero", 17,
      ["G247 with G42 and G141 (approach from the left): the tool is outside the arc, contour",
       "radius DISR - R = 5 - 5 = 0 <= 0 -> alarm 10742 (spec 6.1 'resulting internal radius",
       "<= 0').", A_ROWS],
      tool(5) + ["@p0 G17 G90 G0 X0 Y30 Z20 F500",
                 "@sar G42 G247 G341 G141 DISR=5 DISCL=2 X40 Y-10 Z0 F300", "G1 X60", "M30"],
      [("p0", "G0", (0, 30, 20), None, None)], "sar", 10742,
      "contour radius DISR-R = 0", "6.1, 6.7", ["E1", "E2"])

alarm("alarm_reversal_discl_above_p0", 17,
      ["P0 at Z2 but DISCL=5 above P4 (Z0), G340: the applicate would go 2 -> 2 -> 5 -> 0 (up,",
       "then down) -> alarm 10741 'direction reversal with WAB infeed' (spec 6.1 DISCL, 6.7).",
       A_ROWS],
      tool(5) + ["@p0 G17 G90 G0 X0 Y0 Z2 F500",
                 "@sar G41 G147 G340 DISR=5 DISCL=5 X40 Y-10 Z0 F300", "G1 X60", "M30"],
      [("p0", "G0", (0, 0, 2), None, None)], "sar", 10741,
      "infeed reversal by DISCL", "6.1, 6.7", ["E1", "E2", "D1"])

alarm("alarm_reversal_disrp", 18,
      ["DISRP=30 above P4 (Y0) but P0 at Y20: 20 -> 30 -> 2 -> 0 -> alarm 10741.", A_ROWS],
      tool(5) + ["@p0 G18 G90 G0 Z0 X0 Y20 F500",
                 "@sar G41 G147 G341 DISR=5 DISCL=2 DISRP=30 Z-40 X10 Y0 F300", "G1 Z-60", "M30"],
      [("p0", "G0", (0, 0, 20), None, None)], "sar", 10741,
      "infeed reversal by DISRP", "6.1, 6.7", ["E1", "E2", "D1"])

alarm("alarm_reversal_retraction", 17,
      ["Retraction G148 with DISCL=10 but the end point P0 at Z5: 0 -> 10 -> 5 (up, then down) ->",
       "alarm 10741 on the retraction block.",
       "Rows: G0 only: the selection block and X40 are still in the TRC look-ahead window (MD20240",
       "= 3 blocks, a later block could still change them; E1). Status 2."],
      tool(5) + ["@g0 G17 G90 G0 X-10 Y-10 Z0", "@sel G41 G1 X0 Y0 F400", "X40",
                 "@sar G40 G148 G340 DISR=5 DISCL=10 X70 Y20 Z5", "M30"],
      [("g0", "G0", (-10, -10, 0), None, None)], "sar", 10741,
      "reversal on retraction; rows under TRC", "6.1, 6.7", ["E1", "E2"])

alarm("alarm_g143_retraction_implicit", 17,
      ["G248 with G143 and no end point in the block (implicit end point): alarm 10747 'retraction",
       "direction not defined' (FM 828D p1466, spec 6.7 [M]).",
       "Rows: the blocks before (no TRC: all fixed). Status 2."],
      tool(5) + ["@g0 G17 G90 G0 X-10 Y0 Z0", "@c1 G1 X30 F400", "@sar G248 G340 G143 DISR=5 DISCL=3",
                 "M30"],
      [("g0", "G0", (-10, 0, 0), None, None), ("c1", "G1", (30, 0, 0), None, 400)], "sar", 10747,
      "G143 on retraction with implicit end point", "6.1, 6.7", ["E1", "E2"])

alarm("alarm_g140_g40_retraction_implicit", 19,
      ["G248 with G140 (initial setting) while G40 is active switches to G143; with an implicit end",
       "point that is alarm 10747 as well (FM 828D p1466).",
       "Rows: the blocks before. Status 2."],
      tool(5) + ["@g0 G19 G90 G0 Y-10 Z0 X0", "@c1 G1 Y30 F400", "@sar G248 G341 DISR=5 DISCL=3",
                 "M30"],
      [("g0", "G0", (-10, 0, 0), None, None), ("c1", "G1", (30, 0, 0), None, 400)], "sar", 10747,
      "G140 -> G143 fallback on retraction, implicit end point", "6.1, 6.7", ["E1", "E2"])

alarm("alarm_stopre_before_tangent_block", 17,
      ["STOPRE between the SAR block and the block that defines the tangent: alarm 10746 (spec",
       "6.5 [V]; number per reading E2: 'preprocessing stop with WAB') on the STOPRE line.",
       A_ROWS],
      tool(5) + ["@p0 G17 G90 G0 X0 Y0 Z20 F500",
                 "@sar G41 G147 G340 DISR=5 DISCL=2 X40 Y-10 Z0 F300", "@stop STOPRE", "G1 X60",
                 "M30"],
      [("p0", "G0", (0, 0, 20), None, None)], "stop", 10746,
      "STOPRE between SAR block and tangent block", "6.5, 6.7", ["E1", "E2"])

alarm("alarm_too_many_dummy_blocks", 17,
      ["MD20202 $MC_WAB_MAXNUM_DUMMY_BLOCKS = 2 and three blocks without geometry motion (M8, M9,",
       "M8) between the SAR block (no axes: P4 comes later) and the P4 block: alarm 10740 on the",
       "third dummy block (spec 6.3, 6.7).", A_ROWS],
      tool(5) + ["$MC_WAB_MAXNUM_DUMMY_BLOCKS=2", "@p0 G17 G90 G0 X0 Y0 Z20 F500",
                 "@sar G147 G340 DISR=5 DISCL=2 F300", "M8", "M9", "@d3 M8", "G1 X40 Y-10 Z0",
                 "G1 X60", "M30"],
      [("p0", "G0", (0, 0, 20), None, None)], "d3", 10740,
      "more dummy blocks than MD20202", "6.3, 6.7", ["E1", "E2", "M1"])

# ==========================================================================================
# 5. Matrix: every SAR type x G340/G341 x G140..G143 x G17/G18/G19, approach and retraction
#    (README 'Matrix'). TRC, DISR, DISCL/DISRP/FAD, F and the P0 side follow fixed rotations;
#    P0 is placed from the construction so that every program is valid.

MX_T = [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0), (0.6, 0.8), (-0.8, 0.6)]
MX_P4 = [(10, -5, 0), (-20, 15, -2), (5, 30, 3)]
MX_DISR = [8, 10, 7, 12]
MX_UP = 15          # P0.app = P4.app + 15


def mx_params(v, app4):
    """the DISCL/DISRP/FAD rotation: (kwargs, text)"""
    if v == 0:
        return dict(discl=3, fad=120), "DISCL=3 FAD=120"
    if v == 1:
        return dict(discl=4, disrp=10), "DISCL=4 DISRP=10, no FAD"
    if v == 2:
        return dict(fad=90), "no DISCL, FAD=90"
    return (dict(discl=("AC", app4 + 6), disrp=("AC", app4 + 12), fad=150),
            f"DISCL=AC({num(app4 + 6)}) DISRP=AC({num(app4 + 12)}) FAD=150")


def mx_side(side, s, sigma0):
    """the side sigma the program is built for (README 'Construction', 'The side')"""
    if side == 141:
        return 1
    if side == 142:
        return -1
    if side == 140 and s != 0:
        return s
    return sigma0          # G143, and G140 with G40 (behaves like G143)


def mx_readings(ret, s, kind, g34, side, prm, extra):
    rd = ["K2"] if ret else ["V1", "V2"]
    if ret and s:
        rd.insert(0, "K1")
    if not ret and g34 == 341:
        rd.append("V3")
    if ret and "f_sar" not in extra:
        rd.append("K3")
    dc, dr = prm.get("discl"), prm.get("disrp")
    if any(v is not None and not isinstance(v, tuple) for v in (dc, dr)):
        rd.append("D1")
    if isinstance(dc, tuple) or isinstance(dr, tuple):
        rd.append("D2")
    if kind > 1 and (side == 143 or (side == 140 and s == 0)):
        rd.append("D3")
    if kind > 1 and g34 == 340 and dc is not None:
        rd.append("H1")
    if dc is None:
        rd += ["Z1", "Z2"] if (g34 == 340 and not ret) else ["Z2"]
    return rd


def matrix():
    R = 5.0
    for ret in (False, True):
        i = 0
        for ki, kind in enumerate((1, 2, 3)):
            for gi, g34 in enumerate((340, 341)):
                for si, side in enumerate((140, 141, 142, 143)):
                    for pi, plane in enumerate((17, 18, 19)):
                        mx_case(ret, i, kind, g34, side, plane,
                                trc=(41, 42, 40)[(pi + si + gi + ki + ret) % 3],
                                sigma0=1 if (pi + gi + ki + ret) % 2 == 0 else -1, R=R)
                        i += 1


def mx_case(ret, i, kind, g34, side, plane, trc, sigma0, R):
    s = {41: 1, 42: -1, 40: 0}[trc]
    t = MX_T[i % len(MX_T)]
    n = nl(t)
    p4 = MX_P4[i % len(MX_P4)]
    p4p, app4 = p4[:2], p4[2]
    disr = MX_DISR[(i // 4) % len(MX_DISR)]
    prm, ptxt = mx_params(i % 4, app4)
    code = f"G{kind}4{8 if ret else 7}"
    name = f"mx_{code.lower()}_g{g34}_g{side}_g{plane}"
    trc_txt = f"G{trc}" + (" (selected before, G40 in the SAR block)" if ret and s else "")
    # the side the program is built for, the contour radius and P3 (README 'Construction')
    if kind == 1:
        sigma = sigma0
        L = (R if s else 0) + disr
        p3p = vadd(p4p, vmul(L, t)) if ret else vsub(p4p, vmul(L, t))
        if ret:     # P0 beyond P3 along t, on the side sigma0
            p0p = vadd(p3p, vadd(vmul(20, t), vmul(15 * sigma, n)))
            where = "P0 = P3 + 20*t + 15*sigma0*n_L"
        else:       # P0 behind P3 (against t), on the side sigma0
            p0p = vadd(p3p, vadd(vmul(-20, t), vmul(15 * sigma, n)))
            where = "P0 = P3 - 20*t + 15*sigma0*n_L"
        side_txt = (f"G{side} has no effect on a straight line (the side only exists for "
                    f"G247/G347 and G248/G348, spec 6.1 syntax). P0 is put on the "
                    f"{'left' if sigma > 0 else 'right'} of the tangent line at P4 "
                    f"(sigma0 = {sigma:+d}): {where}.")
    else:
        sigma = mx_side(side, s, sigma0)
        r = disr if s == 0 else (disr + R if sigma == s else disr - R)
        u = vmul(sigma, n)
        if kind == 2:
            p3p = vadd(vadd(p4p, vmul(r, u)), vmul(r if ret else -r, t))
            # approach: the arc starts along -u; retraction: it ends along +u
            p0p = vadd(p3p, vadd(vmul(20, u), vmul(10 if ret else -10, t)))
            where = ("P0 = P3 + 20*u + 10*t (beyond the end of the arc, away from M)" if ret else
                     "P0 = P3 + 20*u - 10*t (behind the start of the arc, away from M)")
            k = r + 20
        else:
            p3p = vadd(p4p, vmul(2 * r, u))
            # the semicircle starts (approach) / ends (retraction) along -t at P3
            p0p = vadd(p3p, vadd(vmul(-20 if ret else 20, t), vmul(10, u)))
            where = ("P0 = P3 - 20*t + 10*u (beyond the end of the arc)" if ret else
                     "P0 = P3 + 20*t + 10*u (behind the start of the arc)")
            k = 2 * r + 10
        fixed = {141: "G141 fixes sigma = +1", 142: "G142 fixes sigma = -1"}.get(side)
        if side == 140 and s:
            fixed = f"G140 with G4{1 if s > 0 else 2} fixes sigma = {s:+d}"
        if fixed is None:
            fixed = ((f"G140 with G40 works like G143" if side == 140 else "G143")
                     + f": P0 is put on the {'left' if sigma > 0 else 'right'} of the tangent "
                     f"line at P4 (sigma0 = {sigma:+d}), so sigma = {sigma:+d}")
        side_txt = (f"{fixed}; r = {f6(r)}; u = sigma*n_L. P0 is placed from the construction: "
                    f"{where}; cross(t, P0-P4) = {f6(k * sigma)} (P0 on the side u).")
    p0 = (*p0p, app4 + MX_UP)
    extra = {}
    if i % 5 != 3:
        extra["f_sar"] = 900 if ret else 500
    feed_txt = f"F{num(extra['f_sar'])}" if "f_sar" in extra else "no F"
    hdr = [f"Matrix case {i + 1} of 72 ({'retraction' if ret else 'approach'}; README 'Matrix'): "
           f"t = MX_T[{i % 6}], P4 = MX_P4[{i % 3}], DISR = MX_DISR[{(i // 4) % 4}], parameter set "
           f"{i % 4} ({ptxt}), {feed_txt} in the SAR block, {trc_txt}.", side_txt,
           f"P0.app = P4.app + {MX_UP}: P0 lies above the plane of P4, so the infeed (approach) / "
           "lift (retraction) runs in one direction."]
    if ret:
        sar_g0 = i % 6 == 1
        if sar_g0:
            hdr.append("G0 is written in the SAR block: the lifts run G0, the curve and the FAD "
                       "lift stay feed motions (K2).")
        kw = dict(sar_motion="G0", write_motion=True) if sar_g0 else {}
        start_p = vsub(p4p, vmul(40, t))
        if s:
            sel, start = start_p, (*vsub(vsub(start_p, vmul(10, t)), vmul(10, n)), app4)
        else:
            sel, start = None, (*start_p, app4)
        title = (f"matrix retraction {code} G{g34} G{side} G{plane}, {trc_txt}; {ptxt}; "
                 f"{feed_txt}" + ("; G0" if sar_g0 else "") + ".")
        checks = (f"matrix: {code} G{g34} G{side} G{plane}, G{trc}, {ptxt}, {feed_txt}"
                  + (", G0" if sar_g0 else ""))
        res = retraction(name, plane, title=title, spec="6.1, 6.2 (retraction)",
                         readings=mx_readings(True, s, kind, g34, side, prm, extra), checks=checks,
                         R=R, trc=trc, kind=kind, g34=g34, side=side, disr=disr, start=start,
                         sel=sel, p4=p4, p0=p0, extra_hdr=hdr, **prm, **extra, **kw)
        assert same(res["p3"][:2], p3p), (name, res["p3"], p3p)
        return
    prev = ("G1", 250.0) if i % 7 == 5 else ("G0", 300.0)
    if prev[0] == "G1":
        hdr.append("The block before the SAR block is G1 F250: the fast part runs G1 F250 (V1).")
    title = (f"matrix approach {code} G{g34} G{side} G{plane}, G{trc}; {ptxt}; {feed_txt}"
             + ("; previous block G1" if prev[0] == "G1" else "") + ".")
    checks = (f"matrix: {code} G{g34} G{side} G{plane}, G{trc}, {ptxt}, {feed_txt}"
              + (", previous G1" if prev[0] == "G1" else ""))
    res = approach(name, plane, title=title, spec="6.1, 6.2",
                   readings=mx_readings(False, s, kind, g34, side, prm, extra), checks=checks,
                   R=R, trc=trc, kind=kind, g34=g34, side=side, disr=disr, prev=prev, p0=p0,
                   p4=p4, cont_end=vadd(p4p, vmul(40, t)), extra_hdr=hdr, **prm, **extra)
    assert same(res["p3"][:2], p3p), (name, res["p3"], p3p)


matrix()

if __name__ == "__main__":
    write_all()
