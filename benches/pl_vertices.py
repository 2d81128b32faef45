#!/usr/bin/env python3
"""How many vertices does a piecewise-linear mesh need to be within eps of S_T?

usage: pl_vertices.py MESH EPS_RELATIVE [--check N] [--simplifier meshoptimizer|pymeshlab]

(pymeshlab: MeshLab's quadric edge collapse with optimal vertex placement, a cross-check; the
default and the table's numbers are meshoptimizer.)

S_T is MESH (OBJ, OFF or PLY; triangles).  eps = EPS_RELATIVE * diagonal of the bounding box
of S_T's vertices.  S_T is simplified with meshoptimizer's quadric-error edge collapse
(`meshopt_simplify`, options 0: topology-preserving, no sloppy/prune; the result keeps a subset
of S_T's vertices at their exact positions) to a target vertex count T (target index count
6*T, i.e. ~2T triangles on a closed surface; the error bound is set to 1.0 = the whole mesh
extent, so the count decides).  The error of a simplified mesh M is measured here, not taken
from meshoptimizer: max over the vertices v of S_T of dist(v, M), the exact Euclidean distance
from v to the nearest point of M's triangles (point-to-triangle distance = min of the three
point-to-segment distances and, when the projection falls inside, the distance to the plane).

Exactness of the nearest-triangle search: each triangle t gets a centroid c_t and a radius r_t
(max distance from c_t to its corners), so dist(v, t) >= |v - c_t| - r_t.  An upper bound
u_v = min over the 16 nearest centroids of the exact distance is computed first.  The max is then
found exactly: vertices are visited in decreasing u_v; for each, every triangle with
|v - c_t| <= u_v + r_t is a candidate (triangles are grouped by r_t in doubling buckets, one
KD-tree per bucket, ball radius u_v + max r in the bucket), the exact distance is the min over
candidates, and the scan stops once the next u_v is <= the running max (its exact distance
cannot exceed it).  `--check N` also compares against brute force over all triangles for N
seeded-random vertices and for the argmax vertex.

The smallest T whose measured max distance <= eps is found by binary search over T in
[4, |V(S_T)|] (the predicate is assumed monotone in T; see the README).  A simplified mesh counts only if it also keeps
the topology of S_T (same Euler characteristic, no edge with other than two faces).
Output: one JSON object.
Deterministic: meshoptimizer is deterministic and no randomness is used except the seeded check.
"""
import json
import os
import sys
import time

import numpy as np
from scipy.spatial import cKDTree
import meshoptimizer


# ----------------------------------------------------------------------------- mesh reading
def read_obj(path):
    vs, fs = [], []
    with open(path) as fh:
        for line in fh:
            if line.startswith('v '):
                vs.append([float(x) for x in line.split()[1:4]])
            elif line.startswith('f '):
                idx = [int(t.split('/')[0]) for t in line.split()[1:]]
                idx = [i - 1 if i > 0 else len(vs) + i for i in idx]
                for k in range(1, len(idx) - 1):
                    fs.append([idx[0], idx[k], idx[k + 1]])
    return np.array(vs, dtype=np.float64), np.array(fs, dtype=np.int64)


def read_off(path):
    with open(path) as fh:
        toks = [l.split('#')[0] for l in fh]
    toks = ' '.join(toks).split()
    assert toks[0].endswith('OFF')
    nv, nf = int(toks[1]), int(toks[2])
    p = 4
    v = np.array(toks[p:p + 3 * nv], dtype=np.float64).reshape(nv, 3)
    p += 3 * nv
    fs = []
    for _ in range(nf):
        n = int(toks[p])
        idx = [int(x) for x in toks[p + 1:p + 1 + n]]
        p += 1 + n
        for k in range(1, n - 1):
            fs.append([idx[0], idx[k], idx[k + 1]])
    return v, np.array(fs, dtype=np.int64)


PLY_T = {'char': 'i1', 'int8': 'i1', 'uchar': 'u1', 'uint8': 'u1', 'short': 'i2', 'int16': 'i2',
         'ushort': 'u2', 'uint16': 'u2', 'int': 'i4', 'int32': 'i4', 'uint': 'u4', 'uint32': 'u4',
         'float': 'f4', 'float32': 'f4', 'double': 'f8', 'float64': 'f8'}


