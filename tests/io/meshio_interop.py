#!/usr/bin/env python3
"""meshio (Debian python3-meshio 7.0) and cmx's io layer read each other's files.

Run by ctest (tests/io/CMakeLists.txt) as

    meshio_interop.py PROBE {meshio-writes|cmx-writes|gmsh-opens}

where PROBE is the cmx_io_probe test program (tests/io/io_probe.cpp), which calls the io API.
`meshio-writes`: every variant meshio writes by default and with its options (VTU, legacy VTK,
Gmsh 4.1 and 2.2, Medit, TetGen; linear and 10-node tets; with and without point/cell data) is
written from a generated jittered ball and must be read by io::read_tet_mesh with the right counts,
every tet positive and not flipped. `cmx-writes`: every format io writes (vtu, vtk, mesh, msh 4.1,
node/ele; vtu/vtk/msh also with the map fields of io/map_fields.hpp) must open in meshio with the
same points, the same tets, positive signed volumes and the fields' values. `gmsh-opens`: Gmsh
itself (Debian gmsh, not installed by scripts/setup-deps.sh; skipped without it) reads io's MSH 4.1
output, with its $NodeData/$ElementData views.

Exits 77 (ctest's SKIP_RETURN_CODE) when meshio, numpy or pytest cannot be imported, so that a
machine without them reports the test as skipped, not passed.
"""
import json
import os
import shutil
import subprocess
import sys

SKIP = 77
PROBE = os.environ.get("CMX_IO_PROBE", "")

try:
    import meshio
    import numpy as np
    import pytest
except ImportError as missing:  # pragma: no cover - depends on the machine
    if __name__ == "__main__":
        print(f"skipped: {missing}")
        sys.exit(SKIP)
    raise


def ball(n=3, radius=2.3, seed=7):
    """A jittered Freudenthal grid of the cubes whose centre lies in a ball; every tet positive.

    Vertices are numbered in order of first use, so every vertex belongs to a tet.
    """
    rng = np.random.default_rng(seed)
    index, points, tets = {}, [], []

    def vertex(c):
        if c not in index:
            index[c] = len(points)
            points.append(np.array(c, dtype=float) + rng.uniform(-0.08, 0.08, 3))
        return index[c]

    perms = [(0, 1, 2), (0, 2, 1), (1, 0, 2), (1, 2, 0), (2, 0, 1), (2, 1, 0)]
    for i in range(-n, n):
        for j in range(-n, n):
            for k in range(-n, n):
                if (i + 0.5) ** 2 + (j + 0.5) ** 2 + (k + 0.5) ** 2 > radius**2:
                    continue
                for perm in perms:
                    c = [i, j, k]
                    tet = [vertex(tuple(c))]
                    for axis in perm:
                        c[axis] += 1
                        tet.append(vertex(tuple(c)))
                    tets.append(tet)
    points, tets = np.array(points), np.array(tets, dtype=np.int64)
    flip = volumes(points, tets) < 0
    tets[flip, 2], tets[flip, 3] = tets[flip, 3].copy(), tets[flip, 2].copy()
    assert (volumes(points, tets) > 0).all()
    return points, tets


def volumes(points, tets):
    a, b, c, d = (points[tets[:, k]] for k in range(4))
    return np.einsum("ij,ij->i", b - a, np.cross(c - a, d - a)) / 6


def quadratic(points, tets):
    """10-node tets (VTK/meshio order: corners, then edges 01 12 02 03 13 23), midpoints after the corners."""
    mids, extra = {}, []
    cells = []
    for t in tets:
        row = list(t)
        for a, b in [(0, 1), (1, 2), (0, 2), (0, 3), (1, 3), (2, 3)]:
            key = (min(t[a], t[b]), max(t[a], t[b]))
            if key not in mids:
                mids[key] = len(points) + len(extra)
                extra.append((points[t[a]] + points[t[b]]) / 2)
            row.append(mids[key])
        cells.append(row)
    return np.vstack([points, np.array(extra)]), np.array(cells, dtype=np.int64)


def probe(*args):
    run = subprocess.run([PROBE, *args], capture_output=True, text=True, check=False)
    assert run.returncode in (0, 3), run.stderr
    return json.loads(run.stdout) if run.stdout.strip() else {}


POINTS, TETS = ball()


def with_data(mesh):
    mesh.point_data = {"temperature": np.arange(len(mesh.points), dtype=float)}
    mesh.cell_data = {"region": [np.ones(len(c.data), dtype=np.int32) for c in mesh.cells]}
    return mesh


def with_gmsh_entities(mesh):
    """Tags that make meshio's Gmsh 4.1 writer emit an $Entities section (binary or ASCII)."""
    mesh.point_data = {"gmsh:dim_tags": np.tile([3, 1], (len(mesh.points), 1))}
    mesh.cell_data = {"gmsh:physical": [np.full(len(c.data), 5) for c in mesh.cells],
                      "gmsh:geometrical": [np.full(len(c.data), 1) for c in mesh.cells]}
    return mesh


