"""cmx: cmx.map and its Result (re-exported by the package cmx)."""
from __future__ import annotations

import json
from fractions import Fraction
from functools import cached_property
from typing import Any, Callable, Dict, Optional, Tuple

import numpy as np

from . import _cmx
from ._cmx import Cancelled, Error, InvalidInput, InvalidOptions, PrecisionLost, Progress, Stuck, TimeLimit
from ._convert import _points, _as_text, _tets, _vertex_count, _fractions


_STATUS_ERRORS = {
    "invalid_input": InvalidInput,
    "invalid_options": InvalidOptions,
    "time_limit": TimeLimit,
    "cancelled": Cancelled,
    "stuck": Stuck,
    "precision_lost": PrecisionLost,
}



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
        corners: str = "random", init: Any = "auto", time_limit: float = 0, threads: int = 0,
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
    corners   with shape: "random" (default) or "farthest", where the generated tetrahedron's
              corners go (`cmx map --corners`: "farthest" gives boundaries to thin fingers and
              knotted tunnels where drawn corners find none).
    init      "auto" (default), "shrink", "tutte", or an (n, 3) array / exact rows: the initial
              target ("given"; init="given" with initial_target=... is the same).
    time_limit  seconds (0: none); a run over it returns status "time_limit".
    threads   stars mapped at once (0: all cores); the output does not depend on it.
    progress  called with a cmx.Progress about five times a second, on this thread, with the GIL;
              return True from it to cancel the run (status "cancelled"); an exception it raises
              stops the run and propagates.
    Other options (the fields of cmx::MapOptions, values as `cmx map` takes them): collapse (bool),
    check (bool), snap ("repair", "chebyshev", "nearest"), order ("priority", "index",
    "random:SEED", "strict-index", each optionally followed by ",defer:A-B": input ids A to B-1
    last; needs init="shrink" or combinatorial=True), filter ("cascade", "interval", "exact",
    "mpfr:BITS"), lp ("certified", "exact"), norm ("l2-upper", "l1"), precision, arith
    ("rational", "double", "mpfr:BITS"), subclusters (int), smooth (int), shelled ("when-stuck",
    "after-pushes", "first": when the fallback star-shapifies by shelling the cone base),
    replay_shelling ("after-nobuenoss", the default: when greedy expansion ends in a NOBUENOSS
    and a shelling is found, the run again replaying it; "off"; "until-greedy", "full": replay a
    shelling of the input from the start, paper Alg. 2), combinatorial (bool: V's values are
    ignored, T need only be oriented alike, the result realises a subdivision of the complex and
    its source is the target; give boundary positions). An unknown keyword raises TypeError.

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
    if corners != "random" and shape is None:
        raise InvalidOptions("cmx.map: corners chooses the corners of a generated shape: it needs shape")
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
        ids, positions = _shape_boundary(shape, corners, exact, vertices, tets)
        p_exact = False

    opts = _run_options(options, init, time_limit, threads, n)

    if exact or p_exact:
        raw = _cmx.map_exact(_as_text(exact, vertices), tets, ids, _as_text(p_exact, positions), opts, progress)
    else:
        raw = _cmx.map_doubles(vertices, tets, ids, positions, opts, progress)
    result = Result(raw)
    if result.status in ("invalid_input", "invalid_options"):
        raise _error(result)
    return result


def _shape_boundary(shape: Any, corners: Any, exact: bool, vertices: Any, tets: np.ndarray) -> Tuple[Any, Any]:
    """The boundary ids and positions of a generated shape (cmx map --shape) for the mesh."""
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
        return _cmx.boundary_for_shape(doubles, tets, shape, corners)
    except Error as e:
        message = str(e)
        cls = InvalidOptions if message.startswith(("unknown shape", "unknown corner choice")) else InvalidInput
        raise cls(message) from None


def _run_options(options: Dict[str, Any], init: Any, time_limit: float, threads: int, n: int) -> Dict[str, Any]:
    """The option dictionary the extension takes: keywords, the run controls and the initial map."""
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
    return opts


def boundary_vertices(T: Any, vertex_count: Optional[int] = None) -> np.ndarray:
    """The boundary vertices of the tet mesh T (vertices of faces in exactly one tet), ascending,
    as a uint32 array. vertex_count defaults to max(T) + 1. Raises InvalidInput for a bad index."""
    t = _tets(T, vertex_count)
    return _cmx.boundary_vertices(t, _vertex_count(t, vertex_count))


def boundary_for_shape(V: Any, T: Any, shape: str, corners: str = "random"):
    """(ids, positions): the boundary vertices of (V, T) and their positions on a generated
    star-shaped domain (`cmx map --shape`), the tetrahedron's corners "random" or "farthest"
    (`cmx map --corners`). Raises cmx.Error when the shape or the corner choice does not parse
    or no valid boundary could be generated for this mesh."""
    exact, v = _points(V, "V")
    if exact:
        v = np.array([[float(Fraction(x)) for x in row] for row in v], dtype=np.float64).reshape(-1, 3)
    return _cmx.boundary_for_shape(v, _tets(T, len(v)), shape, corners)
