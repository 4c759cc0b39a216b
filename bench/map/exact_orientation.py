#!/usr/bin/env python3
"""Exact orientation of every tet of a .tmap, in rationals only (no float filter).

    exact_orientation.py OUT.tmap

Prints one JSON line: tets, and how many are not strictly positive in the target and in the
source, each decided by det[b-a, c-a, d-a] on fractions.Fraction. Slow on large maps, but it cannot
underflow: a float filter can, when a map crowds vertices within 1e-300 of a point (a double
repair cut short by the time limit leaves such crowds), and then counts positive tets as flat.
Exit 0 iff every tet is positive in both.
"""
import json
import sys
from fractions import Fraction


def read_tmap(path):
    with open(path) as f:
        rows = [line.split() for line in f if line.strip() and not line.lstrip().startswith("#")]
    assert rows[0] == ["tmap", "1"] and rows[1][0] == "vertices", "not a tmap 1 file"
    n = int(rows[1][1])
    source = [tuple(Fraction(x) for x in r[:3]) for r in rows[2:2 + n]]
    target = [tuple(Fraction(x) for x in r[3:6]) for r in rows[2:2 + n]]
    assert rows[2 + n][0] == "tets"
    m = int(rows[2 + n][1])
    tets = [tuple(int(v) for v in r) for r in rows[3 + n:3 + n + m]]
    return source, target, tets


def det(a, b, c, d):
    ux, uy, uz = b[0] - a[0], b[1] - a[1], b[2] - a[2]
    vx, vy, vz = c[0] - a[0], c[1] - a[1], c[2] - a[2]
    wx, wy, wz = d[0] - a[0], d[1] - a[1], d[2] - a[2]
    return ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx)


def main():
    source, target, tets = read_tmap(sys.argv[1])
    bad = {name: sum(1 for t in tets if not det(*(p[k] for k in t)) > 0)
           for name, p in (("target", target), ("source", source))}
    print(json.dumps({"tets": len(tets), "target_nonpositive": bad["target"], "source_nonpositive": bad["source"]}))
    return 0 if bad["target"] == 0 and bad["source"] == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
