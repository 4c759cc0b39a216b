"""cmx: exact predicates and Chebyshev centres (re-exported by the package cmx)."""
from __future__ import annotations

import numbers
from fractions import Fraction
from typing import Any, NamedTuple

import numpy as np

from . import _cmx
from ._cmx import InvalidInput, InvalidOptions
from ._convert import _exact_text, _is_exact_array, _has_exact


# ----------------------------------------------------------------------------- kernel, lp

def _point_args(points, dim: int):
    """(exact, points): doubles when every coordinate is a double (or an int a double holds)."""
    rows = []
    exact = False
    for i, p in enumerate(points):
        p = list(p.tolist() if isinstance(p, np.ndarray) else p)
        if len(p) != dim:
            raise InvalidInput(f"point {i}: expected {dim} coordinates, got {len(p)}")
        for x in p:
            if isinstance(x, (bool, np.bool_)):
                raise InvalidInput(f"point {i}: {x!r} is not a number")
            if not isinstance(x, (float, np.floating)) and not (
                    isinstance(x, (int, np.integer)) and abs(int(x)) <= 2**53):
                exact = True
        rows.append(p)
    if exact:
        return True, [tuple(_exact_text(x, f"point {i}") for x in p) for i, p in enumerate(rows)]
    return False, [tuple(float(x) for x in p) for p in rows]


def orient3d(a, b, c, d, arithmetic: str = "cascade") -> int:
    """The exact sign (+1, 0, -1) of det[b-a, c-a, d-a]: +1 for the right-handed unit tet
    (0,0,0), (1,0,0), (0,1,0), (0,0,1). This is the OPPOSITE of Shewchuk's orient3d.
    Points: 3 doubles each, or exact values (Fraction, big int, text "p/q") in any coordinate.
    arithmetic: "cascade" (default), "interval" or "exact" (same sign, different speed).
    Raises cmx.Error for a NaN or infinite coordinate."""
    exact, p = _point_args((a, b, c, d), 3)
    f = _cmx.orient3d_exact if exact else _cmx.orient3d_doubles
    return f(*p, arithmetic)


def orient2d(a, b, c, arithmetic: str = "cascade") -> int:
    """The exact sign of det[b-a, c-a] (+1: counterclockwise) for points of 2 doubles."""
    exact, p = _point_args((a, b, c), 2)
    if exact:
        raise InvalidInput("orient2d: points must be doubles (exact 2D input is not in the C++ API)")
    return _cmx.orient2d_doubles(*p, arithmetic)


class ChebyshevCenter(NamedTuple):
    """The Chebyshev centre: status "interior" (radius > 0), "empty_interior", "infeasible" or
    "unbounded"; centre (3 doubles) and centre_exact (3 Fractions); radius and radius_exact."""
    status: str
    centre: tuple
    centre_exact: tuple
    radius: float
    radius_exact: Fraction

    @property
    def ok(self) -> bool:
        return self.status == "interior"

    @property
    def center(self) -> tuple:
        return self.centre


def chebyshev_center(halfspaces: Any, lp: str = "certified", norm: str = "l2-upper",
                     weight_bits: int = 53) -> ChebyshevCenter:
    """The centre of the largest ball inside {p : a x + b y + c z <= d for each row (a, b, c, d)},
    solved exactly. halfspaces: a (k, 4) array of doubles, or rows of exact values. lp:
    "certified" or "exact"; norm: "l2-upper" (Euclidean ball) or "l1" (axis-parallel cube).
    Raises cmx.Error for NaN / infinite values or an option that does not parse; an empty, flat or
    unbounded set is a status."""
    a = halfspaces if isinstance(halfspaces, np.ndarray) else np.asarray(
        halfspaces, dtype=object if _has_exact(halfspaces) else None)
    if a.ndim != 2 or a.shape[1] != 4:
        raise InvalidInput(f"halfspaces: expected shape (k, 4), got {a.shape}")
    if isinstance(weight_bits, bool) or not isinstance(weight_bits, numbers.Integral) or weight_bits < 0:
        raise InvalidOptions(f"weight_bits: expected a non-negative integer, got {weight_bits!r}")
    if _is_exact_array(a):
        rows = [tuple(_exact_text(x, f"halfspace {i}") for x in row) for i, row in enumerate(a.tolist())]
        d = _cmx.chebyshev_centre_exact(rows, lp, norm, int(weight_bits))
    else:
        d = _cmx.chebyshev_centre_doubles(np.ascontiguousarray(a, dtype=np.float64), lp, norm, int(weight_bits))
    return ChebyshevCenter(d["status"], tuple(d["centre"]), tuple(Fraction(x) for x in d["centre_exact"]),
                           d["radius"], Fraction(d["radius_exact"]))


chebyshev_centre = chebyshev_center
