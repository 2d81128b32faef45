"""pseudomanifold: Python layer over the Rust reference implementation of the parametric
pseudo-manifold (PPM) construction of Siqueira, Xu and Gallier.

The Rust crate is the one implementation; this package converts arrays and errors and
releases the GIL around every heavy call, which runs on the crate's rayon pool. See
docs/python.md and SPEC.md (rows ``PY-*``).

    import pseudomanifold as pm
    K = pm.load("mesh.obj")                    # Sec. 3.1: validated, or ValidationError
    M = K.pps(sprime="pn", profile="paper")    # Ch. 5: the PPS over S'
    out = M.eval(faces, bary)                  # Sec. 6.1.4: positions, normals, K, H
    report = pm.check(K, spec=True)            # ``ppm check --spec --json`` as Python data
"""

from __future__ import annotations

import json
import os
from typing import Any, Mapping, Optional, Union

import numpy as np

from . import _native
from ._native import __version__
from .errors import (
    BuildError,
    CertifyError,
    EvalError,
    MeshError,
    OracleError,
    PseudomanifoldError,
    UsageError,
    ValidationError,
)

__all__ = [
    "__version__",
    "load",
    "load_fit",
    "Surface",
    "Pps",
    "SigmaV",
    "Oracle",
    "OracleResult",
    "CheckReport",
    "check",
    "num_threads",
    "PseudomanifoldError",
    "UsageError",
    "MeshError",
    "ValidationError",
    "BuildError",
    "EvalError",
    "OracleError",
    "CertifyError",
]

PathLike = Union[str, "os.PathLike[str]"]


def num_threads() -> int:
    """Threads of the crate's rayon pool (set ``RAYON_NUM_THREADS`` before the first call)."""
    return _native.num_threads()


def _points(faces: Any, bary: Any) -> tuple[np.ndarray, np.ndarray]:
    f = np.ascontiguousarray(np.asarray(faces).reshape(-1), dtype=np.int64)
    b = np.ascontiguousarray(bary, dtype=np.float64)
    if b.ndim == 1:
        b = b.reshape(1, -1)
    return f, b


class Surface:
    """A triangle mesh validated as a simplicial surface K (Sec. 3.1, Defs. 3.1.1-3.1.6).

    ``Surface(V, F)``: V float (n, 3), F integer (m, 3), 0-based. Validated exactly by the
    crate's validator (SPEC D3.1.1, D3.1.3, D3.1.6, L3.1.1); a mesh that is not a simplicial
    surface raises :class:`ValidationError` with the failing check IDs and their witnesses.
    """

    def __init__(self, V: Any, F: Any) -> None:
        v = np.ascontiguousarray(V, dtype=np.float64)
        f = np.asarray(F)
        if f.dtype.kind not in "iu":
            raise UsageError(f"F must be an integer array, got dtype {f.dtype}")
        if v.ndim != 2 or f.ndim != 2:
            raise UsageError(f"V must be (n, 3) and F (m, 3); got {v.shape} and {f.shape}")
        # uint64 beyond int64 is out of range for any mesh: clip so the validator reports it.
        f = np.ascontiguousarray(np.clip(f, -1, np.iinfo(np.int64).max).astype(np.int64))
        self._k = _native.Surface(v, f)
        self.path: Optional[str] = None

    @classmethod
    def _wrap(cls, k: Any, path: Optional[str]) -> "Surface":
        s = cls.__new__(cls)
        s._k = k
        s.path = path
        return s

    @property
    def num_vertices(self) -> int:
        """Number of vertices of K."""
        return self._k.num_vertices

    @property
    def num_faces(self) -> int:
        """Number of triangles of K."""
        return self._k.num_faces

    @property
    def vertices(self) -> np.ndarray:
        """Vertex positions (n, 3) as stored."""
        return self._k.vertices

    @property
    def faces(self) -> np.ndarray:
        """Triangles (m, 3), 0-based, as stored."""
        return self._k.faces

    def validation_report(self) -> dict:
        """The validator's report (Sec. 3.1): every check with verdict and witnesses."""
        return self._k.validation_report()

    def pps(self, sprime: str = "pn", profile: str = "paper") -> "Pps":
        """The parametric pseudo-surface of Chapter 5 over S' = ``sprime`` ("pn": PN
        triangles, Sec. 6.2; "loop": the Loop limit surface, SPEC LOOP-*) with the parameter
        ``profile`` ("paper" or "authors-code", SPEC AU-*)."""
        return Pps(self, sprime=sprime, profile=profile)

    def sigma_v(self, kappa: Optional[float] = None, patch_degree: Optional[int] = None) -> "SigmaV":
        """The tutorial's (sigma, v)-indexed PPS (SPEC SV-*), S' = PN triangles."""
        return SigmaV(self, kappa=kappa, patch_degree=patch_degree)

    def oracle(self, bits: int = 256, profile: str = "paper", sprime: str = "pn") -> "Oracle":
        """An oracle session on K (docs/oracle.md): every quantity in f64 and at ``bits``."""
        return Oracle(self, bits=bits, profile=profile, sprime=sprime)

    def check(self, spec: bool = True, **options: Any) -> "CheckReport":
        """``ppm check [--spec]`` on K; see :func:`check`."""
        return check(self, spec=spec, **options)

    def __repr__(self) -> str:
        src = f" from {self.path}" if self.path else ""
        return f"<pseudomanifold.Surface{src}: {self.num_vertices} vertices, {self.num_faces} faces>"


