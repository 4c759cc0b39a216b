#!/usr/bin/env python3
"""The map the Shrink-and-Expand program writes, as cmx's checkers read maps.

Its output is an OpenVolumeMesh ASCII file whose vertex lines hold the target positions printed
to 6 significant digits; the exact positions are the string properties `str_exact_position`
(target) and `str_domain_exact_position` (source), "p/q;p/q;p/q" per vertex. This script reads
those, writes a legacy VTK of the nearest doubles of the exact target (what a user of the
program gets when rounding its exact map, the same rounding cmx's doubles start from), with
every tet listed positively in the exact source, and prints one JSON line with the exact
verdict: tets whose exact target orientation is not that of the source (inverted) or zero
(degenerate).

usage: sae_map_to_vtk.py MAP.ovm OUT.vtk
"""
import json
import sys
from fractions import Fraction


def tokens_after(lines, i):
    return int(lines[i + 1]), i + 2


def read_ovm(path):
    lines = open(path).read().split('\n')
    i = lines.index('Vertices')
    nv, i = tokens_after(lines, i)
    i += nv
    assert lines[i] == 'Edges'
    ne, i = tokens_after(lines, i)
    edges = [tuple(map(int, lines[i + k].split())) for k in range(ne)]
    i += ne
    assert lines[i] == 'Faces'
    nf, i = tokens_after(lines, i)
    faces = [list(map(int, lines[i + k].split()))[1:] for k in range(nf)]
    i += nf
    assert lines[i] == 'Polyhedra'
    nc, i = tokens_after(lines, i)
    cells = [list(map(int, lines[i + k].split()))[1:] for k in range(nc)]
    i += nc
    props = {}
    while i < len(lines):
        line = lines[i]
        if line.startswith('VProp string'):
            name = line.split('"')[1]
            props[name] = [lines[i + 1 + k].split(':', 1)[1] for k in range(nv)]
            i += nv + 1
        else:
            i += 1
    return nv, edges, faces, cells, props


def half_edge_from(edges, h):
    a, b = edges[h // 2]
    return a if h % 2 == 0 else b


def cell_vertices(edges, faces, cell):
    def cycle(hf):
        vs = [half_edge_from(edges, h) for h in faces[hf // 2]]
        return vs if hf % 2 == 0 else [vs[0], vs[2], vs[1]]
    first = cycle(cell[0])
    rest = {v for hf in cell[1:] for v in cycle(hf)} - set(first)
    assert len(rest) == 1, 'not a tetrahedron'
    return first + [rest.pop()]


def point(text):
    return [Fraction(x) for x in text.split(';')]


def orient(p, q, r, s):
    a = [q[k] - p[k] for k in range(3)]
    b = [r[k] - p[k] for k in range(3)]
    c = [s[k] - p[k] for k in range(3)]
    d = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])
    return (d > 0) - (d < 0)


def main(src, dst):
    nv, edges, faces, cells, props = read_ovm(src)
    target = [point(t) for t in props['str_exact_position']]
    source = [point(t) for t in props['str_domain_exact_position']]
    tets, inverted, degenerate = [], 0, 0
    for c in cells:
        t = cell_vertices(edges, faces, c)
        if orient(*(source[v] for v in t)) < 0:
            t = [t[0], t[2], t[1], t[3]]
        tets.append(t)
        s = orient(*(target[v] for v in t))
        inverted += s < 0
        degenerate += s == 0
    with open(dst, 'w') as f:
        f.write('# vtk DataFile Version 3.0\nShrink-and-Expand map, nearest doubles of its exact target\n'
                'ASCII\nDATASET UNSTRUCTURED_GRID\n')
        f.write('POINTS %d double\n' % nv)
        for p in target:
            f.write('%r %r %r\n' % tuple(float(x) for x in p))
        f.write('CELLS %d %d\n' % (len(tets), 5 * len(tets)))
        for t in tets:
            f.write('4 %d %d %d %d\n' % tuple(t))
        f.write('CELL_TYPES %d\n' % len(tets))
        f.write('10\n' * len(tets))
    print(json.dumps({'tets': len(tets), 'vertices': nv, 'inverted': inverted, 'degenerate': degenerate,
                      'valid': inverted == 0 and degenerate == 0}))
    return 0 if inverted == 0 and degenerate == 0 else 1


if __name__ == '__main__':
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1], sys.argv[2]))
