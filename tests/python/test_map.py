"""cmx.map on numpy arrays and on exact Fractions; the exact target checked in Python."""
import json
from fractions import Fraction

import numpy as np
import pytest

import cmx
from conftest import exactly_positive, grid_ball


def check_map(r, V, T):
    """The result is a verified map whose exact target has every tet positive (checked here with
    fractions, independently of cmx), whose first len(V) source vertices are the input's."""
    assert r.ok and r.status == "success" and r.message == ""
    assert r.exact_valid
    n = len(V)
    assert r.source.shape[1] == 3 and r.source.dtype == np.float64 and len(r.source) >= n
    assert r.target_double.shape == r.source.shape and r.target_double.dtype == np.float64
    assert r.tets.ndim == 2 and r.tets.shape[1] == 4 and r.tets.dtype == np.uint32
    assert len(r.tets) >= len(T)
    assert len(r.target_exact) == len(r.source)
    assert all(isinstance(x, Fraction) for p in r.target_exact[:5] for x in p)
    assert exactly_positive(r.target_exact, r.tets) == []
    assert exactly_positive(r.source_exact, r.tets) == []
    assert np.array_equal(r.source[:n], np.asarray(V, dtype=np.float64))
    # the doubles are the exact target rounded (snap may move them; they stay close)
    exact_as_double = np.array([[float(x) for x in p] for p in r.target_exact])
    assert np.allclose(exact_as_double, r.target_double, atol=1e-6)
    if r.double_valid:
        assert exactly_positive(r.target_double.tolist(), r.tets) == []
    assert r.report["status"] == "success"
    assert r.report == json.loads(r.report_json)


def test_map_onto_sphere_from_numpy_arrays(ball):
    V, T = ball
    r = cmx.map(V, T, shape="sphere")
    check_map(r, V, T)
    assert r.double_valid and r.double_inverted == 0 and r.double_flat == 0
    # the boundary vertices are where cmx.boundary_for_shape puts them
    ids, positions = cmx.boundary_for_shape(V, T, "sphere")
    assert ids.tolist() == cmx.boundary_vertices(T).tolist()
    assert [r.target_exact[i] for i in ids] == [tuple(Fraction(x) for x in p) for p in positions.tolist()]
    assert "cmx.Result success" in repr(r) and bool(r)


@pytest.mark.parametrize("init", ["auto", "shrink", "tutte"])
def test_map_with_a_boundary_dict(ball, init):
    V, T = ball
    ids = cmx.boundary_vertices(T)
    centre = V.mean(axis=0)
    # the unit cube scaled by 2 about its centre, rotated: a convex target
    c, s = np.cos(0.3), np.sin(0.3)
    R = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])
    boundary = {int(i): tuple(R @ (2 * (V[i] - centre))) for i in ids}
    r = cmx.map(V, T, boundary=boundary, init=init)
    check_map(r, V, T)
    for i, p in boundary.items():
        assert r.target_exact[i] == tuple(Fraction(x) for x in p)


def test_map_with_ids_and_positions_and_with_a_codomain(ball):
    V, T = ball
    ids = cmx.boundary_vertices(T)
    W = V * np.array([1.0, 2.0, 0.5])  # an affine image: every boundary position given by it
    r1 = cmx.map(V, T, boundary=(ids, W[ids]))
    check_map(r1, V, T)
    r2 = cmx.map(V, T, codomain=W)
    check_map(r2, V, T)
    assert r1.target_exact_text == r2.target_exact_text
    assert r1.tets.tolist() == r2.tets.tolist()


def test_exact_input_through_fractions():
    V, T = grid_ball(2)
    # exact vertices that no double holds: thirds, and an interior vertex off the grid
    Vq = [[Fraction(int(round(x * 2)), 3) for x in p] for p in V]
    centre = [Fraction(1, 3)] * 3
    interior = [i for i, p in enumerate(Vq) if all(0 < x < Fraction(2, 3) for x in p)]
    assert interior
    Vq[interior[0]] = [Fraction(1, 3) + Fraction(1, 7**20), Fraction(1, 3), Fraction(1, 3) - Fraction(1, 11)]
    assert exactly_positive(Vq, T) == []
    ids = cmx.boundary_vertices(T)
    boundary = {int(i): tuple(3 * (x - c) for x, c in zip(Vq[i], centre)) for i in ids}
    r = cmx.map(Vq, T, boundary=boundary)
    assert r.ok and r.exact_valid
    assert exactly_positive(r.target_exact, r.tets) == []
    assert r.source_exact[:len(Vq)] == [tuple(p) for p in Vq]
    for i, p in boundary.items():
        assert r.target_exact[i] == p
    # the same as text and as an object array
    r2 = cmx.map(np.array([[str(x) for x in p] for p in Vq], dtype=object), T, boundary=boundary)
    assert r2.target_exact_text == r.target_exact_text
    # homogeneous integers give the same points
    for (x, y, z, w), p in zip(r.target_homogeneous, r.target_exact):
        assert w > 0 and (Fraction(x, w), Fraction(y, w), Fraction(z, w)) == p


