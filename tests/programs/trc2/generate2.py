#!/usr/bin/env python3
"""Writes the second batch of TRC golden cases (this folder, README.md):
side changes, D changes in arcs, G462/G461 at approach/retraction, look-ahead (CDON/CDOF)
and omitted blocks.

It reuses the helpers of tests/programs-pending/trc/generate.py (importing it only registers that file's cases in
its own list, which is emptied here; nothing is written there). As there, nothing here
implements TRC: every case spells out its own hand construction and the script only does the
arithmetic, the line numbering and the plane mapping (G17 (a,o,app) = (X,Y,Z),
G18 = (Z,X,Y), G19 = (Y,Z,X)).

Run: python3 tests/programs/trc2/generate2.py   (deterministic)
"""
import importlib.util
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
_spec = importlib.util.spec_from_file_location(
    "trc_generate", os.path.join(HERE, "..", "..", "programs-pending", "trc", "generate.py"))
g = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(g)
g.CASES.clear()          # keep only the cases of this file
g.HERE = HERE            # write into trc2/

add, words, num, f6, P = g.add, g.words, g.num, g.f6, g.P
LETTERS, PLANE_TXT, CONV = g.LETTERS, g.PLANE_TXT, g.CONV
SQ = math.sqrt


def tool(r=5, extra=()):
    return ["$TC_DP1[1,1]=120", f"$TC_DP6[1,1]={num(r)}", *extra, "T1 D1"]


def two_edges(r1, r2):
    return ["$TC_DP1[1,1]=120", f"$TC_DP6[1,1]={num(r1)}", "$TC_DP1[1,2]=120",
            f"$TC_DP6[1,2]={num(r2)}", "T1 D1"]


def ang(p, c):
    return math.degrees(math.atan2(p[1] - c[1], p[0] - c[0])) % 360


def line_circle(b, d, c, r):
    """Roots s of |b + s d - c| = r (d unit): returns (s1, s2) with s1 <= s2."""
    w = (b[0] - c[0], b[1] - c[1])
    wd = w[0] * d[0] + w[1] * d[1]
    disc = wd * wd - (w[0] ** 2 + w[1] ** 2 - r * r)
    return (-wd - SQ(disc), -wd + SQ(disc))


def at(b, d, s):
    return (b[0] + s * d[0], b[1] + s * d[1])


READ_LA = ("READING (brief): block k (approach line = 0, first contour block = 1) may intersect blocks "
           "k-1 .. k-MD20240; CDON always searches k-2 .. k-N and takes the farthest hit; a hit counts "
           "only strictly inside the earlier (trimmed) equidistant, within the later one, and when the "
           "later element turns towards the compensation side there (cross(t_earlier, t_later) > 0 for "
           "G41, < 0 for G42). Omitted blocks: warning 10763 each, status 0.")

READ_SIDE = ("READING (brief, side change): no corner at the change; the previous element ends on "
             "its normal at its end point, the new block starts on its new-side normal at its start; "
             "a straight joining row (the new block's line and feed, applicate unchanged) connects "
             "them, then the new block's own row.")

# ------------------------------------------------------------------------------------------
# 1. G41 <-> G42 change in a line

add("side_change_g41_g42_g17", 17,
    ["side_change_g41_g42_g17: G41 -> G42 while compensation is active, in a straight line (G17).",
     CONV, PLANE_TXT[17] + ". R = 5.", READ_SIDE,
     "Selection G41 from P0 = (-10,10) to P1 = (0,0); l1 (0,0)->(40,0): t = (1,0), n_L = (0,1),",
     "  G41 offset (0,5): Q1 = (0,5) (the approach line meets y = 5 only at Q1).",
     "l1 ends on its normal at (40,0): (40,5) (no corner with l2: side change).",
     "l2 'G42 X80 F200' (40,0)->(80,0): G42 offset -5*n_L = (0,-5): starts at (40,-5);",
     "  joining row (40,5) -> (40,-5) with l2's line number and F200.",
     "l2/l3: l3 (80,0)->(80,-30) t = (0,-1), n_L = (1,0), G42 offset (-5,0): x = 75.",
     "  cross((1,0),(0,-1)) = -1: right turn = inside for G42 -> y = -5 and x = 75 meet at S = (75,-5)",
     "  (on l2: x in [40,80]; on l3: y in [-30,0]).",
     "Retraction NORM: Qe = (80,-30) + (-5,0) = (75,-30) -> P2 = (90,-40).",
     "Rows: G0 (-10,10) | sel (0,5) | l1 (40,5) | l2 join (40,-5) F200 | l2 (75,-5) | l3 (75,-30) |",
     "  G40 (90,-40)."],
    tool() + ["@g0 G17 G90 G0 X-10 Y10 Z0", "@sel G41 G1 X0 Y0 F100", "@l1 X40",
              "@l2 G42 X80 F200", "@l3 Y-30", "@ret G40 X90 Y-40", "M30"],
    [("g0", "G0", (-10, 10, 0), None, ""), ("sel", "G1", (0, 5, 0), None, 100),
     ("l1", "G1", (40, 5, 0), None, 100), ("l2", "G1", (40, -5, 0), None, 200),
     ("l2", "G1", (75, -5, 0), None, 200), ("l3", "G1", (75, -30, 0), None, 200),
     ("ret", "G1", (90, -40, 0), None, 200)])

# G18: G42 -> G41, slanted new block, inside corner afterwards
t2 = (0.6, 0.8)
st = (30 - 4, 0 + 3)                       # (30,0) + 5*n_L, n_L = (-0.8,0.6)
s_c = (55 - st[0]) / t2[0]
S_18 = (55.0, st[1] + s_c * t2[1])
add("side_change_g42_g41_g18", 18,
    ["side_change_g42_g41_g18: G42 -> G41 while compensation is active (G18), the new block slanted,",
     "followed by an inside corner with the new side.", CONV, PLANE_TXT[18] + ". R = 5.", READ_SIDE,
     "Selection G42 from P0 = (-10,-10) to (0,0); l1 (0,0)->(30,0): t = (1,0), G42 offset",
     "  -5*n_L = (0,-5): Q1 = (0,-5); l1 ends on its normal at (30,-5).",
     "l2 'G41' (30,0)->(60,40): t2 = (0.6,0.8), n_L = (-0.8,0.6), G41 offset (-4,3): starts at (26,3);",
     "  joining row (30,-5) -> (26,3), l2's line and F150.",
     "l3 (60,40)->(60,70): t = (0,1), n_L = (-1,0), offset (-5,0): a = 55, o in [40,70].",
     "  cross(t2,(0,1)) = 0.6 > 0: left turn = inside for G41: (26,3) + s*(0.6,0.8) at a = 55:",
     f"  s = 29/0.6 = {f6(s_c)} (in [0,50]) -> S = {P(S_18)} (o in [40,70]).",
     "Retraction NORM: Qe = (60,70) + (-5,0) = (55,70) -> P2 = (50,80).",
     f"Rows: G0 | sel (0,-5) | l1 (30,-5) | l2 join (26,3) F150 | l2 {P(S_18)} | l3 (55,70) | G40 (50,80)."],
    tool() + [f"@g0 G18 G90 G0 {words(18, -10, -10, 0)}", f"@sel G42 G1 {words(18, 0, 0)} F100",
              f"@l1 {words(18, 30)}", f"@l2 G41 {words(18, 60, 40)} F150", f"@l3 {words(18, None, 70)}",
              f"@ret G40 {words(18, 50, 80)}", "M30"],
    [("g0", "G0", (-10, -10, 0), None, ""), ("sel", "G1", (0, -5, 0), None, 100),
     ("l1", "G1", (30, -5, 0), None, 100), ("l2", "G1", (26, 3, 0), None, 150),
     ("l2", "G1", (*S_18, 0), None, 150), ("l3", "G1", (55, 70, 0), None, 150),
     ("ret", "G1", (50, 80, 0), None, 150)])

# ------------------------------------------------------------------------------------------
# 2. D change in arcs (spiral rows)

READ_D = ("READING (brief; details Q8): the new radius is spread over the block that programs the "
          "new D; a circle becomes a spiral written as ONE G2/G3 row with the programmed centre, from "
          "radius r-+R_old at its start to r-+R_new at its end. Corners at the block's start use "
          "R_old, at its end R_new (FM-W1 08/2005 p2-70: the intersection uses the end value of the "
          "first and the start value of the second block).")

