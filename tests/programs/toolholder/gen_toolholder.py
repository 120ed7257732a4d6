#!/usr/bin/python3
"""Independent cross-check of the toolholder golden cases (tests/programs/toolholder/).

Recomputes every expected machine position of the golden cases with numpy alone, from the
chain formulas in docs/toolholders.md (W1 2.5), NOT from ncoffset's code:

  type T:  L' = l1 + R1 (l2 + R2 (l3 + L))          tool length vector (tip -> carrier point)
  type P:  table offset  D = l2 + R1 (l3 + R2 l4), tool length L + l1, PAROT rotation R1 R2
  type M:  L' = l1 + R1 (l2 + L),  table offset D = l3 + R2 l4, PAROT rotation R2
  MCS = D + F_rot (WCS point) + L'

R(v, a) is the right-hand rotation about v by a degrees (Rodrigues' formula), the identity for
v = 0. TCOFR's angles are found here by a brute-force search over a 3 degree grid refined by
least squares (a different method from the analytic solver in src/tool/toolholder_kinematics.cpp).
Run: python3 gen_toolholder.py  -- prints each case's rows; compare with the .expected files.
"""
import numpy as np


def rot(v, deg):
    v = np.asarray(v, float)
    n = np.linalg.norm(v)
    if n == 0 or deg == 0:
        return np.eye(3)
    k = v / n
    a = np.radians(deg)
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + np.sin(a) * K + (1 - np.cos(a)) * K @ K


def rpy(rx=0, ry=0, rz=0):
    return rot([0, 0, 1], rz) @ rot([0, 1, 0], ry) @ rot([1, 0, 0], rx)


def search(f, preset):
    """All (a1, a2) in [-180, 180) with f(a1, a2) ~ 0: grid, then Newton-free refinement."""
    from itertools import product
    grid = np.arange(-180, 180, 3.0)
    found = []
    for a1, a2 in product(grid, grid):
        if np.linalg.norm(f(a1, a2)) < 0.08:
            x = np.array([a1, a2], float)
            for _ in range(60):  # Gauss-Newton on the residual
                r = f(*x)
                J = np.column_stack([(f(x[0] + 1e-6, x[1]) - r) / 1e-6,
                                     (f(x[0], x[1] + 1e-6) - r) / 1e-6])
                x = x - np.linalg.lstsq(J, r, rcond=None)[0]
            x = (x + 180) % 360 - 180
            if np.linalg.norm(f(*x)) < 1e-9 and not any(np.allclose(x, y, atol=1e-6) for y in found):
                found.append(x)
    # whole turns towards the preset (W1: 750 specified, 10 computed -> 730), then the closest
    found = [x + 360.0 * np.floor((np.asarray(preset) - x) / 360.0 + 0.5) for x in found]
    found.sort(key=lambda x: abs(x[0] - preset[0]) + abs(x[1] - preset[1]))
    return found


def row(line, p):
    p = [0.0 if abs(c) < 5e-10 else c for c in p]
    print(f"  {line}: " + ", ".join(f"{c:.7f}" for c in p))


def head45():
    print("t_swivel_45 (type T, one B axis, pivot 80 above the adapter, L1 = 100)")
    l1, l3, L = np.array([0, 0, -80.]), np.array([0, 0, 80.]), np.array([0, 0, 100.])
    R1 = rot([0, 1, 0], 45)
    Lp = l1 + R1 @ (l3 + L)
    row("G1 X0 Y0 Z0", Lp)
    Q = R1  # TOROT in G17: the frame's axes are the machine axes turned by the head
    row("TOROT G1 Z10", Q @ [0, 0, 10] + Lp)
    row("X10", Q @ [10, 0, 10] + Lp)
    print("  $P_TOOLO", R1 @ [0, 0, 1])


def cardan_tcofr():
    print("t_cardan_tcofr (type T, v1 = C (Z), v2 = A (X), L1 = 100, ROT X30, TCOFR)")
    F = rpy(rx=30)
    f = F @ [0, 0, 1]
    g = lambda a1, a2: rot([0, 0, 1], a1) @ rot([1, 0, 0], a2) @ [0, 0, 1] - f
    for preset in ([0, 0], [170, 0]):
        sols = search(g, preset)
        print("  preset", preset, "solutions", [list(np.round(s, 9)) for s in sols])
    a1, a2 = search(g, [0, 0])[0]
    Lp = rot([0, 0, 1], a1) @ rot([1, 0, 0], a2) @ [0, 0, 100.]
    row("G1 X0 Y0 Z0", F @ [0, 0, 0] + Lp)
    row("Z10", F @ [0, 0, 10] + Lp)
    g1 = lambda a1, a2: rot([0, 1, 0], a1) @ [0, 0, 1] - f
    print("  single B axis, ROT X30: solutions", search(g1, [0, 0]), "-> alarm 14152")


