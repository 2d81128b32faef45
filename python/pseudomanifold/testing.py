"""A pytest helper for other implementations of the PPM surface: compare yours with the
reference at seeded points, and fail with witnesses like ``ppm diff`` (SPEC PY-testing).

    from pseudomanifold.testing import assert_matches_reference

    def test_my_eval():
        assert_matches_reference(my_eval, "mesh.obj", quantity="position", n=2000, seed=1)

``fn(faces, bary)`` receives ``faces`` int64 (n,) and ``bary`` float64 (n, 3) (barycentric
coordinates in the face's corner order, >= 0, sum 1) and returns an array of n values:
(n, 3) for ``position``, ``normal`` and ``sprime``, (n,) for ``gaussian`` and ``mean``.
"""

from __future__ import annotations

import os
from typing import Any, Callable, Optional, Union

import numpy as np

from . import Pps, Surface, load

__all__ = ["assert_matches_reference", "sample_points", "default_tolerance"]

EPS = float(np.finfo(np.float64).eps)

# The reference's own f64 error, relative to the scale of its quantity, is at most a
# cancellation factor times eps: SPEC R-diff-f64-bound measured cancellation factors up to
# 2.2e6 on the corpus (bound 3.9e-8 of the diagonal at worst). A foreign f64 implementation
# that evaluates the same formulas in another order may differ by as much again, so the
# default tolerance is 2**23 eps (1.9e-9) of the quantity's scale: positions and S' in units of
# the bounding-box diagonal, normals (unit vectors) absolutely, curvatures relative to their
# value with 1/diagonal (resp. 1/diagonal^2) as the absolute floor, widened by 2**6 because a
# curvature is a second derivative (two more roundings of a difference quotient's size).
_FACTOR = 2.0**23

QUANTITIES = ("position", "normal", "gaussian", "mean", "sprime")


def default_tolerance(quantity: str, scale: float) -> tuple[float, float]:
    """(rtol, atol) derived from the f64 precision for ``quantity`` on a mesh whose bounding
    box diagonal is ``scale`` (see the comment above for the derivation)."""
    tol = _FACTOR * EPS
    if quantity in ("position", "sprime"):
        return 0.0, tol * scale
    if quantity == "normal":
        return 0.0, tol
    if quantity == "gaussian":
        return 64 * tol, 64 * tol / scale**2
    if quantity == "mean":
        return 64 * tol, 64 * tol / scale
    raise ValueError(f"quantity {quantity!r}: expected one of {QUANTITIES}")


def sample_points(num_faces: int, n: int, seed: int) -> tuple[np.ndarray, np.ndarray]:
    """n seeded (face, barycentric) points: faces uniform, barycentric coordinates uniform on
    the triangle; the first points of each seed include the three corners and an edge
    midpoint of face 0 (where eval switches charts, Sec. 6.1.4)."""
    rng = np.random.default_rng(seed)
    faces = rng.integers(0, num_faces, size=n, dtype=np.int64)
    u = rng.random((n, 2))
    lo, hi = np.minimum(u[:, 0], u[:, 1]), np.maximum(u[:, 0], u[:, 1])
    bary = np.stack([lo, hi - lo, 1.0 - hi], axis=1)
    special = np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [0.5, 0.5, 0.0]])
    k = min(n, len(special))
    bary[:k] = special[:k]
    faces[:k] = 0
    return faces, bary


def _fmt(x: Any) -> str:
    a = np.atleast_1d(np.asarray(x, dtype=float))
    return "(" + ", ".join(f"{v:.17g}" for v in a) + ")" if a.size > 1 else f"{a[0]:.17g}"