# G17, G3 (inside), D1 R=5 -> D2 R=3; outside corner at the start (R_old), inside at the end
C2a = (60.0, 0.0)
d3 = (1 / SQ(2), 1 / SQ(2))
b3 = (60 - 3 / SQ(2), -20 + 3 / SQ(2))      # (60,-20) + 3*n_L, n_L = (-1,1)/sqrt2
s1, s2 = line_circle(b3, d3, C2a, 17)
S2a = at(b3, d3, s1)
E3 = (80 - 3 / SQ(2), 3 / SQ(2))
add("d_change_spiral_g3_g17", 17,
    ["d_change_spiral_g3_g17: D1 (R = 5) -> D2 (R = 3) in a G3 arc under G41 (inside arc): spiral row;",
     "an outside corner at the arc's start (R_old) and an inside corner at its end (R_new).",
     CONV, PLANE_TXT[17] + ".", READ_D,
     "Selection from (-10,-10) to (0,0); l1 (0,0)->(40,0): y = 5, Q1 = (0,5).",
     "Arc 'G3 X60 Y-20 I20 J0 D2': C = (60,0), r = 20, from angle 180 to 270 CCW; CCW tangent",
     "  (-sin, cos): start (0,-1), end (1,0). G3 + G41 = inside: radius r - R.",
     "l1/arc: cross((1,0),(0,-1)) = -1: right turn = outside, 90 deg; G450 circle with R_old = 5 about",
     "  (40,0) from (40,5) to (40,0) + 5*n_L(0,-1) = (45,0), G2, belongs to the arc block (F100).",
     "Spiral: from (45,0) (radius 20-5 = 15, angle 180) towards radius 20-3 = 17 at angle 270.",
     "l3 'G1 X80 Y0' (60,-20)->(80,0): t3 = (1,1)/sqrt2, n_L = (-1,1)/sqrt2; offset with R_new = 3:",
     f"  B3 = (60,-20) + 3*n_L = {P(b3)}; end {P(E3)}. cross((1,0),t3) = 0.707 > 0: inside.",
     "  Intersection with the constant-R_new circle (C, 17): s^2 + 2 s (w.d) + |w|^2 - 289 = 0,",
     f"  w = B3 - C: s = {f6(s1)} or {f6(s2)}; the first is nearest l3's start and on the arc:",
     f"  S = {P(S2a)}, angle {f6(ang(S2a, C2a))} deg (in 180..270); the second lies at angle "
     f"{f6(ang(at(b3, d3, s2), C2a))} deg (not on the arc).",
     f"Retraction NORM: Qe = {P(E3)} -> P2 = (90,-5).",
     f"Rows: G0 | sel (0,5) | l1 (40,5) | arc G2 (45,0) c (40,0) | arc G3 {P(S2a)} c (60,0) |",
     f"  l3 {P(E3)} | G40 (90,-5)."],
    two_edges(5, 3) + ["@g0 G17 G90 G0 X-10 Y-10 Z0", "@sel G41 G1 X0 Y0 F100", "@l1 X40",
                       "@arc G3 X60 Y-20 I20 J0 D2", "@l3 G1 X80 Y0", "@ret G40 X90 Y-5", "M30"],
    [("g0", "G0", (-10, -10, 0), None, ""), ("sel", "G1", (0, 5, 0), None, 100),
     ("l1", "G1", (40, 5, 0), None, 100), ("arc", "G2", (45, 0, 0), (40, 0, 0), 100),
     ("arc", "G3", (*S2a, 0), (60, 0, 0), 100), ("l3", "G1", (*E3, 0), None, 100),
     ("ret", "G1", (90, -5, 0), None, 100)])

# G19, G2 (outside), D1 R=5 -> D2 R=8; tangent start, outside corner at the end with R_new
B2b = (50 + 8 / SQ(2), -20 - 8 / SQ(2))
E2b = (20 + 8 / SQ(2), -50 - 8 / SQ(2))
add("d_change_spiral_g2_g19", 19,
    ["d_change_spiral_g2_g19: D1 (R = 5) -> D2 (R = 8) in a G2 arc under G41 (outside arc, G19): spiral",
     "row from radius 25 to 28, then an outside corner (G450) with R_new = 8.",
     CONV, PLANE_TXT[19] + ".", READ_D,
     "Selection from (-10,10) to (0,0); l1 (0,0)->(30,0): o = 5, Q1 = (0,5); l1 ends at (30,5).",
     "Arc 'G2 to (50,-20) J0 K-20 D2': C = (30,-20), r = 20, from angle 90 to 0 CW; CW tangent",
     "  (sin, -cos): start (1,0) (tangent to l1: nothing inserted, start radius 20+5 = 25 gives (30,5)),",
     "  end (0,-1). G2 + G41 = outside: end radius 20+8 = 28 -> end point (58,-20).",
     "  Spiral row: G2 (30,5) -> (58,-20), centre (30,-20).",
     "l3 (50,-20)->(20,-50): t3 = (-1,-1)/sqrt2, n_L = (1,-1)/sqrt2; cross((0,-1),t3) = -0.707 < 0:",
     "  right turn = outside, 45 deg. G450 circle with R_new = 8 about (50,-20) from (58,-20) (angle 0)",
     f"  to (50,-20) + 8*n_L = {P(B2b)} (angle -45), G2, belongs to l3.",
     f"  l3 -> {P(E2b)}. Retraction NORM {P(E2b)} -> P2 = (10,-60)."],
    two_edges(5, 8) + [f"@g0 G19 G90 G0 {words(19, -10, 10, 0)}", f"@sel G41 G1 {words(19, 0, 0)} F100",
                       f"@l1 {words(19, 30)}", f"@arc G2 {words(19, 50, -20)} J0 K-20 D2",
                       f"@l3 G1 {words(19, 20, -50)}", f"@ret G40 {words(19, 10, -60)}", "M30"],
    [("g0", "G0", (-10, 10, 0), None, ""), ("sel", "G1", (0, 5, 0), None, 100),
     ("l1", "G1", (30, 5, 0), None, 100), ("arc", "G2", (58, -20, 0), (30, -20, 0), 100),
     ("l3", "G2", (*B2b, 0), (50, -20, 0), 100), ("l3", "G1", (*E2b, 0), None, 100),
     ("ret", "G1", (10, -60, 0), None, 100)])

# ------------------------------------------------------------------------------------------
# 3. sign change of the compensation value via a second edge

add("negative_edge_side_change_g17", 17,
    ["negative_edge_side_change_g17: G41 active with D1 (R = 5), then D2 with $TC_DP6[1,2] = -5 in a line.",
     "A negative value means the other side (details Q8 [V2]); READING (brief): a sign change of the",
     "compensation value is handled like a G41 -> G42 change (no corner, joining row), not spread over",
     "the block. Same path as side_change_g41_g42_g17 with F100 throughout.", CONV, PLANE_TXT[17] + ".",
     "l1 (0,0)->(40,0) G41 +5: y = 5, ends on its normal at (40,5).",
     "l2 'X80 D2': G41 with -5 = right side: starts at (40,0) - 5*(0,1) = (40,-5); joining row (40,5) ->",
     "  (40,-5) with l2's line.",
     "l3 (80,0)->(80,-30): offset -5*n_L = (-5,0): x = 75; right turn with the tool on the right =",
     "  inside: S = (75,-5).",
     "Retraction NORM with the active value -5: Qe = (80,-30) - 5*(1,0) = (75,-30) -> P2 = (90,-40).",
     "Rows: G0 (-10,10) | sel (0,5) | l1 (40,5) | l2 (40,-5) | l2 (75,-5) | l3 (75,-30) | G40 (90,-40)."],
    two_edges(5, -5) + ["@g0 G17 G90 G0 X-10 Y10 Z0", "@sel G41 G1 X0 Y0 F100", "@l1 X40",
                        "@l2 X80 D2", "@l3 Y-30", "@ret G40 X90 Y-40", "M30"],
    [("g0", "G0", (-10, 10, 0), None, ""), ("sel", "G1", (0, 5, 0), None, 100),
     ("l1", "G1", (40, 5, 0), None, 100), ("l2", "G1", (40, -5, 0), None, 100),
     ("l2", "G1", (75, -5, 0), None, 100), ("l3", "G1", (75, -30, 0), None, 100),
     ("ret", "G1", (90, -40, 0), None, 100)])

# ------------------------------------------------------------------------------------------
# 4. G462 on the approach

R = 10
n80 = (-1 / SQ(5), 2 / SQ(5))
B80 = (30 + R * n80[0], R * n80[1])
E80 = (20 + R * n80[0], -5 + R * n80[1])
TAIL_HDR = [
    "N70/N80: t = (-1,0) -> (-2,-1)/sqrt5, cross = +0.447: left turn = outside for G42 (26.57 deg);",
    f"  G450 circle about (30,0) from (30,10) to B = (30,0) + 10*(-1,2)/sqrt5 = {P(B80)}, G3, belongs to",
    f"  N80 (F600); N80 -> {P(E80)}. G40 X0 Y0: NORM retraction from there to (0,0) (N80 meets N70,",
    "  so G462 has nothing to do on the retraction)."]
