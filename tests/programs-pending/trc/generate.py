#!/usr/bin/env python3
"""Writes the pending tool radius compensation (TRC) golden cases of this folder:
NAME.MPF (header comment with the hand derivation + program) and NAME.expected.

Nothing here implements TRC: every case spells out its own hand construction (normal points,
intersections, tangent points) with plain formulas, and this script only does the arithmetic,
the line numbering and the mapping of the plane coordinates (a, o, applicate) onto X, Y, Z.
Conventions (README.md): G17 (a,o,app) = (X,Y,Z), G18 = (Z,X,Y), G19 = (Y,Z,X); left normal
n_L = (-t_o, t_a); G41 centre = contour + R*n_L, G42 centre = contour - R*n_L; G2/G3 = sense
in (a,o) seen from +applicate.

Run: python3 tests/programs-pending/trc/generate.py   (deterministic)
"""
import math
import os
import textwrap

HERE = os.path.dirname(os.path.abspath(__file__))
SQ = math.sqrt
CASES = []

# ------------------------------------------------------------------------------------------
# helpers

LETTERS = {17: ("X", "Y", "Z", "I", "J", "K"),
           18: ("Z", "X", "Y", "K", "I", "J"),
           19: ("Y", "Z", "X", "J", "K", "I")}


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
    """(a,o) pair as text."""
    return "(" + f6(p[0]) + "," + f6(p[1]) + ")"


def words(plane, a=None, o=None, n=None, i=None, j=None):
    L = LETTERS[plane]
    out = []
    for letter, v in ((L[0], a), (L[1], o), (L[2], n), (L[3], i), (L[4], j)):
        if v is not None:
            out.append(f"{letter}{num(v)}")
    return " ".join(out)


def add(name, plane, header, body, rows, status=0, errs=(), args=None):
    """body: list of strings; '@lab text' gives the line a label.
    rows: (label, motion, (a,o,app), centre (a,o,app) or None, feed)
    errs: (label, kind, number)  kind 'alarm' or 'warning'."""
    CASES.append((name, plane, header, body, rows, status, errs, args))


def write_all():
    names = set()
    for name, plane, header, body, rows, status, errs, args in CASES:
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
        if args:
            out.append("# args: " + args)
        if status:
            out.append(f"# status: {status}")
        for lab, kind, no in errs:
            out.append(f"# stderr: {name}.MPF:{labels[lab]}: {kind} {no}: *")
        out.append("line,motion,x,y,z,cx,cy,cz,feed")
        for lab, motion, p, c, feed in rows:
            x, y, z = xyz(plane, p)
            if c is None:
                cs = ",,"
            else:
                cx, cy, cz = xyz(plane, c)
                cs = f"{num(cx)},{num(cy)},{num(cz)}"
            fs = "" if motion == "G0" else num(feed)
            out.append(f"{labels[lab]},{motion},{num(x)},{num(y)},{num(z)},{cs},{fs}")
        with open(os.path.join(HERE, name + ".expected"), "w", newline="\n") as f:
            f.write("\n".join(out) + "\n")
    print(f"{len(CASES)} cases written")


def tool(r=5, extra=()):
    return ["$TC_DP1[1,1]=120", f"$TC_DP6[1,1]={num(r)}", *extra, "T1 D1"]


PLANE_TXT = {17: "G17: a=X, o=Y, applicate Z",
             18: "G18: a=Z, o=X, applicate Y (columns x=o, y=app, z=a)",
             19: "G19: a=Y, o=Z, applicate X (columns x=app, y=a, z=o)"}
CONV = "Conventions (README.md): plane coords (a,o); t = unit tangent; n_L = (-t_o, t_a); " \
       "G41 centre = P + R*n_L, G42 centre = P - R*n_L."


def rot(v, deg):
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return (v[0] * c - v[1] * s, v[0] * s + v[1] * c)


# ------------------------------------------------------------------------------------------
# E: equidistant of a line (4 cases: G17/G18/G19, G41/G42)

def line_case(name, plane, side):
    s = 1 if side == 41 else -1
    p0 = (-10, -10 * s)
    q1 = (0, 5 * s)
    qe = (50, 5 * s)
    p2 = (60, 10 * s)
    L = LETTERS[plane]
    hdr = [f"{name}: equidistant of a straight line, G{side}, NORM approach and retraction "
           "(spec 5.1, 5.2; details Q1).",
           CONV, PLANE_TXT[plane] + ".",
           "Tool T1 D1: type 120, radius R = $TC_DP6 = 5, length 0 (MCS = WCS).",
           f"Start P0 = {P(p0)} by G0.  Contour: P1 = (0,0) -> (50,0), t = (1,0), n_L = (0,1).",
           f"G{side}: offset = {'+' if s > 0 else '-'}R*n_L = (0,{5 * s}).",
           f"NORM approach: one straight line P0 -> Q1 = P1 + offset = {P(q1)} (selection block).",
           f"Line: Q1 -> (50,0) + offset = {P(qe)}.",
           f"NORM retraction: last point Qe = {P(qe)} (normal at the end point), then one line to "
           f"the programmed G40 point P2 = {P(p2)}.",
           "No corner anywhere (approach and retraction lines only touch the equidistant at Q1/Qe).",
           "Rows: G0 P0 | selection Q1 | line Qe | G40 P2; applicate 0, F100."]
    body = tool() + [
        f"@g0 G{plane} G90 G0 {words(plane, p0[0], p0[1], 0)}",
        f"@sel G{side} G1 {words(plane, 0, 0)} F100",
        f"@l1 {L[0]}50",
        f"@ret G40 {words(plane, p2[0], p2[1])}",
        "M30"]
    rows = [("g0", "G0", (*p0, 0), None, ""), ("sel", "G1", (*q1, 0), None, 100),
            ("l1", "G1", (*qe, 0), None, 100), ("ret", "G1", (*p2, 0), None, 100)]
    add(name, plane, hdr, body, rows)


line_case("line_g17_g41", 17, 41)
line_case("line_g17_g42", 17, 42)
line_case("line_g18_g41", 18, 41)
line_case("line_g19_g42", 19, 42)


# ------------------------------------------------------------------------------------------
# E: equidistant of arcs (outside r+R, inside r-R) and helices

def arc_case(name, plane, side, g, helix=None):
    # Contour: P1 = (0,0), arc to (40,0) about C = (20,0), r = 20.
    # G2 (CW): start angle 180, t_start = (0,1), t_end = (0,-1).
    # G3 (CCW): t_start = (0,-1), t_end = (0,1).
    ts = (0, 1) if g == 2 else (0, -1)
    te = (0, -1) if g == 2 else (0, 1)
    s = 1 if side == 41 else -1
    nls = (-ts[1], ts[0])
    nle = (-te[1], te[0])
    q1 = (0 + 5 * s * nls[0], 5 * s * nls[1])
    qe = (40 + 5 * s * nle[0], 5 * s * nle[1])
    rr = math.dist(q1, (20, 0))
    kind = "outside (r+R = 25)" if rr > 20 else "inside (r-R = 15)"
    p0 = (-10, -10)
    p2 = (50, -10)
    app_end = helix if helix is not None else 0
    L = LETTERS[plane]
    hdr = [f"{name}: equidistant of a G{g} arc with G{side}: {kind} (spec 5.1: G2+G41 and "
           "G3+G42 outside, G3+G41 and G2+G42 inside)" + (", helix: the applicate moves "
           "linearly through the block" if helix is not None else "") + ".",
           CONV, PLANE_TXT[plane] + ". R = 5.",
           f"Contour: P1 = (0,0), G{g} to (40,0) about C = (20,0), r = 20 (I20 in a).",
           f"  G{g} at the start (angle 180 deg): t = {P(ts)}; at the end (angle 0/360): t = {P(te)}.",
           f"  n_L(start) = {P(nls)}, n_L(end) = {P(nle)}; G{side} offset = "
           f"{'+' if s > 0 else '-'}5*n_L.",
           f"NORM approach: P0 = {P(p0)} -> Q1 = (0,0) {'+' if s > 0 else '-'} 5*n_L(start) = {P(q1)}.",
           f"Arc row: G{g} from Q1 to Qe = (40,0) {'+' if s > 0 else '-'} 5*n_L(end) = {P(qe)}, "
           f"centre C = (20,0) (equidistant circles are concentric), radius |Q1-C| = {f6(rr)}.",
           "  The approach line meets the equidistant circle first at Q1 (checked: the points of "
           "the line just before Q1 lie outside the circle), so nothing is intersected away."]
    if helix is not None:
        hdr.append(f"  Helix: applicate 0 -> {helix} over the block; the centre row is given in the "
                   "plane of the start point (applicate 0).")
    hdr += [f"NORM retraction: Qe -> P2 = {P(p2)} (applicate stays {app_end}).",
            "Rows: G0 P0 | selection Q1 | arc Qe | G40 P2, F100."]
    app_word = {17: "Z", 18: "Y", 19: "X"}[plane]
    hw = f" {app_word}{helix}" if helix is not None else ""
    body = tool() + [
        f"@g0 G{plane} G90 G0 {words(plane, p0[0], p0[1], 0)}",
        f"@sel G{side} G1 {words(plane, 0, 0)} F100",
        f"@arc G{g} {words(plane, 40, 0)}{hw} {L[3]}20 {L[4]}0",
        f"@ret G40 G1 {words(plane, p2[0], p2[1])}",
        "M30"]
    rows = [("g0", "G0", (*p0, 0), None, ""), ("sel", "G1", (*q1, 0), None, 100),
            ("arc", f"G{g}", (*qe, app_end), (20, 0, 0), 100),
            ("ret", "G1", (*p2, app_end), None, 100)]
    add(name, plane, hdr, body, rows)


arc_case("arc_g17_g2_g41_outside", 17, 41, 2)
arc_case("arc_g17_g3_g41_inside", 17, 41, 3)
arc_case("arc_g17_g2_g42_inside", 17, 42, 2)
arc_case("arc_g17_g3_g42_outside", 17, 42, 3)
arc_case("arc_g18_g2_g41_outside", 18, 41, 2)
arc_case("arc_g18_g3_g41_inside", 18, 41, 3)
arc_case("arc_g19_g2_g42_inside", 19, 42, 2)
arc_case("arc_g19_g3_g42_outside", 19, 42, 3)
arc_case("helix_g17_g3_g41_inside", 17, 41, 3, helix=-10)
arc_case("helix_g18_g2_g42_inside", 18, 42, 2, helix=8)
arc_case("helix_g19_g3_g42_outside", 19, 42, 3, helix=-6)

# ------------------------------------------------------------------------------------------
# A: selection / deselection rules

add("norm_g0_selection", 17,
    ["norm_g0_selection: G41 selected in a G0 block and deselected in a G0 block (spec 5.1:",
     "selection only in G0/G1; details Q9: G0 blocks are compensated like G1, PM turning example",
     "selects with G0 G42 and deselects with G0 G40).", CONV, PLANE_TXT[17] + ". R = 5.",
     "Contour: P1 = (0,0) -> (50,0), t = (1,0), n_L = (0,1), G41 offset (0,5).",
     "G0 selection: P0 (-10,-10) -> Q1 = (0,5), a G0 row (feed empty).",
     "G1 X50: (0,5) -> (50,5) F100.  G0 G40 X60 Y10: (50,5) -> (60,10), G0 row."],
    tool() + ["@g0 G17 G90 G0 X-10 Y-10 Z0", "@sel G41 G0 X0 Y0", "@l1 G1 X50 F100",
              "@ret G40 G0 X60 Y10", "M30"],
    [("g0", "G0", (-10, -10, 0), None, ""), ("sel", "G0", (0, 5, 0), None, ""),
     ("l1", "G1", (50, 5, 0), None, 100), ("ret", "G0", (60, 10, 0), None, "")])