def read_ply(path):
    with open(path, 'rb') as fh:
        data = fh.read()
    end = data.index(b'end_header')
    end = data.index(b'\n', end) + 1
    header = data[:end].decode('ascii').splitlines()
    fmt, elems = None, []
    for line in header:
        w = line.split()
        if not w:
            continue
        if w[0] == 'format':
            fmt = w[1]
        elif w[0] == 'element':
            elems.append([w[1], int(w[2]), []])
        elif w[0] == 'property':
            elems[-1][2].append(w[1:])
    body = data[end:]
    if fmt == 'ascii':
        toks = body.split()
        p = 0
        out = {}
        for name, n, props in elems:
            rows = []
            for _ in range(n):
                row = []
                for pr in props:
                    if pr[0] == 'list':
                        c = int(toks[p]); p += 1
                        row.append([float(t) for t in toks[p:p + c]]); p += c
                    else:
                        row.append(float(toks[p])); p += 1
                rows.append(row)
            out[name] = (props, rows)
        vp, vr = out['vertex']
        names = [pr[-1] for pr in vp]
        v = np.array([[r[names.index(a)] for a in 'xyz'] for r in vr], dtype=np.float64)
        fs = []
        for r in out['face'][1]:
            idx = [int(x) for x in r[0]]
            for k in range(1, len(idx) - 1):
                fs.append([idx[0], idx[k], idx[k + 1]])
        return v, np.array(fs, dtype=np.int64)
    assert fmt in ('binary_little_endian', 'binary_big_endian'), fmt
    bo = '<' if fmt == 'binary_little_endian' else '>'
    off = 0
    v = f = None
    for name, n, props in elems:
        if all(pr[0] != 'list' for pr in props):
            dt = np.dtype([(pr[1], bo + PLY_T[pr[0]]) for pr in props])
            arr = np.frombuffer(body, dtype=dt, count=n, offset=off)
            off += n * dt.itemsize
            if name == 'vertex':
                v = np.stack([arr[a].astype(np.float64) for a in 'xyz'], axis=1)
        else:
            assert len(props) == 1 and props[0][0] == 'list', 'face element with extra properties'
            ct, it = bo + PLY_T[props[0][1]], bo + PLY_T[props[0][2]]
            dt = np.dtype([('n', ct), ('i', it, (3,))])
            arr = np.frombuffer(body, dtype=dt, count=n, offset=off)
            if name == 'face' and np.all(arr['n'] == 3):
                f = arr['i'].astype(np.int64)
                off += n * dt.itemsize
            else:  # general polygons: slow path
                fs = []
                cs, isz = np.dtype(ct).itemsize, np.dtype(it).itemsize
                for _ in range(n):
                    c = int(np.frombuffer(body, ct, 1, off)[0]); off += cs
                    idx = np.frombuffer(body, it, c, off).astype(np.int64); off += c * isz
                    for k in range(1, c - 1):
                        fs.append([idx[0], idx[k], idx[k + 1]])
                if name == 'face':
                    f = np.array(fs, dtype=np.int64)
    return v, f


def read_mesh(path):
    ext = os.path.splitext(path)[1].lower()
    return {'.obj': read_obj, '.off': read_off, '.ply': read_ply}[ext](path)


# ----------------------------------------------------------------------------- distances
def point_tri_dist(p, a, b, c):
    """Exact Euclidean distance from points p[i] to triangles (a[i], b[i], c[i]); arrays (n, 3)."""
    def seg(p, a, b):
        ab = b - a
        l2 = np.einsum('ij,ij->i', ab, ab)
        t = np.einsum('ij,ij->i', p - a, ab) / np.where(l2 > 0, l2, 1.0)
        t = np.clip(np.where(l2 > 0, t, 0.0), 0.0, 1.0)
        d = p - (a + t[:, None] * ab)
        return np.sqrt(np.einsum('ij,ij->i', d, d))
    d = np.minimum(np.minimum(seg(p, a, b), seg(p, b, c)), seg(p, c, a))
    n = np.cross(b - a, c - a)
    nn = np.sqrt(np.einsum('ij,ij->i', n, n))
    ok = nn > 0
    s1 = np.einsum('ij,ij->i', np.cross(b - a, p - a), n)
    s2 = np.einsum('ij,ij->i', np.cross(c - b, p - b), n)
    s3 = np.einsum('ij,ij->i', np.cross(a - c, p - c), n)
    inside = ok & (s1 >= 0) & (s2 >= 0) & (s3 >= 0)
    dp = np.abs(np.einsum('ij,ij->i', p - a, n)) / np.where(ok, nn, 1.0)
    return np.where(inside, np.minimum(d, dp), d)