S4 = (40 + 10 / 3, 10.0)
add("g462_approach_from_below_alarm", 17,
    ["g462_approach_from_below_alarm: G462 in the selection block (NORM, G42, R = 10), contour shape of the",
     "G461 example of spec 5.3 (N60 shorter than R, N70 perpendicular, N80 slanted), started from below",
     "so that the approach LINE extended beyond Q1 does cross N70's equidistant (brief's G462 reading).",
     "That crossing is NOT valid under the brief's turn condition, so nothing closes N60/N70: alarm.",
     "(The brief asked for numbers where the line extension hits: with this shape no valid hit exists;",
     "README 'Notes'.)", CONV, PLANE_TXT[17] + ". G42 offset = R*(t_o, -t_a).", READ_LA,
     "Approach P0 = (30,-10) -> P1 = (50,5).",
     "  N60 (50,5)->(50,0) t = (0,-1), offset (-10,0): a = 40, y in [0,5]: Q1 = (40,5).",
     "  N70 (50,0)->(30,0) t = (-1,0), offset (0,10): y = 10, x in [30,50].",
     "  N80 (30,0)->(20,-5) t = (-2,-1)/sqrt5, offset 10*(-1,2)/sqrt5: " + P(B80) + " -> " + P(E80) + ".",
     "N60/N70: right turn = inside (G42); x = 40 and y = 10 meet at (40,10), not on N60 (y in [0,5]): open.",
     "  N70 vs the approach line (30,-10)->(40,5): never reaches y = 10. N80 vs N60, approach: none.",
     "G462 (brief: approach line extended beyond Q1): (40,5) + u*(10,15)/sqrt(325) reaches y = 10 at",
     f"  {P(S4)} (x in [30,50]) - but cross(d, t70) = cross((10,15),(-1,0)) = +15 > 0 while G42 needs",
     "  < 0: the line runs from the material side of y = 10 to its compensation side. Not counted.",
     "  (G461's circle point (41.34,10) is rejected the same way when reached from below.)",
     "-> the junction N60/N70 is never closed: alarm 10751 on the block before it, N60 (brief).",
     "READING (alarm rows, brief): rows only for elements no later block can change: G0 and the approach",
     "  row to Q1 = (40,5) (nothing follows that could still cut it); N60 has no end point. Status 2."],
    tool(10) + ["@g0 G17 G90 G0 X30 Y-10 Z0", "@sel G42 G462 G1 X50 Y5 F1000", "@n60 Y0 F600",
                "@n70 X30", "@n80 X20 Y-5", "@ret G40 X0 Y0", "M30"],
    [("g0", "G0", (30, -10, 0), None, ""), ("sel", "G1", (40, 5, 0), None, 1000)],
    status=2, errs=[("n60", "alarm", 10751)])

add("g462_pm_example_tangent_reading", 17,
    ["g462_pm_example_tangent_reading: the G461 example program of spec 5.3 with G462 instead of G461",
     "(and the G1 the printed program lacks, as in g461_pm_example). R = 10, G42, NORM, G450, CDOF.",
     "READING (mine, NOT the brief's; README 'Disagreements'): spec 5.3 / details Q7 define G462 as the",
     "straight extension of the last TRC block along its END tangent (FM-W1 08/2005 p1-3), and the",
     "approach is symmetric to the retraction (FM p2-79, p94). Mirrored onto the approach: the FIRST",
     "contour element's equidistant (N60) is extended backwards along its START tangent from Q1 and",
     "intersected with the later equidistants, just as G461 extends it by the circle about P1.",
     CONV, PLANE_TXT[17] + ".",
     "N40 (0,0)->(0,20) uncompensated. N50 selection to P1 = (50,5), G462; Q1 = (40,5) (N60: a = 40,",
     "  y in [0,5]). N70: y = 10, x in [30,50]. N60/N70 inside without intersection ((40,10) is not on",
     "  N60); the approach line (0,20)->(40,5) meets y = 10 at x = 26.67 (not in [30,50]).",
     "G462: N60's equidistant a = 40 extended from Q1 against t = (0,-1), i.e. upwards: meets y = 10 at",
     "  S = (40,10) (x in [30,50]) -> approach row (0,20) -> (40,10); N60 omitted (warning 10763).",
     "  (This is the point a complete inside corner needs: the purpose of G461/G462 per FM p1-3.)",
     "  The brief's reading (approach line extended beyond Q1, direction (40,-15)) never reaches y = 10",
     "  and would find nothing.",
     *TAIL_HDR,
     "Rows: N40 (0,20) F10000 | N50 (40,10) F10000 | N70 (30,10) F600 | N80 G3 B | N80 G1 | N90 (0,0)."],
    ["@n10 N10 $TC_DP1[1,1]=120", "N20 $TC_DP6[1,1]=10", "@n30 N30 G1 X0 Y0 F10000 T1 D1",
     "@n40 N40 Y20", "@n50 N50 G42 X50 Y5 G462", "@n60 N60 Y0 F600", "@n70 N70 X30",
     "@n80 N80 X20 Y-5", "@n90 N90 X0 Y0 G40", "N100 M30"],
    [("n40", "G1", (0, 20, 0), None, 10000), ("n50", "G1", (40, 10, 0), None, 10000),
     ("n70", "G1", (30, 10, 0), None, 600), ("n80", "G3", (*B80, 0), (30, 0, 0), 600),
     ("n80", "G1", (*E80, 0), None, 600), ("n90", "G1", (0, 0, 0), None, 600)],
    errs=[("n60", "warning", 10763)])

# ------------------------------------------------------------------------------------------
# 5. G461 / G462 on the retraction: mirror image of the approach example

n1 = (-1 / SQ(5), 2 / SQ(5))                 # n_L of t = (2,1)/sqrt5
Q1m = (20 + 10 * n1[0], -5 + 10 * n1[1])
E1m = (30 + 10 * n1[0], 10 * n1[1])
X461 = 50 - SQ(75)


def retraction_mirror(name, plane, mode):
    L = LETTERS[plane]
    end_e2 = (X461, 10.0) if mode == "G461" else (40.0, 10.0)
    if mode == "G461":
        how = ["G461 (spec 5.3, details Q7; brief): circle about e3's programmed end point Pe = (50,5),",
               "  radius 10, intersected with the earlier equidistants: y = 10 -> (x-50)^2 = 75 ->",
               f"  x = 50 - sqrt(75) = {f6(X461)} (in [30,50]; 58.66 is not): the latest point on e2."]
    else:
        how = ["G462 (details Q7: the last block extended along its end tangent; brief): e3's",
               "  equidistant a = 40 extended beyond its end (40,5) along t = (0,1) meets y = 10 at",
               "  (40,10), in e2's x range [30,50]."]
    hdr = [f"{name}: {mode} on the retraction (in the G40 block): the mirror image of the G461 approach",
           "example of spec 5.3 (path reversed, G42 -> G41): the last block e3 is shorter than R and",
           "meets no earlier equidistant.", CONV, PLANE_TXT[plane] + ". R = 10, G450, CDOF.",
           f"Approach NORM from P0 = (0,-10) to P1 = (20,-5); e1 (20,-5)->(30,0): t = (2,1)/sqrt5,",
           f"  n_L = (-1,2)/sqrt5, offset 10*n_L: Q1 = {P(Q1m)}, e1 ends at {P(E1m)}.",
           "e1/e2: e2 (30,0)->(50,0) t = (1,0); cross = -0.447: right turn = outside (G41), 26.57 deg:",
           f"  G450 circle about (30,0) from {P(E1m)} to (30,10), G2, belongs to e2 (F600).",
           "e2: y = 10, x in [30,50]. e3 (50,0)->(50,5): t = (0,1), n_L = (-1,0): a = 40, y in [0,5].",
           "e2/e3: left turn = inside; (40,10) is not on e3 (y in [0,5]): no intersection; e3 vs e1 and",
           "  the approach line: none. The NORM retraction line (40,5)->(0,20) meets y = 10 at x = 26.67:",
           "  not on e2.", *how,
           f"  -> e2 ends at {P(end_e2)}; e3 omitted (warning 10763); the retraction row runs from there",
           "  to P2 = (0,20) (it cuts nothing: it stays above y = 10).",
           f"Rows: G0 (0,-10) | sel {P(Q1m)} F1000 | e1 {P(E1m)} F600 | e2 G2 (30,10) c (30,0) |",
           f"  e2 G1 {P(end_e2)} | G40 (0,20)."]
    body = tool(10) + [f"@g0 G{plane} G90 G0 {words(plane, 0, -10, 0)}",
                       f"@sel G41 G1 {words(plane, 20, -5)} F1000", f"@e1 {words(plane, 30, 0)} F600",
                       f"@e2 {words(plane, 50)}", f"@e3 {words(plane, None, 5)}",
                       f"@ret G40 {mode} {words(plane, 0, 20)}", "M30"]
    rows = [("g0", "G0", (0, -10, 0), None, ""), ("sel", "G1", (*Q1m, 0), None, 1000),
            ("e1", "G1", (*E1m, 0), None, 600), ("e2", "G2", (30, 10, 0), (30, 0, 0), 600),
            ("e2", "G1", (*end_e2, 0), None, 600), ("ret", "G1", (0, 20, 0), None, 600)]
    add(name, plane, hdr, body, rows, errs=[("e3", "warning", 10763)])


retraction_mirror("g461_retraction_mirror_g17", 17, "G461")
retraction_mirror("g462_retraction_mirror_g18", 18, "G462")

# ------------------------------------------------------------------------------------------
# 6. look-ahead: CDON bottlenecks in G18/G19, 4 blocks back, CDOF vs CDON