add("norm_one_plane_axis", 17,
    ["norm_one_plane_axis: only one plane axis in the selection block; the other is added with",
     "its last position (spec 5.1, FM-W1 08/2005 2-41).", CONV, PLANE_TXT[17] + ". R = 5.",
     "G0 X-10 Y0, then 'G41 G1 X0': P1 = (0, 0) (Y filled in with its last value 0).",
     "First contour element Y30: (0,0) -> (0,30), t = (0,1), n_L = (-1,0), G41 offset (-5,0).",
     "NORM: P0 (-10,0) -> Q1 = (-5,0).  Line (-5,0) -> (-5,30).",
     "Retraction G40 X-10 Y40: Qe = (0,30) + (-5,0) = (-5,30) -> P2 (-10,40)."],
    tool() + ["@g0 G17 G90 G0 X-10 Y0 Z0", "@sel G41 G1 X0 F100", "@l1 Y30",
              "@ret G40 X-10 Y40", "M30"],
    [("g0", "G0", (-10, 0, 0), None, ""), ("sel", "G1", (-5, 0, 0), None, 100),
     ("l1", "G1", (-5, 30, 0), None, 100), ("ret", "G1", (-10, 40, 0), None, 100)])

add("norm_no_plane_axis", 17,
    ["norm_no_plane_axis: G41 in a block without a plane axis: no selection takes place in that",
     "block (spec 5.1, FM-W1 08/2005 2-41). READING: G41 stays modal and the selection happens in",
     "the next G0/G1 block with a plane axis; the Z block itself moves uncompensated.",
     CONV, PLANE_TXT[17] + ". R = 5.",
     "G0 X-10 Y-10 Z5 | 'G41 G1 Z0 F100': plain Z move at (-10,-10) |",
     "'X0 Y0' = selection block, first element X50: t = (1,0), n_L = (0,1) -> Q1 = (0,5) |",
     "X50 -> (50,5) | G40 X60 Y10 -> (60,10)."],
    tool() + ["@g0 G17 G90 G0 X-10 Y-10 Z5", "@z G41 G1 Z0 F100", "@sel X0 Y0", "@l1 X50",
              "@ret G40 X60 Y10", "M30"],
    [("g0", "G0", (-10, -10, 5), None, ""), ("z", "G1", (-10, -10, 0), None, 100),
     ("sel", "G1", (0, 5, 0), None, 100), ("l1", "G1", (50, 5, 0), None, 100),
     ("ret", "G1", (60, 10, 0), None, 100)])

add("d0_no_compensation", 17,
    ["d0_no_compensation: G41 with D0 (no offset active): no compensation, the tool centre",
     "follows the programmed contour (spec 5.1: D0 -> no TRC; FM-W1 2-41).",
     "T1 has radius 5 but D0 deselects every offset. Rows = programmed points."],
    ["$TC_DP1[1,1]=120", "$TC_DP6[1,1]=5", "T1 D0", "@g0 G17 G90 G0 X-10 Y-10 Z0",
     "@sel G41 G1 X0 Y0 F100", "@l1 X50", "@l2 Y-40", "@ret G40 X60 Y-50", "M30"],
    [("g0", "G0", (-10, -10, 0), None, ""), ("sel", "G1", (0, 0, 0), None, 100),
     ("l1", "G1", (50, 0, 0), None, 100), ("l2", "G1", (50, -40, 0), None, 100),
     ("ret", "G1", (60, -50, 0), None, 100)])

add("g41_in_g2_alarm", 17,
    ["g41_in_g2_alarm: G41 programmed in a G2 block. TRC can only be selected in a G0/G1 block",
     "(spec 5.1, FM-W1 08/2005 2-41): alarm 10753 'activation of tool radius compensation only",
     "possible in linear block' (number from memory, spec 5.6 [M]) on the G2 block.",
     "Rows before it: the G0 to (-10,0). Status 2."],
    tool() + ["@g0 G17 G90 G0 X-10 Y0 Z0", "@bad G41 G2 X10 Y0 I10 J0 F100", "X20",
              "G40 X30", "M30"],
    [("g0", "G0", (-10, 0, 0), None, "")], status=2, errs=[("bad", "alarm", 10753)])

add("g40_after_selection", 17,
    ["g40_after_selection: G40 in the block directly after the selection block cancels the",
     "selection (spec 5.1, FM-W1 08/2005 2-41): no compensation at all, rows = programmed points.",
     "READING: the selection block then ends at its programmed point (0,0), uncompensated."],
    tool() + ["@g0 G17 G90 G0 X-10 Y-10 Z0", "@sel G41 G1 X0 Y0 F100", "@ret G40 X50 Y10",
              "M30"],
    [("g0", "G0", (-10, -10, 0), None, ""), ("sel", "G1", (0, 0, 0), None, 100),
     ("ret", "G1", (50, 10, 0), None, 100)])

add("kont_not_behind", 17,
    ["kont_not_behind: KONT with a start point in front of the contour behaves like NORM",
     "(spec 5.2; details Q2: behind <=> (P0-P1).n1 < 0).", CONV, PLANE_TXT[17] + ". R = 5.",
     "P0 = (-10,10), P1 = (0,0), first element (0,0)->(50,0): t1 = (1,0), n1 = n_L = (0,1).",
     "(P0-P1).n1 = (-10,10).(0,1) = 10 >= 0 -> not behind -> NORM: line P0 -> Q1 = (0,5).",
     "Line (0,5) -> (50,5). Retraction (KONT still active): P2 = (60,10), Pe = (50,0),",
     "ne = (0,1): (P2-Pe).ne = 10 >= 0 -> not behind -> NORM: Qe = (50,5) -> P2."],
    tool() + ["@g0 G17 G90 G0 X-10 Y10 Z0", "@sel G41 KONT G1 X0 Y0 F100", "@l1 X50",
              "@ret G40 X60 Y10", "M30"],
    [("g0", "G0", (-10, 10, 0), None, ""), ("sel", "G1", (0, 5, 0), None, 100),
     ("l1", "G1", (50, 5, 0), None, 100), ("ret", "G1", (60, 10, 0), None, 100)])


# ------------------------------------------------------------------------------------------
# KONT approach/retraction from behind: PM example (spec 5.4) with the details Q2 model

def kont_case(name, g45, plane=17, side=41):
    R = 5.0
    P0 = (35.0, 0.0)
    P1 = (10.0, 10.0)
    d = math.dist(P0, P1)                      # sqrt(725)
    Lt = SQ(d * d - R * R)                     # sqrt(700)
    u = ((P1[0] - P0[0]) / d, (P1[1] - P0[1]) / d)
    ca, sa = Lt / d, R / d
    dirT = (u[0] * ca - u[1] * sa, u[0] * sa + u[1] * ca)   # rotate u by +alpha (CCW)
    T = (P0[0] + Lt * dirT[0], P0[1] + Lt * dirT[1])
    Q1 = (5.0, 10.0)
    sT = (5.0 - P0[0]) / dirT[0]
    S1 = (5.0, P0[1] + sT * dirT[1])
    defl_in = math.degrees(math.acos(dirT[1]))             # angle between dirT and (0,1)
    # corners
    A2 = (5.0, 60.0)
    B2 = (13.0, 64.0)
    A3 = (53.0, 34.0)
    t3 = (-40 / SQ(2000), -20 / SQ(2000))
    n3 = (-t3[1], t3[0])
    B3 = (50 + R * n3[0], 30 + R * n3[1])
    Qe = (10 + R * n3[0], 10 + R * n3[1])
    # retraction
    Pe = (10.0, 10.0)
    P2 = (-20.0, 50.0)
    dd = math.dist(Pe, P2)                     # 50
    beta = math.degrees(math.acos(R / dd))
    ue = ((P2[0] - Pe[0]) / dd, (P2[1] - Pe[1]) / dd)
    m = rot(ue, beta)
    T2 = (Pe[0] + R * m[0], Pe[1] + R * m[1])
    dirR = ((P2[0] - T2[0]), (P2[1] - T2[1]))
    lr = math.hypot(*dirR)
    dirR = (dirR[0] / lr, dirR[1] / lr)
    # intersection of N60's equidistant (Qe + s*t3) with line T2 + w*dirR
    det = t3[0] * (-dirR[1]) - t3[1] * (-dirR[0])
    rx, ry = T2[0] - Qe[0], T2[1] - Qe[1]
    s_ = (rx * (-dirR[1]) - ry * (-dirR[0])) / det
    S2 = (Qe[0] + s_ * t3[0], Qe[1] + s_ * t3[1])
    defl_out = math.degrees(math.acos(t3[0] * dirR[0] + t3[1] * dirR[1]))
    ang = lambda p, c: math.degrees(math.atan2(p[1] - c[1], p[0] - c[0]))
    hdr = [f"{name}: KONT approach and retraction from behind the contour with {g45} (spec 5.2,",
           "5.4 PM example; details Q2). The program is the PM example N10..N60 (spec 5.4) plus the",
           "retraction 'G40 X-20 Y50' quoted in details Q2 (numbered N70 here); R = 5.",
           CONV, PLANE_TXT[17] + ".",
           "Contour (closed triangle, G41 keeps the tool outside):",
           "  N40 (10,10)->(10,60) t1=(0,1) n1=(-1,0); N50 (10,60)->(50,30) t=(0.8,-0.6) n=(0.6,0.8);",
           "  N60 (50,30)->(10,10) t3=(-2,-1)/sqrt5=(-0.894427,-0.447214) n3=(0.447214,-0.894427).",
           "  N40/N50: cross(t1,t2) = -0.8 < 0 right turn = outside (G41); deflection acos(-0.6) = "
           "126.87 deg.",
           "  N50/N60: cross = -0.894427 < 0 outside; deflection acos(-0.447214) = 116.57 deg.",
           ("  G450: both get transition circles." if g45 == "G450" else
            "  G451: both deflections >= MD20210 = 100 deg -> automatic switch to the circle "
            "(spec 5.4, details Q4)."),
           "  Circle N40/N50 (belongs to N50): about (10,60) from A=(5,60) to B=(10,60)+5*(0.6,0.8)"
           "=(13,64), G2.",
           f"  Circle N50/N60 (belongs to N60): about (50,30) from A=(53,34) to B=(50,30)+5*n3="
           f"{P(B3)}, G2.",
           f"  N60 ends at Qe = (10,10)+5*n3 = {P(Qe)}.",
           "Approach N30 from P0 = (35,0) (after N20 G1 Z-5) to P1 = (10,10): (P0-P1).n1 = "
           "(25,-10).(-1,0) = -25 < 0 -> behind.",
           f"  Tangent from P0 to circle(P1,5): d = |P0-P1| = sqrt(725) = {f6(d)}, length "
           f"L = sqrt(725-25) = sqrt(700) = {f6(Lt)},",
           f"  alpha = asin(5/d) = {f6(math.degrees(math.asin(R / d)))} deg; u = (P1-P0)/d = "
           f"{P(u)}; travel direction = u turned +alpha (so that P1 is on the right, G41) = "
           f"{P(dirT)};",
           f"  T = P0 + L*dir = {P(T)} (details Q2: (9.0374, 5.0935))."]
    if g45 == "G450":
        hdr += [f"  G450: N30 = line P0 -> T, then G2 about P1 from T (angle {f6(ang(T, P1))} deg) to "
                f"Q1 = (5,10) (angle 180 deg), sweep {f6(ang(T, P1) % 360 - 180)} deg; both rows belong to "
                "N30 (KONT sub-blocks, details Q2)."]
    else:
        hdr += [f"  G451: deflection between dir and t1 = acos({f6(dirT[1])}) = {f6(defl_in)} deg < 100 -> "
                "intersection: the line P0 + s*dir meets N40's equidistant x = 5 (extended backwards)",
                f"  at s = 30/{f6(-dirT[0])} = {f6(sT)}: S1 = {P(S1)} (details Q2: (5, 5.8856)). N30 = one "
                "line P0 -> S1.",
                "  READING (README 'extensions'): N40's row starts at S1 (its equidistant extended "
                "backwards past Q1 = (5,10)); no extra row."]
    hdr += [f"Retraction N70 G40 to P2 = (-20,50): Pe = (10,10), ne = n3; (P2-Pe).ne = "
            f"{f6((P2[0] - Pe[0]) * n3[0] + (P2[1] - Pe[1]) * n3[1])} < 0 -> behind.",
            f"  Tangent point T2 on circle(Pe,5) of the line to P2 with Pe on the right: |P2-Pe| = 50, "
            f"beta = acos(5/50) = {f6(beta)} deg,",
            f"  T2 = Pe + 5*(u_e turned +beta), u_e = (-0.6,0.8): T2 = {P(T2)} (details Q2: (5.7201, 7.4150))."]
    if g45 == "G450":
        hdr += [f"  G450: N70 = G2 about Pe from Qe (angle {f6(ang(Qe, Pe))}) to T2 (angle "
                f"{f6(ang(T2, Pe))}), sweep {f6((ang(Qe, Pe) - ang(T2, Pe)) % 360)} deg (details Q2: 85.43), "
                "then line T2 -> P2; both rows N70 (KONT sub-blocks)."]
    else:
        hdr += [f"  G451: deflection between t3 and the direction T2->P2 {P(dirR)} = {f6(defl_out)} deg "
                "< 100 -> intersection of N60's equidistant Qe + s*t3 with the line T2-P2:",
                f"  s = {f6(s_)} -> S2 = {P(S2)} (details Q2: (8.1068, 3.4632)).",
                "  READING: N60's row runs on along its own equidistant to S2; N70 = one line S2 -> P2."]
    hdr += ["All rows at Z-5 with F500 (N10 sets F500, modal)."]
    body = ["$TC_DP1[1,1]=120", "$TC_DP6[1,1]=5", "@n10 N10 G17 T1 D1 G0 X35 Y0 Z0 F500",
            "@n20 N20 G1 Z-5", f"@n30 N30 G41 KONT {g45} X10 Y10", "@n40 N40 Y60",
            "@n50 N50 X50 Y30", "@n60 N60 X10 Y10", "@n70 N70 G40 X-20 Y50", "N80 M30"]
    if side == 42:
        L = LETTERS[plane]
        hdr = [f"{name}: the mirror image of kont_{g45.lower()}_pm_example in G{plane} with G42: every",
               "ordinate o is negated (a reflection turns left into right, so G41 becomes G42 and G2 "
               "becomes G3); the derivation below is that of the G17/G41 original, whose (a,o) values "
               "map to this case as (a,o) -> (a,-o); applicate -5 as in the original.",
               PLANE_TXT[plane] + ".",
               "--- original derivation (G17, G41): " + " ".join(hdr[0:3])] + hdr[3:]
        body = ["$TC_DP1[1,1]=120", "$TC_DP6[1,1]=5",
                f"@n10 N10 G{plane} T1 D1 G0 {L[0]}35 {L[1]}0 {L[2]}0 F500", f"@n20 N20 G1 {L[2]}-5",
                f"@n30 N30 G42 KONT {g45} {L[0]}10 {L[1]}-10", f"@n40 N40 {L[1]}-60",
                f"@n50 N50 {L[0]}50 {L[1]}-30", f"@n60 N60 {L[0]}10 {L[1]}-10",
                f"@n70 N70 G40 {L[0]}-20 {L[1]}-50", "N80 M30"]
    z = -5
    rows = [("n10", "G0", (35, 0, 0), None, ""), ("n20", "G1", (35, 0, z), None, 500)]
    if g45 == "G450":
        rows += [("n30", "G1", (*T, z), None, 500), ("n30", "G2", (5, 10, z), (10, 10, z), 500),
                 ("n40", "G1", (5, 60, z), None, 500)]
    else:
        rows += [("n30", "G1", (*S1, z), None, 500), ("n40", "G1", (5, 60, z), None, 500)]
    rows += [("n50", "G2", (13, 64, z), (10, 60, z), 500), ("n50", "G1", (*A3, z), None, 500),
             ("n60", "G2", (*B3, z), (50, 30, z), 500)]
    if g45 == "G450":
        rows += [("n60", "G1", (*Qe, z), None, 500)]
    if g45 == "G450":
        rows += [("n70", "G2", (*T2, z), (10, 10, z), 500), ("n70", "G1", (-20, 50, z), None, 500)]
    else:
        rows += [("n60", "G1", (*S2, z), None, 500), ("n70", "G1", (-20, 50, z), None, 500)]
    if side == 42:
        flip = lambda q: None if q is None else (q[0], -q[1], q[2])
        rows = [(lab, {"G2": "G3", "G3": "G2"}.get(mo, mo), flip(pp), flip(cc), fe)
                for lab, mo, pp, cc, fe in rows]
    add(name, plane, hdr, body, rows)


