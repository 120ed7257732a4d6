#!/usr/bin/env python3
"""Writes the radius-compensation benchmark program of issue 22 in both dialects.

  trc_contour.py DIR [--blocks N] [--decimals] [--arcs cr|ij]

writes DIR/TRC.MPF with DIR/TOOLS.INI (SINUMERIK, for ncoffset) and DIR/trc.ngc with
DIR/tool.tbl (LinuxCNC rs274) and prints the number of blocks and of moves.

The program (docs/performance.md §24): laps around a 100 x 60 mm rectangle with R10 corners,
G1 lines and G2/G3 arcs alternating, outside the part with a tool of 8 mm diameter. The side of
compensation alternates from lap to lap: even laps G41 clockwise, odd laps G42 counter-clockwise
(both keep the tool outside: climb and conventional milling). Each lap is 13 blocks and 13 moves:

    G0 X-20 Y-20                 rapid to the start point beside the part
    G1 Z-1 F1000                 plunge (the depth cycles through 5 levels)
    G41 G1 X10 Y0                approach: compensation selected on a line
    (4 lines and 4 arcs)         the contour, starting and ending at X10 Y0
    G40 G1 X-25 Y-20             retract: compensation deselected on a line
    G0 Z5                        lift

The retract point differs from the next lap's start point, so no block is without motion; every
corner of the contour is tangential, so neither interpreter inserts a transition element and
both produce one move per block (the approach and retract lines themselves differ: ncoffset
moves to the normal at the contour's start (NORM), rs274 to the tangent of the offset arc).
With --decimals the rectangle is shifted and sized so that every coordinate has decimals
(X12.345 Y6.789, 100.25 x 60.5, corner radius 10.125, depths in steps of 0.75).
Prologue: 2 blocks (plane/units, tool); epilogue: M30 / M2. Blocks = 3 + 13 x laps.
"""
import argparse
import os

BLOCKS_PER_LAP = 13
PROLOGUE_BLOCKS = 3  # two blocks before the laps, the end of program after them
TOOL_RADIUS_MM = 4.0  # diameter 8 mm
TOOL_LENGTH_MM = 50.0


def number(milli):
    """A coordinate in thousandths of a mm as the shortest decimal text (10, -0.375, 12.345)."""
    sign = "-" if milli < 0 else ""
    whole, frac = divmod(abs(milli), 1000)
    return f"{sign}{whole}" if frac == 0 else f"{sign}{whole}.{frac:03d}".rstrip("0")


class Shape:
    """The rectangle in thousandths of a millimetre (integers: exact text in both dialects)."""

    def __init__(self, decimals):
        if decimals:
            self.ox, self.oy, self.w, self.h, self.r = 12345, 6789, 100250, 60500, 10125
            self.zstep, self.zclear = 750, 5125
        else:
            self.ox, self.oy, self.w, self.h, self.r = 0, 0, 100000, 60000, 10000
            self.zstep, self.zclear = 1000, 5000
        self.start = (self.ox - 20000, self.oy - 20000)
        self.retract = (self.ox - 25000, self.oy - 20000)


def contour(s, clockwise):
    """The 8 elements from (x0+r, y0) back to it: (kind, x, y, i, j); kind 'G1', 'G2' or 'G3',
    i/j the centre relative to the element's start."""
    x0, y0, x1, y1, r = s.ox, s.oy, s.ox + s.w, s.oy + s.h, s.r
    if clockwise:
        return [("G2", x0, y0 + r, 0, r), ("G1", x0, y1 - r, 0, 0),
                ("G2", x0 + r, y1, r, 0), ("G1", x1 - r, y1, 0, 0),
                ("G2", x1, y1 - r, 0, -r), ("G1", x1, y0 + r, 0, 0),
                ("G2", x1 - r, y0, -r, 0), ("G1", x0 + r, y0, 0, 0)]
    return [("G1", x1 - r, y0, 0, 0), ("G3", x1, y0 + r, 0, r),
            ("G1", x1, y1 - r, 0, 0), ("G3", x1 - r, y1, -r, 0),
            ("G1", x0 + r, y1, 0, 0), ("G3", x0, y1 - r, 0, -r),
            ("G1", x0, y0 + r, 0, 0), ("G3", x0 + r, y0, r, 0)]


