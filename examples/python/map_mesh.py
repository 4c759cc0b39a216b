#!/usr/bin/env python3
"""Maps a tetrahedral mesh read with meshio onto a sphere-like star-shaped domain with cmx, and
writes the map as a VTU (target positions as points, source positions as point data "source").

    python3 examples/python/map_mesh.py [INPUT] [-o OUTPUT.vtu] [--shape sphere]

INPUT is any tet mesh meshio reads (.vtu, .vtk, .mesh, .msh, ...); without it a small jittered
cube mesh is generated and written to ball.vtu beside the output first. Open OUTPUT.vtu in
ParaView; the "source" point data (Warp By Vector of source - target, or a glyph) shows where each
vertex came from. Exit status 0 when the exact map is verified.
Needs the cmx module (PYTHONPATH=build/release/python, or pip install .), numpy and meshio.
"""
import argparse
import itertools
import os
import sys

import meshio
import numpy as np

import cmx


def generated_ball(k=4, jitter=0.2, seed=7):
    """A cube of k^3 cells, 6 tets each, interior vertices jittered: a ball with interior vertices."""
    grid = np.array(list(itertools.product(range(k + 1), repeat=3)), dtype=float) / k
    index = lambda a, b, c: (a * (k + 1) + b) * (k + 1) + c
    tets = []
    for a, b, c in itertools.product(range(k), repeat=3):
        for perm in itertools.permutations(range(3)):
            p, tet = [a, b, c], [index(a, b, c)]
            for axis in perm:
                p[axis] += 1
                tet.append(index(*p))
            tets.append(tet)
    interior = np.all((grid > 0) & (grid < 1), axis=1)
    grid[interior] += np.random.default_rng(seed).uniform(-jitter / k, jitter / k, (interior.sum(), 3))
    return grid, np.array(tets)


def positively_oriented(V, T):
    """T with every tet turned to cmx's orientation, det[b-a, c-a, d-a] > 0 (file formats differ)."""
    T = np.array(T, dtype=np.int64)
    d = np.einsum("ij,ij->i", np.cross(V[T[:, 1]] - V[T[:, 0]], V[T[:, 2]] - V[T[:, 0]]), V[T[:, 3]] - V[T[:, 0]])
    T[d < 0] = T[d < 0][:, [0, 1, 3, 2]]
    return T


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("input", nargs="?", help="tet mesh to map (default: a generated one)")
    parser.add_argument("-o", "--output", default="mapped.vtu", help="VTU to write (default: mapped.vtu)")
    parser.add_argument("--shape", default="sphere", help="target domain (cmx map --shape; default: sphere)")
    args = parser.parse_args()

    path = args.input
    if path is None:
        V, T = generated_ball()
        path = os.path.join(os.path.dirname(os.path.abspath(args.output)), "ball.vtu")
        meshio.write(path, meshio.Mesh(V, [("tetra", T)]))
        print(f"wrote a generated mesh to {path}")

    mesh = meshio.read(path)
    if "tetra" not in mesh.cells_dict:
        sys.exit(f"{path}: no tetrahedra")
    V = np.asarray(mesh.points[:, :3], dtype=np.float64)
    T = positively_oriented(V, mesh.cells_dict["tetra"])
    print(f"{path}: {len(V)} vertices, {len(T)} tets; mapping onto '{args.shape}'")

    r = cmx.map(V, T, shape=args.shape)
    print(f"status: {r.status}{': ' + r.message if r.message else ''}")
    if not r.ok:
        return 1
    out = meshio.Mesh(r.target_double, [("tetra", r.tets.astype(np.int64))], point_data={"source": r.source})
    meshio.write(args.output, out)
    print(f"wrote {args.output}: {len(r.source)} vertices ({len(r.source) - len(V)} added), {len(r.tets)} tets")
    print(f"exact_valid: {r.exact_valid}")
    print(f"double_valid: {r.double_valid} (inverted {r.double_inverted}, flat {r.double_flat})")
    print(f"seconds: {r.report.get('seconds', {}).get('total', '?')}")
    return 0 if r.exact_valid else 1


if __name__ == "__main__":
    sys.exit(main())