def load(path: PathLike, triangulate: bool = False) -> Surface:
    """Read OFF, OBJ or PLY and validate it (Sec. 3.1).

    Raises :class:`MeshError` (with ``file``/``line``/``byte``/``element``) when the file
    cannot be read, :class:`ValidationError` when it is not a simplicial surface.
    """
    p = os.fspath(path)
    return Surface._wrap(_native.load(p, triangulate), p)


class Pps:
    """The parametric pseudo-surface M of Chapter 5 (Defs. 5.2.1-5.4.2, Eq. 5.1), evaluated
    by eval(sigma, lambda, mu, nu) of Sec. 6.1.4."""

    def __init__(self, surface: Surface, sprime: str = "pn", profile: str = "paper") -> None:
        self.surface = surface
        self._p = _native.PpsHandle(surface._k, sprime, profile)

    @property
    def sprime(self) -> str:
        """S' of Sec. 5.1: "pn" or "loop"."""
        return self._p.sprime

    @property
    def profile(self) -> str:
        """The parameter profile: "paper" or "authors-code"."""
        return self._p.profile

    def eval(self, faces: Any, bary: Any, attributes: str = "curvature") -> dict:
        """eval(sigma, lambda, mu, nu) of Sec. 6.1.4 at n points (SPEC C6.1.4-*, D5.4.2).

        ``faces`` (n,) face ids, ``bary`` (n, 3) barycentric coordinates in the face's corner
        order (>= 0, sum 1). Returns ``{"positions": (n, 3), "normals": (n, 3),
        "gaussian": (n,), "mean": (n,)}``; normals and curvatures come from the analytic
        derivatives of theta_v (order-2 jets), as ``ppm sample``. ``attributes="positions"``
        computes the positions only (plain f64 eval, faster). Raises :class:`EvalError`
        naming the first point that cannot be evaluated.
        """
        f, b = _points(faces, bary)
        pos, nrm, gauss, mean = self._p.eval(f, b, attributes)
        out = {"positions": pos}
        if nrm is not None:
            out.update(normals=nrm, gaussian=gauss, mean=mean)
        return out

    def eval_sprime(self, faces: Any, bary: Any) -> np.ndarray:
        """S' at n points (Sec. 5.1): (n, 3)."""
        f, b = _points(faces, bary)
        return self._p.eval_sprime(f, b)

    def sample(self, level: int) -> tuple[np.ndarray, np.ndarray, dict]:
        """M sampled by midpoint subdivision at ``level`` (Sec. 6.2, ``ppm sample``):
        ``(V, F, {"normals", "gaussian", "mean"})``; watertight whenever K is closed."""
        v, f, n, g, h = self._p.sample(int(level))
        return v, f, {"normals": n, "gaussian": g, "mean": h}


class SigmaV:
    """The tutorial's (sigma, v)-indexed construction (SPEC SV-D3, SV-D11, SV-D13): 3 n_t
    p-domains, S' = PN triangles. Positions only (it has no curvature evaluation)."""

    def __init__(self, surface: Surface, kappa: Optional[float] = None, patch_degree: Optional[int] = None) -> None:
        kw = {}
        if kappa is not None:
            kw["kappa"] = float(kappa)
        if patch_degree is not None:
            kw["patch_degree"] = int(patch_degree)
        self.surface = surface
        self._p = _native.SigmaVHandle(surface._k, **kw)

    def eval(self, faces: Any, bary: Any) -> dict:
        """eval at n points: ``{"positions": (n, 3)}``."""
        f, b = _points(faces, bary)
        return {"positions": self._p.eval(f, b)}

    def sample(self, level: int) -> tuple[np.ndarray, np.ndarray, dict]:
        """Sampled by midpoint subdivision at ``level``: ``(V, F, attributes)``."""
        v, f, n, g, h = self._p.sample(int(level))
        return v, f, {"normals": n, "gaussian": g, "mean": h}


