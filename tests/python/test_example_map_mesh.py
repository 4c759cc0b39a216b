"""examples/python/map_mesh.py runs (generated input, and a given .vtu) and writes a VTU with the
target as points and the source as point data."""
import os
import subprocess
import sys

import numpy as np
import pytest

import cmx
from conftest import exactly_positive, grid_ball

meshio = pytest.importorskip("meshio")
SOURCE_DIR = os.environ.get("CMX_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
EXAMPLE = os.path.join(SOURCE_DIR, "examples", "python", "map_mesh.py")


def run_example(tmp_path, *args):
    p = subprocess.run([sys.executable, EXAMPLE, *args], cwd=tmp_path, capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, (p.stdout, p.stderr)
    return p.stdout


def check_output(path, input_vertices):
    m = meshio.read(path)
    T = m.cells_dict["tetra"]
    assert len(m.points) >= input_vertices
    assert m.point_data["source"].shape == m.points.shape
    assert exactly_positive(m.points.tolist(), T) == []  # the written doubles are a valid map
    assert exactly_positive(m.point_data["source"].tolist(), T) == []


def test_example_on_its_generated_mesh(tmp_path):
    out = run_example(tmp_path)
    assert "status: success" in out and "exact_valid: True" in out and "double_valid:" in out
    check_output(tmp_path / "mapped.vtu", 125)


def test_example_on_a_given_mesh(tmp_path):
    V, T = grid_ball(3, jitter=0.1)
    # written with the tets reversed: the example turns them to cmx's orientation
    meshio.write(tmp_path / "in.vtk", meshio.Mesh(V, [("tetra", T[:, [0, 1, 3, 2]])]))
    out = run_example(tmp_path, "in.vtk", "-o", "out.vtu", "--shape", "star")
    assert "exact_valid: True" in out
    check_output(tmp_path / "out.vtu", len(V))
