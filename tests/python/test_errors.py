"""Bad input and bad options raise cmx.Error subclasses whose message names the problem."""
import math

import numpy as np
import pytest

import cmx
from conftest import grid_ball


@pytest.fixture
def small():
    V, T = grid_ball(2, jitter=0.1)
    ids = cmx.boundary_vertices(T)
    return V, T, ids


def test_exception_hierarchy():
    for cls in (cmx.InvalidInput, cmx.InvalidOptions, cmx.TimeLimit, cmx.Cancelled, cmx.Stuck, cmx.PrecisionLost):
        assert issubclass(cls, cmx.Error)
    assert issubclass(cmx.Error, Exception)
    assert issubclass(cmx.InvalidInput, ValueError) and issubclass(cmx.InvalidOptions, ValueError)
    assert issubclass(cmx.TimeLimit, TimeoutError)


def test_nan_coordinate(small):
    V, T, ids = small
    V = V.copy()
    V[5, 1] = math.nan
    with pytest.raises(cmx.InvalidInput, match=r"vertex 5: coordinate y is NaN") as e:
        cmx.map(V, T, boundary=(ids, V[ids] if 5 not in ids else np.nan_to_num(V[ids])))
    assert e.value.reason == "invalid_input" and e.value.status == "invalid_input"
    with pytest.raises(cmx.InvalidInput, match=r"vertex 5: coordinate y is NaN"):
        cmx.map(V, T, shape="sphere")


def test_out_of_range_tet_index(small):
    V, T, ids = small
    T = T.copy()
    T[3, 2] = len(V) + 10
    with pytest.raises(cmx.InvalidInput, match=rf"tet 3: vertex {len(V) + 10} out of range \({len(V)} vertices\)"):
        cmx.map(V, T, shape="sphere")
    T[3, 2] = -1
    with pytest.raises(cmx.InvalidInput, match=r"tet 3: vertex -1 out of range"):
        cmx.map(V, T, boundary=(ids, V[ids]))


def test_boundary_missing_a_vertex(small):
    V, T, ids = small
    boundary = {int(i): tuple(V[i]) for i in ids[1:]}
    with pytest.raises(cmx.InvalidInput) as e:
        cmx.map(V, T, boundary=boundary)
    assert f"vertex {ids[0]}" in str(e.value), str(e.value)
    assert e.value.reason == "boundary_mismatch"
    # an interior vertex given a position
    interior = next(i for i in range(len(V)) if i not in set(ids.tolist()))
    boundary = {int(i): tuple(V[i]) for i in ids}
    boundary[interior] = tuple(V[interior])
    with pytest.raises(cmx.InvalidInput, match=rf"{interior}"):
        cmx.map(V, T, boundary=boundary)


def test_not_a_ball_and_inverted_tets(small):
    V, T, ids = small
    Tm = T.copy()
    Tm[0] = Tm[0][[0, 1, 3, 2]]  # one tet inverted
    with pytest.raises(cmx.InvalidInput) as e:
        cmx.map(V, Tm, boundary=(ids, V[ids]))
    assert "tet" in str(e.value)
    # two disjoint balls
    V2, T2 = np.vstack([V, V + 3]), np.vstack([T, T + len(V)])
    with pytest.raises(cmx.InvalidInput, match="not a ball|connected") as e:
        cmx.map(V2, T2, shape="sphere")
    with pytest.raises(cmx.InvalidInput) as e:
        cmx.map(V2, T2, codomain=V2)
    assert e.value.reason == "not_ball", (e.value.reason, str(e.value))


def test_bad_shapes_of_arrays(small):
    V, T, ids = small
    with pytest.raises(cmx.InvalidInput, match=r"V: expected shape \(n, 3\)"):
        cmx.map(V[:, :2], T, shape="sphere")
    with pytest.raises(cmx.InvalidInput, match=r"T: expected shape \(m, 4\)"):
        cmx.map(V, T[:, :3], shape="sphere")
    with pytest.raises(cmx.InvalidInput, match=r"T: vertex indices must be integers"):
        cmx.map(V, T.astype(float), shape="sphere")
    with pytest.raises(cmx.InvalidInput, match=r"codomain: .* rows for"):
        cmx.map(V, T, codomain=V[:-1])
    with pytest.raises(cmx.InvalidInput, match=r"not a number"):
        cmx.map([[object(), 0, 0]] * len(V), T, shape="sphere")
    with pytest.raises(cmx.InvalidInput, match=r"'abc' is not an exact number"):
        cmx.map([["abc", "0", "0"]] + [[str(x) for x in p] for p in V[1:]], T, boundary=(ids, V[ids]))


def test_exactly_one_of_boundary_codomain_shape(small):
    V, T, ids = small
    with pytest.raises(ValueError, match="exactly one of boundary, codomain or shape"):
        cmx.map(V, T)
    with pytest.raises(cmx.InvalidOptions, match=r"got boundary, shape"):
        cmx.map(V, T, boundary=(ids, V[ids]), shape="sphere")


def test_bad_option_values(small):
    V, T, ids = small
    with pytest.raises(cmx.InvalidOptions, match=r"option snap: 'bogus'"):
        cmx.map(V, T, shape="sphere", snap="bogus")
    with pytest.raises(cmx.InvalidOptions, match=r"option filter: 'naive'"):
        cmx.map(V, T, shape="sphere", filter="naive")
    with pytest.raises(cmx.InvalidOptions, match=r"option threads: expected a non-negative integer, got -1"):
        cmx.map(V, T, shape="sphere", threads=-1)
    with pytest.raises(cmx.InvalidOptions, match=r"option time_limit: -1"):
        cmx.map(V, T, shape="sphere", time_limit=-1)
    with pytest.raises(cmx.InvalidOptions, match=r"option shelled: 'always'"):
        cmx.map(V, T, shape="sphere", shelled="always")
    with pytest.raises(cmx.InvalidOptions, match=r"option subclusters"):
        cmx.map(V, T, shape="sphere", subclusters=9)
    with pytest.raises(cmx.InvalidOptions, match=r"option collapse: expected True or False"):
        cmx.map(V, T, shape="sphere", collapse="yes")
    with pytest.raises(cmx.InvalidOptions, match=r"option init: 'sideways'"):
        cmx.map(V, T, shape="sphere", init="sideways")
    with pytest.raises(cmx.InvalidOptions, match=r"unknown shape 'blob'"):
        cmx.map(V, T, shape="blob")


def test_unknown_keyword_is_a_type_error(small):
    V, T, ids = small
    with pytest.raises(TypeError, match=r"unexpected keyword argument 'smoothing'"):
        cmx.map(V, T, shape="sphere", smoothing=3)


def test_cpp_errors_arrive_as_cmx_error(tmp_path):
    with pytest.raises(cmx.Error, match="nowhere.vtu"):
        cmx.read(tmp_path / "nowhere.vtu")
    with pytest.raises(cmx.Error, match="NaN|infinite"):
        cmx.orient3d((0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, math.nan))
    with pytest.raises(cmx.Error):
        cmx.chebyshev_center([[1, 0, 0, 1]], lp="simplex-of-doom")
    with pytest.raises(cmx.Error, match="vertex 9"):
        cmx._cmx.boundary_vertices(np.array([[0, 1, 2, 9]], dtype=np.uint32), 4)