def load_fit(path: PathLike) -> SigmaV:
    """A fitted surface written by ``ppm fit -o`` (seed 002, adaptive manifold fitting; SPEC
    AF-format-roundtrip): the (sigma, v) PPS over its base mesh, read bit-exactly. ``eval``
    takes faces of the base mesh; ``surface`` is None (the base mesh lives in the file)."""
    s = SigmaV.__new__(SigmaV)
    s.surface = None
    s._p = _native.SigmaVHandle.from_fit(os.fspath(path))
    return s


class OracleResult(dict):
    """Answers of one vectorised oracle query, as ``ppm oracle`` gives them line by line.

    Keys: ``value`` (n, k) float64, the multi-precision reference rounded to f64 (NaN where
    not ok); ``value_str`` (list of lists of decimal strings, the reference as printed);
    ``f64`` (n, k) the same quantity in f64; ``difference`` (n,) |f64 - mp| computed at
    ``bits`` (the printed bound of their difference; NaN where not ok); ``ok`` (n,) bool;
    ``errors`` [(index, kind, message)]; ``info`` (list of dicts or None); ``bits``.
    """


def _rows(cols: list, n: int) -> np.ndarray:
    k = max((len(c) for c in cols), default=0)
    a = np.full((n, k), np.nan)
    for i, c in enumerate(cols):
        if c:
            a[i, : len(c)] = [np.nan if x is None else x for x in c]
    return a


def _num(s: str) -> float:
    if s == "true":
        return 1.0
    if s == "false":
        return 0.0
    try:
        return float(s)
    except ValueError:
        return float("nan")


class Oracle:
    """The reference oracle (docs/oracle.md) on K, vectorised: each method sends one
    protocol request per point to the crate's oracle ``Session`` (the same handlers as
    ``ppm oracle``) and returns an :class:`OracleResult` with the multi-precision value, the
    f64 value and their difference."""

    def __init__(self, surface: Surface, bits: int = 256, profile: str = "paper", sprime: str = "pn") -> None:
        self.surface = surface
        self._o = _native.OracleHandle(surface._k, int(bits), profile, sprime)

    @property
    def bits(self) -> int:
        """Precision of the reference values, in bits."""
        return self._o.bits

    def handle_line(self, line: str) -> dict:
        """One JSON-lines request, answered exactly as ``ppm oracle`` answers it."""
        return json.loads(self._o.handle_line(line))

    def query(self, op: str, **fields: Any) -> OracleResult:
        """Any numerical op of the protocol, vectorised: array fields (``p`` (n, 2),
        ``bary`` (n, 3), ``v``/``u``/``w``/``face`` (n,)) give one request per row; scalars
        are repeated."""
        n = None
        cols: dict[str, Any] = {}
        for name, val in fields.items():
            if val is None:
                continue
            a = np.asarray(val)
            per_row = (name in ("p", "bary") and a.ndim == 2) or (name in ("v", "u", "w", "face") and a.ndim == 1)
            if per_row:
                if n is not None and len(a) != n:
                    raise UsageError(f"field {name} has {len(a)} rows, expected {n}")
                n = len(a)
            cols[name] = (a, per_row)
        n = 1 if n is None else n
        reqs = []
        for i in range(n):
            body = {}
            for name, (a, per_row) in cols.items():
                x = a[i] if per_row else a
                body[name] = x.tolist() if isinstance(x, np.ndarray) else (x.item() if isinstance(x, np.generic) else x)
            reqs.append(json.dumps(body))
        rows = self._o.batch(op, reqs)
        ok = np.array([r[0] for r in rows], dtype=bool)
        value_str = [r[1] for r in rows]
        res = OracleResult(
            value=_rows([[_num(s) for s in r[1]] for r in rows], n),
            value_str=value_str,
            f64=_rows([r[2] for r in rows], n),
            difference=np.array([np.nan if r[3] is None else r[3] for r in rows]),
            ok=ok,
            errors=[(i, r[4][0], r[4][1]) for i, r in enumerate(rows) if r[4] is not None],
            info=[None if r[5] is None else json.loads(r[5]) for r in rows],
            bits=self.bits,
        )
        return res

    # The Chapter 4 quantities (Defs. 4.1.6-4.1.10) and the Chapter 5 ones.
    def g(self, v: Any, p: Any) -> OracleResult:
        """g_v(p) (Def. 4.1.6)."""
        return self.query("g", v=v, p=p)

    def g_inv(self, v: Any, p: Any) -> OracleResult:
        """g_v^-1(p) (Def. 4.1.6)."""
        return self.query("g_inv", v=v, p=p)

    def phi(self, u: Any, w: Any, p: Any) -> OracleResult:
        """phi_wu(p), p in Omega_uw, to Omega_wu (Def. 4.1.10; note the paper's index order)."""
        return self.query("phi", u=u, w=w, p=p)

    def member(self, u: Any, w: Any, p: Any, test: str = "literal") -> OracleResult:
        """p in Omega_uw? (Def. 4.1.9 literally, or ``test="lens"``: Sec. 6.1.3). ``value`` is
        1.0/0.0 (NaN: undecided at the precision); ``difference`` 1 where f64 disagrees."""
        return self.query("member", u=u, w=w, p=p, test=test)

    def rotate(self, u: Any, w: Any, p: Any) -> OracleResult:
        """R_(u,w)(p) (Def. 4.1.8)."""
        return self.query("rotate", u=u, w=w, p=p)

    def gamma(self, v: Any, p: Any) -> OracleResult:
        """The weight gamma_v(p) = xi(|p|) (Defs. 5.3.1-5.3.2)."""
        return self.query("gamma", v=v, p=p)

    def psi(self, v: Any, p: Any) -> OracleResult:
        """The shape function psi_v(p) (Def. 5.2.1)."""
        return self.query("psi", v=v, p=p)

    def theta(self, v: Any, p: Any) -> OracleResult:
        """theta_v(p) (Def. 5.4.2, Eq. 5.1)."""
        return self.query("theta", v=v, p=p)

    def theta_derivatives(self, v: Any, p: Any, order: int = 3) -> OracleResult:
        """Every partial derivative of theta_v at p up to ``order`` (jets)."""
        return self.query("theta_derivatives", v=v, p=p, order=order)

    def eval(self, faces: Any, bary: Any) -> OracleResult:
        """eval(sigma, lambda, mu, nu) (Sec. 6.1.4)."""
        f, b = _points(faces, bary)
        return self.query("eval", face=f, bary=b)

    def sprime(self, faces: Any, bary: Any) -> OracleResult:
        """S' (Sec. 5.1, PN triangles)."""
        f, b = _points(faces, bary)
        return self.query("sprime", face=f, bary=b)