kont_case("kont_g450_pm_example", "G450")
kont_case("kont_g451_pm_example", "G451")
kont_case("kont_g450_g18_g42_mirrored", "G450", 18, 42)
kont_case("kont_g451_g19_g42_mirrored", "G451", 19, 42)

add("kont_start_inside_circle", 17,
    ["kont_start_inside_circle: KONT with the start point behind the contour and closer to the",
     "contour start point than R: no tangent to the circle about P1 exists -> alarm 10755 'activation",
     "of tool radius compensation via KONT not possible in current start point' (spec 5.2, 5.6;",
     "number from memory [M]) on the selection block.", CONV, PLANE_TXT[17] + ". R = 5.",
     "P0 = (2,-2), P1 = (0,0), first element X50: n1 = (0,1); (P0-P1).n1 = -2 < 0: behind;",
     "|P0-P1| = sqrt(8) = 2.83 < 5. Rows: the G0 only. Status 2."],
    tool() + ["@g0 G17 G90 G0 X2 Y-2 Z0", "@sel G41 KONT G450 G1 X0 Y0 F100", "X50", "G40 X60 Y10",
              "M30"],
    [("g0", "G0", (2, -2, 0), None, "")], status=2, errs=[("sel", "alarm", 10755)])


# ------------------------------------------------------------------------------------------
# O: outside corners

def outside_ll(name, plane, side, mode, extra_hdr=(), extra_body=(), feed2=200, words_sel=""):
    """Line (0,0)->(50,0) then line 90 deg turn to the outside: G41 turns right (->(50,-40)),
    G42 turns left (->(50,40))."""
    s = 1 if side == 41 else -1
    e2 = (50, -40 * s)
    q1 = (0, 5 * s)
    A = (50, 5 * s)
    B = (55, 0)
    E = (55, -40 * s)
    p0 = (-10, -10 * s)
    p2 = (60, -50 * s)
    L = LETTERS[plane]
    arc = "G2" if side == 41 else "G3"
    hdr = [f"{name}: outside corner line-line (90 deg) with G{side} and {mode} (spec 5.4; details Q3).",
           CONV, PLANE_TXT[plane] + ". R = 5.", *extra_hdr,
           f"Contour: (0,0) -> (50,0) t1 = (1,0) -> {P(e2)} t2 = (0,{-s}).",
           f"cross(t1,t2) = {-s} -> {'right' if s > 0 else 'left'} turn = outside for G{side}; "
           "deflection 90 deg.",
           f"Offsets: line 1 at o = {5 * s}; line 2: n_L(t2) = ({s},0), G{side} offset "
           f"{'+' if s > 0 else '-'}5*n_L = (5,0) -> a = 55.",
           f"A = end of equidistant 1 = {P(A)}; B = start of equidistant 2 = {P(B)}."]
    rows_corner = []
    if mode == "G450":
        hdr += [f"G450: transition circle radius R about the corner (50,0) from A to B, {arc} "
                f"({'clockwise' if side == 41 else 'counter-clockwise'}, 90 deg); it belongs to the "
                f"NEXT block (line 2) and takes its feed F{feed2}."]
        rows_corner = [("l2", arc, (*B, 0), (50, 0, 0), feed2)]
    else:
        S = (55, 5 * s)
        hdr += [f"G451 (deflection 90 < MD20210 = 100): intersection of the equidistants S = {P(S)}.",
                "READING (README 'extensions'): line 1 runs on to S, line 2 starts at S (its own "
                "equidistant, extended backwards); no extra rows."]
        A = S
        rows_corner = []
    hdr += [f"Approach NORM P0 = {P(p0)} -> Q1 = {P(q1)}; line 1 -> its corner point; line 2 -> {P(E)};",
            f"retraction NORM Qe = {P(E)} (n at the end of line 2) -> P2 = {P(p2)}."]
    body = tool() + list(extra_body) + [
        f"@g0 G{plane} G90 G0 {words(plane, p0[0], p0[1], 0)}",
        f"@sel G{side} {mode} G1 {words(plane, 0, 0)} F100{words_sel}",
        f"@l1 {L[0]}50",
        f"@l2 {L[1]}{num(e2[1])} F{feed2}",
        f"@ret G40 {words(plane, p2[0], p2[1])}",
        "M30"]
    rows = [("g0", "G0", (*p0, 0), None, ""), ("sel", "G1", (*q1, 0), None, 100),
            ("l1", "G1", (*A, 0), None, 100), *rows_corner,
            ("l2", "G1", (*E, 0), None, feed2), ("ret", "G1", (*p2, 0), None, feed2)]
    add(name, plane, hdr, body, rows)


outside_ll("g450_line_line_g17_g41", 17, 41, "G450")
outside_ll("g450_line_line_g18_g42", 18, 42, "G450")
outside_ll("g451_line_line_g17_g41", 17, 41, "G451")
outside_ll("g451_line_line_g19_g42", 19, 42, "G451")
outside_ll("g450_disc0_g17_g41", 17, 41, "G450",
           extra_hdr=["DISC=0 (programmed in the selection block) = plain transition circle (spec 5.4, "
                      "details Q3): same path as g450_line_line_g17_g41."],
           words_sel=" DISC=0")


