#!/usr/bin/env python3
"""The crowd of interior vertices around p_c in a cmx exact map (.tmap), and whether
homotheties about p_c can open it. Exact arithmetic throughout (fractions).

Usage: bench/map/crowd_probe.py MAP.tmap PX PY PZ

Prints the tets that the nearest doubles of the exact target make inverted or flat, the vertices
within 1e-8 of p_c by decade of distance, the neighbours of the innermost ones, and for every set
S_r of vertices within r of p_c (r = 1e-19 .. 1e-8) the largest factor 2^k (k among 1 .. 60)
whose homothety about p_c keeps every tet joining S_r to the other vertices strictly positive.
"""
import math
import sys
from collections import Counter, defaultdict
from fractions import Fraction


def read_tmap(path):
    lines = open(path).read().split('\n')
    n = int(lines[1].split()[1])
    target = [[Fraction(s) for s in lines[2 + i].split()[3:6]] for i in range(n)]
    tets = [tuple(map(int, l.split())) for l in lines[3 + n:] if l.strip()]
    return target, [t for t in tets if len(t) == 4]


def orient(p, q, r, s):
    a = [q[i] - p[i] for i in range(3)]
    b = [r[i] - p[i] for i in range(3)]
    c = [s[i] - p[i] for i in range(3)]
    return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])


def main():
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    x, tets = read_tmap(sys.argv[1])
    pc = [Fraction(s) for s in sys.argv[2:5]]
    dist = [max(abs(p[k] - pc[k]) for k in range(3)) for p in x]
    decade = lambda v: math.floor(math.log10(dist[v])) if dist[v] else -999
    nearest = [[Fraction(float(c)) for c in p] for p in x]
    bad = [t for t in tets if orient(*(nearest[v] for v in t)) <= 0]
    print('tets', len(tets), 'not positive in the nearest doubles', len(bad))
    print('their vertices by decade of distance from p_c:', sorted(Counter(decade(v) for v in set(sum(bad, ()))).items()))
    print('all vertices within 1e-8 by decade:', sorted(Counter(decade(v) for v in range(len(x)) if dist[v] < Fraction(1, 10**8)).items()))
    tets_of, neighbours = defaultdict(list), defaultdict(set)
    for i, t in enumerate(tets):
        for v in t:
            tets_of[v].append(i)
            neighbours[v].update(w for w in t if w != v)
    log_d = lambda v: round(math.log10(dist[v]), 1) if dist[v] else -999
    for v in sorted((v for v in range(len(x)) if dist[v]), key=lambda v: dist[v])[:4]:
        print('vertex', v, 'at 1e%.1f, neighbours at' % log_d(v), sorted(log_d(w) for w in neighbours[v]))

    def scales(inside, factor):
        moved = lambda v: [pc[k] + factor * (x[v][k] - pc[k]) for k in range(3)] if v in inside else x[v]
        joining = {i for v in inside for i in tets_of[v] if any(w not in inside for w in tets[i])}
        return all(orient(*(moved(v) for v in tets[i])) > 0 for i in joining), len(joining)

    for e in range(-19, -7):
        inside = {v for v in range(len(x)) if 0 < dist[v] < Fraction(10) ** e}
        if not inside:
            continue
        best, joining = 0, 0
        for k in (1, 2, 4, 8, 16, 24, 32, 40, 50, 60):
            ok, joining = scales(inside, Fraction(2) ** k)
            best = k if ok else best
        print('r = 1e%d: |S_r| = %d, %d joining tets, largest 2^k tried that keeps them positive: k = %d'
              % (e, len(inside), joining, best))


if __name__ == '__main__':
    main()
