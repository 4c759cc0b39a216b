"""Shared helpers of the pytest suites of the Python module cmx (tests/python).

The ctest entries run each file through run_pytest.py with PYTHONPATH at the built module
(<build>/python); run by hand: PYTHONPATH=build/release/python python3 -m pytest tests/python
"""
import itertools
from fractions import Fraction

import numpy as np
import pytest


def grid_ball(k=3, jitter=0.0, seed=1):
    """A cube [0, 1]^3 of k^3 cells, each split into 6 tets (Kuhn), positively oriented; interior
    vertices moved by up to jitter * cell size (a mesh with (k-1)^3 interior vertices)."""
    idx = lambda a, b, c: (a * (k + 1) + b) * (k + 1) + c
    V = np.array([[a, b, c] for a in range(k + 1) for b in range(k + 1) for c in range(k + 1)], dtype=np.float64) / k
    T = []
    for a, b, c in itertools.product(range(k), repeat=3):
        for perm in itertools.permutations(range(3)):
            p = [a, b, c]
            tet = [idx(*p)]
            for axis in perm:
                p[axis] += 1
                tet.append(idx(*p))
            T.append(tet)
    T = np.array(T, dtype=np.int64)
    if jitter:
        rng = np.random.default_rng(seed)
        interior = np.all((V > 0) & (V < 1), axis=1)
        V[interior] += rng.uniform(-jitter / k, jitter / k, size=(interior.sum(), 3))
    d = np.einsum("ij,ij->i", np.cross(V[T[:, 1]] - V[T[:, 0]], V[T[:, 2]] - V[T[:, 0]]), V[T[:, 3]] - V[T[:, 0]])
    T[d < 0] = T[d < 0][:, [0, 1, 3, 2]]
    return V, T


def orient3d_fraction(a, b, c, d):
    """det[b-a, c-a, d-a] in exact Fraction arithmetic."""
    u = [b[i] - a[i] for i in range(3)]
    v = [c[i] - a[i] for i in range(3)]
    w = [d[i] - a[i] for i in range(3)]
    return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
            + u[2] * (v[0] * w[1] - v[1] * w[0]))


def exactly_positive(points, tets):
    """The indices of the tets that are not positive (orient3d <= 0) in exact arithmetic."""
    P = [tuple(Fraction(x) for x in p) for p in points]
    return [i for i, t in enumerate(tets) if orient3d_fraction(*(P[int(v)] for v in t)) <= 0]


@pytest.fixture
def ball():
    return grid_ball(3, jitter=0.15)