def lap_blocks(s, lap, ngc, arcs):
    """The 13 blocks of one lap as text lines."""
    n = number
    even = lap % 2 == 0
    side = "G41" if even else "G42"
    depth = -s.zstep * (1 + lap % 5)
    radius_word = "R" if ngc else "CR="
    out = [f"G0 X{n(s.start[0])} Y{n(s.start[1])}", f"G1 Z{n(depth)} F1000",
           f"{side} G1 X{n(s.ox + s.r)} Y{n(s.oy)}"]
    for kind, x, y, i, j in contour(s, clockwise=even):
        if kind == "G1":
            out.append(f"G1 X{n(x)} Y{n(y)}")
        elif arcs == "ij":
            out.append(f"{kind} X{n(x)} Y{n(y)} I{n(i)} J{n(j)}")
        else:
            out.append(f"{kind} X{n(x)} Y{n(y)} {radius_word}{n(s.r)}")
    out += [f"G40 G1 X{n(s.retract[0])} Y{n(s.retract[1])}", f"G0 Z{n(s.zclear)}"]
    return out


def laps_for(blocks):
    return max(1, round((blocks - PROLOGUE_BLOCKS) / BLOCKS_PER_LAP))


def write(directory, blocks=100000, decimals=False, arcs="cr"):
    """Writes TRC.MPF, TOOLS.INI, trc.ngc and tool.tbl into `directory`; returns a dict with
    their paths, the number of blocks and the number of moves each interpreter must make."""
    os.makedirs(directory, exist_ok=True)
    s = Shape(decimals)
    laps = laps_for(blocks)
    paths = {k: os.path.join(directory, v) for k, v in
             (("mpf", "TRC.MPF"), ("init", "TOOLS.INI"), ("ngc", "trc.ngc"), ("tbl", "tool.tbl"))}
    with open(paths["init"], "w") as f:
        f.write("; T1 D1: end mill of 8 mm diameter, 50 mm long (TO_INI format)\nCHANDATA(1)\n"
                f"$TC_DP1[1,1]=120\n$TC_DP3[1,1]={TOOL_LENGTH_MM:g}\n"
                f"$TC_DP6[1,1]={TOOL_RADIUS_MM:g}\nM17\n")
    # rs274 of Debian 12 reads the tool table in inches whatever the program's units
    # (/work/shared/peers.md, LinuxCNC issue #1279); D is the diameter.
    with open(paths["tbl"], "w") as f:
        f.write(f"T1 P1 Z{TOOL_LENGTH_MM / 25.4:.9f} D{2 * TOOL_RADIUS_MM / 25.4:.9f}\n")
    for ngc in (False, True):
        with open(paths["ngc" if ngc else "mpf"], "w", buffering=1 << 20) as f:
            if ngc:
                f.write("G21 G90 G17 G40 G49 G94\nT1 M6 G43\n")
            else:
                f.write(f"; issue 22 benchmark: {laps} laps, G41/G42 alternating "
                        "(bench/trc_contour.py)\nG17 G90 G94 G71\nT1 D1\n")
            for lap in range(laps):
                f.write("\n".join(lap_blocks(s, lap, ngc, arcs)))
                f.write("\n")
            f.write("M2\n" if ngc else "M30\n")
    paths.update(blocks=PROLOGUE_BLOCKS + BLOCKS_PER_LAP * laps, moves=BLOCKS_PER_LAP * laps,
                 laps=laps)
    return paths


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("directory")
    ap.add_argument("--blocks", type=int, default=100000, help="about this many blocks")
    ap.add_argument("--decimals", action="store_true", help="decimals in every coordinate")
    ap.add_argument("--arcs", choices=("cr", "ij"), default="cr",
                    help="arcs by radius (CR= / R) or by centre (I J), default cr")
    a = ap.parse_args()
    p = write(a.directory, a.blocks, a.decimals, a.arcs)
    print(f"{p['blocks']} blocks, {p['moves']} moves: {p['mpf']} (--init {p['init']}), {p['ngc']}")


if __name__ == "__main__":
    main()