def g450_line_arc(name, mode):
    # line (0,0)->(50,0); G2 to (58,-16) about C=(38,-16), r=20: start rel (12,16)/20=(0.6,0.8)
    C = (38, -16)
    B = (38 + 25 * 0.6, -16 + 25 * 0.8)           # (53,4)
    E = (63, -16)
    p2 = (70, -25)
    hdr = [f"{name}: outside corner line -> arc (G2, outside equidistant r+R) with G41 and {mode} "
           "(spec 5.4; details Q3).", CONV, PLANE_TXT[17] + ". R = 5.",
           "Contour: (0,0)->(50,0) t1=(1,0); G2 X58 Y-16 I-12 J-16: C = (38,-16), r = 20, start rel "
           "(12,16) = 20*(0.6,0.8).",
           "  CW tangent at the start = (sin, -cos) of the start angle = (0.8,-0.6); cross(t1,t2) = -0.6 "
           "< 0 right turn = outside (G41);",
           "  deflection = acos(0.8) = 36.87 deg. G2 with G41 -> equidistant circle radius 25.",
           "A = (50,5); B = C + 25*(0.6,0.8) = (53,4); arc end (58,-16) = C + 20*(1,0) -> Qe = C + "
           "25*(1,0) = (63,-16)."]
    if mode == "G450":
        hdr += ["G450: transition circle about (50,0) from A (90 deg) to B (angle 53.13 deg), G2, "
                "belongs to the G2 block (F100).",
                "Rows: line to A | [G2 block] G2 A->B centre (50,0) | G2 B->(63,-16) centre (38,-16)."]
        corner = [("arc", "G2", (53, 4, 0), (50, 0, 0), 100)]
        start_arc = "arc"
    else:
        sx = 38 + SQ(184)
        hdr += ["G451: intersection of y = 5 with circle(C,25): (x-38)^2 + 21^2 = 625 -> (x-38)^2 = 184,",
                f"  x = 38 + sqrt(184) = {f6(sx)} (the root nearest the corner; the other, 24.435, "
                "is far behind). S = (" + f6(sx) + ",5).",
                "  S lies beyond A on line 1 (x > 50) and before B on the circle (angle "
                f"{f6(math.degrees(math.atan2(21, SQ(184))))} > 53.13 deg, CW runs to smaller angles).",
                "READING (README 'extensions'; G451 extends straight lines and circles along themselves, "
                "FM 01/2015 p1426): rows",
                "  line (0,5) -> S | G2 S -> (63,-16) centre C (the arc starts earlier on its own circle)."]
        corner = []
    l1end = (50, 5) if mode == "G450" else (38 + SQ(184), 5)
    hdr += ["Approach NORM (-10,-10) -> (0,5); retraction NORM Qe = (63,-16) -> P2 = (70,-25)."]
    body = tool() + ["@g0 G17 G90 G0 X-10 Y-10 Z0", f"@sel G41 {mode} G1 X0 Y0 F100", "@l1 X50",
                     "@arc G2 X58 Y-16 I-12 J-16", "@ret G40 G1 X70 Y-25", "M30"]
    rows = [("g0", "G0", (-10, -10, 0), None, ""), ("sel", "G1", (0, 5, 0), None, 100),
            ("l1", "G1", (*l1end, 0), None, 100), *corner,
            ("arc", "G2", (*E, 0), (38, -16, 0), 100), ("ret", "G1", (*p2, 0), None, 100)]
    add(name, 17, hdr, body, rows)


g450_line_arc("g450_line_arc_g17_g41", "G450")
g450_line_arc("g451_line_arc_g17_g41", "G451")


def arc_line(name, plane, mode):
    # G2 from (30,-20) about (50,-20) r=20 to (50,0): end tangent (1,0); line to (62,-16) t=(0.6,-0.8)
    L = LETTERS[plane]
    C = (50, -20)
    q1 = (25, -20)
    A = (50, 5)
    B = (54, 3)
    E = (66, -13)
    p0 = (20, -30)
    p2 = (70, -30)
    hdr = [f"{name}: outside corner arc (G2, outside r+R) -> line with G41 and {mode} (spec 5.4).",
           CONV, PLANE_TXT[plane] + ". R = 5.",
           "Contour: P1 = (30,-20); G2 to (50,0) about C = (50,-20) (I20 J0 in (a,o)), r = 20: start "
           "angle 180 deg,",
           "  t_start = (0,1), n_L = (-1,0) -> Q1 = (25,-20); end angle 90 deg, t_end = (1,0), "
           "A = C + 25*(0,1) = (50,5).",
           "Line (50,0)->(62,-16): t2 = (12,-16)/20 = (0.6,-0.8), n_L = (0.8,0.6): B = (50,0)+5*(0.8,0.6) "
           "= (54,3), end (62,-16)+(4,3) = (66,-13).",
           "cross(t_end,t2) = -0.8 < 0 right turn = outside (G41); deflection acos(0.6) = 53.13 deg."]
    if mode == "G450":
        hdr += ["G450: transition circle about (50,0) from A (90 deg) to B (36.87 deg), G2, belongs to "
                "the line block."]
        corner = [("l2", "G2", (*B, 0), (50, 0, 0), 100)]
    else:
        sq = SQ(336)
        sv = 16 - sq
        S = (54 + 0.6 * sv, 3 - 0.8 * sv)
        hdr += ["G451: line 2's equidistant B + s*t2 meets circle(C,25): |(4+0.6s, 23-0.8s)|^2 = 625",
                "  -> s^2 - 32 s + 545 = 625 -> s^2 - 32 s - 80 = 0 -> s = 16 - sqrt(336) = "
                f"{f6(sv)} (the root with s < 0: line extended backwards).",
                f"  S = (54 + 0.6 s, 3 - 0.8 s) = {P(S)}; angle about C = "
                f"{f6(math.degrees(math.atan2(S[1] + 20, S[0] - 50)))} deg < 90: the arc is extended "
                "beyond its end (CW).",
                "READING (README 'extensions'): arc row G2 Q1 -> S centre C | line row S -> E."]
        A = S
        corner = []
    hdr += [f"Approach NORM P0 = {P(p0)} -> Q1 = (25,-20). Retraction NORM Qe = (66,-13) -> "
            f"P2 = {P(p2)}."]
    body = tool() + [f"@g0 G{plane} G90 G0 {words(plane, p0[0], p0[1], 0)}",
                     f"@sel G41 {mode} G1 {words(plane, 30, -20)} F100",
                     f"@arc G2 {words(plane, 50, 0)} {L[3]}20 {L[4]}0",
                     f"@l2 G1 {words(plane, 62, -16)}",
                     f"@ret G40 {words(plane, p2[0], p2[1])}", "M30"]
    rows = [("g0", "G0", (*p0, 0), None, ""), ("sel", "G1", (*q1, 0), None, 100),
            ("arc", "G2", (*A, 0), (*C, 0), 100), *corner,
            ("l2", "G1", (*E, 0), None, 100), ("ret", "G1", (*p2, 0), None, 100)]
    add(name, plane, hdr, body, rows)


arc_line("g450_arc_line_g17_g41", 17, "G450")
arc_line("g450_arc_line_g19_g41", 19, "G450")
arc_line("g451_arc_line_g18_g41", 18, "G451")

# arc -> arc, G42, G450
add("g450_arc_arc_g17_g42", 17,
    ["g450_arc_arc_g17_g42: outside corner arc -> arc (both G3, outside r+R for G42) with G450",
     "(spec 5.4).", CONV, PLANE_TXT[17] + ". R = 5; G42 offset = -5*n_L = +5*(t_o, -t_a).",
     "Arc 1: P1 = (30,20), G3 to (50,0) about C1 = (50,20) (I20 J0), r = 20: start angle 180,",
     "  t = (0,-1), G42 offset (-5,0) -> Q1 = (25,20) (radius 25 = outside); end angle 270, t = (1,0),",
     "  offset (0,-5) -> A = (50,-5).",
     "Arc 2: G3 from (50,0) to (46,28) about C2 = (34,12) (I-16 J12), r = 20: start rel (16,-12) =",
     "  20*(0.8,-0.6), CCW tangent (0.6,0.8), offset 5*(0.8,-0.6) -> B = (54,-3) = C2 + 25*(0.8,-0.6);",
     "  end rel (12,16) = 20*(0.6,0.8) -> Qe = C2 + 25*(0.6,0.8) = (49,32).",
     "Corner at (50,0): cross((1,0),(0.6,0.8)) = 0.8 > 0 left turn = outside for G42; deflection 53.13.",
     "G450: circle about (50,0) from A (270 deg) to B (323.13 deg), G3, belongs to arc 2 (F100).",
     "Approach NORM (20,30) -> (25,20). Retraction: end tangent of arc 2 (-0.8,0.6), offset",
     "  5*(0.6,0.8) -> Qe = (49,32) -> P2 = (45,45).",
     "Rows: G0 | sel (25,20) | G3 (50,-5) c (50,20) | [arc 2] G3 (54,-3) c (50,0) | G3 (49,32) c (34,12)",
     "| G40 (45,45)."],
    tool() + ["@g0 G17 G90 G0 X20 Y30 Z0", "@sel G42 G450 G1 X30 Y20 F100", "@a1 G3 X50 Y0 I20 J0",
              "@a2 G3 X46 Y28 I-16 J12", "@ret G40 G1 X45 Y45", "M30"],
    [("g0", "G0", (20, 30, 0), None, ""), ("sel", "G1", (25, 20, 0), None, 100),
     ("a1", "G3", (50, -5, 0), (50, 20, 0), 100), ("a2", "G3", (54, -3, 0), (50, 0, 0), 100),
     ("a2", "G3", (49, 32, 0), (34, 12, 0), 100), ("ret", "G1", (45, 45, 0), None, 100)])


def sharp(name, limit):
    r2 = SQ(2)
    B = (50 + 5 / r2, -5 / r2)
    E = (20 + 5 / r2, -30 - 5 / r2)
    S = (55 + 5 * r2, 5)
    hdr = [f"{name}: G451 at a sharp outside corner (deflection 135 deg) with MD20210 "
           f"CUTCOM_CORNER_LIMIT = {limit} (spec 5.4; details Q4).", CONV, PLANE_TXT[17] + ". R = 5.",
           "Contour: (0,0)->(50,0) t1=(1,0) -> (20,-30) t2=(-1,-1)/sqrt2; cross = -1/sqrt2 < 0 right "
           "turn = outside (G41);",
           "  deflection = acos(t1.t2) = acos(-0.707107) = 135 deg.",
           f"  A = (50,5); n_L(t2) = (1,-1)/sqrt2 -> B = (50 + 5/sqrt2, -5/sqrt2) = {P(B)}; end of line 2 "
           f"= (20,-30) + 5*n_L = {P(E)}."]
    if limit <= 135:
        hdr += [f"READING (details Q4): deflection 135 >= MD20210 = {limit} -> G451 switches to the "
                "G450 circle: G2 about (50,0) from A (90 deg) to B (-45 deg), sweep 135, belongs to line 2."]
        corner = [("l2", "G2", (*B, 0), (50, 0, 0), 100)]
    else:
        hdr += [f"Deflection 135 < MD20210 = {limit} -> intersection: S = P + R/cos(67.5 deg) * "
                "bisector(n1,n2);",
                "  on y = 5 and the line through B with slope 1: x = B_x + (5 - B_y) = 55 + 5*sqrt2 = "
                f"{f6(S[0])}; S = {P(S)}.",
                "READING (README 'extensions'): line 1 row ends at S, line 2 row starts there."]
        corner = [("l1", "G1", (*S, 0), None, 100)]
    hdr += ["Approach NORM (-10,-10) -> (0,5); retraction NORM from " + P(E) + " to P2 = (30,-40)."]
    body = tool() + [f"$MC_CUTCOM_CORNER_LIMIT={limit}", "@g0 G17 G90 G0 X-10 Y-10 Z0",
                     "@sel G41 G451 G1 X0 Y0 F100", "@l1 X50", "@l2 X20 Y-30", "@ret G40 X30 Y-40", "M30"]
    rows = [("g0", "G0", (-10, -10, 0), None, ""), ("sel", "G1", (0, 5, 0), None, 100),
            *([("l1", "G1", (50, 5, 0), None, 100)] if not corner or corner[0][0] != "l1" else []),
            *corner, ("l2", "G1", (*E, 0), None, 100),
            ("ret", "G1", (30, -40, 0), None, 100)]
    add(name, 17, hdr, body, rows)


sharp("g451_beyond_corner_limit", 100)
sharp("g451_corner_limit_150", 150)


