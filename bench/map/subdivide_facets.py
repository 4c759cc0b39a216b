#!/usr/bin/env python3
"""Random stellar subdivisions of a facet list, keeping a deferred vertex range's full subcomplex.

usage: subdivide_facets.py IN.facets OUT.facets FIRST END SEED EDGES TETS

Splits EDGES random edges (at a new vertex on the edge, every tet around it in two) and then TETS
random tets (at a new vertex inside, one tet in four), choosing with Python's random.Random(SEED).
An edge whose two ends both lie in [FIRST, END) is never split, so the full subcomplex of those ids
(the dunce hat of `cmx generate-mesh --shape dunce-hat-ball:C`, its last 8 ids) stays what it was,
and new vertices get ids from the old vertex count on, outside the range. The result is the same
ball, subdivided: a stellar subdivision does not change the topology. Whether it is still shellable
is for cmx's shelling search to say. The bench uses it to test the shelling replay on inputs it was
not tuned on (bench/map/replay_cases.sh, SUBDIVIDED=...).
"""
import random
import sys


def read_facets(path):
    tets = []
    with open(path) as f:
        for line in f:
            line = line.strip()
            if line and not line.startswith('#'):
                tets.append(tuple(int(x) for x in line.split()))
    return tets


def edges_of(tets):
    out = set()
    for t in tets:
        for i in range(4):
            for j in range(i + 1, 4):
                out.add((min(t[i], t[j]), max(t[i], t[j])))
    return sorted(out)


def split_edge(tets, a, b, m):
    out = []
    for t in tets:
        if a in t and b in t:
            out.append(tuple(m if v == b else v for v in t))  # orientation kept: m replaces b
            out.append(tuple(m if v == a else v for v in t))
        else:
            out.append(t)
    return out


def split_tet(tets, k, m):
    t = tets[k]
    rest = tets[:k] + tets[k + 1:]
    return rest + [tuple(m if j == i else t[j] for j in range(4)) for i in range(4)]


def main():
    if len(sys.argv) != 8:
        sys.exit(__doc__)
    src, dst = sys.argv[1], sys.argv[2]
    first, end, seed, n_edges, n_tets = (int(x) for x in sys.argv[3:8])
    tets = read_facets(src)
    n = 1 + max(max(t) for t in tets)
    rng = random.Random(seed)
    for _ in range(n_edges):
        candidates = [e for e in edges_of(tets) if not (first <= e[0] < end and first <= e[1] < end)]
        a, b = rng.choice(candidates)
        tets = split_edge(tets, a, b, n)
        n += 1
    for _ in range(n_tets):
        tets = split_tet(tets, rng.randrange(len(tets)), n)
        n += 1
    with open(dst, 'w') as f:
        f.write('# facet list: %s with %d edge and %d tet stellar subdivisions (seed %d), '
                '0-based vertex ids\n' % (src.split('/')[-1], n_edges, n_tets, seed))
        for t in tets:
            f.write(' '.join(map(str, t)) + '\n')


if __name__ == '__main__':
    main()
