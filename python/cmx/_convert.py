"""cmx: conversions of array-like and exact input (re-exported by the package cmx)."""
from __future__ import annotations

import decimal
import math
import numbers
from fractions import Fraction
from typing import Any, Optional

import numpy as np

from ._cmx import InvalidInput


# ----------------------------------------------------------------------------- conversions

def _exact_text(x: Any, what: str) -> str:
    """One coordinate as the exact text cmx reads ("p/q", "p" or a decimal)."""
    if isinstance(x, str):
        return x.strip()
    if isinstance(x, (bool, np.bool_)):
        raise InvalidInput(f"{what}: {x!r} is not a number")
    if isinstance(x, (float, np.floating)):
        x = float(x)
        if not math.isfinite(x):
            return repr(x)  # cmx reports it, naming the vertex and the coordinate
        return str(Fraction(x))
    if isinstance(x, (numbers.Rational, np.integer, decimal.Decimal)):
        try:
            return str(Fraction(x))
        except (ValueError, OverflowError):  # Decimal NaN / infinity
            return str(x)
    raise InvalidInput(f"{what}: {x!r} is not a number (float, int, Fraction or text)")


def _is_exact_array(a: np.ndarray) -> bool:
    if a.dtype.kind in "OUS":
        return True
    if a.dtype.kind in "iu" and a.size and int(np.abs(a).max()) > 2**53:
        return True  # integers a double cannot hold
    return False


def _points(P: Any, what: str, rows: Optional[int] = None):
    """(exact, data): an (n, 3) float64 array, or a list of text triples when P holds exact values."""
    if isinstance(P, np.ndarray):
        a = P
    else:
        try:
            a = np.asarray(P, dtype=object if _has_exact(P) else None)
        except (ValueError, TypeError) as e:
            raise InvalidInput(f"{what}: not an (n, 3) array of coordinates ({e})") from None
    if a.ndim == 1 and a.size == 0:
        a = a.reshape(0, 3)
    if a.ndim != 2 or a.shape[1] != 3:
        raise InvalidInput(f"{what}: expected shape (n, 3), got {a.shape}")
    if rows is not None and a.shape[0] != rows:
        raise InvalidInput(f"{what}: {a.shape[0]} rows for {rows} vertices")
    if _is_exact_array(a):
        return True, [tuple(_exact_text(x, f"{what}[{i}]") for x in row) for i, row in enumerate(a.tolist())]
    if a.dtype.kind not in "fiub" or a.dtype.kind == "b":
        raise InvalidInput(f"{what}: coordinates of dtype {a.dtype} are not numbers")
    return False, np.ascontiguousarray(a, dtype=np.float64)


def _has_exact(P: Any) -> bool:
    """Whether a nested sequence holds an exact value (Fraction, Decimal, str, big int)."""
    try:
        for row in P:
            for x in row:
                if isinstance(x, (Fraction, decimal.Decimal, str)) or (
                        isinstance(x, int) and not isinstance(x, bool) and abs(x) > 2**53):
                    return True
    except TypeError:
        return False
    return False


def _as_text(exact: bool, data) -> list:
    if exact:
        return data
    return [tuple(str(Fraction(float(x))) if math.isfinite(x) else repr(float(x)) for x in row) for row in data]


def _tets(T: Any, vertex_count: Optional[int], what: str = "T") -> np.ndarray:
    """T as a C-contiguous (m, 4) uint32 array, every index checked against vertex_count."""
    a = np.asarray(T)
    if a.ndim == 1 and a.size == 0:
        a = a.reshape(0, 4)
    if a.ndim != 2 or a.shape[1] != 4:
        raise InvalidInput(f"{what}: expected shape (m, 4), got {a.shape}")
    if a.size and a.dtype.kind not in "iu":
        if a.dtype.kind == "O" and all(isinstance(x, numbers.Integral) for x in a.flat):
            a = a.astype(np.int64)
        else:
            raise InvalidInput(f"{what}: vertex indices must be integers, got dtype {a.dtype}")
    if a.size:
        bad = np.argwhere((a < 0) | (a >= (vertex_count if vertex_count is not None else 2**32)))
        if bad.size:
            i, k = bad[0]
            limit = f"{vertex_count} vertices" if vertex_count is not None else "indices below 2^32"
            raise InvalidInput(f"{what}: tet {i}: vertex {int(a[i, k])} out of range ({limit})")
    return np.ascontiguousarray(a, dtype=np.uint32)


def _vertex_count(T: np.ndarray, vertex_count: Optional[int]) -> int:
    if vertex_count is not None:
        return int(vertex_count)
    return int(T.max()) + 1 if T.size else 0


def _fractions(rows) -> list:
    return [tuple(Fraction(x) for x in row) for row in rows]
