"""cmx: mesh files (re-exported by the package cmx)."""
from __future__ import annotations

from typing import Any

import numpy as np

from . import _cmx
from ._cmx import InvalidInput
from ._convert import _points, _tets, _fractions
from ._map import Result


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