add("cdon_bottleneck_g18_g42", 18,
    ["cdon_bottleneck_g18_g42: CDON bottleneck in G18 with G42, R = 6: a groove 4 wide (< R < 2R) and 5",
     "deep; only N10 and N40 intersect (spec 5.5; details Q5).", CONV, PLANE_TXT[18] + ".", READ_LA,
     "G42 offset = -6*n_L = 6*(t_o, -t_a).",
     "  N10 (0,0)->(30,0) t=(1,0): o = -6, a in [0,30];",
     "  N20 (30,0)->(30,5) t=(0,1): a = 36, o in [0,5];    (N10/N20 left turn = outside for G42: N10",
     "      ends at its normal point (30,-6))",
     "  N30 (30,5)->(34,5) t=(1,0): o = -1, a in [30,34];  (N20/N30 right turn = inside)",
     "  N40 (34,5)->(34,-20) t=(0,-1): a = 28, o in [-20,5];  (N30/N40 right turn = inside)",
     "N20/N30: (36,-1) not on N20; N30/N40: (28,-1) not on N30 -> both open. N10/N30, N20/N40 parallel;",
     "  N30 vs approach line (-10,-10)->(0,-6): no.",
     "N40 (k = 4) vs N10 (k-3): (28,-6): strictly inside N10's (0..30), o in [-20,5]; cross((1,0),(0,-1))",
     "  = -1 < 0: valid for G42. -> N10 ends at (28,-6), N40 starts there; N20, N30 omitted.",
     "Retraction NORM: Qe = (34,-20) + (-6,0) = (28,-20) -> P2 = (20,-30).",
     "Rows: G0 (-10,-10) | sel (0,-6) | N10 (28,-6) | N40 (28,-20) | G40 (20,-30)."],
    tool(6) + ["$MC_CUTCOM_MAXNUM_CHECK_BLOCKS=3", f"@g0 G18 G90 G0 {words(18, -10, -10, 0)}",
               f"@sel G42 CDON G1 {words(18, 0, 0)} F100", f"@n10 N10 {words(18, 30)}",
               f"@n20 N20 {words(18, None, 5)}", f"@n30 N30 {words(18, 34)}",
               f"@n40 N40 {words(18, None, -20)}", f"@n50 N50 G40 {words(18, 20, -30)}", "M30"],
    [("g0", "G0", (-10, -10, 0), None, ""), ("sel", "G1", (0, -6, 0), None, 100),
     ("n10", "G1", (28, -6, 0), None, 100), ("n40", "G1", (28, -20, 0), None, 100),
     ("n50", "G1", (20, -30, 0), None, 100)],
    errs=[("n20", "warning", 10763), ("n30", "warning", 10763)])

add("cdon_bottleneck_g19_g41", 19,
    ["cdon_bottleneck_g19_g41: CDON bottleneck in G19 with G41, R = 5: a groove 3 wide and 3 deep",
     "entered from a wall running along +o (spec 5.5; details Q5).", CONV, PLANE_TXT[19] + ".", READ_LA,
     "  N10 (0,0)->(0,30) t=(0,1), n_L=(-1,0): a = -5, o in [0,30]; Q1 = (-5,0);",
     "  N20 (0,30)->(3,30) t=(1,0), n_L=(0,1): o = 35, a in [0,3];   (N10/N20 right turn = outside:",
     "      N10 ends at (-5,30))",
     "  N30 (3,30)->(3,33) t=(0,1): a = -2, o in [30,33];            (N20/N30 left turn = inside)",
     "  N40 (3,33)->(-20,33) t=(-1,0), n_L=(0,-1): o = 28, a in [-20,3]; (N30/N40 left = inside)",
     "N20/N30: (-2,35) not on N20; N30/N40: (-2,28) not on N30 -> open. N10/N30, N20/N40 parallel.",
     "N40 (k = 4) vs N10 (k-3): (-5,28): strictly inside N10's (o in 0..30), a in [-20,3];",
     "  cross((0,1),(-1,0)) = 1 > 0: valid for G41. N10 ends at (-5,28); N20, N30 omitted.",
     "Approach NORM (-10,-10) -> (-5,0). Retraction NORM: Qe = (-20,33) + 5*(0,-1) = (-20,28) ->",
     "  P2 = (-30,20).",
     "Rows: G0 (-10,-10) | sel (-5,0) | N10 (-5,28) | N40 (-20,28) | G40 (-30,20)."],
    tool() + ["$MC_CUTCOM_MAXNUM_CHECK_BLOCKS=3", f"@g0 G19 G90 G0 {words(19, -10, -10, 0)}",
              f"@sel G41 CDON G1 {words(19, 0, 0)} F100", f"@n10 N10 {words(19, None, 30)}",
              f"@n20 N20 {words(19, 3)}", f"@n30 N30 {words(19, None, 33)}",
              f"@n40 N40 {words(19, -20)}", f"@n50 N50 G40 {words(19, -30, 20)}", "M30"],
    [("g0", "G0", (-10, -10, 0), None, ""), ("sel", "G1", (-5, 0, 0), None, 100),
     ("n10", "G1", (-5, 28, 0), None, 100), ("n40", "G1", (-20, 28, 0), None, 100),
     ("n50", "G1", (-30, 20, 0), None, 100)],
    errs=[("n20", "warning", 10763), ("n30", "warning", 10763)])

t40 = (2 / SQ(4.25), -0.5 / SQ(4.25))
nl40 = (-t40[1], t40[0])
b40 = (42 + 5 * nl40[0], -4 + 5 * nl40[1])
e40 = (44 + 5 * nl40[0], -4.5 + 5 * nl40[1])
s_45 = (45 - b40[0]) / t40[0]
y_45 = b40[1] + s_45 * t40[1]
s_39 = (39 - b40[0]) / t40[0]
add("cdon_check_blocks_4", 17,
    ["cdon_check_blocks_4: CDON with MD20240 = 4: the only intersection is 4 blocks back (N50 with",
     "N10); N20, N30 and N40 are omitted (spec 5.4/5.5; details Q5). With the default 3 it would not",
     "be found.", CONV, PLANE_TXT[17] + ". R = 5, G41.", READ_LA,
     "  N10 (0,0)->(40,0): y = 5, x in [0,40] (N10/N20 right turn = outside: ends at (40,5));",
     "  N20 (40,0)->(40,-4) t=(0,-1): x = 45, y in [-4,0];",
     "  N30 (40,-4)->(42,-4) t=(1,0): y = 1, x in [40,42]   (N20/N30 inside: (45,1) not on N20: open);",
     "  N40 (42,-4)->(44,-4.5) t = (2,-0.5)/sqrt(4.25), n_L = (0.242536,0.970143):",
     f"      {P(b40)} -> {P(e40)}  (N30/N40: cross = -0.243: right turn = outside, 14.04 deg);",
     "  N50 (44,-4.5)->(44,20) t=(0,1): x = 39, y in [-4.5,20]  (N40/N50: cross = 0.970: inside;",
     f"      x = 39 on N40's line at s = {f6(s_39)} < 0: open).",
     "Non-consecutive checks: N30 vs N10 parallel; N40 vs N20: x = 45 at s = "
     f"{f6(s_45)}, y = {f6(y_45)} > 0: not on N20;",
     "  N40 vs N10: y = 5 at s < 0; N50 vs N30: (39,1) not on N30; N50 vs N20: parallel;",
     "  N50 (k = 5) vs N10 (k-4): (39,5), strictly inside N10's (0..40), y in [-4.5,20], cross = 1 > 0.",
     "-> N10 ends at (39,5), N50 starts there; N20, N30, N40 omitted (warning 10763 each).",
     "Approach NORM (-10,10) -> (0,5). Retraction NORM: Qe = (39,20) -> P2 = (30,30).",
     "Rows: G0 | sel (0,5) | N10 (39,5) | N50 (39,20) | G40 (30,30)."],
    tool() + ["$MC_CUTCOM_MAXNUM_CHECK_BLOCKS=4", "@g0 G17 G90 G0 X-10 Y10 Z0",
              "@sel G41 CDON G1 X0 Y0 F100", "@n10 N10 X40", "@n20 N20 Y-4", "@n30 N30 X42",
              "@n40 N40 X44 Y-4.5", "@n50 N50 Y20", "@n60 N60 G40 X30 Y30", "M30"],
    [("g0", "G0", (-10, 10, 0), None, ""), ("sel", "G1", (0, 5, 0), None, 100),
     ("n10", "G1", (39, 5, 0), None, 100), ("n50", "G1", (39, 20, 0), None, 100),
     ("n60", "G1", (30, 30, 0), None, 100)],
    errs=[("n20", "warning", 10763), ("n30", "warning", 10763), ("n40", "warning", 10763)])

# CDOF nearest vs CDON farthest: a loop round a pocket (needs an arc, see README)
t30 = (0.8, -0.6)
nl30 = (0.6, 0.8)
b30 = (27.2 + 5 * nl30[0], 0.4 + 5 * nl30[1])
LOOP_HDR = [
    CONV, PLANE_TXT[17] + ". R = 5, G41, MD20240 = 3.", READ_LA,
    "CDOF (brief): searches back only when a junction is open, nearest block first, stops at the",
    "  first hit. Why an arc: with straight elements only, two valid hits on consecutive earlier",
    "  blocks are impossible (README 'Notes'), so N20 is an arc of 343.74 deg (a loop).",
    "Contour (numbering: approach 0, N10 1, N20 2, N30 3, N40 4):",
    "  N10 (0,0)->(30,0): y = 5, x in [0,30]; Q1 = (0,5).",
    "  N20 'G3 X27.2 Y0.4 I0 J10': C = (30,10), r = 10, from angle 270 CCW to 253.74 deg",
    "      ((27.2,0.4) = C + 10*(-0.28,-0.96)); G3 + G41 = inside: equidistant circle (C, 5); its",
    "      start (30,5) continues N10 tangentially. End tangent (0.96,-0.28).",
    "  N30 (27.2,0.4)->(32,-3.2): t = (0.8,-0.6), n_L = (0.6,0.8): " + P(b30) + " -> (35,0.8);",
    "      N20/N30: cross = -0.352: right turn = outside (closed).",
    "  N40 (32,-3.2)->(32,20): t = (0,1), n_L = (-1,0): x = 27, y in [-3.2,20];",
    "      N30/N40: cross = 0.8: inside; x = 27 on N30's line at s = -4 < 0: OPEN junction.",
    "N40's equidistant x = 27 against the earlier ones:",
    "  N20 (k-2): (27-30)^2 + (y-10)^2 = 25 -> y = 6 or 14. (27,6): angle 233.13 deg, on the arc,",
    "    CCW tangent (0.8,-0.6), cross((0.8,-0.6),(0,1)) = 0.8 > 0: VALID.",
    "    (27,14): angle 126.87, tangent (-0.8,-0.6), cross = -0.8: not valid (also farther from N40's start).",
    "  N10 (k-3): (27,5): strictly inside (0..30), y in [-3.2,20], cross((1,0),(0,1)) = 1: VALID.",
    "  Other checks: N30 vs N10: y = 5 at s = -1 (no); N20, N30 vs the approach line: no.",
    "Retraction NORM: Qe = (32,20) + (-5,0) = (27,20) -> P2 = (20,30) (outside circle (C,5), no cut)."]
