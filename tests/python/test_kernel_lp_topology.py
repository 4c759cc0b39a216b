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
