"""cmx: ball check and Eq. (1) (re-exported by the package cmx)."""
from __future__ import annotations

from typing import Any, NamedTuple, Optional

import numpy as np

from . import _cmx
from ._convert import _tets, _vertex_count


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


def replay_shelling(T: Any, seed: int = 1, attempts: int = 8, vertex_count: Optional[int] = None,
                    check_every: int = 0) -> dict:
    """The shelling fallback of paper Sec. 4.3, topology only (what `cmx topo-expand` runs when
    stuck): split every chord (interior edge or face whose vertices all lie on the boundary), look
    for a shelling of the ball (at most `attempts` greedy attempts), convert it by Alg. 2 and
    replay it from the start with the boundary in place, checking Eq. (1) at every expansion. A
    dict with shelling_found, attempts, best_removed, completed, expansions, input_expansions, chord_expansions,
    eq1_failures, left, boundary_splits, cluster_splits, free_splits, empty_cone_edge_splits,
    message; the chord splits as arrays chord_kind (1 edge, 2 face), chord_split ((c, 3), -1
    where unused) and chord_vertex (new interior vertices numbered from vertex_count on); and the
    sequence as arrays step_kind (0 vertex, 1 edge split, 2 face split), step_split, step_vertex
    (split vertices numbered after the chords') and step_expanded (False: already expanded,
    skipped). check_every = k > 0 also checks the cluster mesh simply connected before the first
    expansion, after every k-th and at the end (keys checks, check_failures; O(T) each)."""
    for name, value, least in (("attempts", attempts, 1), ("seed", seed, 0), ("check_every", check_every, 0)):
        if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < least \
                or value >= 2**64:
            raise _cmx.InvalidOptions(f"option {name}: expected an integer >= {least}, got {value!r}")
    t = _tets(T, vertex_count)
    return _cmx.replay_shelling(t, _vertex_count(t, vertex_count), int(seed), int(attempts), int(check_every))