def flat(name, md):
    r101 = SQ(101)
    B = (50 + 5 / r101, 50 / r101)
    E = (100 + 5 / r101, -5 + 50 / r101)
    S = (50 + 5 * (r101 - 10), 5)
    hdr = [f"{name}: G450 at a flat outside corner (deflection 5.71 deg) with MD20230 "
           f"CUTCOM_CURVE_INSERT_LIMIT = {md} (details Q4).", CONV, PLANE_TXT[17] + ". R = 5.",
           "Contour: (0,0)->(50,0) t1=(1,0) -> (100,-5) t2=(10,-1)/sqrt101; cross = -1/sqrt101 < 0 right "
           "turn = outside (G41);",
           "  deflection = atan(1/10) = 5.710593 deg. n_L(t2) = (1,10)/sqrt101.",
           f"  A = (50,5); B = (50 + 5/sqrt101, 50/sqrt101) = {P(B)}; line 2 ends at (100,-5) + 5*n_L "
           f"= {P(E)}."]
    if md > 5.8:
        hdr += [f"READING (details Q4): deflection 5.71 < MD20230 = {md} -> intersection instead of the "
                "circle, even under G450:",
                "  S on y = 5: x = 50 + R*tan(delta/2) = 50 + 5*(sqrt101 - 10) (tan(delta/2) = "
                f"(1 - cos)/sin = sqrt101 - 10) = {f6(S[0])}.",
                "Rows (README 'extensions'): line 1 row ends at S, line 2 row starts there."]
        corner = [("l1", "G1", (*S, 0), None, 100)]
    else:
        hdr += [f"MD20230 = {md}: no corner is flat enough -> the G450 circle: G2 about (50,0) from A to B "
                "(sweep 5.71 deg), belongs to line 2."]
        corner = [("l2", "G2", (*B, 0), (50, 0, 0), 100)]
    hdr += ["Approach NORM (-10,-10) -> (0,5); retraction NORM from line 2's end to P2 = (110,-10)."]
    body = tool() + [f"$MC_CUTCOM_CURVE_INSERT_LIMIT={md}", "@g0 G17 G90 G0 X-10 Y-10 Z0",
                     "@sel G41 G450 G1 X0 Y0 F100", "@l1 X50", "@l2 X100 Y-5", "@ret G40 X110 Y-10",
                     "M30"]
    rows = [("g0", "G0", (-10, -10, 0), None, ""), ("sel", "G1", (0, 5, 0), None, 100),
            *([("l1", "G1", (50, 5, 0), None, 100)] if not corner or corner[0][0] != "l1" else []),
            *corner, ("l2", "G1", (*E, 0), None, 100),
            ("ret", "G1", (110, -10, 0), None, 100)]
    add(name, 17, hdr, body, rows)


flat("g450_flat_curve_insert_limit", 10)
flat("g450_flat_curve_insert_limit_0", 0)


def reversal(name, plane, side, mode):
    s = 1 if side == 41 else -1
    arc = "G2" if side == 41 else "G3"
    L = LETTERS[plane]
    hdr = [f"{name}: reversal (deflection 180 deg) with G{side} and {mode} (spec 5.4; details Q3/Q4).",
           CONV, PLANE_TXT[plane] + ". R = 5.",
           "Contour: (0,0)->(50,0) t1=(1,0) -> (20,0) t2=(-1,0). Equidistants o = "
           f"{5 * s} and o = {-5 * s}: parallel, no intersection.",
           "READING: a reversal is an outside corner with deflection 180 deg (the tool has to go round "
           "the end point; an 'inside' reading has no intersection at all).",
           ("G450: " if mode == "G450" else "G451: 180 >= MD20210 = 100 -> circle (details Q4): ") +
           f"semicircle about (50,0) from A = (50,{5 * s}) through (55,0) to B = (50,{-5 * s}), {arc}, "
           "belongs to line 2.",
           f"Line 2: B -> (20,{-5 * s}). Retraction NORM: Qe = (20,{-5 * s}) -> P2 = (10,{-15 * s})."]
    body = tool() + [f"@g0 G{plane} G90 G0 {words(plane, -10, -10 * s, 0)}",
                     f"@sel G{side} {mode} G1 {words(plane, 0, 0)} F100",
                     f"@l1 {L[0]}50", f"@l2 {L[0]}20", f"@ret G40 {words(plane, 10, -15 * s)}", "M30"]
    rows = [("g0", "G0", (-10, -10 * s, 0), None, ""), ("sel", "G1", (0, 5 * s, 0), None, 100),
            ("l1", "G1", (50, 5 * s, 0), None, 100), ("l2", arc, (50, -5 * s, 0), (50, 0, 0), 100),
            ("l2", "G1", (20, -5 * s, 0), None, 100), ("ret", "G1", (10, -15 * s, 0), None, 100)]
    add(name, plane, hdr, body, rows)


reversal("reversal_g450_g17_g41", 17, 41, "G450")
reversal("reversal_g451_g18_g42", 18, 42, "G451")

add("g450_intermediate_block", 17,
    ["g450_intermediate_block: a block without plane motion (Z infeed) between the two blocks of a",
     "G450 outside corner is executed at P* = end of the first equidistant, before the transition",
     "circle (spec 5.4; details Q3, Q9). One such block is within MD20250 (ncoffset default 1).",
     CONV, PLANE_TXT[17] + ". R = 5.",
     "Contour as g450_line_line_g17_g41: (0,0)->(50,0)->(50,-40), G41, outside corner 90 deg.",
     "Rows: sel (0,5,0) | X50 -> P* = A = (50,5,0) | Z-2 at P*: (50,5,-2) F100 | [Y-40 block]",
     "G2 (55,0,-2) about (50,0,-2) F200 | (55,-40,-2) F200 | G40 (60,-50,-2)."],
    tool() + ["@g0 G17 G90 G0 X-10 Y-10 Z0", "@sel G41 G450 G1 X0 Y0 F100", "@l1 X50", "@z Z-2",
              "@l2 Y-40 F200", "@ret G40 X60 Y-50", "M30"],
    [("g0", "G0", (-10, -10, 0), None, ""), ("sel", "G1", (0, 5, 0), None, 100),
     ("l1", "G1", (50, 5, 0), None, 100), ("z", "G1", (50, 5, -2), None, 100),
     ("l2", "G2", (55, 0, -2), (50, 0, -2), 200), ("l2", "G1", (55, -40, -2), None, 200),
     ("ret", "G1", (60, -50, -2), None, 200)])


# ------------------------------------------------------------------------------------------
# I: inside corners and tangent transitions

def inside_ll(name, plane, side):
    s = 1 if side == 41 else -1
    e2 = (50, 40 * s)
    S = (45, 5 * s)
    E = (45, 40 * s)
    p0 = (-10, -10 * s)
    p2 = (40, 50 * s)
    L = LETTERS[plane]
    hdr = [f"{name}: inside corner line-line (90 deg) with G{side} (spec 5.4: intersection of the",
           "equidistants, both blocks shortened).", CONV, PLANE_TXT[plane] + ". R = 5.",
           f"Contour: (0,0)->(50,0) t1=(1,0) -> {P(e2)} t2=(0,{s}); cross(t1,t2) = {s}: "
           f"{'left' if s > 0 else 'right'} turn = inside for G{side}.",
           f"Equidistants: o = {5 * s} and a = 50 - 5 = 45 (n_L(t2) = ({-s},0), G{side}). S = {P(S)}: on "
           "both segments (a in [0,50], o between 0 and the end).",
           f"Rows: sel (0,{5 * s}) | line 1 -> S | line 2 S -> {P(E)} | retraction NORM Qe = {P(E)} -> "
           f"P2 = {P(p2)}."]
    body = tool() + [f"@g0 G{plane} G90 G0 {words(plane, p0[0], p0[1], 0)}",
                     f"@sel G{side} G1 {words(plane, 0, 0)} F100", f"@l1 {L[0]}50",
                     f"@l2 {L[1]}{num(e2[1])}", f"@ret G40 {words(plane, p2[0], p2[1])}", "M30"]
    rows = [("g0", "G0", (*p0, 0), None, ""), ("sel", "G1", (0, 5 * s, 0), None, 100),
            ("l1", "G1", (*S, 0), None, 100), ("l2", "G1", (*E, 0), None, 100),
            ("ret", "G1", (*p2, 0), None, 100)]
    add(name, plane, hdr, body, rows)


inside_ll("inside_line_line_g17_g41", 17, 41)
inside_ll("inside_line_line_g18_g42", 18, 42)
inside_ll("inside_line_line_g19_g41", 19, 41)

sx = 38 + SQ(104)
add("inside_line_arc_g17_g41", 17,
    ["inside_line_arc_g17_g41: inside corner line -> arc (G3, inside r-R) with G41 (spec 5.4).",
     CONV, PLANE_TXT[17] + ". R = 5.",
     "Contour: (0,0)->(50,0) t1=(1,0); G3 X58 Y16 I-12 J16: C = (38,16), r = 20, start rel (12,-16) =",
     "  20*(0.6,-0.8); CCW tangent (-sin, cos) = (0.8,0.6); cross(t1,t2) = 0.6 > 0 left turn = inside;",
     "  G3 with G41 -> equidistant radius 15; B = C + 15*(0.6,-0.8) = (47,4); end (58,16) -> Qe = (53,16).",
     "Intersection of y = 5 with circle(C,15): (x-38)^2 + 11^2 = 225 -> (x-38)^2 = 104 ->",
     f"  x = 38 +- sqrt(104) = {f6(sx)} or {f6(38 - SQ(104))}. The second (angle 227 deg) is not on the",
     "  arc (which runs from -53.13 to 0 deg); the first, at angle atan2(-11, 10.198) = -47.17 deg, is on",
     f"  it, after B: S = ({f6(sx)}, 5) (also the one nearest the start of the next block, spec 5.4).",
     "Rows: sel (0,5) | line -> S | G3 S -> (53,16) centre (38,16) | retraction NORM: end tangent (0,1),",
     "  n_L = (-1,0), Qe = (53,16) -> P2 = (50,30)."],
    tool() + ["@g0 G17 G90 G0 X-10 Y-10 Z0", "@sel G41 G1 X0 Y0 F100", "@l1 X50",
              "@arc G3 X58 Y16 I-12 J16", "@ret G40 G1 X50 Y30", "M30"],
    [("g0", "G0", (-10, -10, 0), None, ""), ("sel", "G1", (0, 5, 0), None, 100),
     ("l1", "G1", (sx, 5, 0), None, 100), ("arc", "G3", (53, 16, 0), (38, 16, 0), 100),
     ("ret", "G1", (50, 30, 0), None, 100)])

sv = 16 - SQ(176)
S_al = (46 + 0.6 * sv, 3 + 0.8 * sv)
add("inside_arc_line_g17_g41", 17,
    ["inside_arc_line_g17_g41: inside corner arc (G3, inside r-R) -> line with G41 (spec 5.4).",
     CONV, PLANE_TXT[17] + ". R = 5.",
     "Contour: P1 = (30,20); G3 X50 Y0 I20 J0: C = (50,20), r = 20, start angle 180 (t = (0,-1),",
     "  n_L = (1,0) -> Q1 = (35,20), radius 15), end angle 270, t = (1,0).",
     "Line (50,0)->(62,16): t2 = (0.6,0.8), n_L = (-0.8,0.6): equidistant B + s*t2 with B = (46,3);",
     "  end (62,16)+(-4,3) = (58,19). cross((1,0),t2) = 0.8 > 0 left turn = inside.",
     "Intersection with circle(C,15): |(-4+0.6s, -17+0.8s)|^2 = 225 -> s^2 - 32 s + 305 = 225 ->",
     f"  s^2 - 32 s + 80 = 0 -> s = 16 - sqrt(176) = {f6(sv)} (nearest the start of the line) ->",
     f"  S = (46 + 0.6 s, 3 + 0.8 s) = {P(S_al)}; angle about C = "
     f"{f6(math.degrees(math.atan2(S_al[1] - 20, S_al[0] - 50)) % 360)} deg (< 270: arc shortened at its end).",
     "Rows: G0 (20,30) | sel (35,20) | G3 -> S centre (50,20) | line S -> (58,19) |",
     "  retraction NORM Qe = (58,19) -> P2 = (60,30)."],
    tool() + ["@g0 G17 G90 G0 X20 Y30 Z0", "@sel G41 G1 X30 Y20 F100", "@arc G3 X50 Y0 I20 J0",
              "@l2 G1 X62 Y16", "@ret G40 X60 Y30", "M30"],
    [("g0", "G0", (20, 30, 0), None, ""), ("sel", "G1", (35, 20, 0), None, 100),
     ("arc", "G3", (*S_al, 0), (50, 20, 0), 100), ("l2", "G1", (58, 19, 0), None, 100),
     ("ret", "G1", (60, 30, 0), None, 100)])

