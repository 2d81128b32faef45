//! Curved isocomplexes in the plane (Mello–Velho Sec. 4): the linear isocurve O = f̂⁻¹(c) and
//! the curved one 𝒪 = (f̂∘X)⁻¹(c) = X⁻¹(O), sampled as X|σ⁻¹ of points of each linear piece θ.
//!
//! Points on an edge are inverted once per edge with the edge's own 1-D map (bisection), so
//! the two triangles of an interior edge share them and the output is watertight.

use super::complex::PlanarComplex;
use super::inverse::newton;
use super::params::ComplexMap;
use crate::report::{CheckResult, Witness};
use crate::sdiff::common::rational::{from_f64, to_f64, Q};
use num_traits::{Signed, Zero};
use serde_json::json;
use std::collections::HashMap;

/// Points per linear piece (the paper's "m samples"; see the design note: 8).
pub(crate) const SAMPLES_PER_PIECE: usize = 8;

/// A polyline set: points in the plane and segments between them.
#[derive(Debug, Clone, Default)]
pub struct Polylines {
    /// Points.
    pub points: Vec<[f64; 2]>,
    /// Segments as point indices.
    pub segments: Vec<[usize; 2]>,
}

impl Polylines {
    /// Wavefront OBJ text: `v x y 0` and `l a b` records.
    pub fn to_obj(&self) -> String {
        let mut s = String::new();
        for p in &self.points {
            s.push_str(&format!("v {:.17} {:.17} 0\n", p[0], p[1]));
        }
        for e in &self.segments {
            s.push_str(&format!("l {} {}\n", e[0] + 1, e[1] + 1));
        }
        s
    }
    /// (components, closed loops) of the segment graph.
    pub fn topology(&self) -> (usize, usize) {
        let n = self.points.len();
        let mut sets = crate::numeric::UnionFind::new(n);
        let mut deg = vec![0usize; n];
        for e in &self.segments {
            deg[e[0]] += 1;
            deg[e[1]] += 1;
            sets.union(e[0], e[1]);
        }
        let mut comps: HashMap<usize, bool> = HashMap::new();
        for (v, &dv) in deg.iter().enumerate().take(n) {
            if dv == 0 {
                continue;
            }
            let r = sets.find(v);
            let closed = comps.entry(r).or_insert(true);
            if deg[v] != 2 {
                *closed = false;
            }
        }
        (comps.len(), comps.values().filter(|c| **c).count())
    }
}

/// Why the isocurve cannot be built.
#[derive(Debug, thiserror::Error)]
pub enum IsoError {
    /// f̂ is required to avoid the level c at vertices (f : V → ℝ − {c}, Sec. 1).
    #[error("vertex {vertex}: f = c = {value}; Sec. 1 takes f : V → ℝ − {{c}}")]
    LevelAtVertex {
        /// The vertex.
        vertex: usize,
        /// The value.
        value: String,
    },
}

/// The linear and curved isocurves and the checks made on them.
#[derive(Debug, Clone)]
pub struct Isocurves {
    /// O.
    pub linear: Polylines,
    /// 𝒪 (sampled).
    pub curved: Polylines,
    /// Checks (SD-L168 …).
    pub report: Vec<CheckResult>,
}

fn edge_point(f: &[Q], c: &Q, a: u32, b: u32) -> Q {
    // u with (1 − u) f_a + u f_b = c.
    let (fa, fb) = (&f[a as usize], &f[b as usize]);
    (c - fa) / (fb - fa)
}