LOOP_BODY = ["@g0 G17 G90 G0 X-10 Y10 Z0", "@sel G41 {} G1 X0 Y0 F100", "@n10 X30",
             "@n20 G3 X27.2 Y0.4 I0 J10", "@n30 G1 X32 Y-3.2", "@n40 Y20", "@ret G40 X20 Y30", "M30"]

add("cdof_nearest_loop", 17,
    ["cdof_nearest_loop: CDOF takes the NEAREST valid earlier intersection (spec 5.5: CDOF stops at",
     "the first intersection found; details Q5), on a contour where an earlier one also exists",
     "(cdon_farthest_loop: same contour with CDON).", *LOOP_HDR,
     "CDOF at N40 (N30/N40 open): N30 none, N20 hit (27,6) -> stop. N20 ends at (27,6) after",
     "  323.13 deg; N30 omitted (warning 10763; its G450 circle goes with it); N40 starts at (27,6).",
     "Rows: G0 | sel (0,5) | N10 (30,5) | N20 G3 (27,6) c (30,10) | N40 (27,20) | G40 (20,30)."],
    tool() + ["$MC_CUTCOM_MAXNUM_CHECK_BLOCKS=3"] + [b.format("CDOF") for b in LOOP_BODY],
    [("g0", "G0", (-10, 10, 0), None, ""), ("sel", "G1", (0, 5, 0), None, 100),
     ("n10", "G1", (30, 5, 0), None, 100), ("n20", "G3", (27, 6, 0), (30, 10, 0), 100),
     ("n40", "G1", (27, 20, 0), None, 100), ("ret", "G1", (20, 30, 0), None, 100)],
    errs=[("n30", "warning", 10763)])

add("cdon_farthest_loop", 17,
    ["cdon_farthest_loop: CDON takes the FARTHEST valid earlier intersection ('last intersection",
     "found', spec 5.5; details Q5) on the contour of cdof_nearest_loop.", *LOOP_HDR,
     "CDON at N40: hits on N20 (27,6) and N10 (27,5); the farthest block wins: N10 ends at (27,5),",
     "  N20 and N30 omitted (warning 10763 each), N40 starts at (27,5).",
     "Rows: G0 | sel (0,5) | N10 (27,5) | N40 (27,20) | G40 (20,30)."],
    tool() + ["$MC_CUTCOM_MAXNUM_CHECK_BLOCKS=3"] + [b.format("CDON") for b in LOOP_BODY],
    [("g0", "G0", (-10, 10, 0), None, ""), ("sel", "G1", (0, 5, 0), None, 100),
     ("n10", "G1", (27, 5, 0), None, 100), ("n40", "G1", (27, 20, 0), None, 100),
     ("ret", "G1", (20, 30, 0), None, 100)],
    errs=[("n20", "warning", 10763), ("n30", "warning", 10763)])

# ------------------------------------------------------------------------------------------
# 7. closed triangle pocket: CDON must not cut it


def triangle(name, mode):
    hdr = [f"{name}: a closed triangle pocket traversed counter-clockwise with G41 (tool inside, every",
           f"corner inside) and {mode}: the last side crosses the first side's equidistant near the start,",
           "which must NOT count as a bottleneck (brief: the turn condition keeps a closed contour from",
           "being cut at its start); "
           + ("CDON gives the same rows as CDOF (triangle_pocket_cdof)." if mode == "CDON" else
              "the CDOF reference for triangle_pocket_cdon."),
           CONV, PLANE_TXT[17] + ". R = 5, MD20240 = 3.", READ_LA,
           "  e1 (0,0)->(60,0): t=(1,0): y = 5; Q1 = (0,5);",
           "  e2 (60,0)->(0,45): t=(-0.8,0.6), n_L=(-0.6,-0.8): 0.6x + 0.8y = 31, from (57,-4) to (-3,41);",
           "  e3 (0,45)->(0,0): t=(0,-1), n_L=(1,0): x = 5.",
           "Corners (all left turns = inside): e1/e2: y = 5 -> x = 45: (45,5) (e2 param 15 of 75);",
           "  e2/e3: x = 5 -> y = 35: (5,35).",
           "e3 (k = 3) vs e1 (k-2): (5,5), strictly inside e1's (0..45) and on e3 - but cross((1,0),(0,-1))",
           "  = -1 < 0 (the later element turns away from the G41 side): NOT counted. With CDOF no search",
           "  (no open junction). e3 vs the approach line (x in [-10,0]): none.",
           "Retraction (k = 4) from Qe = (0,0) + 5*(1,0) = (5,0) to P2 = (10,-10): meets neither y = 5 nor",
           "  0.6x + 0.8y = 31. Approach from (-10,-10) to (0,5): meets neither x = 5 nor e2.",
           "Rows: G0 (-10,-10) | sel (0,5) | e1 (45,5) | e2 (5,35) | e3 (5,0) | G40 (10,-10)."]
    body = tool() + ["$MC_CUTCOM_MAXNUM_CHECK_BLOCKS=3", "@g0 G17 G90 G0 X-10 Y-10 Z0",
                     f"@sel G41 {mode} G1 X0 Y0 F100", "@e1 X60", "@e2 X0 Y45", "@e3 Y0",
                     "@ret G40 X10 Y-10", "M30"]
    rows = [("g0", "G0", (-10, -10, 0), None, ""), ("sel", "G1", (0, 5, 0), None, 100),
            ("e1", "G1", (45, 5, 0), None, 100), ("e2", "G1", (5, 35, 0), None, 100),
            ("e3", "G1", (5, 0, 0), None, 100), ("ret", "G1", (10, -10, 0), None, 100)]
    add(name, 17, hdr, body, rows)


triangle("triangle_pocket_cdon", "CDON")
triangle("triangle_pocket_cdof", "CDOF")

add("triangle_pocket_cdon_from_inside", 17,
    ["triangle_pocket_cdon_from_inside: the triangle pocket of triangle_pocket_cdon with CDON, but the",
     "approach comes from inside the pocket, P0 = (20,20), and the retraction goes back there - the",
     "usual pocket program. Expected: NOT cut, the rows of CDOF (brief: a closed contour must not be",
     "cut at its start).", CONV, PLANE_TXT[17] + ". R = 5, MD20240 = 3.",
     "Contour, equidistants and corners as triangle_pocket_cdon: Q1 = (0,5), e1/e2 (45,5), e2/e3 (5,35),",
     "  e3 ends on its normal at Qe = (5,0).",
     "Approach (20,20) -> (0,5): meets e3's equidistant x = 5 at (5,8.75) (y in e3's [0,35]); the",
     "  retraction (5,0) -> (20,20) meets e1's y = 5 at (8.75,5) (x in e1's [0,45]).",
     "  Both crossings pass the brief's turn condition (approach d = (-0.8,-0.6), t3 = (0,-1):",
     "  cross = 0.8 > 0; t1 = (1,0), retraction (0.6,0.8): cross = 0.8 > 0) and lie within MD20240",
     "  (approach = block 0, e3 = block 3; e1 = block 1, retraction = block 4), so the brief's rules",
     "  as written would cut the pocket (approach to (5,8.75), e1 and e2 omitted).",
     "READING (needed for 'must not be cut'; README 'Notes'): the approach and retraction lines are",
     "  not used for a non-consecutive CDON hit while every junction is closed. No junction is open",
     "  here (all corners intersect), so nothing is searched, as with CDOF.",
     "Rows: G0 (20,20) | sel (0,5) | e1 (45,5) | e2 (5,35) | e3 (5,0) | G40 (20,20)."],
    tool() + ["$MC_CUTCOM_MAXNUM_CHECK_BLOCKS=3", "@g0 G17 G90 G0 X20 Y20 Z0",
              "@sel G41 CDON G1 X0 Y0 F100", "@e1 X60", "@e2 X0 Y45", "@e3 Y0",
              "@ret G40 X20 Y20", "M30"],
    [("g0", "G0", (20, 20, 0), None, ""), ("sel", "G1", (0, 5, 0), None, 100),
     ("e1", "G1", (45, 5, 0), None, 100), ("e2", "G1", (5, 35, 0), None, 100),
     ("e3", "G1", (5, 0, 0), None, 100), ("ret", "G1", (20, 20, 0), None, 100)])

# ------------------------------------------------------------------------------------------
# 8. omitted blocks with applicate motion (G18)