k = SQ(185 / 160)
S_aa = (44 + 4 * k, 18 - 12 * k)
add("inside_arc_arc_g17_g41", 17,
    ["inside_arc_arc_g17_g41: inside corner arc -> arc (both G3, inside r-R) with G41 (spec 5.4).",
     CONV, PLANE_TXT[17] + ". R = 5.",
     "Arc 1: P1 = (30,20), G3 X50 Y0 I20 J0, C1 = (50,20), r = 20 -> equidistant radius 15, Q1 = (35,20);",
     "  end tangent (1,0). Arc 2: G3 X58 Y16 I-12 J16, C2 = (38,16), r = 20, start tangent (0.8,0.6):",
     "  left turn = inside; equidistant radius 15; end Qe = C2 + 15*(1,0) = (53,16).",
     "Circles (C1,15) and (C2,15): d = |C2-C1| = |(-12,-4)| = sqrt(160); mid M = (44,18);",
     "  h = sqrt(15^2 - 40) = sqrt(185); points M +- h*(4,-12)/sqrt(160) = M +- k*(4,-12),",
     f"  k = sqrt(185/160) = {f6(k)}: {P(S_aa)} and {P((44 - 4 * k, 18 + 12 * k))}.",
     f"  The first lies on arc 1 (angle {f6(math.degrees(math.atan2(S_aa[1] - 20, S_aa[0] - 50)) % 360)} "
     "in 180..270) and on arc 2 (angle "
     f"{f6(math.degrees(math.atan2(S_aa[1] - 16, S_aa[0] - 38)))} in -53.13..0): S = {P(S_aa)}.",
     "Rows: G0 (20,30) | sel (35,20) | G3 -> S c (50,20) | G3 S -> (53,16) c (38,16) |",
     "  retraction NORM (53,16) -> (50,30)."],
    tool() + ["@g0 G17 G90 G0 X20 Y30 Z0", "@sel G41 G1 X30 Y20 F100", "@a1 G3 X50 Y0 I20 J0",
              "@a2 G3 X58 Y16 I-12 J16", "@ret G40 G1 X50 Y30", "M30"],
    [("g0", "G0", (20, 30, 0), None, ""), ("sel", "G1", (35, 20, 0), None, 100),
     ("a1", "G3", (*S_aa, 0), (50, 20, 0), 100), ("a2", "G3", (53, 16, 0), (38, 16, 0), 100),
     ("ret", "G1", (50, 30, 0), None, 100)])

add("tangent_line_arc_line_g17_g41", 17,
    ["tangent_line_arc_line_g17_g41: tangential transitions line -> arc -> line: nothing is inserted",
     "and nothing is intersected; the equidistants meet end to start (spec 5.4; details Q3).",
     CONV, PLANE_TXT[17] + ". R = 5.",
     "Contour: (0,0)->(50,0); G3 X70 Y20 I0 J20 (C = (50,20), r = 20, start angle 270: t = (1,0),",
     "  tangent to the line); G1 Y50 (t = (0,1) = tangent at the arc end, angle 0).",
     "G41: line y = 5 -> (50,5); arc inside radius 15: (50,5) -> (65,20); line x = 65 -> (65,50).",
     "Retraction NORM: Qe = (65,50) -> P2 = (60,60)."],
    tool() + ["@g0 G17 G90 G0 X-10 Y-10 Z0", "@sel G41 G1 X0 Y0 F100", "@l1 X50",
              "@arc G3 X70 Y20 I0 J20", "@l2 G1 Y50", "@ret G40 X60 Y60", "M30"],
    [("g0", "G0", (-10, -10, 0), None, ""), ("sel", "G1", (0, 5, 0), None, 100),
     ("l1", "G1", (50, 5, 0), None, 100), ("arc", "G3", (65, 20, 0), (50, 20, 0), 100),
     ("l2", "G1", (65, 50, 0), None, 100), ("ret", "G1", (60, 60, 0), None, 100)])

add("tangent_line_arc_line_g18_g42", 18,
    ["tangent_line_arc_line_g18_g42: tangential transitions line -> G2 arc -> line with G42: nothing",
     "inserted (spec 5.4).", CONV, PLANE_TXT[18] + ". R = 5; G42 offset = 5*(t_o, -t_a).",
     "Contour (a,o): (0,0)->(50,0) t=(1,0), offset (0,-5); G2 to (70,-20) about C = (50,-20) (K0 I-20):",
     "  start angle 90, CW tangent (1,0) (tangent); G2 with G42 = inside, radius 15: (50,-5) -> (65,-20);",
     "  line (70,-20)->(70,-50): t = (0,-1), offset (-5,0): (65,-20) -> (65,-50).",
     "Retraction NORM (65,-50) -> P2 = (60,-60)."],
    tool() + ["@g0 G18 G90 G0 Z-10 X10 Y0", "@sel G42 G1 Z0 X0 F100", "@l1 Z50",
              "@arc G2 Z70 X-20 K0 I-20", "@l2 G1 X-50", "@ret G40 Z60 X-60", "M30"],
    [("g0", "G0", (-10, 10, 0), None, ""), ("sel", "G1", (0, -5, 0), None, 100),
     ("l1", "G1", (50, -5, 0), None, 100), ("arc", "G2", (65, -20, 0), (50, -20, 0), 100),
     ("l2", "G1", (65, -50, 0), None, 100), ("ret", "G1", (60, -60, 0), None, 100)])

add("inside_intermediate_block", 17,
    ["inside_intermediate_block: a block without plane motion (Z infeed) between the two blocks of an",
     "inside corner is executed at the corner point S (details Q9 [D]).", CONV, PLANE_TXT[17] + ". R = 5.",
     "Contour as inside_line_line_g17_g41: (0,0)->(50,0)->(50,40), G41, S = (45,5).",
     "Rows: sel (0,5,0) | X50 -> (45,5,0) | Z-2 at S: (45,5,-2) | Y40 -> (45,40,-2) |",
     "  G40 (40,50,-2)."],
    tool() + ["@g0 G17 G90 G0 X-10 Y-10 Z0", "@sel G41 G1 X0 Y0 F100", "@l1 X50", "@z Z-2", "@l2 Y40",
              "@ret G40 X40 Y50", "M30"],
    [("g0", "G0", (-10, -10, 0), None, ""), ("sel", "G1", (0, 5, 0), None, 100),
     ("l1", "G1", (45, 5, 0), None, 100), ("z", "G1", (45, 5, -2), None, 100),
     ("l2", "G1", (45, 40, -2), None, 100), ("ret", "G1", (40, 50, -2), None, 100)])


add("norm_approach_cuts_equidistant", 17,
    ["norm_approach_cuts_equidistant: the NORM approach line cuts the first element's equidistant",
     "before the normal point Q1: that intersection replaces Q1 and the element starts there (details",
     "Q1: with G460 the approach line is intersected with the following equidistant like an inside",
     "corner).", CONV, PLANE_TXT[17] + ". R = 5.",
     "First element: G3 X40 Y0 I20 J0 from (0,0): C = (20,0), r = 20, G41 inside: radius 15,",
     "  Q1 = (5,0), Qe = (35,0) (as arc_g17_g3_g41_inside).",
     "Approach from P0 = (40,-10): line P0 + s*(Q1-P0) = (40-35s, -10+10s) on the circle",
     "  (x-20)^2 + y^2 = 225: (20-35s)^2 + (10s-10)^2 = 225 -> 1325 s^2 - 1600 s + 275 = 0 ->",
     "  s = (1600 +- 1050)/2650 = 1 (Q1) or 11/53. s = 11/53: S = (40 - 385/53, -10 + 110/53) =",
     f"  (1735/53, -420/53) = {P((1735 / 53, -420 / 53))}; angle about C = "
     f"{f6(math.degrees(math.atan2(-420 / 53, 1735 / 53 - 20)) % 360)} deg, inside the arc's range 180..360.",
     "Rows: G0 (40,-10) | selection -> S | G3 S -> (35,0) centre (20,0) | retraction (35,0) -> (50,-10)."],
    tool() + ["@g0 G17 G90 G0 X40 Y-10 Z0", "@sel G41 G1 X0 Y0 F100", "@arc G3 X40 Y0 I20 J0",
              "@ret G40 G1 X50 Y-10", "M30"],
    [("g0", "G0", (40, -10, 0), None, ""), ("sel", "G1", (1735 / 53, -420 / 53, 0), None, 100),
     ("arc", "G3", (35, 0, 0), (20, 0, 0), 100), ("ret", "G1", (50, -10, 0), None, 100)])

add("norm_retraction_cuts_equidistant", 17,
    ["norm_retraction_cuts_equidistant: the NORM retraction line from Qe cuts the last element's",
     "equidistant again: that intersection replaces Qe, the element ends there and the retraction",
     "starts there (details Q1, symmetric to the approach).", CONV, PLANE_TXT[17] + ". R = 5.",
     "Element: G3 X40 Y0 I20 J0 from (0,0), C = (20,0), G41 inside radius 15: Q1 = (5,0), Qe = (35,0).",
     "Retraction to P2 = (0,-10): line Qe + s*(P2-Qe) = (35-35s, -10s) on (x-20)^2 + y^2 = 225:",
     "  (15-35s)^2 + 100 s^2 = 225 -> 1325 s^2 - 1050 s = 0 -> s = 0 (Qe) or 42/53.",
     f"  s = 42/53: S = (35 - 1470/53, -420/53) = (385/53, -420/53) = {P((385 / 53, -420 / 53))};",
     f"  angle {f6(math.degrees(math.atan2(-420 / 53, 385 / 53 - 20)) % 360)} deg, on the arc (180..360).",
     "Rows: G0 (-10,-10) | selection (5,0) | G3 (5,0) -> S centre (20,0) | G40 S -> (0,-10)."],
    tool() + ["@g0 G17 G90 G0 X-10 Y-10 Z0", "@sel G41 G1 X0 Y0 F100", "@arc G3 X40 Y0 I20 J0",
              "@ret G40 G1 X0 Y-10", "M30"],
    [("g0", "G0", (-10, -10, 0), None, ""), ("sel", "G1", (5, 0, 0), None, 100),
     ("arc", "G3", (385 / 53, -420 / 53, 0), (20, 0, 0), 100), ("ret", "G1", (0, -10, 0), None, 100)])

add("dummy_blocks_limit", 17,
    ["dummy_blocks_limit: more blocks without plane motion in a row than MD20250",
     "CUTCOM_MAXNUM_DUMMY_BLOCKS (set to 2 here) while G41 is active -> alarm 10762 'too many empty",
     "blocks between two traversing blocks with active tool radius compensation' (spec 5.4/5.6, details",
     "Q5/Q9; number [M]) on the third such block (Z-3).", CONV, PLANE_TXT[17] + ". R = 5.",
     "READING (README 'alarms'): rows only for blocks whose end points were fixed before the alarm:",
     "G0 and the selection block (0,5). X50 waits for its successor, Z-1/Z-2 wait with it. Status 2."],
    tool() + ["$MC_CUTCOM_MAXNUM_DUMMY_BLOCKS=2", "@g0 G17 G90 G0 X-10 Y-10 Z0",
              "@sel G41 G1 X0 Y0 F100", "X50", "Z-1", "Z-2", "@bad Z-3", "Y-40", "G40 X60 Y-50", "M30"],
    [("g0", "G0", (-10, -10, 0), None, ""), ("sel", "G1", (0, 5, 0), None, 100)],
    status=2, errs=[("bad", "alarm", 10762)])