class CheckReport(dict):
    """The report of ``ppm check [--spec] --json`` as Python data (the same serde JSON: same
    rows, same verdicts). ``passes`` is what ``ppm check`` exits 0 for."""

    passes: bool = False

    @property
    def rows(self) -> list:
        """Every check row: validation, extra (s_v), Chapter 4, Chapter 5, in report order."""
        out = list(self.get("checks", [])) + list(self.get("extra_checks", []))
        if self.get("chapter4"):
            out += self["chapter4"].get("checks", [])
        out += self.get("chapter5", [])
        return out


def _flags(options: Mapping[str, Any]) -> list[str]:
    flags: list[str] = []
    for name, val in options.items():
        if val is None or val is False:
            continue
        if name == "sprime":
            name = "surface"
        flag = "--" + name.replace("_", "-")
        if val is True:
            flags.append(flag)
        else:
            flags += [flag, os.fspath(val) if isinstance(val, os.PathLike) else str(val)]
    return flags


def check(surface: Union[Surface, PathLike], spec: bool = True, *, labels: bool = False, **options: Any) -> CheckReport:
    """``ppm check [--labels] [--spec] --json`` as Python data (SPEC PY-check-report).

    ``surface`` is a :class:`Surface` or a mesh path (read as ``ppm check FILE`` reads it; a
    file that is not a simplicial surface gives a report with ``is_simplicial_surface``
    false, not an exception). ``options`` are the command's flags: ``seed``, ``samples``,
    ``precision`` ("f64" or "mp:BITS"), ``mp_backend``, ``max_configs``, ``certificates``,
    ``no_surface``, ``sprime`` (``--surface``: "pn" or "loop"); they are parsed by the
    command's own parser, so defaults and validation are the command's.
    """
    flags = _flags(options)
    if isinstance(surface, Surface):
        text, ok = surface._k.check_json(spec, labels, flags)
    else:
        text, ok = _native.check_file(os.fspath(surface), spec, labels, flags)
    rep = CheckReport(json.loads(text))
    rep.passes = ok
    return rep
