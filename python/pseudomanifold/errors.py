"""Typed exceptions of the pseudomanifold Python layer.

Every error of the Rust crate reaches Python as one of these (the extension instantiates them
with the attributes listed), never as a bare RuntimeError or a panic.
"""

from __future__ import annotations

__all__ = [
    "PseudomanifoldError",
    "UsageError",
    "MeshError",
    "ValidationError",
    "BuildError",
    "EvalError",
    "OracleError",
    "CertifyError",
]


class PseudomanifoldError(Exception):
    """Base class of every error raised by pseudomanifold."""


class UsageError(PseudomanifoldError, ValueError):
    """An argument out of range (array shape, profile name, precision, check option)."""


class MeshError(PseudomanifoldError, OSError):
    """A mesh file could not be read or parsed (mesh::MeshError).

    Attributes: ``kind`` (io, unknown_format, parse, encoding, truncated, too_large,
    not_triangle, cannot_triangulate, too_few_sides, empty), ``file``, and where the Rust
    error carries it ``line`` (1-based, text formats), ``byte`` (binary offset) or
    ``element`` (``(kind, index)``, binary PLY); the others are None.
    """

    kind: str | None = None
    file: str | None = None
    line: int | None = None
    byte: int | None = None
    element: tuple[str, int] | None = None


class ValidationError(PseudomanifoldError, ValueError):
    """The mesh is not a simplicial surface (Sec. 3.1, Defs. 3.1.1-3.1.6).

    Attributes: ``checks`` (the failing SPEC IDs, e.g. ``["D3.1.6(edges)"]``), ``witnesses``
    (``{id: [{"text", "data"}, ...]}``, the first offenders of each), ``classes`` (defect
    classes, e.g. ``["boundary"]``) and ``report`` (the validator's whole report, the JSON of
    ``ppm check --json``).
    """

    checks: list[str] = []
    witnesses: dict = {}
    classes: list[str] = []
    report: dict = {}


class BuildError(PseudomanifoldError):
    """The surface could not be built (Loop S' on an unsupported mesh, fit refused by
    R-fit-budget, coordinates out of range)."""


class EvalError(PseudomanifoldError, ValueError):
    """An evaluation failed (no such face, barycentric coordinates not >= 0 with sum 1, ...).

    Attributes (vectorised calls): ``index`` of the first failing point, its ``face`` and
    ``bary``.
    """

    index: int | None = None
    face: int | None = None
    bary: list[float] | None = None


class OracleError(PseudomanifoldError):
    """The oracle session failed as a whole (per-point errors are returned, not raised)."""


class CertifyError(PseudomanifoldError):
    """A certification argument, file or merge failed (certify::CertifyError)."""