def test_options_reach_the_run(ball):
    V, T = ball
    seen = []
    r = cmx.map(V, T, shape="tet", init="shrink", snap="nearest", order="index", filter="exact",
                subclusters=0, collapse=False, threads=1, time_limit=60, shelled="after-pushes",
                progress=seen.append)
    check_map(r, V, T)
    assert seen and all(isinstance(p, cmx.Progress) for p in seen)
    assert {p.phase for p in seen} <= {"expansion", "collapse", "doubles", "verification", "shelling search"}
    assert "expansion" in {p.phase for p in seen}


def test_strict_index_order(ball):
    # The planned order (rank before class) maps too, and a misspelt order is an error.
    V, T = ball
    check_map(cmx.map(V, T, shape="tet", init="shrink", order="strict-index"), V, T)
    with pytest.raises(cmx.InvalidOptions, match="strict_index"):
        cmx.map(V, T, shape="tet", init="shrink", order="strict_index")


def test_deferred_order(ball):
    # A deferred id range maps with init="shrink" only: the local repair renumbers vertices.
    V, T = ball
    check_map(cmx.map(V, T, shape="tet", init="shrink", order="priority,defer:0-5"), V, T)
    with pytest.raises(cmx.InvalidOptions, match=r"only --init shrink"):
        cmx.map(V, T, shape="tet", order="priority,defer:0-5")
    with pytest.raises(cmx.InvalidOptions, match=r"option order: 'priority,defer:5-0'"):
        cmx.map(V, T, shape="tet", init="shrink", order="priority,defer:5-0")


def test_replay_shelling(ball):
    # Alg. 2 replayed from the start maps the small ball too; a misspelt mode is an error.
    V, T = ball
    check_map(cmx.map(V, T, shape="sphere", init="shrink", replay_shelling="full"), V, T)
    # The modes that replay only after a NOBUENOSS (the default) or never: no NOBUENOSS here.
    for mode in ("after-nobuenoss", "off"):
        r = cmx.map(V, T, shape="sphere", init="shrink", replay_shelling=mode)
        check_map(r, V, T)
        assert "replay" not in r.report["expansion"]
    with pytest.raises(cmx.InvalidOptions, match=r"option replay_shelling: 'always'"):
        cmx.map(V, T, shape="sphere", replay_shelling="always")


def test_given_initial_target(ball):
    V, T = ball
    r0 = cmx.map(V, T, shape="sphere")
    n = len(V)
    # a valid map of the input vertices: start from it
    start = r0.target_double[:n] if len(r0.source) == n and r0.double_valid else None
    if start is None:
        pytest.skip("the first map added vertices or has invalid doubles")
    ids = cmx.boundary_vertices(T)
    r = cmx.map(V, T, boundary=(ids, start[ids]), init=start)
    check_map(r, V, T)


def test_combinatorial_map_ignores_the_positions(ball):
    """combinatorial=True: V carries no geometry (zeros here); the tets, oriented alike, are realised
    in the target, whose source columns are the realisation itself."""
    V, T = ball
    ids, positions = cmx.boundary_for_shape(V, T, "star")
    r = cmx.map(np.zeros_like(V), T, boundary=(ids, positions), combinatorial=True)
    assert r.ok and r.exact_valid
    assert r.report["input"]["combinatorial"] is True
    assert r.report["verdict"]["source_positive"] is True  # here: a subdivision of the complex
    assert exactly_positive(r.target_exact, r.tets) == []
    assert r.source_exact == r.target_exact
    # without it, the zero positions are flat tets: refused
    with pytest.raises(cmx.InvalidInput):
        cmx.map(np.zeros_like(V), T, boundary=(ids, positions))


def test_farthest_corners_for_a_generated_shape(ball):
    V, T = ball
    ids, drawn = cmx.boundary_for_shape(V, T, "sphere")
    ids_far, far = cmx.boundary_for_shape(V, T, "sphere", corners="farthest")
    assert ids_far.tolist() == ids.tolist()
    assert np.allclose(np.linalg.norm(far, axis=1), 1.0, atol=1e-15)
    assert not np.array_equal(far, drawn)  # another placement of the same shape
    r = cmx.map(V, T, shape="sphere", corners="farthest")
    check_map(r, V, T)
    assert [r.target_exact[i] for i in ids] == [tuple(Fraction(x) for x in p) for p in far.tolist()]
    with pytest.raises(cmx.InvalidOptions, match="unknown corner choice 'nearest'"):
        cmx.map(V, T, shape="sphere", corners="nearest")
    with pytest.raises(cmx.InvalidOptions, match="it needs shape"):
        cmx.map(V, T, boundary=(ids, far), corners="farthest")
    with pytest.raises(cmx.Error, match="unknown corner choice"):
        cmx.boundary_for_shape(V, T, "tet", corners="middle")