# (name, file name, meshio.write keywords, tet type, mesh decoration)
MESHIO_VARIANTS = [
    ("vtu-default-binary-zlib", "m.vtu", {}, "tetra", None),
    ("vtu-ascii", "m.vtu", {"binary": False}, "tetra", None),
    ("vtu-binary-uncompressed", "m.vtu", {"compression": None}, "tetra", None),
    ("vtu-uint64-zlib", "m.vtu", {"header_type": "UInt64"}, "tetra", None),
    ("vtu-uint64-uncompressed", "m.vtu", {"header_type": "UInt64", "compression": None}, "tetra", None),
    ("vtu-zlib-with-data", "m.vtu", {}, "tetra", with_data),
    ("vtu-zlib-tetra10", "m.vtu", {}, "tetra10", None),
    ("vtk-default-51-binary", "m.vtk", {}, "tetra", None),
    ("vtk-51-ascii", "m.vtk", {"binary": False}, "tetra", None),
    ("vtk-42-binary", "m.vtk", {"file_format": "vtk42"}, "tetra", None),
    ("vtk-42-ascii", "m.vtk", {"file_format": "vtk42", "binary": False}, "tetra", None),
    ("vtk-42-binary-tetra10", "m.vtk", {"file_format": "vtk42"}, "tetra10", None),
    ("vtk-51-binary-with-data", "m.vtk", {}, "tetra", with_data),
    ("vtk-51-binary-tetra10", "m.vtk", {}, "tetra10", None),
    ("gmsh-default-41-binary", "m.msh", {"file_format": "gmsh"}, "tetra", None),
    ("gmsh-41-ascii", "m.msh", {"file_format": "gmsh", "binary": False}, "tetra", None),
    ("gmsh-41-binary-entities", "m.msh", {"file_format": "gmsh"}, "tetra", with_gmsh_entities),
    ("gmsh-41-ascii-entities", "m.msh", {"file_format": "gmsh", "binary": False}, "tetra", with_gmsh_entities),
    ("gmsh-41-binary-with-data", "m.msh", {"file_format": "gmsh"}, "tetra", with_data),
    ("gmsh-41-binary-tetra10", "m.msh", {"file_format": "gmsh"}, "tetra10", None),
    ("gmsh-22-binary", "m.msh", {"file_format": "gmsh22"}, "tetra", None),
    ("gmsh-22-ascii", "m.msh", {"file_format": "gmsh22", "binary": False}, "tetra", None),
    ("gmsh-22-ascii-tetra10", "m.msh", {"file_format": "gmsh22", "binary": False}, "tetra10", None),
    ("medit", "m.mesh", {}, "tetra", None),
    ("tetgen", "m.node", {}, "tetra", None),
]


@pytest.mark.parametrize("name,filename,options,cell_type,decorate", MESHIO_VARIANTS, ids=[v[0] for v in MESHIO_VARIANTS])
def test_meshio_writes_cmx_reads(tmp_path, name, filename, options, cell_type, decorate):
    points, cells = (POINTS, TETS) if cell_type == "tetra" else quadratic(POINTS, TETS)
    mesh = meshio.Mesh(points, [(cell_type, cells)])
    if decorate:
        mesh = decorate(mesh)
    path = str(tmp_path / filename)
    meshio.write(path, mesh, **options)
    got = probe("read", path)
    assert "error" not in got, got
    assert got["vertices"] == len(POINTS)  # a 10-node mesh loses its midpoints, and only them
    assert got["tets"] == len(TETS)
    assert got["positive"] == len(TETS) and not got["flipped"]
    assert got["dropped_higher_order_nodes"] == len(points) - len(POINTS)


def test_meshio_lzma_vtu_is_refused_by_name(tmp_path):
    path = str(tmp_path / "lzma.vtu")
    meshio.write(path, meshio.Mesh(POINTS, [("tetra", TETS)]), compression="lzma")
    got = probe("read", path)
    assert got["kind"] == "unsupported" and "vtkLZMADataCompressor" in got["error"], got


def cmx_output(tmp_path, filename, mapped):
    """The ball written by meshio as Medit (17 digits: exact doubles), then by cmx as `filename`."""
    source = str(tmp_path / "ball.mesh")
    meshio.write(source, meshio.Mesh(POINTS, [("tetra", TETS)]))
    out = str(tmp_path / filename)
    got = probe("map", source, out, str(len(POINTS) - 5)) if mapped else probe("convert", source, out)
    assert "error" not in got, got
    return meshio.read(out)


def tets_of(mesh):
    blocks = [c.data for c in mesh.cells if c.type == "tetra"]
    assert len(blocks) == 1, [c.type for c in mesh.cells]
    return blocks[0]