def assert_matches_reference(
    fn: Callable[[np.ndarray, np.ndarray], Any],
    mesh: Union[str, "os.PathLike[str]", Surface, Pps],
    *,
    quantity: str = "position",
    n: int = 1000,
    seed: int = 0,
    rtol: Optional[float] = None,
    atol: Optional[float] = None,
    sprime: str = "pn",
    profile: str = "paper",
    max_witnesses: int = 10,
) -> dict:
    """Compare ``fn(faces, bary)`` with the reference at ``n`` seeded points.

    ``mesh`` is a path, a :class:`~pseudomanifold.Surface` or a built
    :class:`~pseudomanifold.Pps` (then ``sprime``/``profile`` are its own). A point fails when
    ``|theirs - reference| > atol + rtol * |reference|`` (Euclidean for vectors), or when one
    is finite and the other not; a wrong shape or a non-numeric result fails at once. On
    failure raises AssertionError listing the witnesses (face, barycentric point, both values,
    deviation), worst first, as ``ppm diff`` does. Returns a summary dict (points, worst
    deviation, tolerance) when every point agrees.
    """
    if quantity not in QUANTITIES:
        raise ValueError(f"quantity {quantity!r}: expected one of {QUANTITIES}")
    if isinstance(mesh, Pps):
        pps = mesh
    else:
        surface = mesh if isinstance(mesh, Surface) else load(mesh)
        pps = surface.pps(sprime=sprime, profile=profile)
    V = pps.surface.vertices
    scale = float(np.linalg.norm(V.max(axis=0) - V.min(axis=0))) or 1.0
    d_rtol, d_atol = default_tolerance(quantity, scale)
    rtol = d_rtol if rtol is None else rtol
    atol = d_atol if atol is None else atol

    faces, bary = sample_points(pps._p.num_faces, n, seed)
    if quantity == "sprime":
        ref = pps.eval_sprime(faces, bary)
    else:
        out = pps.eval(faces, bary, attributes="positions" if quantity == "position" else "curvature")
        ref = out[{"position": "positions", "normal": "normals"}.get(quantity, quantity)]

    what = f"{quantity} on {getattr(pps.surface, 'path', None) or 'the mesh'} ({pps.sprime}, {pps.profile})"
    try:
        theirs = np.asarray(fn(faces.copy(), bary.copy()), dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise AssertionError(f"{what}: the result is not a numeric array: {e}") from None
    if theirs.shape != ref.shape:
        raise AssertionError(
            f"{what}: wrong shape: got {theirs.shape}, the reference gives {ref.shape} for n = {n} points"
        )

    if ref.ndim == 2:
        dev = np.linalg.norm(theirs - ref, axis=1)
        size = np.linalg.norm(ref, axis=1)
        fin_t, fin_r = np.isfinite(theirs).all(axis=1), np.isfinite(ref).all(axis=1)
    else:
        dev = np.abs(theirs - ref)
        size = np.abs(ref)
        fin_t, fin_r = np.isfinite(theirs), np.isfinite(ref)
    tol = atol + rtol * np.where(np.isfinite(size), size, 0.0)
    # Both undefined (a singular point of the reference, NaN curvature) is agreement; one
    # undefined is a witness with infinite deviation; otherwise compare (NaN > tol is False,
    # so deviations are formed only where both are finite).
    dev = np.where(fin_t & fin_r, dev, np.where(fin_t == fin_r, 0.0, np.inf))
    bad = np.flatnonzero(dev > tol)
    worst = float(dev.max()) if dev.size else 0.0
    if bad.size:
        order = bad[np.argsort(-dev[bad], kind="stable")][:max_witnesses]
        lines = [
            f"{what}: {bad.size} of {n} points deviate (seed {seed}; worst {worst:.3e};"
            f" tolerance atol {atol:.3e} + rtol {rtol:.3e}·|reference|):"
        ]
        for i in order:
            lines.append(
                f"  face {faces[i]}, bary {_fmt(bary[i])}: theirs {_fmt(theirs[i])},"
                f" reference {_fmt(ref[i])}, deviation {dev[i]:.3e} > {tol[i]:.3e}"
            )
        if bad.size > len(order):
            lines.append(f"  ... and {bad.size - len(order)} more")
        raise AssertionError("\n".join(lines))
    return {"points": n, "seed": seed, "worst_deviation": worst, "rtol": rtol, "atol": atol}
