"""cmx.orient3d / orient2d, cmx.chebyshev_center, cmx.is_ball and the other topology queries."""
from fractions import Fraction

import numpy as np
import pytest

import cmx
from conftest import grid_ball, orient3d_fraction

O, X, Y, Z = (0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)


def test_version():
    assert isinstance(cmx.__version__, str) and cmx.__version__.count(".") == 2


@pytest.mark.parametrize("arithmetic", ["cascade", "interval", "exact"])
def test_orient3d_signs(arithmetic):
    assert cmx.orient3d(O, X, Y, Z, arithmetic) == 1
    assert cmx.orient3d(O, X, Z, Y, arithmetic) == -1
    assert cmx.orient3d(O, X, Y, (1.0, 1.0, 0.0), arithmetic) == 0
    # exactly coplanar only in exact arithmetic: thirds
    t = Fraction(1, 3)
    assert cmx.orient3d((0, 0, 0), (t, 0, 0), (0, t, 0), (t, t, 0), arithmetic) == 0
    assert cmx.orient3d((0, 0, 0), (t, 0, 0), (0, t, 0), ("1/3", "1/3", "1e-300"),
                        arithmetic) == 1


def test_orient3d_is_exact_on_nearly_coplanar_doubles():
    rng = np.random.default_rng(5)
    for _ in range(200):
        a, b, c = rng.uniform(-1, 1, (3, 3))
        s, u = rng.uniform(0, 1, 2)
        d = a + s * (b - a) + u * (c - a)  # on the plane up to rounding
        exact = orient3d_fraction(*[[Fraction(float(x)) for x in p] for p in (a, b, c, d)])
        assert cmx.orient3d(a, b, c, d) == (exact > 0) - (exact < 0)


def test_orient2d():
    assert cmx.orient2d((0, 0), (1, 0), (0, 1)) == 1
    assert cmx.orient2d((0, 0), (0, 1), (1, 0)) == -1
    assert cmx.orient2d((0, 0), (1, 1), (2, 2)) == 0


def test_chebyshev_center_of_the_unit_cube():
    rows = [[-1, 0, 0, 0], [1, 0, 0, 1], [0, -1, 0, 0], [0, 1, 0, 1], [0, 0, -1, 0], [0, 0, 1, 1]]
    c = cmx.chebyshev_center(np.array(rows, dtype=float))
    assert c.ok and c.status == "interior"
    assert c.centre_exact == (Fraction(1, 2),) * 3 and c.center == (0.5, 0.5, 0.5)
    assert c.radius_exact == Fraction(1, 2) and c.radius == 0.5
    # exact rows: the cube [0, 1/3]^3
    third = [[-1, 0, 0, 0], [1, 0, 0, Fraction(1, 3)], [0, -1, 0, 0], [0, 1, 0, "1/3"], [0, 0, -1, 0],
             [0, 0, 1, Fraction(1, 3)]]
    c = cmx.chebyshev_centre(third, lp="exact")
    assert c.centre_exact == (Fraction(1, 6),) * 3 and c.radius_exact == Fraction(1, 6)
    assert cmx.chebyshev_center([[1, 0, 0, -1], [-1, 0, 0, -1]] + rows[2:]).status == "infeasible"
    assert cmx.chebyshev_center(rows[:5]).radius == 0.5  # open in +z: the ball still fits in x and y
    assert cmx.chebyshev_center(rows[:1]).status == "unbounded"


def test_is_ball_and_boundary():
    V, T = grid_ball(3)
    b = cmx.is_ball(T)
    assert b.ok and b and b.message == ""
    faces = cmx.boundary_faces(T)
    assert faces.shape == (6 * 9 * 2, 3)
    assert sorted(set(faces.ravel().tolist())) == cmx.boundary_vertices(T).tolist()
    assert len(cmx.boundary_vertices(T)) == 4**3 - 2**3
    two = np.vstack([T, T + len(V)])
    b = cmx.is_ball(two)
    assert not b and b.message
    bad = cmx.is_ball(np.array([[0, 1, 2, 7]]), 4)
    assert not bad.ok and "7" in bad.message
    assert not cmx.is_ball([[0, 1, 2, -1]]).ok


