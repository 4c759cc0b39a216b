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

from . import _cmx
from ._cmx import (Cancelled, Error, InvalidInput, InvalidOptions, PrecisionLost, Progress, Stuck,
                   TimeLimit)
from ._map import Result, map, boundary_vertices, boundary_for_shape
from ._kernel_lp import orient3d, orient2d, ChebyshevCenter, chebyshev_center, chebyshev_centre
from ._topology import BallCheck, is_ball, boundary_faces, is_expandable, expand_topologically, replay_shelling
from ._io import Mesh, read, write

__version__ = _cmx.__version__

__all__ = [
    "map", "Result", "Progress", "boundary_vertices", "boundary_for_shape", "orient3d", "orient2d",
    "chebyshev_center", "chebyshev_centre", "ChebyshevCenter", "is_ball", "BallCheck", "boundary_faces",
    "is_expandable", "expand_topologically", "replay_shelling", "read", "write", "Mesh", "Error", "InvalidInput",
    "InvalidOptions", "TimeLimit", "Cancelled", "Stuck", "PrecisionLost", "__version__",
]
