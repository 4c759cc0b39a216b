"""cmx: exact bijective maps of tetrahedral meshes onto star-shaped domains.

    import numpy as np, cmx
    V, T = ...                              # (n, 3) float64 and (m, 4) int arrays: a ball
    r = cmx.map(V, T, shape="sphere")       # or boundary={id: (x, y, z)} or codomain=W
    print(r.status, r.exact_valid, r.double_valid)
    r.target_double                         # (N, 3) float64; r.target_exact: Fraction triples
    r.tets                                  # (M, 4) uint32: the refined mesh (input vertices first)

Exact input: give V (and boundary positions) as lists or object arrays of fractions.Fraction
(or int, or text "p/q"); they are passed to cmx exactly. Positive orientation: det[b-a, c-a, d-a]
> 0 for a tet (a, b, c, d) (cmx.orient3d).

Errors: every exception cmx raises for bad input derives from cmx.Error. cmx.map raises
InvalidInput or InvalidOptions (both also ValueError) for those outcomes and returns a Result for
every other one (Result.ok is False unless status is "success"); Result.raise_for_status()
raises TimeLimit, Cancelled, Stuck or PrecisionLost for those. Ctrl-C during a run stops it at
the next step and raises KeyboardInterrupt.
"""
from __future__ import annotations

import decimal
import json
import math
import numbers
from fractions import Fraction
from functools import cached_property
from typing import Any, Callable, NamedTuple, Optional

import numpy as np

from . import _cmx
from ._cmx import (Cancelled, Error, InvalidInput, InvalidOptions, PrecisionLost, Progress, Stuck,
                   TimeLimit)

__version__ = _cmx.__version__

__all__ = [
    "map", "Result", "Progress", "boundary_vertices", "boundary_for_shape", "orient3d", "orient2d",
    "chebyshev_center", "chebyshev_centre", "ChebyshevCenter", "is_ball", "BallCheck", "boundary_faces",
    "is_expandable", "expand_topologically", "read", "write", "Mesh", "Error", "InvalidInput",
    "InvalidOptions", "TimeLimit", "Cancelled", "Stuck", "PrecisionLost", "__version__",
]

_STATUS_ERRORS = {
    "invalid_input": InvalidInput,
    "invalid_options": InvalidOptions,
    "time_limit": TimeLimit,
    "cancelled": Cancelled,
    "stuck": Stuck,
    "precision_lost": PrecisionLost,
}


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


# ----------------------------------------------------------------------------- map

class Result:
    """The outcome of cmx.map.

    status      "success", "time_limit", "cancelled", "stuck" or "precision_lost" (invalid input and
                options raise instead); ok is status == "success".
    message     why, when not ok ("" on success); reason: a stable name of the case.
    tets        (M, 4) uint32: the output mesh, positively oriented in source and target. The input's
                vertices come first, in input order, then the vertices cmx added.
    source      (N, 3) float64 source positions (added vertices lie inside input tets);
                source_exact: Fraction triples.
    target_exact   the exact map, a list of N Fraction triples (target_exact_text: "p/q" strings;
                target_homogeneous: integer text x, y, z, w with w > 0).
    target_double  (N, 3) float64 doubles of the target (option snap), checked exactly.
    exact_valid, double_valid   the independent exact checks of the exact target and of the doubles
                (every tet positive, boundary kept, a refinement of the input);
                double_inverted, double_flat count the tets of target_double that are not positive.
    report      statistics and timings (dict; the `cmx map --report` fields).
    Arrays are empty (0 rows) when the run did not succeed.
    """

    def __init__(self, raw: _cmx.MapResult):
        self._raw = raw

    status = property(lambda self: self._raw.status)
    message = property(lambda self: self._raw.message)
    reason = property(lambda self: self._raw.reason)
    ok = property(lambda self: self._raw.ok)
    exact_valid = property(lambda self: self._raw.exact_valid)
    double_valid = property(lambda self: self._raw.double_valid)
    double_inverted = property(lambda self: self._raw.double_inverted)
    double_flat = property(lambda self: self._raw.double_flat)
    input_vertices = property(lambda self: self._raw.input_vertices)
    report_json = property(lambda self: self._raw.report_json)
    # Converted on first use, then kept (the arrays are copies of the C++ result).
    tets = cached_property(lambda self: self._raw.tets)
    source = cached_property(lambda self: self._raw.source)
    target_double = cached_property(lambda self: self._raw.target)
    target_exact_text = cached_property(lambda self: self._raw.target_exact)
    target_exact = cached_property(lambda self: _fractions(self.target_exact_text))
    source_exact_text = cached_property(lambda self: self._raw.source_exact)
    source_exact = cached_property(lambda self: _fractions(self.source_exact_text))
    target_homogeneous = cached_property(
        lambda self: [tuple(int(x) for x in row) for row in self._raw.target_homogeneous])
    report = cached_property(lambda self: json.loads(self.report_json) if self.report_json else {})

    @property
    def target(self) -> np.ndarray:
        """The same as target_double."""
        return self.target_double

    def raise_for_status(self) -> "Result":
        """Raises the cmx.Error subclass of the status (with the message) unless ok; returns self."""
        if not self.ok:
            raise _error(self)
        return self

    def __bool__(self) -> bool:
        return self.ok

    def __repr__(self) -> str:
        if self.ok:
            return (f"<cmx.Result success: {len(self.source)} vertices, {len(self.tets)} tets, "
                    f"exact_valid={self.exact_valid}, double_valid={self.double_valid}>")
        return f"<cmx.Result {self.status}: {self.message}>"