add("g40_in_g2_alarm", 17,
    ["g40_in_g2_alarm: G40 programmed in a G2 block: deselection only in a G0/G1 block -> alarm 10754",
     "'deactivation of tool radius compensation only possible in linear block' (spec 5.6, number [M];",
     "symmetric to the selection rule of FM-W1 2-41) on that block.", CONV, PLANE_TXT[17] + ". R = 5.",
     "Rows (README 'alarms'): G0 and the selection block (0,5); X50 still waits for its successor.",
     "Status 2."],
    tool() + ["@g0 G17 G90 G0 X-10 Y-10 Z0", "@sel G41 G1 X0 Y0 F100", "X50",
              "@bad G40 G2 X60 Y-10 I0 J-10", "M30"],
    [("g0", "G0", (-10, -10, 0), None, ""), ("sel", "G1", (0, 5, 0), None, 100)],
    status=2, errs=[("bad", "alarm", 10754)])

# ------------------------------------------------------------------------------------------
# B: bottlenecks, alarms

GROOVE_HDR = [
    CONV, PLANE_TXT[17] + ". R = 5 (tool diameter 10).",
    "Contour (a narrow groove, 4 wide and 4 deep, beside a wall):",
    "  N10 (0,0)->(40,0) t=(1,0): equidistant y = 5, x in [0,40];",
    "  N20 (40,0)->(40,-4) t=(0,-1): x = 45, y in [-4,0];   (N10/N20: right turn = outside)",
    "  N30 (40,-4)->(44,-4) t=(1,0): y = 1, x in [40,44];   (N20/N30: left turn = inside)",
    "  N40 (44,-4)->(44,20) t=(0,1): x = 39, y in [-4,20];  (N30/N40: left turn = inside)",
    "N20/N30: x = 45 and y = 1 meet at (45,1), on neither segment (N20 would run backwards) -> no",
    "  intersection; N30/N40: (39,1), not on N30's segment -> none. N10/N30, N20/N40: parallel.",
    "N10/N40 (non-consecutive, 3 blocks apart): y = 5 and x = 39 meet at (39,5), on both segments."]

add("cdon_bottleneck", 17,
    ["cdon_bottleneck: bottleneck detection CDON with MD20240 = 3: only the equidistants of N10 and N40",
     "intersect, so N20 and N30 are omitted (spec 5.5, PM-NC p286 example; details Q5). The PM",
     "example is a figure without coordinates; this contour reproduces its structure.", *GROOVE_HDR,
     "Result: N10 ends at S = (39,5), N40 starts there; N20, N30 produce no rows. Details Q5 [V]:",
     "  warning 10763 for an omitted block, program not interrupted (status 0). READING: one warning per",
     "  omitted block, printed as 'FILE:LINE: warning 10763: ...' (ncoffset has no warning format yet).",
     "Approach NORM (-10,10) -> (0,5) (first element N10). Retraction N50 NORM: Pe = (44,20),",
     "  ne = (-1,0) -> Qe = (39,20) -> P2 = (30,30).",
     "Rows: G0 | sel (0,5) | N10 (39,5) | N40 (39,20) | N50 (30,30)."],
    tool() + ["$MC_CUTCOM_MAXNUM_CHECK_BLOCKS=3", "@g0 G17 G90 G0 X-10 Y10 Z0",
              "@sel G41 CDON G1 X0 Y0 F100", "@n10 N10 X40", "@n20 N20 Y-4", "@n30 N30 X44",
              "@n40 N40 Y20", "@n50 N50 G40 X30 Y30", "M30"],
    [("g0", "G0", (-10, 10, 0), None, ""), ("sel", "G1", (0, 5, 0), None, 100),
     ("n10", "G1", (39, 5, 0), None, 100), ("n40", "G1", (39, 20, 0), None, 100),
     ("n50", "G1", (30, 30, 0), None, 100)],
    errs=[("n20", "warning", 10763), ("n30", "warning", 10763)])

add("cdof_bottleneck", 17,
    ["cdof_bottleneck: the groove of cdon_bottleneck with CDOF (the initial setting). READING: the",
     "result is the same: with CDOF the search for a block's intersection goes back to the previous",
     "block 'and if necessary to even earlier blocks' (PM-NC p286), and 'predictive examination of more",
     "than two adjacent blocks is thus possible with CDON and CDOF' (FM-W1 11/2006 p82); N40's search",
     "finds N10 within MD20240 = 3 blocks (spec 5.4/5.5; details Q5).", *GROOVE_HDR,
     "Result: N10 ends at S = (39,5), N40 starts there; N20 and N30 omitted with warning 10763 each.",
     "Rows: G0 | sel (0,5) | N10 (39,5) | N40 (39,20) | N50 (30,30)."],
    tool() + ["$MC_CUTCOM_MAXNUM_CHECK_BLOCKS=3", "@g0 G17 G90 G0 X-10 Y10 Z0",
              "@sel G41 CDOF G1 X0 Y0 F100", "@n10 N10 X40", "@n20 N20 Y-4", "@n30 N30 X44",
              "@n40 N40 Y20", "@n50 N50 G40 X30 Y30", "M30"],
    [("g0", "G0", (-10, 10, 0), None, ""), ("sel", "G1", (0, 5, 0), None, 100),
     ("n10", "G1", (39, 5, 0), None, 100), ("n40", "G1", (39, 20, 0), None, 100),
     ("n50", "G1", (30, 30, 0), None, 100)],
    errs=[("n20", "warning", 10763), ("n30", "warning", 10763)])

add("cdon_bottleneck_check_blocks_2", 17,
    ["cdon_bottleneck_check_blocks_2: the same groove with MD20240 CUTCOM_MAXNUM_CHECK_BLOCKS = 2: the",
     "only intersection (N10/N40) is 3 blocks apart, beyond the reviewed blocks -> alarm 10751 'danger",
     "of collision due to tool radius compensation' (spec 5.5/5.6; 10751 text: 'has not been able to",
     "calculate a point of intersection for the reviewed number of traversing blocks').", *GROOVE_HDR,
     "READING (README 'alarms'): the alarm names the first block whose equidistant cannot be used",
     "  (N20: its end has no valid intersection), and only rows whose end points were fixed are written:",
     "  sel (0,5) and N10 ending at A = (40,5) (the N10/N20 outside corner; the transition circle",
     "  belongs to N20 and is not written). Status 2."],
    tool() + ["$MC_CUTCOM_MAXNUM_CHECK_BLOCKS=2", "@g0 G17 G90 G0 X-10 Y10 Z0",
              "@sel G41 CDON G1 X0 Y0 F100", "@n10 N10 X40", "@n20 N20 Y-4", "@n30 N30 X44",
              "@n40 N40 Y20", "@n50 N50 G40 X30 Y30", "M30"],
    [("g0", "G0", (-10, 10, 0), None, ""), ("sel", "G1", (0, 5, 0), None, 100),
     ("n10", "G1", (40, 5, 0), None, 100)],
    status=2, errs=[("n20", "alarm", 10751)])

add("inside_arc_radius_too_small", 17,
    ["inside_arc_radius_too_small: a slot end (inside G3 arc) of radius 3 < R = 5 with G41; the slot is",
     "6 wide, the tool 10: no equidistant exists and the neighbouring equidistants are parallel",
     "-> alarm 10751 (details Q6 last row: model [D]; spec 5.6).", CONV, PLANE_TXT[17] + ".",
     "Contour: (0,-3)->(20,-3) t=(1,0): equidistant y = 2; G3 X20 Y3 I0 J3: C = (20,0), r = 3, G3 with G41",
     "  = inside, radius 3 - 5 = -2 < 0: no equidistant; (20,3)->(0,3) t=(-1,0), n_L = (0,-1): y = -2.",
     "  y = 2 and y = -2 never meet; the retraction line from (0,-2) to (-10,10) crosses y = 2 at x = -3.3,",
     "  outside the first equidistant (x in [0,20]) -> no intersection within MD20240 = 3 blocks.",
     "READING (README 'alarms'): alarm on the first block whose equidistant cannot be used = the arc;",
     "  rows only for blocks with fixed end points: G0 and the selection block (Q1 = (0,-3)+(0,5) =",
     "  (0,2)); the first line's end depends on the failed corner and is not written. Status 2."],
    tool() + ["@g0 G17 G90 G0 X-10 Y-10 Z0", "@sel G41 G1 X0 Y-3 F100", "@l1 X20", "@arc G3 X20 Y3 I0 J3",
              "@l2 G1 X0", "@ret G40 X-10 Y10", "M30"],
    [("g0", "G0", (-10, -10, 0), None, ""), ("sel", "G1", (0, 2, 0), None, 100)],
    status=2, errs=[("arc", "alarm", 10751)])

add("inside_fillet_radius_too_small", 17,
    ["inside_fillet_radius_too_small: an inside fillet of radius 2 < R = 5 between two lines whose",
     "equidistants do intersect: the fillet is omitted like a bottleneck block (details Q6 last row,",
     "model [D]; with the default CDOF the search for the second line goes back past the fillet, spec",
     "5.5). Warning 10763 on the fillet (README 'alarms'); status 0.", CONV, PLANE_TXT[17] + ".",
     "Contour: (0,0)->(30,0): y = 5; G3 X32 Y2 I0 J2 (C = (30,2), r = 2, inside radius -3: none);",
     "  (32,2)->(32,30) t=(0,1), n_L=(-1,0): x = 27, y in [2,30].",
     "  y = 5 and x = 27 meet at S = (27,5): on both segments (x in [0,30], y in [2,30]).",
     "Rows: sel (0,5) | line 1 -> (27,5) | (fillet: no row) | line 2 -> (27,30) | retraction NORM",
     "  Qe = (27,30) -> P2 = (20,40)."],
    tool() + ["@g0 G17 G90 G0 X-10 Y-10 Z0", "@sel G41 CDOF G1 X0 Y0 F100", "@l1 X30",
              "@arc G3 X32 Y2 I0 J2", "@l2 G1 Y30", "@ret G40 X20 Y40", "M30"],
    [("g0", "G0", (-10, -10, 0), None, ""), ("sel", "G1", (0, 5, 0), None, 100),
     ("l1", "G1", (27, 5, 0), None, 100), ("l2", "G1", (27, 30, 0), None, 100),
     ("ret", "G1", (20, 40, 0), None, 100)],
    errs=[("arc", "warning", 10763)])

add("plane_change_alarm", 17,
    ["plane_change_alarm: G18 while G41 is active -> alarm 10757 (spec 5.1, 5.6 [V]) on the G18 block.",
     CONV, PLANE_TXT[17] + ". R = 5.",
     "Selection (-10,-10) -> Q1 = (0,5) (first element X50). X50's end would depend on the next motion",
     "  block, which never comes. READING (README 'alarms'): rows only for blocks whose end point was",
     "  fixed before the alarm: G0 and the selection block. Status 2."],
    tool() + ["@g0 G17 G90 G0 X-10 Y-10 Z0", "@sel G41 G1 X0 Y0 F100", "@l1 X50", "@bad G18",
              "Z10", "G40 X60", "M30"],
    [("g0", "G0", (-10, -10, 0), None, ""), ("sel", "G1", (0, 5, 0), None, 100)],
    status=2, errs=[("bad", "alarm", 10757)])

