"""Distributed runs on Dask (``dask.distributed``): certification in shards and ``check
--spec`` over a directory of meshes, as tasks of any Dask cluster (docs/python.md).

Each task calls the crate through the extension (the GIL is released, the work runs on the
worker's rayon pool); the merge is the crate's (``certify::merge``), so a sharded run writes
the same certificate and summary as ``ppm certify`` (SPEC PY-dask-certify).

    from dask.distributed import Client, LocalCluster
    client = Client(LocalCluster(n_workers=2, threads_per_worker=1))   # or Client("tcp://scheduler:8786")
    certify(12, client, shards=8, out="certificate.json", summary="summary.md")
"""

from __future__ import annotations

import json
import os
from pathlib import Path
from typing import Any, Optional, Union

from . import _native

__all__ = ["certify", "certify_shard", "check_directory", "MESH_SUFFIXES", "strip_timings"]

MESH_SUFFIXES = (".off", ".obj", ".ply")


def certify_shard(max_degree: int, k: int, n: int, jobs: int = 1) -> str:
    """Task: ``ppm certify --max-degree M --shard K/N --jobs J``; the certificate as JSON."""
    return _native.certify_shard(int(max_degree), (int(k), int(n)), int(jobs))


def certify(
    max_degree: int,
    client: Any,
    shards: Optional[int] = None,
    *,
    out: Union[str, "os.PathLike[str]"] = "certificate.json",
    summary: Optional[Union[str, "os.PathLike[str]"]] = None,
    jobs: int = 1,
) -> dict:
    """Certify every degree configuration 3..=``max_degree`` (certify::all_configs) on the
    cluster of ``client``: shard K of ``shards`` (every N-th configuration, as ``ppm certify
    --shard K/N``) is one task, the parts are joined by the crate's merge and written as
    ``ppm certify --out OUT --summary SUMMARY`` writes them (the summary is also returned).

    ``shards`` defaults to twice the number of workers; ``jobs`` is the threads per task.
    Returns ``{"certificate": dict, "summary": str, "out": path, "shards": n}``.
    """
    if shards is None:
        shards = max(1, 2 * len(client.scheduler_info().get("workers", {})))
    shards = int(shards)
    futures = [
        client.submit(certify_shard, max_degree, k, shards, jobs, pure=False, key=f"ppm-certify-M{max_degree}-{k}of{shards}")
        for k in range(1, shards + 1)
    ]
    parts = client.gather(futures)
    merged = _native.certify_merge(parts)
    table = _native.certify_write(merged, os.fspath(out), None if summary is None else os.fspath(summary))
    return {"certificate": json.loads(merged), "summary": table, "out": os.fspath(out), "shards": shards}


def strip_timings(cert: dict) -> dict:
    """A certificate without what depends on the run rather than on the proofs: wall time,
    per-result milliseconds (the f64 rounding and whole-chart g_v bounds' included), thread count, shard tag, the order of the results (a run lists
    them in proving order, ``merge`` sorted by configuration and property) and the file's
    shared-statement table (``statements``: a compaction of the files; every result carries
    its statement once read), for comparing two runs."""
    c = {k: v for k, v in cert.items() if k not in ("wall_millis", "jobs", "shard", "statements")}
    rs = []
    for r in cert.get("results", []):
        r = {k: v for k, v in r.items() if k != "millis"}
        if isinstance(r.get("f64_rounding"), dict):
            # The f64 rounding bound's own time (CERT-f64-rounding) is a timing too.
            r["f64_rounding"] = {k: v for k, v in r["f64_rounding"].items() if k != "millis"}
        if isinstance(r.get("g_chart"), dict):
            # So is the whole-chart g_v bound's (CERT-f64-g-chart).
            r["g_chart"] = {k: v for k, v in r["g_chart"].items() if k != "millis"}
        rs.append(r)
    c["results"] = sorted(rs, key=lambda r: json.dumps([r["key"], r["property"]], sort_keys=True))
    return c


def _check_one(path: str, spec: bool, flags: list) -> dict:
    """Task: ``ppm check --spec --json FILE`` (the report, or the error that stopped it)."""
    try:
        text, ok = _native.check_file(path, spec, False, flags)
        return {"report": json.loads(text), "passes": bool(ok)}
    except Exception as e:  # a mesh that cannot be read is a result of the run, not a crash
        return {"error": {"type": type(e).__name__, "message": str(e)}, "passes": False}


def check_directory(path: Union[str, "os.PathLike[str]"], client: Any, *, spec: bool = True, recursive: bool = False, **options: Any) -> dict:
    """``ppm check --spec --json`` on every mesh (.off, .obj, .ply) of a directory, one task
    per mesh, merged into one report: ``{"directory", "meshes": {name: report or error},
    "passes": {name: bool}, "unexpected_failures": {name: [IDs]}, "ok": bool}``.

    ``options`` are the flags of :func:`pseudomanifold.check` (seed, samples, precision,
    max_configs, ...), the same for every mesh.
    """
    from . import _flags

    root = Path(path)
    it = root.rglob("*") if recursive else root.iterdir()
    files = sorted(p for p in it if p.is_file() and p.suffix.lower() in MESH_SUFFIXES)
    flags = _flags(options)
    futures = [client.submit(_check_one, str(p), spec, flags, pure=False) for p in files]
    results = client.gather(futures)
    meshes, passes, unexpected = {}, {}, {}
    for p, r in zip(files, results):
        name = str(p.relative_to(root))
        meshes[name] = r.get("report", r)
        passes[name] = r["passes"]
        rep = r.get("report")
        if rep is not None:
            ids = list((rep.get("chapter4") or {}).get("unexpected_failures", []))
            ids += [c["id"] for c in rep.get("chapter5", []) if c.get("verdict") == "fails"]
            if ids:
                unexpected[name] = ids
    return {
        "directory": os.fspath(path),
        "meshes": meshes,
        "passes": passes,
        "unexpected_failures": unexpected,
        "ok": bool(files) and all(passes.values()),
    }