def _error(r: Result) -> Error:
    e = _STATUS_ERRORS.get(r.status, Error)(r.message or r.status)
    e.status, e.reason, e.result = r.status, r.reason, r
    return e


def _boundary_arg(boundary: Any, n: int):
    """(ids as uint32 array, positions) from a dict {id: (x, y, z)} or a pair (ids, positions)."""
    if isinstance(boundary, dict):
        ids, positions = list(boundary.keys()), list(boundary.values())
    else:
        try:
            ids, positions = boundary
        except (TypeError, ValueError):
            raise InvalidInput("boundary: expected a dict {vertex id: (x, y, z)} or a pair (ids, positions)") from None
    ids = np.asarray(ids)
    if ids.ndim != 1 or (ids.size and ids.dtype.kind not in "iu"):
        raise InvalidInput("boundary: vertex ids must be a 1-dimensional sequence of integers")
    if ids.size:
        bad = np.flatnonzero((ids < 0) | (ids >= n))
        if bad.size:
            raise InvalidInput(f"boundary: vertex {int(ids[bad[0]])} out of range ({n} vertices)")
    return np.ascontiguousarray(ids, dtype=np.uint32), positions


def map(V: Any, T: Any, boundary: Any = None, codomain: Any = None, shape: Optional[str] = None, *,
        init: Any = "auto", time_limit: float = 0, threads: int = 0,
        progress: Optional[Callable[[Progress], Any]] = None, **options: Any) -> Result:
    """Maps the ball mesh (V, T) bijectively onto a star-shaped domain, exactly.

    V         (n, 3) float64 array (taken exactly as the doubles it holds), or a list / object array
              of exact values (fractions.Fraction, int, or text "p/q" / "0.1"): exact input.
    T         (m, 4) integer array of vertex indices, every tet positively oriented, no unused vertex.
    Exactly one of:
      boundary  {vertex id: (x, y, z)} or a pair (ids, positions): the position of every boundary
                vertex (cmx.boundary_vertices(T) lists them), doubles or exact values;
      codomain  an (n, 3) array of the same vertices (same connectivity) whose boundary vertices
                give the positions (its interior vertices are ignored);
      shape     a generated star-shaped domain: "sphere", "tet", "stiff-tet", "star" or "star:SEED"
                (the shapes of `cmx map --shape`).
    init      "auto" (default), "shrink", "tutte", or an (n, 3) array / exact rows: the initial
              target ("given"; init="given" with initial_target=... is the same).
    time_limit  seconds (0: none); a run over it returns status "time_limit".
    threads   stars mapped at once (0: all cores); the output does not depend on it.
    progress  called with a cmx.Progress about five times a second, on this thread, with the GIL;
              return True from it to cancel the run (status "cancelled"); an exception it raises
              stops the run and propagates.
    Other options (the fields of cmx::MapOptions, values as `cmx map` takes them): collapse (bool),
    check (bool), snap ("repair", "chebyshev", "nearest"), order ("priority", "index",
    "random:SEED"), filter ("cascade", "interval", "exact", "mpfr:BITS"), lp ("certified", "exact"),
    norm ("l2-upper", "l1"), precision, arith ("rational", "double", "mpfr:BITS"), subclusters (int),
    smooth (int). An unknown keyword raises TypeError.

    Returns a cmx.Result. Raises cmx.InvalidInput (bad mesh, index, NaN, boundary, not a ball, not
    star-shaped, ...; .reason names the check) or cmx.InvalidOptions (a value that does not parse),
    both with cmx's message; ValueError subclasses both. Every other outcome is a Result (see
    Result.raise_for_status). The GIL is released during the computation; Ctrl-C (any signal
    handler that raises) stops the run at its next step and the exception propagates.
    """
    given = [name for name, value in (("boundary", boundary), ("codomain", codomain), ("shape", shape))
             if value is not None]
    if len(given) != 1:
        raise InvalidOptions("cmx.map: give exactly one of boundary, codomain or shape"
                             + (f" (got {', '.join(given)})" if given else ""))
    exact, vertices = _points(V, "V")
    n = len(vertices)
    tets = _tets(T, n)

    if boundary is not None:
        ids, positions = _boundary_arg(boundary, n)
        p_exact, positions = _points(positions, "boundary positions", rows=len(ids))
    elif codomain is not None:
        p_exact, W = _points(codomain, "codomain", rows=n)
        ids = _cmx.boundary_vertices(tets, n)
        positions = [W[i] for i in ids] if p_exact else W[ids]
    else:
        if not isinstance(shape, str):
            raise InvalidOptions(f"shape: expected a name such as 'sphere', got {shape!r}")
        if exact:
            doubles = np.array([[float(Fraction(x)) for x in row] for row in vertices], dtype=np.float64).reshape(-1, 3)
        else:
            doubles = vertices
        bad = np.argwhere(~np.isfinite(doubles))
        if bad.size:
            i, k = bad[0]
            raise InvalidInput(f"vertex {i}: coordinate {'xyz'[k]} is {'NaN' if np.isnan(doubles[i, k]) else 'infinite'}")
        try:
            ids, positions = _cmx.boundary_for_shape(doubles, tets, shape)
        except Error as e:
            message = str(e)
            cls = InvalidOptions if message.startswith("unknown shape") else InvalidInput
            raise cls(message) from None
        p_exact = False

    opts = dict(options)
    opts["time_limit"] = time_limit
    opts["threads"] = threads
    if isinstance(init, str):
        opts["init"] = init
    else:
        opts["init"] = "given"
        opts["initial_target"] = init
    if "initial_target" in opts:
        t_exact, t = _points(opts.pop("initial_target"), "initial_target", rows=n)
        if t_exact:
            opts["initial_target"] = t
        else:
            opts["initial_target_doubles"] = t

    if exact or p_exact:
        raw = _cmx.map_exact(_as_text(exact, vertices), tets, ids, _as_text(p_exact, positions), opts, progress)
    else:
        raw = _cmx.map_doubles(vertices, tets, ids, positions, opts, progress)
    result = Result(raw)
    if result.status in ("invalid_input", "invalid_options"):
        raise _error(result)
    return result