class TriIndex:
    def __init__(self, v, f):
        self.a, self.b, self.c = v[f[:, 0]], v[f[:, 1]], v[f[:, 2]]
        self.cen = (self.a + self.b + self.c) / 3.0
        r = np.stack([np.linalg.norm(x - self.cen, axis=1) for x in (self.a, self.b, self.c)], 1)
        self.r = r.max(axis=1) * (1 + 1e-12) + 1e-300
        self.tree = cKDTree(self.cen)
        # buckets of triangles by radius (doubling), one KD-tree each
        lo = self.r.min()
        bucket = np.floor(np.log2(self.r / lo)).astype(int)
        self.buckets = []
        for bk in np.unique(bucket):
            ids = np.nonzero(bucket == bk)[0]
            self.buckets.append((ids, cKDTree(self.cen[ids]), self.r[ids].max()))

    def dist_to(self, p, tris):
        return point_tri_dist(p, self.a[tris], self.b[tris], self.c[tris])

    def upper(self, pts, k=16):
        k = min(k, len(self.cen))
        _, nb = self.tree.query(pts, k=k)
        nb = nb.reshape(len(pts), k)
        d = self.dist_to(np.repeat(pts, k, axis=0), nb.ravel()).reshape(len(pts), k)
        return d.min(axis=1)

    def exact(self, pt, u):
        """Exact distance from one point pt given an upper bound u."""
        best = u
        for ids, tree, rmax in self.buckets:
            cand = tree.query_ball_point(pt, u + rmax)
            if not cand:
                continue
            t = ids[np.asarray(cand)]
            dc = np.linalg.norm(self.cen[t] - pt, axis=1)
            t = t[dc - self.r[t] <= u]
            if len(t):
                best = min(best, self.dist_to(np.repeat(pt[None], len(t), 0), t).min())
        return best

    def brute(self, pt):
        return self.dist_to(np.repeat(pt[None], len(self.a), 0), np.arange(len(self.a))).min()


def max_vertex_distance(pts, v, f):
    """Exact max over pts of the distance to the triangle mesh (v, f); returns (max, argmax, evaluated)."""
    ti = TriIndex(v, f)
    u = np.empty(len(pts))
    for s in range(0, len(pts), 20000):
        u[s:s + 20000] = ti.upper(pts[s:s + 20000])
    order = np.argsort(-u, kind='stable')
    best, arg, n = -1.0, -1, 0
    for i in order:
        if u[i] <= best:
            break
        d = ti.exact(pts[i], u[i])
        n += 1
        if d > best:
            best, arg = d, int(i)
    return best, arg, n, ti


# ----------------------------------------------------------------------------- simplification
def simplify(v32, idx, target_vertices, f_count):
    dest = np.zeros(idx.size, dtype=np.uint32)
    err = np.zeros(1, dtype=np.float32)
    target_idx = min(idx.size, 3 * max(4, int(round(target_vertices * f_count / (len(v32))))))
    n = meshoptimizer.simplify(dest, idx, v32, target_index_count=target_idx,
                               target_error=1.0, options=0, result_error=err)
    f = dest[:n].reshape(-1, 3).astype(np.int64)
    return f, float(err[0])


def simplify_pymeshlab(v, f, target_vertices):
    import pymeshlab
    ms = pymeshlab.MeshSet()
    ms.add_mesh(pymeshlab.Mesh(vertex_matrix=v, face_matrix=f.astype(np.int32)))
    ms.meshing_decimation_quadric_edge_collapse(
        targetfacenum=max(4, int(round(target_vertices * len(f) / len(v)))),
        preservetopology=True, preserveboundary=True, optimalplacement=True,
        planarquadric=False, autoclean=True)
    m = ms.current_mesh()
    return np.asarray(m.vertex_matrix(), dtype=np.float64), np.asarray(m.face_matrix(), dtype=np.int64)


def euler(f):
    e = np.sort(np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]]), axis=1)
    ue, cnt = np.unique(e, axis=0, return_counts=True)
    return len(np.unique(f)) - len(ue) + len(f), int((cnt != 2).sum())