def table_p():
    print("p_table_w1 (W1 example 4.1: type P, v1 = A, v2 = B, B = 45, l2 = -l4, l4 = 15 in Z, L1 = 13)")
    l2, l4, L = np.array([0, 0, -15.]), np.array([0, 0, 15.]), np.array([0, 0, 13.])
    R1, R2 = rot([1, 0, 0], 0), rot([0, 1, 0], 45)
    D = l2 + R1 @ (np.zeros(3) + R2 @ l4)
    row("TCARR=1 X0 Y10 Z0", D + [0, 10, 0] + L)
    P = R1 @ R2
    row("PAROT X0 Y0 Z0", D + P @ [0, 0, 0] + L)
    row("X10 Y0 Z0", D + P @ [10, 0, 0] + L)
    row("PAROTOF X10 Y0 Z0", D + [10, 0, 0] + L)
    F = rpy(ry=-45)
    f = F @ [0, 0, 1]
    g = lambda a1, a2: rot([1, 0, 0], a1) @ rot([0, 1, 0], a2) @ f - [0, 0, 1]
    sols = search(g, [0, 45])
    print("  ROT Y-45 TCOFR: solutions", [list(np.round(s, 9)) for s in sols])
    a1, a2 = sols[0]
    D2 = l2 + rot([1, 0, 0], a1) @ (rot([0, 1, 0], a2) @ l4)
    row("TCOFR X0 Y0 Z0 (under ROT Y-45)", D2 + F @ [0, 0, 0] + L)


def mixed_m():
    print("m_turning_828d (PM 828D 'CUTMOD' example: type M, v1 = B (tool), v2 = C, G18, L1 = 12, L2 = 1)")
    L = np.array([12., 0, 1.])  # turning tool in G18: L1 on X, L2 on Z
    row("G18 T1 D1 TCARR=2 X0 Y0 Z0", L)
    Lp = rot([0, 1, 0], 30) @ L
    row("$TC_CARR13=30 TCARR=2 X0 Y0 Z0", Lp)
    print("m_table_c (type M: tool B = -30 with l1 = (0,0,-60), l2 = (0,0,60); table C = 90, "
          "l3 = (-10,0,0), l4 = (10,0,0); L1 = 50)")
    L = np.array([0, 0, 50.])
    R1, R2 = rot([0, 1, 0], -30), rot([0, 0, 1], 90)
    Lp = np.array([0, 0, -60.]) + R1 @ (np.array([0, 0, 60.]) + L)
    D = np.array([-10., 0, 0]) + R2 @ [10., 0, 0]
    row("X0 Y0 Z0", D + Lp)
    row("PAROT X10 Y0 Z0", D + R2 @ [10, 0, 0] + Lp)


def zero_axes():
    print("t_zero_axes (rotary axis vectors zero: the holder only adds l1 + l2 + l3; L1 = 100)")
    L = np.array([0, 0, 100.])
    Lp = np.array([10., 0, 0]) + rot([0, 0, 0], 30) @ (np.array([0, 5., 0]) + rot([0, 0, 0], 60) @ (np.array([0, 0, 20.]) + L))
    row("G1 X0 Y0 Z0", Lp)


def trc_toframe():
    print("t_trc_toframe (type T, B = 90, L1 = 50, R 5, TOROT, G41 square in the frame's XY)")
    Q = rot([0, 1, 0], 90)
    Lp = Q @ [0, 0, 50.]
    for name, p in (("N10", [0, -10, 0]), ("N20", [0, 5, 0]), ("N30", [40, 5, 0]), ("N40", [40, -10, 0])):
        row(name, Q @ p + Lp)


def lentoax():
    print("t_lentoax (type T, B = 90, milling tool G17): unit vectors of L1, L2, L3 in the BCS")
    R = rot([0, 1, 0], 90)
    for k, e in ((1, [0, 0, 1]), (2, [0, 1, 0]), (3, [1, 0, 0])):
        print(f"  L{k}", np.round(R @ e, 12))


def more_tcofr():
    print("t_cardan_tcofry (cardan C/A, no frame, TCOFRY, L1 = 100)")
    g = lambda a1, a2: rot([0, 0, 1], a1) @ rot([1, 0, 0], a2) @ [0, 0, 1] - [0, 1, 0]
    s = search(g, [0, 0])
    print("  solutions", [list(np.round(x, 9)) for x in s])
    row("X0 Y0 Z0", rot([0, 0, 1], s[0][0]) @ rot([1, 0, 0], s[0][1]) @ [0, 0, 100.])
    print("t_cardan_limits (ROT X30, A limited to -90..-1, then A on a 25 degree Hirth grid)")
    f = rpy(rx=30) @ [0, 0, 1]
    g = lambda a1, a2: rot([0, 0, 1], a1) @ rot([1, 0, 0], a2) @ [0, 0, 1] - f
    s = search(g, [0, 0])
    print("  within limits", [list(np.round(x, 9)) for x in s if -90 <= x[1] <= -1])
    print("  Hirth 25: A", [25 * np.round(x[1] / 25) for x in s][0])
    print("t_torot_variants (no holder): BCS of X1 Y2 Z3")
    for name, cols in (("TOROT G17", "XYZ"), ("TOROTY G17", "YZX"), ("TOROTX G17", "ZXY"),
                       ("TOFRAME G18", "ZXY"), ("TOFRAMEZ G19", "YZX")):
        e = {"X": np.array([1., 0, 0]), "Y": np.array([0, 1., 0]), "Z": np.array([0, 0, 1.])}
        row(name, 1 * e[cols[0]] + 2 * e[cols[1]] + 3 * e[cols[2]])


if __name__ == "__main__":
    more_tcofr()
    head45()
    cardan_tcofr()
    table_p()
    mixed_m()
    zero_axes()
    trc_toframe()
    lentoax()