add("cdon_omitted_applicate_g18", 18,
    ["cdon_omitted_applicate_g18: the groove of cdon_bottleneck (tests/programs/trc) in G18, with an",
     "applicate (Y) move in both omitted blocks: their plane motion is dropped, their applicate motion",
     "runs at the intersection point, in program order, as rows of their own (spec 5.5; details Q5/Q9).",
     CONV, PLANE_TXT[18] + ". R = 5, G41, CDON, MD20240 = 3.", READ_LA,
     "  N10 (0,0)->(40,0): o = 5, a in [0,40]; N20 (40,0)->(40,-4) [applicate -> -2]: a = 45;",
     "  N30 (40,-4)->(44,-4) [applicate -> -3]: o = 1, a in [40,44]; N40 (44,-4)->(44,20): a = 39.",
     "  N20/N30: (45,1) not on N20; N30/N40: (39,1) not on N30: open. N40 vs N10 (k-3): (39,5), valid",
     "  (cross((1,0),(0,1)) = 1 > 0).",
     "-> N10 ends at (39,5) (applicate 0); N20 row: (39,5) applicate -2; N30 row: applicate -3; N40",
     "  from there to (39,20) at -3; retraction NORM Qe = (39,20) -> P2 = (30,30), applicate -3.",
     "Rows (a,o,app): G0 (-10,10,0) | sel (0,5,0) | N10 (39,5,0) | N20 (39,5,-2) | N30 (39,5,-3) |",
     "  N40 (39,20,-3) | G40 (30,30,-3); warnings 10763 on N20 and N30."],
    tool() + ["$MC_CUTCOM_MAXNUM_CHECK_BLOCKS=3", f"@g0 G18 G90 G0 {words(18, -10, 10, 0)}",
              f"@sel G41 CDON G1 {words(18, 0, 0)} F100", f"@n10 N10 {words(18, 40)}",
              f"@n20 N20 {words(18, None, -4, -2)}", f"@n30 N30 {words(18, 44, None, -3)}",
              f"@n40 N40 {words(18, None, 20)}", f"@n50 N50 G40 {words(18, 30, 30)}", "M30"],
    [("g0", "G0", (-10, 10, 0), None, ""), ("sel", "G1", (0, 5, 0), None, 100),
     ("n10", "G1", (39, 5, 0), None, 100), ("n20", "G1", (39, 5, -2), None, 100),
     ("n30", "G1", (39, 5, -3), None, 100), ("n40", "G1", (39, 20, -3), None, 100),
     ("n50", "G1", (30, 30, -3), None, 100)],
    errs=[("n20", "warning", 10763), ("n30", "warning", 10763)])

# ------------------------------------------------------------------------------------------
# 9. DISC in G18 / G19 (docs/radius-compensation.md "DISC", details Q3 model [D])

DISC_MODEL = [
    "MODEL (docs 'DISC', details Q3 [D]): rational quadratic Bezier A -> S -> B, A = end of the first",
    "  equidistant, B = start of the second, S = where the tangents at A and B meet, P = corner point;",
    "  o = R + DISC/100*(|PS| - R), h = |P - mid(A,B)|, w = (o - h)/(|PS| - o) (puts C(1/2) at",
    "  distance o from P on the bisector).",
    "  C(t) = ((1-t)^2 A + 2wt(1-t) S + t^2 B)/((1-t)^2 + 2wt(1-t) + t^2).",
    "  Written as n straight G1 chords C((i-1)/n) -> C(i/n), i = 1..n, uniform in t; n = the smallest",
    "  power of two >= 2 for which every chord deviates <= 0.001 mm (distance of C((i-1/2)/n) from the",
    "  chord line). All chord rows carry the line and feed of the second block (G450 circle rule, Q3).",
    "  MD20220 CUTCOM_MAX_DISC default 50 does not limit DISC = 30."]


def bez(A, S, B, w, t):
    u = 1 - t
    d = u * u + 2 * w * t * u + t * t
    return ((u * u * A[0] + 2 * w * t * u * S[0] + t * t * B[0]) / d,
            (u * u * A[1] + 2 * w * t * u * S[1] + t * t * B[1]) / d)


def chord_dev(p, q, m):
    """distance of m from the line p-q"""
    dx, dy = q[0] - p[0], q[1] - p[1]
    return abs(dx * (m[1] - p[1]) - dy * (m[0] - p[0])) / SQ(dx * dx + dy * dy)