def test_topological_expansion():
    V, T = grid_ball(3)
    x = cmx.expand_topologically(T)
    interior = sorted(set(range(len(V))) - set(cmx.boundary_vertices(T).tolist()))
    assert x["complete"] and sorted(x["sequence"].tolist()) == interior
    assert x["initially_simply_connected"]
    assert cmx.is_expandable(T, interior, interior[0]) in (True, False)
    with pytest.raises(cmx.Error):
        cmx.expand_topologically(T, order="sideways")


def _split(T, simplex, m):
    """The tets after splitting an edge or face `simplex` at new vertex m: each tet containing it
    becomes one tet per vertex of the simplex, that vertex replaced by m (orientation kept)."""
    out = []
    for t in T:
        if all(v in t for v in simplex):
            for v in simplex:
                out.append([m if w == v else w for w in t])
        else:
            out.append(list(t))
    return out


def test_replay_shelling_replays_alg2_checked_independently():
    V, T = grid_ball(3)
    r = cmx.replay_shelling(T, check_every=1)
    assert r["shelling_found"] and r["completed"], r["message"]
    assert r["checks"] == r["expansions"] + 1 and r["check_failures"] == 0
    interior = set(range(len(V))) - set(cmx.boundary_vertices(T).tolist())
    assert r["input_expansions"] == len(interior)
    assert r["chord_expansions"] == len(r["chord_vertex"])
    assert r["expansions"] == int(r["step_expanded"].sum())
    assert r["expansions"] == r["input_expansions"] + r["chord_expansions"] + r["cluster_splits"]
    assert r["eq1_failures"] == 0 and r["left"] == 0
    # Replay the steps here, with the API's own Eq. (1) test and ball check: the cluster is the
    # interior at first; a split vertex joins it when its simplex is interior and has a cluster
    # vertex (a boundary split makes a boundary vertex, an all-expanded one a free split).
    tets = [list(map(int, t)) for t in T]
    n = len(V)
    cluster = set(interior)
    for split, v in zip(r["chord_split"].tolist(), r["chord_vertex"].tolist()):
        simplex = [s for s in split if s >= 0]
        assert v == n and all(s not in cluster for s in simplex)  # a chord: all its vertices on the boundary
        tets = _split(tets, simplex, v)
        n += 1
        cluster.add(v)
    for i, (kind, split, v, expanded) in enumerate(zip(r["step_kind"].tolist(), r["step_split"].tolist(),
                                                        r["step_vertex"].tolist(), r["step_expanded"].tolist())):
        if kind != 0:
            simplex = [s for s in split if s >= 0]
            assert len(simplex) == kind + 1 and v == n
            faces = [set(f) for f in cmx.boundary_faces(tets, n).tolist()]
            on_boundary = any(set(simplex) <= f for f in faces)
            tets = _split(tets, simplex, v)
            n += 1
            if not on_boundary and any(s in cluster for s in simplex):
                cluster.add(v)
        assert expanded == (v in cluster), i
        if not expanded:
            continue
        if len(cluster) > 1:  # the last one goes automatically
            assert cmx.is_expandable(tets, sorted(cluster), v, vertex_count=n), i
        cluster.remove(v)
    assert not cluster
    assert cmx.is_ball(tets, n)
    assert n == len(V) + len(r["chord_vertex"]) + r["boundary_splits"] + r["cluster_splits"] + r["free_splits"]


def test_replay_shelling_errors():
    V, T = grid_ball(2)
    for bad in (0, -1, 1.5, True):
        with pytest.raises(cmx.InvalidOptions):
            cmx.replay_shelling(T, attempts=bad)
    with pytest.raises(cmx.InvalidOptions):
        cmx.replay_shelling(T, seed=-3)
    with pytest.raises(cmx.InvalidOptions):
        cmx.replay_shelling(T, check_every=-1)
    with pytest.raises(cmx.Error, match="not a ball"):
        cmx.replay_shelling(np.vstack([T, T[:1]]))  # a repeated tet
