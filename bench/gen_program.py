#!/usr/bin/env python3
"""Writes a plain-G1 benchmark program (docs/performance.md).

  gen_program.py BLOCKS OUT.MPF            SINUMERIK part program (N.. G1 X Y Z F1000 ... M30)
  gen_program.py BLOCKS OUT.ngc --ngc      the same moves for LinuxCNC rs274 (G21 G90 ... M2)

Coordinates come from the same generators as bench/interp_bench.cpp, so consecutive blocks
never end at the same point: every block produces one segment.
"""
import sys


def fixed3(milli):
    sign = "-" if milli < 0 else ""
    milli = abs(milli)
    return f"{sign}{milli // 1000}.{milli % 1000:03d}"


def main():
    blocks = int(sys.argv[1])
    out = sys.argv[2]
    ngc = "--ngc" in sys.argv[3:]
    x, y, z = 12345, 678, 91
    m32 = 0xFFFFFFFF
    with open(out, "w", buffering=1 << 20) as f:
        w = f.write
        if ngc:
            w("G21 G90 G17 G40 G49 G94\n")
        for i in range(1, blocks + 1):
            x = (x * 1103515245 + 12345) & m32
            y = (y * 22695477 + 1) & m32
            z = (z * 1664525 + 1013904223) & m32
            xs = fixed3((x >> 8) % 400000 - 200000)
            ys = fixed3((y >> 8) % 400000 - 200000)
            zs = fixed3((z >> 8) % 100000 - 50000 + (i & 1))
            if ngc:
                # rs274ngc refuses line numbers above 99999: number modulo 100000.
                w(f"N{i % 100000} G1 X{xs} Y{ys} Z{zs} F1000\n")
            else:
                w(f"N{i * 10} G1 X{xs} Y{ys} Z{zs} F1000\n")
        w("M2\n" if ngc else "M30\n")


if __name__ == "__main__":
    main()