/// Builds O and 𝒪 = X⁻¹(O) and checks them.
pub fn isocurves(
    k: &PlanarComplex,
    cm: &ComplexMap,
    f: &[Q],
    c: &Q,
) -> Result<Isocurves, IsoError> {
    for (v, fv) in f.iter().enumerate() {
        if fv == c {
            return Err(IsoError::LevelAtVertex {
                vertex: v,
                value: c.to_string(),
            });
        }
    }
    let mut lin = Polylines::default();
    let mut cur = Polylines::default();
    let mut edge_ids: HashMap<(u32, u32), (usize, usize)> = HashMap::new();
    let mut inv = CheckResult::new(
        "SD-L168(inverse)",
        "every curved point is X|σ⁻¹ of its linear point, inside σ, to the printed tolerance",
    );
    let mut worst = 0.0f64;
    for (fi, t) in k.triangles.iter().enumerate() {
        let m = &cm.maps[fi];
        let tol = super::inverse::tolerance(m);
        inv.tolerance = Some(inv.tolerance.map_or(tol, |x: f64| x.max(tol)));
        let mut crossings = Vec::new();
        for la in 0..3 {
            let lb = (la + 1) % 3;
            let (a, b) = (t[la], t[lb]);
            if ((&f[a as usize] - c).is_positive()) != ((&f[b as usize] - c).is_positive()) {
                let key = (a.min(b), a.max(b));
                let id = match edge_ids.get(&key) {
                    Some(&id) => id,
                    None => {
                        let u = edge_point(f, c, key.0, key.1);
                        let (p0, p1) =
                            (&k.points_f64[key.0 as usize], &k.points_f64[key.1 as usize]);
                        let uf = to_f64(&u);
                        lin.points
                            .push([p0[0] + uf * (p1[0] - p0[0]), p0[1] + uf * (p1[1] - p0[1])]);
                        // Invert X on the edge: find u' with X(edge(u')) = edge(u).
                        let (lo, hi) = (
                            t.iter().position(|&v| v == key.0).unwrap_or(0),
                            t.iter().position(|&v| v == key.1).unwrap_or(0),
                        );
                        let up = invert_edge(m, lo, hi, uf);
                        cur.points
                            .push([p0[0] + up * (p1[0] - p0[0]), p0[1] + up * (p1[1] - p0[1])]);
                        let id = (lin.points.len() - 1, cur.points.len() - 1);
                        edge_ids.insert(key, id);
                        id
                    }
                };
                crossings.push(id);
            }
        }
        if crossings.len() != 2 {
            continue;
        }
        let ((ia, ca), (ib, cb)) = (crossings[0], crossings[1]);
        lin.segments.push([ia, ib]);
        // Interior samples of the piece θ, inverted by Newton in σ's chart.
        let bary = |p: [f64; 2]| -> [f64; 2] {
            let q = [
                from_f64(p[0]).unwrap_or_default(),
                from_f64(p[1]).unwrap_or_default(),
            ];
            let w = k.barycentric(fi, &q);
            [to_f64(&w[1]), to_f64(&w[2])]
        };
        let (pa, pb) = (lin.points[ia], lin.points[ib]);
        let mut prev = ca;
        for j in 1..SAMPLES_PER_PIECE {
            let s = j as f64 / SAMPLES_PER_PIECE as f64;
            let y = bary([pa[0] + s * (pb[0] - pa[0]), pa[1] + s * (pb[1] - pa[1])]);
            inv.examined += 1;
            match newton(m, y, y) {
                Some(pre) if pre.residual <= tol => {
                    worst = worst.max(pre.residual);
                    let w = [1.0 - pre.st[0] - pre.st[1], pre.st[0], pre.st[1]];
                    if w.iter().any(|x| *x < -1e-12) {
                        inv.offend(|| {
                            Witness::new(
                                format!("triangle {fi}: preimage {w:?} is outside σ"),
                                json!({"triangle": fi, "w": w}),
                            )
                        });
                    }
                    let tp = t.map(|v| k.points_f64[v as usize]);
                    let p = [
                        w[0] * tp[0][0] + w[1] * tp[1][0] + w[2] * tp[2][0],
                        w[0] * tp[0][1] + w[1] * tp[1][1] + w[2] * tp[2][1],
                    ];
                    cur.points.push(p);
                    let id = cur.points.len() - 1;
                    cur.segments.push([prev, id]);
                    prev = id;
                }
                other => {
                    let res = other.map(|p| p.residual);
                    inv.offend(|| Witness::new(format!("triangle {fi}: Newton failed for target (s,t) = {y:?} (residual {res:?})"), json!({"triangle": fi, "target": y})));
                }
            }
        }
        cur.segments.push([prev, cb]);
    }
    inv.worst_deviation = Some(worst);
    if inv.examined == 0 {
        inv.skip("the level set misses every triangle");
    }
    let mut topo = CheckResult::new("SD-L168", "Sec. 4: 𝒪 = X⁻¹(O) has the topology of O (components and closed loops) and no self-crossing");
    let (lc, ll) = lin.topology();
    let (cc, cl) = cur.topology();
    topo.examined = cur.segments.len() as u64;
    if (lc, ll) != (cc, cl) {
        topo.offend(|| {
            Witness::new(
                format!("O has {lc} components ({ll} closed), 𝒪 has {cc} ({cl} closed)"),
                json!({"linear": [lc, ll], "curved": [cc, cl]}),
            )
        });
    }
    for (i, j) in crossing_segments(&cur) {
        topo.offend(|| {
            Witness::new(
                format!("curved segments {i} and {j} cross"),
                json!({"segments": [i, j]}),
            )
        });
    }
    topo.note = format!("O: {lc} components, {ll} closed; 𝒪: {cc} components, {cl} closed");
    if topo.examined == 0 {
        topo.skip("the level set misses every triangle");
    }
    Ok(Isocurves {
        linear: lin,
        curved: cur,
        report: vec![inv, topo],
    })
}

