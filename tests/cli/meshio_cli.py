#!/usr/bin/env python3
"""The cmx program and meshio (Debian python3-meshio) on each other's files.

Run by ctest (tests/cli/CMakeLists.txt) as

    meshio_cli.py CMX

`meshio-files`: every variant meshio writes (the list of tests/io/meshio_interop.py: VTU, legacy
VTK, Gmsh 4.1 and 2.2, Medit, TetGen; linear and 10-node tets) of a jittered ball opens in
`cmx info` as a ball with consistent orientation and the right counts, and maps with `cmx map`
onto a sphere, verified (exit 0, `exact_valid`), the .tmap then read back by `cmx info` (target, then
--source) as a ball with every tet positive. `map-outputs`: every display format `cmx map` writes
(vtu, vtk, msh, mesh) and the TetGen files `cmx convert` makes of its .tmap open in meshio with
the .tmap's counts, positive volumes, and (vtu, vtk, msh) the source positions and the `added`
flags that the .tmap implies.

Exits 77 (ctest's SKIP_RETURN_CODE) when meshio, numpy or pytest cannot be imported.
"""
import json
import os
import subprocess
import sys
from fractions import Fraction

SKIP = 77
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "io"))
try:
    import meshio
    import numpy as np
    import pytest
    from meshio_interop import MESHIO_VARIANTS, POINTS, TETS, quadratic, volumes
except ImportError as missing:  # pragma: no cover - depends on the machine
    if __name__ == "__main__":
        print(f"skipped: {missing}")
        sys.exit(SKIP)
    raise

CMX = os.environ.get("CMX_EXE", "")


def cmx(*args):
    return subprocess.run([CMX, *args], capture_output=True, text=True, check=False)


def info(path, *extra):
    run = cmx("info", path, "--json", *extra)
    assert run.returncode == 0, run.stderr
    return json.loads(run.stdout)


def read_tmap(path):
    """Counts, exact source positions and tets of a .tmap (format in README.md)."""
    with open(path) as f:
        lines = [line.split() for line in f if line.strip() and not line.startswith("#")]
    n = int(lines[1][1])
    source = [[Fraction(x) for x in row[:3]] for row in lines[2:2 + n]]
    m = int(lines[2 + n][1])
    tets = np.array([[int(v) for v in row] for row in lines[3 + n:3 + n + m]], dtype=np.int64)
    return source, tets


LINEAR_AND_QUADRATIC = [v for v in MESHIO_VARIANTS if v[3] in ("tetra", "tetra10")]


@pytest.mark.parametrize("name,filename,options,cell_type,decorate", LINEAR_AND_QUADRATIC,
                         ids=[v[0] for v in LINEAR_AND_QUADRATIC])
def test_meshio_files_open_in_info_and_map(tmp_path, name, filename, options, cell_type, decorate):
    points, cells = (POINTS, TETS) if cell_type == "tetra" else quadratic(POINTS, TETS)
    mesh = meshio.Mesh(points, [(cell_type, cells)])
    if decorate:
        mesh = decorate(mesh)
    path = str(tmp_path / filename)
    meshio.write(path, mesh, **options)
    got = info(path)
    assert got["is_ball"] is True, got
    assert got["orientation"]["verdict"] == "consistent", got
    assert (got["vertices"], got["tets"]) == (len(POINTS), len(TETS)), got
    out, report = str(tmp_path / "mapped"), str(tmp_path / "report.json")
    run = cmx("map", path, "--shape", "sphere", "-o", out, "--report", report, "-q")
    assert run.returncode == 0, run.stderr
    with open(report) as f:
        verdict = json.load(f)["verdict"]
    assert verdict["exact_valid"] is True, verdict
    for geometry in ([], ["--source"]):
        mapped = info(out + ".tmap", *geometry)
        assert mapped["is_ball"] is True, mapped
        assert mapped["tets"] >= len(TETS) and mapped["orientation"]["positive"] == mapped["tets"], mapped


@pytest.mark.parametrize("fmt", ["vtu", "vtk", "msh", "mesh", "node"])
def test_map_outputs_open_in_meshio(tmp_path, fmt):
    ball = str(tmp_path / "ball.vtu")
    meshio.write(ball, meshio.Mesh(POINTS, [("tetra", TETS)]))
    out = str(tmp_path / "mapped")
    run = cmx("map", ball, "--shape", "star:5", "-o", out, "--format", "vtu,vtk,msh,mesh", "-q")
    assert run.returncode == 0, run.stderr
    if fmt == "node":
        run = cmx("convert", out + ".tmap", out + ".node", "-q")
        assert run.returncode == 0, run.stderr
    source, tets = read_tmap(out + ".tmap")
    mesh = meshio.read(out + "." + fmt)
    blocks = [c.data for c in mesh.cells if c.type == "tetra"]
    assert len(blocks) == 1
    assert len(mesh.points) == len(source) and np.array_equal(blocks[0], tets)
    assert (volumes(mesh.points, blocks[0]) > 0).all()
    if fmt in ("vtu", "vtk", "msh"):
        nearest = np.array([[float(x) for x in p] for p in source])
        assert np.array_equal(mesh.point_data["source"], nearest)
        added = np.asarray(mesh.cell_data["added"][0]).reshape(-1).astype(int)
        assert np.array_equal(added, (tets >= len(POINTS)).any(axis=1).astype(int))
        assert (np.asarray(mesh.cell_data["source_volume"][0]).reshape(-1) > 0).all()
        # cmx's own reader takes the file with its fields (cmx info on a display output).
        got = info(out + "." + fmt)
        assert got["tets"] == len(tets) and got["orientation"]["positive"] == len(tets), got


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    os.environ["CMX_EXE"] = sys.argv[1]
    status = pytest.main([__file__, "-q", "--tb=short", "-p", "no:cacheprovider"])
    return 1 if status == pytest.ExitCode.NO_TESTS_COLLECTED else int(status)


if __name__ == "__main__":
    sys.exit(main())