# G461 example of spec 5.3
R = 10
Sx = 50 - SQ(75)
n80 = (-1 / SQ(5), 2 / SQ(5))      # G42 offset direction (t_o, -t_a) of t = (-2,-1)/sqrt5
B80 = (30 + R * n80[0], R * n80[1])
E80 = (20 + R * n80[0], -5 + R * n80[1])
add("g461_pm_example", 17,
    ["g461_pm_example: the G461 example program of spec 5.3 (FM-W1 11/2006 p94), R = 10, G42, NORM,",
     "G450, CDOF (initial settings). CHANGE: 'G1' added to N30; as printed the program has no G1 and",
     "would run every block in G0 although it sets F10000/F600 (READING: the manual's G1 was lost).",
     CONV, PLANE_TXT[17] + ". G42 offset = R*(t_o, -t_a).",
     "N40 (0,0)->(0,20) uncompensated. N50 selection to P1 = (50,5), G461.",
     "  N60 (50,5)->(50,0) t=(0,-1), offset (-10,0): x = 40, y in [0,5] (5 long, shorter than R).",
     "  N70 (50,0)->(30,0) t=(-1,0), offset (0,10): y = 10, x in [30,50].",
     "  N80 (30,0)->(20,-5) t=(-2,-1)/sqrt5, offset 10*(-1,2)/sqrt5: " + P(B80) + " -> " + P(E80) + ".",
     "N60/N70: right turn = inside for G42: x = 40 and y = 10 meet at (40,10), not on N60's",
     "  segment -> N60 has no usable intersection. With NORM the approach line ends at Q1 = (40,5);",
     "  the line (0,20)->(40,5) meets y = 10 at x = 26.67 (not in [30,50]) and N80's equidistant",
     "  (y = 0.5x - 3.819660) at x = 27.22 (not in [15.53,25.53]).",
     "G461 (spec 5.3, details Q7; READING for the approach side, symmetric to retraction): the",
     "  approach block's offset curve is extended by the circle about P1 = (50,5), radius 10 (through",
     "  Q1), used only to find an intersection: with y = 10: (x-50)^2 = 100 - 25 = 75 ->",
     f"  x = 50 - sqrt(75) = {f6(Sx)} (in [30,50]; 58.66 is not). N80's line is 14.47 > 10 from (50,5).",
     f"  -> the approach block is one line (0,20) -> S = ({f6(Sx)},10); N70 starts at S; N60 is",
     "  omitted (warning 10763 on N60, as for any omitted block, README 'alarms').",
     "N70/N80: left turn = outside for G42 (cross = +0.447); G450 circle about (30,0) from (30,10) to",
     f"  B = {P(B80)}, G3, belongs to N80 (F600). N80 -> {P(E80)}.",
     "N90 G40 X0 Y0: NORM retraction from Qe = " + P(E80) + " to (0,0) (no intersection involved).",
     "Rows: N40 G1 (0,20) F10000 | N50 G1 S F10000 | N70 G1 (30,10) F600 | N80 G3 B c (30,0) | N80 G1 Qe |",
     "  N90 G1 (0,0)."],
    ["@n10 N10 $TC_DP1[1,1]=120", "N20 $TC_DP6[1,1]=10", "@n30 N30 G1 X0 Y0 F10000 T1 D1",
     "@n40 N40 Y20", "@n50 N50 G42 X50 Y5 G461", "@n60 N60 Y0 F600", "@n70 N70 X30",
     "@n80 N80 X20 Y-5", "@n90 N90 X0 Y0 G40", "N100 M30"],
    [("n40", "G1", (0, 20, 0), None, 10000), ("n50", "G1", (Sx, 10, 0), None, 10000),
     ("n70", "G1", (30, 10, 0), None, 600), ("n80", "G3", (*B80, 0), (30, 0, 0), 600),
     ("n80", "G1", (*E80, 0), None, 600), ("n90", "G1", (0, 0, 0), None, 600)],
    errs=[("n60", "warning", 10763)])


# ------------------------------------------------------------------------------------------
# M: radius sources, side flips, frames, D change

# OFFN
add("offn_allowance", 17,
    ["offn_allowance: OFFN=2 adds to the tool radius: compensation distance 5 + 2 = 7 (spec 5.1,",
     "PM-NC p251).", CONV, PLANE_TXT[17] + ".",
     "Contour as g450_line_line_g17_g41 with R = 7: Q1 = (0,7); A = (50,7); G450 circle radius 7",
     "about (50,0) to B = (57,0), G2, belongs to Y-40 (F200); line 2 -> (57,-40); retraction -> (60,-50)."],
    tool() + ["@g0 G17 G90 G0 X-10 Y-10 Z0", "@sel G41 G450 G1 X0 Y0 F100 OFFN=2", "@l1 X50",
              "@l2 Y-40 F200", "@ret G40 X60 Y-50", "M30"],
    [("g0", "G0", (-10, -10, 0), None, ""), ("sel", "G1", (0, 7, 0), None, 100),
     ("l1", "G1", (50, 7, 0), None, 100), ("l2", "G2", (57, 0, 0), (50, 0, 0), 200),
     ("l2", "G1", (57, -40, 0), None, 200), ("ret", "G1", (60, -50, 0), None, 200)])

add("wear_radius", 17,
    ["wear_radius: the compensation distance is radius + wear: $TC_DP6 = 5, $TC_DP15 = -1 -> R = 4",
     "(spec 1.2; 5.1).", CONV, PLANE_TXT[17] + ".",
     "Contour as g450_line_line_g17_g41 with R = 4: Q1 = (0,4); A = (50,4); G2 about (50,0) to",
     "B = (54,0) (F200, belongs to Y-40); -> (54,-40); retraction -> (60,-50)."],
    ["$TC_DP1[1,1]=120", "$TC_DP6[1,1]=5", "$TC_DP15[1,1]=-1", "T1 D1",
     "@g0 G17 G90 G0 X-10 Y-10 Z0", "@sel G41 G450 G1 X0 Y0 F100", "@l1 X50",
     "@l2 Y-40 F200", "@ret G40 X60 Y-50", "M30"],
    [("g0", "G0", (-10, -10, 0), None, ""), ("sel", "G1", (0, 4, 0), None, 100),
     ("l1", "G1", (50, 4, 0), None, 100), ("l2", "G2", (54, 0, 0), (50, 0, 0), 200),
     ("l2", "G1", (54, -40, 0), None, 200), ("ret", "G1", (60, -50, 0), None, 200)])

add("negative_radius", 17,
    ["negative_radius: a negative compensation value works on the other side: G41 with $TC_DP6 = -5",
     "behaves like G42 with 5 (details Q8 [V2]: PM-F 10.2004 p8-28, PM-NC p256).", CONV,
     PLANE_TXT[17] + ".",
     "Contour (0,0)->(50,0)->(50,-40): offset -5*n_L: line 1 at y = -5, line 2 (t=(0,-1), n_L=(1,0))",
     "  at x = 45. The right turn is an INSIDE corner for the right side: S = (45,-5).",
     "Rows: sel (0,-5) | line 1 -> (45,-5) | line 2 -> (45,-40) | retraction Qe = (45,-40) -> (40,-50)."],
    ["$TC_DP1[1,1]=120", "$TC_DP6[1,1]=-5", "T1 D1", "@g0 G17 G90 G0 X-10 Y10 Z0",
     "@sel G41 G450 G1 X0 Y0 F100", "@l1 X50", "@l2 Y-40", "@ret G40 X40 Y-50", "M30"],
    [("g0", "G0", (-10, 10, 0), None, ""), ("sel", "G1", (0, -5, 0), None, 100),
     ("l1", "G1", (45, -5, 0), None, 100), ("l2", "G1", (45, -40, 0), None, 100),
     ("ret", "G1", (40, -50, 0), None, 100)])

add("frame_rot_z90", 17,
    ["frame_rot_z90: TRC works in the WCS; a rotating frame turns the compensated path as a whole",
     "(G41 stays left of the contour as programmed). ROT Z90 maps WCS (x,y) -> MCS (-y,x).",
     "WCS path as g450_line_line_g17_g41 (R = 5): (-10,-10) | (0,5) | (50,5) | G2 (55,0) c (50,0) |",
     "  (55,-40) | (60,-50).",
     "MCS: (10,-10) | (-5,0) | (-5,50) | G2 (0,55) c (0,50) (a rotation about Z keeps the sense) |",
     "  (40,55) | (50,60)."],
    tool() + ["ROT Z90", "@g0 G17 G90 G0 X-10 Y-10 Z0", "@sel G41 G450 G1 X0 Y0 F100", "@l1 X50",
              "@l2 Y-40 F200", "@ret G40 X60 Y-50", "M30"],
    [("g0", "G0", (10, -10, 0), None, ""), ("sel", "G1", (-5, 0, 0), None, 100),
     ("l1", "G1", (-5, 50, 0), None, 100), ("l2", "G2", (0, 55, 0), (0, 50, 0), 200),
     ("l2", "G1", (40, 55, 0), None, 200), ("ret", "G1", (50, 60, 0), None, 200)])

add("frame_mirror_x", 17,
    ["frame_mirror_x: MIRROR X0: the control swaps G41/G42 (and G2/G3) in the mirrored system, which is",
     "the same as compensating in the WCS and mirroring the result: in the MCS the tool runs on the",
     "RIGHT of the mirrored contour (spec 5.1; frames: mirroring one axis swaps G2/G3 in the output).",
     "WCS path as g450_line_line_g17_g41 (R = 5): (-10,-10) | (0,5) | (50,5) | G2 (55,0) c (50,0) |",
     "  (55,-40) | (60,-50).  MCS x -> -x: (10,-10) | (0,5) | (-50,5) | G3 (-55,0) c (-50,0) |",
     "  (-55,-40) | (-60,-50).  Check: MCS contour (0,0)->(-50,0) runs along -X with the tool at +Y:",
     "  that is its right side (G42 in MCS terms)."],
    tool() + ["MIRROR X0", "@g0 G17 G90 G0 X-10 Y-10 Z0", "@sel G41 G450 G1 X0 Y0 F100", "@l1 X50",
              "@l2 Y-40 F200", "@ret G40 X60 Y-50", "M30"],
    [("g0", "G0", (10, -10, 0), None, ""), ("sel", "G1", (0, 5, 0), None, 100),
     ("l1", "G1", (-50, 5, 0), None, 100), ("l2", "G3", (-55, 0, 0), (-50, 0, 0), 200),
     ("l2", "G1", (-55, -40, 0), None, 200), ("ret", "G1", (-60, -50, 0), None, 200)])

add("d_change_under_trc", 17,
    ["d_change_under_trc: D1 (R = 5) -> D2 (R = 3) while G41 is active: the new radius applies from the",
     "block with D2 and is spread over the whole block, so the line becomes inclined from",
     "(start + R_old*n) to (end + R_new*n) (details Q8 [V] PM-F 11/2006 p353). The corner between",
     "X50 and X100 is tangential (nothing inserted); it uses R_old at the start of the varying block.",
     CONV, PLANE_TXT[17] + ".",
     "Rows: sel (0,5) | X50 -> (50,5) | X100 D2 -> (100,3) | retraction NORM with R = 3: Qe = (100,3)",
     "  -> P2 = (110,10)."],
    ["$TC_DP1[1,1]=120", "$TC_DP6[1,1]=5", "$TC_DP1[1,2]=120", "$TC_DP6[1,2]=3", "T1 D1",
     "@g0 G17 G90 G0 X-10 Y-10 Z0", "@sel G41 G1 X0 Y0 F100", "@l1 X50", "@l2 X100 D2",
     "@ret G40 X110 Y10", "M30"],
    [("g0", "G0", (-10, -10, 0), None, ""), ("sel", "G1", (0, 5, 0), None, 100),
     ("l1", "G1", (50, 5, 0), None, 100), ("l2", "G1", (100, 3, 0), None, 100),
     ("ret", "G1", (110, 10, 0), None, 100)])

if __name__ == "__main__":
    write_all()