def boundary_vertices(T: Any, vertex_count: Optional[int] = None) -> np.ndarray:
    """The boundary vertices of the tet mesh T (vertices of faces in exactly one tet), ascending,
    as a uint32 array. vertex_count defaults to max(T) + 1. Raises InvalidInput for a bad index."""
    t = _tets(T, vertex_count)
    return _cmx.boundary_vertices(t, _vertex_count(t, vertex_count))


def boundary_for_shape(V: Any, T: Any, shape: str):
    """(ids, positions): the boundary vertices of (V, T) and their positions on a generated
    star-shaped domain (`cmx map --shape`). Raises cmx.Error when the shape does not parse or no
    valid boundary could be generated for this mesh."""
    exact, v = _points(V, "V")
    if exact:
        v = np.array([[float(Fraction(x)) for x in row] for row in v], dtype=np.float64).reshape(-1, 3)
    return _cmx.boundary_for_shape(v, _tets(T, len(v)), shape)


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


# ----------------------------------------------------------------------------- topology

class BallCheck(NamedTuple):
    """ok, and what is wrong and where when not ok; truthy when ok."""
    ok: bool
    message: str

    def __bool__(self) -> bool:
        return self.ok


def is_ball(T: Any, vertex_count: Optional[int] = None) -> BallCheck:
    """Whether the tets form a combinatorial 3-ball (consistently oriented, manifold, boundary one
    sphere, every vertex used); coordinates are not looked at. vertex_count defaults to max(T)+1."""
    a = np.asarray(T)
    if a.size and a.dtype.kind in "iu" and a.ndim == 2 and (a < 0).any():
        i, k = np.argwhere(a < 0)[0]
        return BallCheck(False, f"tet {i} names vertex {int(a[i, k])}, out of range")
    t = _tets(T, None)
    ok, message = _cmx.is_ball(t, _vertex_count(t, vertex_count))
    return BallCheck(ok, message)


def boundary_faces(T: Any, vertex_count: Optional[int] = None) -> np.ndarray:
    """The boundary faces as a (k, 3) uint32 array, oriented outwards for positive tets."""
    t = _tets(T, vertex_count)
    return _cmx.boundary_faces(t, _vertex_count(t, vertex_count))