def main():
    args = sys.argv[1:]
    check = 0
    simplifier = 'meshoptimizer'
    if '--simplifier' in args:
        i = args.index('--simplifier')
        simplifier = args[i + 1]
        del args[i:i + 2]
    if '--check' in args:
        i = args.index('--check')
        check = int(args[i + 1])
        del args[i:i + 2]
    path, rel = args[0], float(args[1])
    t0 = time.time()
    v, f = read_mesh(path)
    diag = float(np.linalg.norm(v.max(0) - v.min(0)))
    eps = rel * diag
    v32 = np.ascontiguousarray(v, dtype=np.float32)
    idx = np.ascontiguousarray(f.ravel(), dtype=np.uint32)
    chi0, nm0 = euler(f)
    cache = {}

    def measure(T):
        if T not in cache:
            if simplifier == 'pymeshlab':
                vs, fs = simplify_pymeshlab(v, f, T)
                merr = float('nan')
            else:
                fs, merr = simplify(v32, idx, T, len(f))
                vs = v
            used = int(len(np.unique(fs)))
            d, arg, n, _ = max_vertex_distance(v, vs, fs)
            chi, nm = euler(fs)
            cache[T] = dict(target=T, vertices=used, faces=int(len(fs)), max_distance=d,
                            topology_ok=bool(chi == chi0 and nm == 0 and nm0 == 0),
                            max_distance_rel=d / diag, argmax_vertex=arg,
                            meshopt_error_rel=merr)
            print(f'# T={T} V={used} F={len(fs)} max={d:.6g} ({d / diag:.4g} of diag) '
                  f'exact-evaluated={n} euler={chi} nonmanifold-edges={nm}', file=sys.stderr)
        return cache[T]

    def ok(m):  # within eps and the same topology (Euler characteristic, every edge in 2 faces)
        return m['max_distance'] <= eps and m['topology_ok']

    lo, hi = 4, len(v)  # invariant: ok(measure(hi)) (T = |V| is S_T itself, distance 0)
    if ok(measure(lo)):
        hi = lo
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if ok(measure(mid)):
            hi = mid
        else:
            lo = mid
    bisect_T = hi
    # the predicate is not monotone in T (see the README): scan below the bisection answer,
    # every target in [hi-10, hi) and then every max(1, hi//100) down to 0.85*hi, and report the
    # smallest passing target found among all evaluated ones.
    step = max(1, hi // 100)
    scan = set(range(max(4, hi - 10), hi)) | set(range(hi - step, max(4, int(0.85 * hi)) - 1, -step))
    below = []
    for T in sorted(scan, reverse=True):
        if T < 4:
            continue
        m = measure(T)
        below.append(dict(target=T, vertices=m['vertices'], max_distance_rel=m['max_distance_rel'],
                          within=ok(m)))
    passing = [T for T, m in cache.items() if ok(m)]
    hi = min(passing, key=lambda T: (cache[T]['vertices'], T))
    best = measure(hi)
    if simplifier == 'pymeshlab':
        vs, fs = simplify_pymeshlab(v, f, hi)
    else:
        fs, _ = simplify(v32, idx, hi, len(f))
        vs = v
    chi, nonmanifold_edges = euler(fs)
    bis = cache[bisect_T]
    out = dict(mesh=path, vertices=int(len(v)), faces=int(len(f)), diagonal=diag,
               epsilon_relative=rel, epsilon=eps, simplifier='meshoptimizer (PyPI meshoptimizer '
               + 'package) meshopt_simplify, options=0, target_error=1.0, count-driven'
               if simplifier != 'pymeshlab' else 'pymeshlab meshing_decimation_quadric_edge_collapse'
               + ' (preservetopology, optimalplacement, autoclean), count-driven',
               pl_vertices=best['vertices'], pl_faces=best['faces'], pl_target=hi,
               pl_max_distance=best['max_distance'], pl_max_distance_rel=best['max_distance_rel'],
               pl_meshopt_error_rel=best['meshopt_error_rel'],
               pl_dof=3 * best['vertices'], euler_input=chi0, euler_pl=chi,
               nonmanifold_edges_input=nm0, nonmanifold_edges_pl=nonmanifold_edges,
               bisection=dict(target=bisect_T, vertices=bis['vertices'],
                              max_distance_rel=bis['max_distance_rel'],
                              failing_neighbour_target=lo,
                              failing_neighbour_vertices=cache[lo]['vertices'] if lo in cache else None),
               topology_rejected=sorted(m['vertices'] for m in cache.values()
                                        if m['max_distance'] <= eps and not m['topology_ok']),
               scan_below=dict(evaluated=len(below), passing=sum(b['within'] for b in below),
                               smallest_passing_vertices=best['vertices']), evaluations=len(cache), seconds=round(time.time() - t0, 1))
    if check:
        ti = TriIndex(vs, fs)
        rng = np.random.default_rng(12345)
        sample = list(rng.choice(len(v), size=min(check, len(v)), replace=False)) + [best['argmax_vertex']]
        worst = 0.0
        for i in sample:
            u = ti.upper(v[i:i + 1])[0]
            worst = max(worst, abs(ti.exact(v[i], u) - ti.brute(v[i])))
        out['check'] = dict(points=len(sample), max_abs_diff_vs_brute_force=worst)
    print(json.dumps(out, indent=1, default=lambda o: o.item()))


if __name__ == '__main__':
    main()