@pytest.mark.parametrize("filename", ["m.vtu", "m.vtk", "m.mesh", "m.msh", "m.node", "m.ele"])
def test_cmx_writes_meshio_reads(tmp_path, filename):
    mesh = cmx_output(tmp_path, filename, mapped=False)
    assert np.array_equal(mesh.points, POINTS)
    assert np.array_equal(tets_of(mesh), TETS)
    assert (volumes(mesh.points, tets_of(mesh)) > 0).all()


def affine_image(p):
    """io_probe.cpp's target map."""
    return np.column_stack([2 * p[:, 0] + 0.25 * p[:, 1] + 1, 1.5 * p[:, 1] - 2, 0.5 * p[:, 2] + 0.5])


def min_dihedral_deg(points, tets):
    """Smallest interior dihedral angle per tet, from the face normals (independent of io's code)."""
    p = [points[tets[:, k]] for k in range(4)]
    faces = [(1, 2, 3), (0, 2, 3), (0, 1, 3), (0, 1, 2)]  # face opposite vertex k
    normals = []
    for k, (a, b, c) in enumerate(faces):
        n = np.cross(p[b] - p[a], p[c] - p[a])
        inward = np.einsum("ij,ij->i", n, p[k] - p[a]) > 0
        n[inward] *= -1
        normals.append(n / np.linalg.norm(n, axis=1)[:, None])
    angles = [180 - np.degrees(np.arccos(np.clip(np.einsum("ij,ij->i", normals[k], normals[l]), -1, 1)))
              for k in range(4) for l in range(k + 1, 4)]
    return np.min(angles, axis=0)


def cell_field(mesh, name):
    """A cell field of the one tet block, flat (meshio reads legacy VTK scalars as n x 1)."""
    blocks = mesh.cell_data[name]
    assert len(blocks) == 1
    return np.asarray(blocks[0]).reshape(-1)


@pytest.mark.parametrize("filename", ["m.vtu", "m.vtk", "m.msh"])
def test_cmx_map_fields_open_in_meshio(tmp_path, filename):
    mesh = cmx_output(tmp_path, filename, mapped=True)
    target = affine_image(POINTS)
    tets = tets_of(mesh)
    assert np.array_equal(tets, TETS)
    assert np.allclose(mesh.points, target, rtol=0, atol=1e-12)
    assert (volumes(mesh.points, tets) > 0).all()
    assert np.array_equal(mesh.point_data["source"], POINTS)
    added = (TETS >= len(POINTS) - 5).any(axis=1)
    assert added.any() and not added.all()
    assert np.array_equal(cell_field(mesh, "added").astype(int), added.astype(int))
    assert np.allclose(cell_field(mesh, "source_volume"), volumes(POINTS, TETS), rtol=1e-12, atol=0)
    assert np.allclose(cell_field(mesh, "target_volume"), volumes(target, TETS), rtol=1e-12, atol=0)
    assert np.allclose(cell_field(mesh, "min_dihedral_deg"), min_dihedral_deg(target, TETS), rtol=0, atol=1e-6)
    # cmx's own readers still read the file (cmx info on a display output).
    got = probe("read", str(tmp_path / filename))
    assert got["vertices"] == len(POINTS) and got["positive"] == len(TETS), got


@pytest.mark.parametrize("mapped", [False, True])
def test_gmsh_opens_cmx_msh(tmp_path, mapped):
    cmx_output(tmp_path, "m.msh", mapped)
    check = tmp_path / "check.geo"
    check.write_text('Merge "m.msh";\nPrintf("views=%g", PostProcessing.NbViews);\n')
    run = subprocess.run([shutil.which("gmsh"), str(check), "-0"], cwd=tmp_path, capture_output=True, text=True, check=False)
    log = run.stdout + run.stderr
    assert run.returncode == 0 and "Error" not in log, log
    assert f"{len(POINTS)} nodes" in log and f"{len(TETS)} elements" in log, log
    assert f"views={5 if mapped else 0}" in log, log


SELECTIONS = {"meshio-writes": "meshio_writes or lzma", "cmx-writes": "cmx_writes or map_fields", "gmsh-opens": "gmsh_opens"}


def main():
    if len(sys.argv) != 3 or sys.argv[2] not in SELECTIONS:
        print(__doc__)
        return 2
    if sys.argv[2] == "gmsh-opens" and shutil.which("gmsh") is None:
        print("skipped: no gmsh on PATH")
        return SKIP
    os.environ["CMX_IO_PROBE"] = sys.argv[1]
    selection = SELECTIONS[sys.argv[2]]
    status = pytest.main([__file__, "-q", "--tb=short", "-p", "no:cacheprovider", "-k", selection])
    return 1 if status == pytest.ExitCode.NO_TESTS_COLLECTED else int(status)


if __name__ == "__main__":
    sys.exit(main())