fn invert_edge(m: &super::maps::SimplexMap, la: usize, lb: usize, u: f64) -> f64 {
    // x_{lb} along the edge from local la to lb, increasing from 0 to 1 when SD-L101(edges) holds.
    let at = |x: f64| -> f64 {
        let mut st = [0.0f64; 3];
        st[la] = 1.0 - x;
        st[lb] = x;
        let (s, t) = (st[1], st[2]);
        let d = m.den.eval_f64(s, t);
        m.num[lb].eval_f64(s, t) / d
    };
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    for _ in 0..80 {
        let mid = 0.5 * (lo + hi);
        if at(mid) < u {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// Pairs of segments that cross properly (exact orientation signs on the f64 points), other
/// than neighbours sharing an endpoint.
fn crossing_segments(p: &Polylines) -> Vec<(usize, usize)> {
    let q = |x: [f64; 2]| {
        [
            from_f64(x[0]).unwrap_or_default(),
            from_f64(x[1]).unwrap_or_default(),
        ]
    };
    let orient = |a: &[Q; 2], b: &[Q; 2], c: &[Q; 2]| {
        ((&b[0] - &a[0]) * (&c[1] - &a[1]) - (&b[1] - &a[1]) * (&c[0] - &a[0])).signum()
    };
    let segs: Vec<[[Q; 2]; 2]> = p
        .segments
        .iter()
        .map(|e| [q(p.points[e[0]]), q(p.points[e[1]])])
        .collect();
    let mut out = Vec::new();
    // Quadratic, bounded by the isocurve size (a few points per triangle); fine for the
    // complexes of the paper.
    for i in 0..segs.len() {
        for j in (i + 1)..segs.len() {
            let (a, b) = (p.segments[i], p.segments[j]);
            if a.iter().any(|x| b.contains(x)) {
                continue;
            }
            let (s, t) = (&segs[i], &segs[j]);
            let d1 = orient(&s[0], &s[1], &t[0]);
            let d2 = orient(&s[0], &s[1], &t[1]);
            let d3 = orient(&t[0], &t[1], &s[0]);
            let d4 = orient(&t[0], &t[1], &s[1]);
            if d1 * d2 < Q::zero() && d3 * d4 < Q::zero() {
                out.push((i, j));
            }
        }
    }
    out
}
