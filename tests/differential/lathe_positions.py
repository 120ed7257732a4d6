#!/usr/bin/env python3
"""Differential test of the cutting edge positions against LinuxCNC's rs274 (lathe compensation).

For every LinuxCNC tool orientation Q0..Q9 and each of four lathe profiles of this script's own
(an OD with chamfer, fillet and shoulder under G42, the same backwards under G41, a face with a
chamfer into an OD under G42, a bore with its bottom under G41; G18, mm, nose radius 0.8 mm),
rs274's canonical trace and ncoffset's CSV (--coords wcs: the tool tip P with compensation,
without lengths) must agree segment by segment to 1e-4 mm (rs274 prints 4 decimals), with the
SINUMERIK cutting edge position SL that the orientation corresponds to:

    Q  1 2 3 4 5 6 7 8 9 0
    SL 4 3 2 1 5 8 7 6 9 0

(LinuxCNC numbers the positions as SINUMERIK does with X mirrored; docs/cutting-edge-
positions.md). The entry and exit moves are left out: LinuxCNC's entry differs from NORM by design
(tests/differential/README.md). rs274 is a test-time oracle only, installed by setup_rs274.sh;
nothing of LinuxCNC is kept in this repository.

Exit status: 0 all agree; 1 a disagreement or an error; 77 skipped (rs274 cannot be had here).
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
SKIP = 77
TOL = 1e-4  # mm
RADIUS = 0.8  # mm
Q_TO_SL = {1: 4, 2: 3, 3: 2, 4: 1, 5: 5, 6: 8, 7: 7, 8: 6, 9: 9, 0: 0}

# (name, side, start point, first contour point, contour blocks, end point); X radius values.
PROFILES = [
    ('od_g42', 'G42', 'X30 Z5', 'X14 Z0',
     ['G1 X16 Z-2', 'G1 Z-20', 'G2 X20 Z-24 I4 K0', 'G1 X25', 'G1 Z-35'], 'X35'),
    ('od_back_g41', 'G41', 'X35 Z-40', 'X25 Z-35',
     ['G1 Z-24', 'G1 X20', 'G3 X16 Z-20 I0 K4', 'G1 Z-2', 'G1 X14 Z0'], 'Z5'),
    ('face_od_g42', 'G42', 'X3 Z5', 'X5 Z0', ['G1 X24', 'G1 X25 Z-1', 'G1 Z-10'], 'X30'),
    ('bore_g41', 'G41', 'X10 Z5', 'X15 Z0', ['G1 Z-20', 'G1 X10', 'G1 X8 Z-22'], 'Z5'),
]


def find_rs274(args):
    if args.rs274:
        return args.rs274
    p = subprocess.run(['bash', os.path.join(HERE, 'setup_rs274.sh')], stdin=subprocess.DEVNULL,
                       capture_output=True, text=True)
    if p.returncode == SKIP:
        return None
    if p.returncode != 0:
        raise SystemExit(f"setup_rs274.sh failed ({p.returncode}):\n{p.stderr}")
    return p.stdout.strip().splitlines()[-1]


def rs274_path(rs274, work, q, profile):
    name, side, start, first, blocks, end = profile
    tbl, ngc, out = (os.path.join(work, f) for f in ('t.tbl', 't.ngc', 'out.txt'))
    with open(tbl, 'w') as f:  # Debian's rs274 reads tool tables in inches (peers.md)
        f.write(f"T1 P1 Z0 X0 D{2 * RADIUS / 25.4:.8f} Q{q}\n")
    with open(ngc, 'w') as f:
        f.write(f"G21 G18 G90 G40 G49 F200\nT1 M6\nG0 {start}\n{side}\nG1 {first}\n")
        f.write(''.join(b + '\n' for b in blocks) + f"G40\nG1 {end}\nM2\n")
    home = os.path.join(work, 'home')
    os.makedirs(home, exist_ok=True)
    env = dict(os.environ, HOME=home,
               LD_LIBRARY_PATH=os.path.join(os.path.dirname(os.path.dirname(rs274)), 'lib'))
    p = subprocess.run([rs274, '-g', '-t', tbl, '-v', os.path.join(home, 'p.var'), ngc, out],
                       env=env, stdin=subprocess.DEVNULL, capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError(f"rs274 failed on {name} Q{q}: {p.stderr.strip()}")
    path = []
    for line in open(out):
        m = re.search(r'STRAIGHT_FEED\(([^)]*)\)', line)
        if m:
            v = [float(x) for x in m.group(1).split(',')]
            path.append(('G1', v[0], v[2], None))
        m = re.search(r'ARC_FEED\(([^)]*)\)', line)
        if m:  # G18: first = Z, second = X; rotation > 0 counter-clockwise seen from +Y
            v = [float(x) for x in m.group(1).split(',')]
            path.append(('G3' if v[4] > 0 else 'G2', v[1], v[0], (v[3], v[2])))
    return path


def ncoffset_path(ncoffset, work, sl, profile):
    name, side, start, first, blocks, end = profile
    mpf = os.path.join(work, 't.MPF')
    with open(mpf, 'w') as f:
        f.write(f"$TC_DP1[1,1]=500 $TC_DP2[1,1]={sl} $TC_DP6[1,1]={RADIUS}\n")
        f.write(f"G18 G90 G0 {start} T1 D1 F200\n{side} G1 {first}\n")
        f.write(''.join(b + '\n' for b in blocks) + f"G40 G1 {end}\nM30\n")
    p = subprocess.run([ncoffset, '--coords', 'wcs', mpf], capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError(f"ncoffset failed on {name} SL{sl}: {p.stderr.strip()}")
    path = []
    for line in p.stdout.strip().splitlines()[1:]:
        f = line.split(',')
        if f[1] == 'G0':
            continue
        centre = (float(f[5]), float(f[7])) if f[1] in ('G2', 'G3') else None
        path.append((f[1], float(f[2]), float(f[4]), centre))
    return path


def same(a, b):
    if a[0] != b[0] or abs(a[1] - b[1]) > TOL or abs(a[2] - b[2]) > TOL:
        return False
    return a[3] is None or (abs(a[3][0] - b[3][0]) <= TOL and abs(a[3][1] - b[3][1]) <= TOL)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    ap.add_argument('--ncoffset', required=True)
    ap.add_argument('--rs274', help='path of rs274 (default: installed by setup_rs274.sh)')
    args = ap.parse_args()
    rs274 = find_rs274(args)
    if rs274 is None:
        print("differential_rs274_lathe: SKIP: LinuxCNC's rs274 is not available")
        return SKIP
    failures, segments = [], 0
    with tempfile.TemporaryDirectory(prefix='ncoffset-lathe-') as work:
        for profile in PROFILES:
            for q, sl in Q_TO_SL.items():
                rs = rs274_path(rs274, work, q, profile)[1:-1]  # without entry and exit
                nc = ncoffset_path(os.path.abspath(args.ncoffset), work, sl, profile)[1:-1]
                segments += len(nc)
                if len(rs) != len(nc) or not all(same(a, b) for a, b in zip(rs, nc)):
                    failures.append(f"{profile[0]} Q{q} / SL{sl}:\n  rs274   : {rs}\n"
                                    f"  ncoffset: {nc}")
    for f in failures:
        print(f"DISAGREEMENT {f}")
    print(f"differential_rs274_lathe: {len(PROFILES) * len(Q_TO_SL) - len(failures)} of "
          f"{len(PROFILES) * len(Q_TO_SL)} profile/orientation runs agree within {TOL} mm "
          f"({segments} segments), {len(failures)} disagree")
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
