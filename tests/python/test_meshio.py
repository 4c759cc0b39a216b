"""Round trips between cmx and meshio (Debian python3-meshio): a map written by meshio is read
back by cmx.read and meshio; cmx.write output is read by meshio; .tmap keeps the exact map."""
from fractions import Fraction

import numpy as np
import pytest

import cmx
from conftest import exactly_positive

meshio = pytest.importorskip("meshio")


@pytest.fixture
def mapped(ball):
    V, T = ball
    r = cmx.map(V, T, shape="sphere")
    assert r.ok and r.exact_valid and r.double_valid
    return r


@pytest.mark.parametrize("ext", [".vtu", ".vtk", ".mesh"])
def test_result_written_by_meshio_reads_back_in_cmx_and_meshio(mapped, tmp_path, ext):
    path = tmp_path / f"mapped{ext}"
    m = meshio.Mesh(mapped.target_double, [("tetra", mapped.tets.astype(np.int64))],
                    point_data={"source": mapped.source} if ext != ".mesh" else {})
    meshio.write(path, m)

    back = cmx.read(path)
    assert back.tets.tolist() == mapped.tets.tolist()
    assert np.array_equal(back.points, mapped.target_double)  # doubles survive 17 digits exactly
    # exact: the rationals of the file's text (.mesh: decimals) or binary doubles (.vtu, .vtk)
    assert [[float(x) for x in p] for p in back.points_exact] == mapped.target_double.tolist()
    assert exactly_positive(back.points_exact, back.tets) == []

    again = meshio.read(path)
    assert np.array_equal(again.points, mapped.target_double)
    assert again.cells_dict["tetra"].tolist() == mapped.tets.tolist()
    if ext != ".mesh":
        assert np.array_equal(again.point_data["source"], mapped.source)


@pytest.mark.parametrize("ext", [".vtu", ".vtk", ".msh"])
def test_cmx_write_reads_in_meshio(mapped, tmp_path, ext):
    path = tmp_path / f"source{ext}"
    cmx.write(path, points=mapped.source, tets=mapped.tets)
    m = meshio.read(path)
    assert np.array_equal(m.points, mapped.source)
    assert m.cells_dict["tetra"].tolist() == mapped.tets.tolist()
    # a meshio.Mesh is written directly too
    path2 = tmp_path / f"again{ext}"
    cmx.write(path2, m)
    assert cmx.read(path2).tets.tolist() == mapped.tets.tolist()


def test_tmap_and_ovm_keep_the_exact_map(mapped, tmp_path):
    path = tmp_path / "map.tmap"
    cmx.write(path, mapped)
    back = cmx.read(path)
    assert back.target_exact == mapped.target_exact
    assert back.points_exact == mapped.source_exact
    assert back.tets.tolist() == mapped.tets.tolist()
    assert np.array_equal(back.target, np.array([[float(x) for x in p] for p in mapped.target_exact]))
    # exact positions as Fractions through .ovm (its exact property)
    ovm = tmp_path / "target.ovm"
    cmx.write(ovm, points=mapped.target_exact, tets=mapped.tets)
    m = cmx.read(ovm)
    assert m.points_exact == mapped.target_exact and m.target_exact is None


def test_cmx_write_errors_name_the_file(tmp_path):
    with pytest.raises(cmx.Error, match="unknown|extension"):
        cmx.write(tmp_path / "x.unknown", points=np.zeros((4, 3)), tets=[[0, 1, 2, 3]])
    with pytest.raises(cmx.InvalidInput, match="tet 0: vertex 7 out of range"):
        cmx.write(tmp_path / "x.vtu", points=np.zeros((4, 3)), tets=[[0, 1, 2, 7]])