def is_expandable(T: Any, cluster_vertices: Any, vertex: int, vertex_count: Optional[int] = None) -> bool:
    """Eq. (1): whether `vertex` of the cluster mesh on cluster_vertices is topologically expandable."""
    t = _tets(T, vertex_count)
    return _cmx.is_expandable(t, _vertex_count(t, vertex_count),
                              np.ascontiguousarray(cluster_vertices, dtype=np.uint32), int(vertex))


def expand_topologically(T: Any, cluster_vertices: Any = (), order: str = "priority",
                         vertex_count: Optional[int] = None) -> dict:
    """Greedy topological expansion (paper Sec. 5.1) of the cluster mesh on cluster_vertices (empty:
    the interior vertices): a dict with complete, sequence, remaining, initially_simply_connected."""
    t = _tets(T, vertex_count)
    return _cmx.expand_topologically(t, _vertex_count(t, vertex_count),
                                     np.ascontiguousarray(np.asarray(cluster_vertices, dtype=np.int64),
                                                          dtype=np.uint32), order)


# ----------------------------------------------------------------------------- io

class Mesh:
    """A tet mesh as cmx.read returns it: points (n, 3) float64, points_exact (Fraction triples;
    points_exact_text as "p/q" text), tets (m, 4) uint32; for a .tmap also target (n, 3) and
    target_exact (else None)."""

    def __init__(self, points=None, tets=None, points_exact=None, target=None, target_exact=None):
        self.points = points
        self.tets = tets
        self.points_exact_text = points_exact
        self.target = target
        self.target_exact_text = target_exact

    @property
    def points_exact(self):
        return None if self.points_exact_text is None else _fractions(self.points_exact_text)

    @property
    def target_exact(self):
        return None if self.target_exact_text is None else _fractions(self.target_exact_text)

    def __repr__(self) -> str:
        kind = "map" if self.target_exact_text else "mesh"
        return f"<cmx.Mesh ({kind}): {len(self.points)} vertices, {len(self.tets)} tets>"


def read(path) -> Mesh:
    """Reads a tet mesh; the format from the extension (.ovm .vtu .vtk .mesh .msh .node/.ele .tmap).
    Coordinates are read exactly; tets come back positively oriented. Raises cmx.Error naming the
    file (and line) for a file that cannot be read or is malformed."""
    d = _cmx.read(str(path))
    target = d["target_exact"] or None
    return Mesh(d["points"], d["tets"], d["points_exact"], d["target"] if target else None, target)


def write(path, mesh: Any = None, *, points=None, tets=None, target=None) -> None:
    """Writes a tet mesh; the format from the extension (as read; a .tmap needs a target).

    mesh: a cmx.Mesh, a cmx.Result (its source, tets and exact target), or a meshio.Mesh (its
    points and "tetra" cells); or give points (doubles or exact values), tets and, for a .tmap,
    target as keywords. Exact positions are written exactly where the format holds them (.ovm,
    .tmap). The write is atomic. Raises cmx.Error naming the file."""
    pe, te = [], []
    if mesh is not None:
        if points is not None or tets is not None or target is not None:
            raise TypeError("cmx.write: give a mesh or points/tets/target, not both")
        if isinstance(mesh, Result):
            if not mesh.ok:
                raise InvalidInput(f"cmx.write: the result is not a map ({mesh.status})")
            points, pe, tets = mesh.source, mesh.source_exact_text, mesh.tets
            target, te = mesh.target_double, mesh.target_exact_text
        elif isinstance(mesh, Mesh):
            points, pe, tets = mesh.points, mesh.points_exact_text or [], mesh.tets
            target, te = mesh.target, mesh.target_exact_text or []
        elif hasattr(mesh, "points") and hasattr(mesh, "cells_dict"):  # meshio.Mesh
            points, tets = mesh.points, mesh.cells_dict.get("tetra")
            if tets is None:
                raise InvalidInput("cmx.write: the meshio mesh has no tetra cells")
        else:
            raise TypeError(f"cmx.write: cannot write a {type(mesh).__name__}")
    if points is None or tets is None:
        raise TypeError("cmx.write: points and tets are required")
    if not len(pe):
        exact, p = _points(points, "points")
        if exact:
            pe, p = p, np.zeros((0, 3))
    else:
        p = np.ascontiguousarray(points, dtype=np.float64)
    t = _tets(tets, len(p) if len(p) else len(pe), "tets")
    tp = np.zeros((0, 3))
    if target is not None and not len(te):
        t_exact, tp = _points(target, "target")
        if t_exact:
            te, tp = tp, np.zeros((0, 3))
    elif target is not None:
        tp = np.ascontiguousarray(target, dtype=np.float64)
    _cmx.write(str(path), p, list(pe), t, tp, list(te))