def disc_curve(A, S, B, Pc, R, disc):
    """numbers of the model above: (o, h, |PS|, w, n, max deviation at n and at n/2, points)."""
    PS = math.hypot(S[0] - Pc[0], S[1] - Pc[1])
    o = R + disc / 100 * (PS - R)
    M = ((A[0] + B[0]) / 2, (A[1] + B[1]) / 2)
    h = math.hypot(M[0] - Pc[0], M[1] - Pc[1])
    w = (o - h) / (PS - o)
    devs = {}
    n = 2
    while True:
        devs[n] = max(chord_dev(bez(A, S, B, w, (i - 1) / n), bez(A, S, B, w, i / n),
                                bez(A, S, B, w, (i - 0.5) / n)) for i in range(1, n + 1))
        if devs[n] <= 0.001:
            break
        n *= 2
    pts = [bez(A, S, B, w, i / n) for i in range(1, n + 1)]
    return o, h, PS, w, n, devs[n], devs.get(n // 2), pts


def um(v):
    return f"{v * 1000:.3f} um"


# G18, G42, R = 5, 90 deg
Pd = (50.0, 0.0)
Ad, Bd, Sd = (50.0, -5.0), (55.0, 0.0), (55.0, -5.0)
od, hd, PSd, wd, nd, devd, devd2, ptsd = disc_curve(Ad, Sd, Bd, Pd, 5, 30)
add("disc_30_g18_g42", 18,
    ["disc_30_g18_g42: DISC=30 under G450 at one 90 deg outside corner in G18 with G42 (spec 5.4,",
     "details Q3): the transition circle becomes the DISC curve, written as straight chords.",
     CONV, PLANE_TXT[18] + ". R = 5, G42 offset = -5*n_L = 5*(t_o, -t_a).", *DISC_MODEL,
     "Approach NORM from P0 = (-10,-20) to P1 = (0,0): N10 (0,0)->(50,0) t = (1,0), offset (0,-5):",
     "  Q1 = (0,-5) (the line meets o = -5 only at Q1); N10's equidistant o = -5.",
     "N10/N11: N11 (50,0)->(50,40) t = (0,1), n_L = (-1,0), offset (5,0): a = 55. cross((1,0),(0,1)) = 1",
     "  > 0: left turn = outside for G42, deflection 90 deg. P = (50,0), A = (50,-5), B = (55,0),",
     f"  S = (55,-5); |PS| = 5*sqrt2 = {f6(PSd)}.",
     f"  o = 5 + 0.3*({f6(PSd)} - 5) = {f6(od)}; h = 5*cos45 = {f6(hd)};",
     f"  w = ({f6(od)} - {f6(hd)})/({f6(PSd)} - {f6(od)}) = {f6(wd)}.",
     f"  n = {nd} chords: max deviation {um(devd)} (n = {nd // 2}: {um(devd2)} > 1 um).",
     f"  First chord ends at C(1/{nd}) = {P(ptsd[0])}; middle point C(1/2) = P + o*(1,-1)/sqrt2 =",
     f"  {P(ptsd[nd // 2 - 1])}; the last ends at B.",
     "Retraction NORM: Qe = (50,40) + (5,0) = (55,40) -> P2 = (70,50).",
     f"Rows (a,o): G0 (-10,-20) | sel (0,-5) F100 | N10 (50,-5) | {nd} chords of N11 (line N11, F200) |",
     "  N11 (55,40) F200 | G40 (70,50)."],
    tool() + [f"@g0 G18 G90 G0 {words(18, -10, -20, 0)}", "DISC=30",
              f"@sel G42 G450 G1 {words(18, 0, 0)} F100", f"@n10 {words(18, 50)}",
              f"@n11 {words(18, None, 40)} F200", f"@ret G40 {words(18, 70, 50)}", "M30"],
    [("g0", "G0", (-10, -20, 0), None, ""), ("sel", "G1", (0, -5, 0), None, 100),
     ("n10", "G1", (50, -5, 0), None, 100)]
    + [("n11", "G1", (*p, 0), None, 200) for p in ptsd]
    + [("n11", "G1", (55, 40, 0), None, 200), ("ret", "G1", (70, 50, 0), None, 200)])

# G19, G41, R = 6, 60 deg deflection
E11 = (50.0, -17.320508076)          # as programmed (9 decimals): 20 * (cos -60, sin -60) from (40,0)
L11 = math.hypot(E11[0] - 40, E11[1])
t11 = ((E11[0] - 40) / L11, E11[1] / L11)
n11 = (-t11[1], t11[0])
Pe = (40.0, 0.0)
Ae = (40.0, 6.0)
Be = (40 + 6 * n11[0], 6 * n11[1])
# S: the tangent at A (o = 6) meets the line through B along t11
Se = (Be[0] + (6 - Be[1]) / t11[1] * t11[0], 6.0)
defl = math.degrees(math.acos(t11[0]))
oe, he, PSe, we, ne, deve, deve2, ptse = disc_curve(Ae, Se, Be, Pe, 6, 30)
Qe11 = (E11[0] + 6 * n11[0], E11[1] + 6 * n11[1])
add("disc_30_g19_g41", 19,
    ["disc_30_g19_g41: DISC=30 under G450 at one 60 deg outside corner (deflection) in G19 with G41",
     "(spec 5.4, details Q3): the transition circle becomes the DISC curve, written as straight chords.",
     CONV, PLANE_TXT[19] + ". R = 6, G41 offset = 6*n_L.", *DISC_MODEL,
     "Approach NORM from P0 = (-10,10) to P1 = (0,0): N10 (0,0)->(40,0) t = (1,0), n_L = (0,1): o = 6,",
     "  Q1 = (0,6) (the line meets o = 6 only at Q1).",
     f"N11 (40,0)->{P(E11)} (programmed Y50 Z-17.320508076, length {f6(L11)}): t = {P(t11)},",
     f"  n_L = {P(n11)}; cross((1,0),t) = {f6(t11[1])} < 0: right turn = outside for G41, deflection",
     f"  {f6(defl)} deg. P = (40,0), A = (40,6), B = P + 6*n_L = {P(Be)}; S = where o = 6 meets the",
     f"  line through B along t: {P(Se)} (= P + 6/cos30*(sin30,cos30)); |PS| = 6/cos30 = {f6(PSe)}.",
     f"  o = 6 + 0.3*({f6(PSe)} - 6) = {f6(oe)}; h = 6*cos30 = {f6(he)};",
     f"  w = ({f6(oe)} - {f6(he)})/({f6(PSe)} - {f6(oe)}) = {f6(we)}.",
     f"  n = {ne} chords: max deviation {um(deve)} (n = {ne // 2}: {um(deve2)} > 1 um).",
     f"  First chord ends at C(1/{ne}) = {P(ptse[0])}; middle point C(1/2) = P + o*(sin30,cos30) =",
     f"  {P(ptse[ne // 2 - 1])}; the last ends at B.",
     f"Retraction NORM: Qe = {P(E11)} + 6*n_L = {P(Qe11)} -> P2 = (70,-10)",
     "  (moves to the tool side, cuts nothing).",
     f"Rows (a,o): G0 (-10,10) | sel (0,6) F100 | N10 (40,6) | {ne} chords of N11 (line N11, F250) |",
     f"  N11 {P(Qe11)} F250 | G40 (70,-10)."],
    tool(6) + [f"@g0 G19 G90 G0 {words(19, -10, 10, 0)}", "DISC=30",
               f"@sel G41 G450 G1 {words(19, 0, 0)} F100", f"@n10 {words(19, 40)}",
               f"@n11 {words(19, *E11)} F250", f"@ret G40 {words(19, 70, -10)}", "M30"],
    [("g0", "G0", (-10, 10, 0), None, ""), ("sel", "G1", (0, 6, 0), None, 100),
     ("n10", "G1", (40, 6, 0), None, 100)]
    + [("n11", "G1", (*p, 0), None, 250) for p in ptse]
    + [("n11", "G1", (*Qe11, 0), None, 250), ("ret", "G1", (70, -10, 0), None, 250)])

# ------------------------------------------------------------------------------------------
# 10. G461 / G462 at the approach in G18/G19, G461 at the retraction in G19:
#     the spec 5.3 geometry rotated or mirrored

SQ75 = SQ(75)
R5 = 1 / SQ(5)
READ_G46X = ("READING (docs 'Selection, approach, retraction', details Q7): G461 = circle of radius R about "
             "the approach block's programmed end point P1 (retraction: the last block's programmed end "
             "point) intersected with the later (earlier) equidistants; G462 on the approach = the first "
             "element's equidistant extended backwards along its start tangent from Q1. The approach "
             "(retraction) line runs straight to that point; the blocks in between are omitted with "
             "warning 10763.")

# 10a. G461 approach, G18: spec 5.3 rotated by +90 deg, (a,o) -> (-o,a); G42 stays
S10a = (-10.0, 50 - SQ75)
add("g461_approach_rot90_g18", 18,
    ["g461_approach_rot90_g18: the G461 example of spec 5.3 (R = 10, G42, NORM, G450, CDOF) in G18,",
     "rotated by +90 deg ((a,o) -> (-o,a); a rotation keeps G42 and G3). The spec's N40 is the G0",
     "block here; the F words are those of the spec program.",
     CONV, PLANE_TXT[18] + ". G42 offset = -10*n_L = 10*(t_o, -t_a).", READ_G46X,
     "G0 to (-20,0). Selection G42 G461 to P1 = (-5,50), F10000.",
     "  N60 (-5,50)->(0,50) t = (1,0), offset (0,-10): o = 40, a in [-5,0] (5 long < R): Q1 = (-5,40).",
     "  N70 (0,50)->(0,30) t = (0,-1), n_L = (1,0), offset (-10,0): a = -10, o in [30,50].",
     f"  N80 (0,30)->(5,20) t = (1,-2)/sqrt5, n_L = (2,1)/sqrt5, offset -10*n_L: "
     f"{P((-20 * R5, 30 - 10 * R5))} -> {P((5 - 20 * R5, 20 - 10 * R5))}.",
     "N60/N70: cross((1,0),(0,-1)) = -1: right turn = inside for G42; o = 40 and a = -10 meet at",
     "  (-10,40), not on N60 (a in [-5,0]): no intersection. The NORM approach line (-20,0)->(-5,40)",
     "  meets a = -10 at o = 26.67 (not in [30,50]).",
     "G461: circle about P1 = (-5,50), radius 10, with a = -10: (o-50)^2 = 100 - 25 = 75 ->",
     f"  o = 50 - sqrt75 = {f6(S10a[1])} (in [30,50]; 58.66 is not). S = {P(S10a)}.",
     "  Approach line (-20,0) -> S: d = (10,41.34), cross(d, t70) = 10*(-1) - 41.34*0 = -10 < 0:",
     "  it enters from the compensation side (valid for G42). N60 omitted (warning 10763).",
     "N70/N80: cross((0,-1),(1,-2)/sqrt5) = 0.447 > 0: left turn = outside for G42, 26.57 deg: G450",
     f"  circle about (0,30) from (-10,30) to {P((-20 * R5, 30 - 10 * R5))}, G3 (angle 180 -> 206.57 deg),",
     "  belongs to N80 (F600).",
     f"N90 G40 to (0,0): NORM retraction from {P((5 - 20 * R5, 20 - 10 * R5))} (N80 meets N70, so G461",
     "  has nothing to do there).",
     f"Rows (a,o): G0 (-20,0) | sel {P(S10a)} F10000 | N70 (-10,30) F600 | N80 G3 c (0,30) |",
     "  N80 G1 | N90 (0,0)."],
    tool(10) + [f"@g0 G18 G90 G0 {words(18, -20, 0, 0)}",
                f"@sel N50 G42 G1 {words(18, -5, 50)} G461 F10000", f"@n60 N60 {words(18, 0)} F600",
                f"@n70 N70 {words(18, None, 30)}", f"@n80 N80 {words(18, 5, 20)}",
                f"@n90 N90 {words(18, 0, 0)} G40", "N100 M30"],
    [("g0", "G0", (-20, 0, 0), None, ""), ("sel", "G1", (*S10a, 0), None, 10000),
     ("n70", "G1", (-10, 30, 0), None, 600),
     ("n80", "G3", (-20 * R5, 30 - 10 * R5, 0), (0, 30, 0), 600),
     ("n80", "G1", (5 - 20 * R5, 20 - 10 * R5, 0), None, 600),
     ("n90", "G1", (0, 0, 0), None, 600)],
    errs=[("n60", "warning", 10763)])

# 10b. G461 approach, G19: spec 5.3 mirrored o -> -o; G42 -> G41, G3 -> G2
S10b = (50 - SQ75, -10.0)
add("g461_approach_mirror_g19", 19,
    ["g461_approach_mirror_g19: the G461 example of spec 5.3 (R = 10, NORM, G450, CDOF) in G19,",
     "mirrored o -> -o (a mirror turns G42 into G41 and G3 into G2). The spec's N40 is the G0 block",
     "here; the F words are those of the spec program.",
     CONV, PLANE_TXT[19] + ". G41 offset = 10*n_L.", READ_G46X,
     "G0 to (0,-20). Selection G41 G461 to P1 = (50,-5), F10000.",
     "  N60 (50,-5)->(50,0) t = (0,1), n_L = (-1,0): a = 40, o in [-5,0] (5 long < R): Q1 = (40,-5).",
     "  N70 (50,0)->(30,0) t = (-1,0), n_L = (0,-1): o = -10, a in [30,50].",
     f"  N80 (30,0)->(20,5) t = (-2,1)/sqrt5, n_L = (-1,-2)/sqrt5: "
     f"{P((30 - 10 * R5, -20 * R5))} -> {P((20 - 10 * R5, 5 - 20 * R5))}.",
     "N60/N70: cross((0,1),(-1,0)) = 1 > 0: left turn = inside for G41; a = 40 and o = -10 meet at",
     "  (40,-10), not on N60 (o in [-5,0]): no intersection. The NORM approach line (0,-20)->(40,-5)",
     "  meets o = -10 at a = 26.67 (not in [30,50]).",
     "G461: circle about P1 = (50,-5), radius 10, with o = -10: (a-50)^2 = 75 ->",
     f"  a = 50 - sqrt75 = {f6(S10b[0])} (in [30,50]; 58.66 is not). S = {P(S10b)}.",
     "  Approach line (0,-20) -> S: d = (41.34,10), cross(d, t70) = 41.34*0 - 10*(-1) = 10 > 0:",
     "  it enters from the compensation side (valid for G41). N60 omitted (warning 10763).",
     "N70/N80: cross((-1,0),(-2,1)/sqrt5) = -0.447 < 0: right turn = outside for G41, 26.57 deg:",
     f"  G450 circle about (30,0) from (30,-10) to {P((30 - 10 * R5, -20 * R5))}, G2 (angle 270 ->",
     "  243.43 deg), belongs to N80 (F600).",
     f"N90 G40 to (0,0): NORM retraction from {P((20 - 10 * R5, 5 - 20 * R5))}.",
     f"Rows (a,o): G0 (0,-20) | sel {P(S10b)} F10000 | N70 (30,-10) F600 | N80 G2 c (30,0) |",
     "  N80 G1 | N90 (0,0)."],
    tool(10) + [f"@g0 G19 G90 G0 {words(19, 0, -20, 0)}",
                f"@sel N50 G41 G1 {words(19, 50, -5)} G461 F10000", f"@n60 N60 {words(19, None, 0)} F600",
                f"@n70 N70 {words(19, 30)}", f"@n80 N80 {words(19, 20, 5)}",
                f"@n90 N90 {words(19, 0, 0)} G40", "N100 M30"],
    [("g0", "G0", (0, -20, 0), None, ""), ("sel", "G1", (*S10b, 0), None, 10000),
     ("n70", "G1", (30, -10, 0), None, 600),
     ("n80", "G2", (30 - 10 * R5, -20 * R5, 0), (30, 0, 0), 600),
     ("n80", "G1", (20 - 10 * R5, 5 - 20 * R5, 0), None, 600),
     ("n90", "G1", (0, 0, 0), None, 600)],
    errs=[("n60", "warning", 10763)])

# 10c. G461 retraction, G19: g461_retraction_mirror_g17 rotated by -90 deg, (a,o) -> (o,-a); G41
S10c = (10.0, -50 + SQ75)
Q10c = (10 * 2 * R5 - 5, -20 + 10 * R5)
E10c = (10 * 2 * R5, -30 + 10 * R5)
add("g461_retraction_rot_g19", 19,
    ["g461_retraction_rot_g19: G461 in the G40 block in G19: the geometry of g461_retraction_mirror_g17",
     "(the spec 5.3 path reversed, G41) rotated by -90 deg ((a,o) -> (o,-a); G41 and G2 stay). The last",
     "block e3 is shorter than R and meets no earlier equidistant.",
     CONV, PLANE_TXT[19] + ". R = 10, G41 offset = 10*n_L, G450, CDOF.", READ_G46X,
     "Approach NORM from P0 = (-10,0) to P1 = (-5,-20), F1000.",
     f"  e1 (-5,-20)->(0,-30) t = (1,-2)/sqrt5, n_L = (2,1)/sqrt5: Q1 = {P(Q10c)}, e1 ends at {P(E10c)}.",
     "e1/e2: e2 (0,-30)->(0,-50) t = (0,-1), n_L = (1,0): a = 10, o in [-50,-30];",
     "  cross(t1,t2) = -1/sqrt5 < 0: right turn = outside for G41, 26.57 deg: G450 circle about",
     f"  (0,-30) from {P(E10c)} to (10,-30), G2 (angle 26.57 -> 0 deg), belongs to e2 (F600).",
     "e3 (0,-50)->(5,-50) t = (1,0), n_L = (0,1): o = -40, a in [0,5].",
     "e2/e3: cross((0,-1),(1,0)) = 1 > 0: left turn = inside; (10,-40) is not on e3 (a in [0,5]):",
     "  no intersection; e3 vs e1 and the approach line: none. The NORM retraction line",
     "  (5,-40) -> (20,0) meets a = 10 at o = -26.67: not on e2.",
     "G461 (G40 block): circle about e3's programmed end point Pe = (5,-50), radius 10, with a = 10:",
     f"  (o+50)^2 = 75 -> o = -50 + sqrt75 = {f6(S10c[1])} (in [-50,-30]; -58.66 is not): the latest",
     f"  point on e2. -> e2 ends at {P(S10c)}; e3 omitted (warning 10763); the retraction row runs",
     "  from there to P2 = (20,0) (moves away from a = 10: cuts nothing).",
     f"Rows (a,o): G0 (-10,0) | sel {P(Q10c)} F1000 | e1 {P(E10c)} F600 |",
     f"  e2 G2 (10,-30) c (0,-30) | e2 G1 {P(S10c)} | G40 (20,0)."],
    tool(10) + [f"@g0 G19 G90 G0 {words(19, -10, 0, 0)}",
                f"@sel G41 G1 {words(19, -5, -20)} F1000", f"@e1 {words(19, 0, -30)} F600",
                f"@e2 {words(19, None, -50)}", f"@e3 {words(19, 5)}",
                f"@ret G40 G461 {words(19, 20, 0)}", "M30"],
    [("g0", "G0", (-10, 0, 0), None, ""), ("sel", "G1", (*Q10c, 0), None, 1000),
     ("e1", "G1", (*E10c, 0), None, 600), ("e2", "G2", (10, -30, 0), (0, -30, 0), 600),
     ("e2", "G1", (*S10c, 0), None, 600), ("ret", "G1", (20, 0, 0), None, 600)],
    errs=[("e3", "warning", 10763)])

# 10d. G462 approach, G19: spec 5.3 rotated by 180 deg, (a,o) -> (-a,-o); G42 and G3 stay
add("g462_approach_rot180_g19", 19,
    ["g462_approach_rot180_g19: G462 in the selection block in G19: the spec 5.3 program with G462",
     "(as g462_pm_example_tangent_reading) rotated by 180 deg ((a,o) -> (-a,-o); G42 and G3 stay).",
     "The spec's N40 is the G0 block here; the F words are those of the spec program.",
     CONV, PLANE_TXT[19] + ". R = 10, G450, CDOF.", "G42 offset = -10*n_L = 10*(t_o, -t_a).",
     READ_G46X,
     "G0 to (0,-20). Selection G42 G462 to P1 = (-50,-5), F10000.",
     "  N60 (-50,-5)->(-50,0) t = (0,1), n_L = (-1,0), offset (10,0): a = -40, o in [-5,0]:",
     "    Q1 = (-40,-5).",
     "  N70 (-50,0)->(-30,0) t = (1,0), n_L = (0,1), offset (0,-10): o = -10, a in [-50,-30].",
     f"  N80 (-30,0)->(-20,5) t = (2,1)/sqrt5, n_L = (-1,2)/sqrt5, offset -10*n_L: "
     f"{P((-30 + 10 * R5, -20 * R5))} -> {P((-20 + 10 * R5, 5 - 20 * R5))}.",
     "N60/N70: cross((0,1),(1,0)) = -1: right turn = inside for G42; (-40,-10) is not on N60",
     "  (o in [-5,0]): no intersection. The NORM approach line (0,-20)->(-40,-5) meets o = -10 at",
     "  a = -26.67 (not in [-50,-30]).",
     "G462: N60's equidistant a = -40 extended backwards from Q1 = (-40,-5) against t = (0,1), i.e.",
     "  towards -o: meets o = -10 at S = (-40,-10), in N70's range [-50,-30].",
     "  Approach line (0,-20) -> S: d = (-40,10), cross(d, t70) = -40*0 - 10*1 = -10 < 0: it enters",
     "  from the compensation side (valid for G42). N60 omitted (warning 10763).",
     "N70/N80: cross((1,0),(2,1)/sqrt5) = 0.447 > 0: left turn = outside for G42, 26.57 deg: G450",
     f"  circle about (-30,0) from (-30,-10) to {P((-30 + 10 * R5, -20 * R5))}, G3 (angle 270 ->",
     "  296.57 deg), belongs to N80 (F600).",
     f"N90 G40 to (0,0): NORM retraction from {P((-20 + 10 * R5, 5 - 20 * R5))} (N80 meets N70, so",
     "  G462 has nothing to do there).",
     "Rows (a,o): G0 (0,-20) | sel (-40,-10) F10000 | N70 (-30,-10) F600 | N80 G3 c (-30,0) | N80 G1 |",
     "  N90 (0,0)."],
    tool(10) + [f"@g0 G19 G90 G0 {words(19, 0, -20, 0)}",
                f"@sel N50 G42 G1 {words(19, -50, -5)} G462 F10000", f"@n60 N60 {words(19, None, 0)} F600",
                f"@n70 N70 {words(19, -30)}", f"@n80 N80 {words(19, -20, 5)}",
                f"@n90 N90 {words(19, 0, 0)} G40", "N100 M30"],
    [("g0", "G0", (0, -20, 0), None, ""), ("sel", "G1", (-40, -10, 0), None, 10000),
     ("n70", "G1", (-30, -10, 0), None, 600),
     ("n80", "G3", (-30 + 10 * R5, -20 * R5, 0), (-30, 0, 0), 600),
     ("n80", "G1", (-20 + 10 * R5, 5 - 20 * R5, 0), None, 600),
     ("n90", "G1", (0, 0, 0), None, 600)],
    errs=[("n60", "warning", 10763)])

if __name__ == "__main__":
    g.write_all()
