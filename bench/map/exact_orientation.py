#!/usr/bin/env python3
"""Second opinion on the orientations of an exact map (.tmap), in exact rationals only.

usage: exact_orientation.py OUT.tmap
Prints one JSON line: how many tets are not strictly positive in the target and in the source,
computed with fractions.Fraction and no floating-point filter at all. Exit 0 iff none.

Why it exists: ../shared/tools/verify_tmap.py filters each determinant in floating point and
takes the float sign unless |det| < 1e-9 * scale^3. When a tet's coordinates are below about
1e-103 (vertices crowding around a shrink point at the origin), both the determinant and that
threshold underflow to 0, and a positive tet is counted as not positive. This script decides
those tets exactly. Standard library only.
"""
import json
import sys
from fractions import Fraction


def det(a, b, c, d):
    ax, ay, az = b[0] - a[0], b[1] - a[1], b[2] - a[2]
    bx, by, bz = c[0] - a[0], c[1] - a[1], c[2] - a[2]
    cx, cy, cz = d[0] - a[0], d[1] - a[1], d[2] - a[2]
    return ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx)


def main():
    if len(sys.argv) != 2:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        sys.exit(2)
    rows = [l.split() for l in open(sys.argv[1]) if l.strip() and not l.startswith('#')]
    assert rows[0][0] == 'tmap' and rows[1][0] == 'vertices', 'not a tmap file'
    n = int(rows[1][1])
    source = [tuple(Fraction(x) for x in r[:3]) for r in rows[2:2 + n]]
    target = [tuple(Fraction(x) for x in r[3:6]) for r in rows[2:2 + n]]
    assert rows[2 + n][0] == 'tets', 'no tets line'
    tets = [tuple(int(x) for x in r[:4]) for r in rows[3 + n:3 + n + int(rows[2 + n][1])]]
    bad_t = sum(1 for t in tets if not det(*(target[k] for k in t)) > 0)
    bad_s = sum(1 for t in tets if not det(*(source[k] for k in t)) > 0)
    print(json.dumps({'tets': len(tets), 'target_nonpositive': bad_t, 'source_nonpositive': bad_s}))
    sys.exit(0 if bad_t == 0 and bad_s == 0 else 1)


if __name__ == '__main__':
    main()
