//! Curved isocomplexes in the plane (Mello–Velho Sec. 4): the linear isocurve O = f̂⁻¹(c) and
//! the curved one 𝒪 = (f̂∘X)⁻¹(c) = X⁻¹(O), sampled as X|σ⁻¹ of points of each linear piece θ.
//!
//! Points on an edge are inverted once per edge with the edge's own 1-D map (bisection), so
//! the two triangles of an interior edge share them and the output is watertight.

use super::complex::PlanarComplex;
use super::inverse::newton;
use super::params::ComplexMap;
use crate::numeric::predicates::orient2;
use crate::report::{CheckResult, Witness};
use crate::sdiff::common::rational::{from_f64, to_f64, Q};
use num_traits::Signed;
use serde_json::json;
use std::cmp::Ordering;
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
    match crossing_segments(&cur) {
        Ok(pairs) => {
            for (i, j) in pairs {
                topo.offend(|| {
                    Witness::new(
                        format!("curved segments {i} and {j} cross"),
                        json!({"segments": [i, j]}),
                    )
                });
            }
        }
        Err(i) => topo.offend(|| {
            Witness::new(
                format!("curved point {i} is not finite: crossings undecided"),
                json!({"point": i}),
            )
        }),
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
/// than neighbours sharing an endpoint, in lexicographic order; `Err(i)` names a non-finite
/// point, for which no sign is defined.
///
/// A sweep over the segments sorted by their smallest x: a proper crossing is a point inside
/// both segments, so two segments whose x-ranges (or y-ranges) are disjoint never cross, and
/// only pairs with overlapping boxes reach the exact predicate (`numeric::predicates`).
fn crossing_segments(p: &Polylines) -> Result<Vec<(usize, usize)>, usize> {
    if let Some(i) = p
        .points
        .iter()
        .position(|x| !x.iter().all(|c| c.is_finite()))
    {
        return Err(i);
    }
    let ends = |e: &[usize; 2]| (p.points[e[0]], p.points[e[1]]);
    let range = |a: f64, b: f64| (a.min(b), a.max(b));
    let boxes: Vec<[(f64, f64); 2]> = p
        .segments
        .iter()
        .map(|e| {
            let (a, b) = ends(e);
            [range(a[0], b[0]), range(a[1], b[1])]
        })
        .collect();
    let mut order: Vec<usize> = (0..boxes.len()).collect();
    order.sort_by(|&i, &j| boxes[i][0].0.total_cmp(&boxes[j][0].0).then(i.cmp(&j)));
    // c and d strictly on opposite sides of the line ab (the points are finite: every sign is
    // defined).
    let apart = |a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]| {
        matches!(
            (orient2(a, b, c), orient2(a, b, d)),
            (Some(Ordering::Less), Some(Ordering::Greater))
                | (Some(Ordering::Greater), Some(Ordering::Less))
        )
    };
    let mut out = Vec::new();
    for (k, &i) in order.iter().enumerate() {
        let x_hi = boxes[i][0].1;
        for &j in &order[k + 1..] {
            if boxes[j][0].0 > x_hi {
                break;
            }
            let (yi, yj) = (boxes[i][1], boxes[j][1]);
            if yi.1 < yj.0 || yj.1 < yi.0 {
                continue;
            }
            let (a, b) = (p.segments[i], p.segments[j]);
            if a.iter().any(|x| b.contains(x)) {
                continue;
            }
            let (s, t) = (ends(&a), ends(&b));
            if apart(s.0, s.1, t.0, t.1) && apart(t.0, t.1, s.0, s.1) {
                out.push((i.min(j), i.max(j)));
            }
        }
    }
    out.sort_unstable();
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sdiff::common::rational::from_f64;
    use num_traits::Zero;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    /// Every pair, the signs in exact rationals: the definition the sweep must reproduce.
    fn crossing_all_pairs(p: &Polylines) -> Vec<(usize, usize)> {
        let q = |x: [f64; 2]| x.map(|c| from_f64(c).unwrap_or_default());
        let orient = |a: &[Q; 2], b: &[Q; 2], c: &[Q; 2]| {
            ((&b[0] - &a[0]) * (&c[1] - &a[1]) - (&b[1] - &a[1]) * (&c[0] - &a[0])).signum()
        };
        let mut out = Vec::new();
        for i in 0..p.segments.len() {
            for j in (i + 1)..p.segments.len() {
                let (a, b) = (p.segments[i], p.segments[j]);
                if a.iter().any(|x| b.contains(x)) {
                    continue;
                }
                let s = [q(p.points[a[0]]), q(p.points[a[1]])];
                let t = [q(p.points[b[0]]), q(p.points[b[1]])];
                let d1 = orient(&s[0], &s[1], &t[0]) * orient(&s[0], &s[1], &t[1]);
                let d2 = orient(&t[0], &t[1], &s[0]) * orient(&t[0], &t[1], &s[1]);
                if d1 < Q::zero() && d2 < Q::zero() {
                    out.push((i, j));
                }
            }
        }
        out
    }

    #[test]
    fn sd_l168_crossing_sweep_equals_all_pairs_on_random_polylines() {
        let mut rng = ChaCha8Rng::seed_from_u64(168);
        let mut crossings = 0;
        for case in 0..200 {
            // Points on a coarse grid (collinear and touching cases are frequent) or anywhere.
            let grid = case % 2 == 0;
            let n = rng.gen_range(2..40);
            let points: Vec<[f64; 2]> = (0..n)
                .map(|_| {
                    if grid {
                        [
                            rng.gen_range(0..5) as f64 / 4.0,
                            rng.gen_range(0..5) as f64 / 4.0,
                        ]
                    } else {
                        [rng.gen::<f64>(), rng.gen::<f64>()]
                    }
                })
                .collect();
            let segments: Vec<[usize; 2]> = (0..rng.gen_range(1..40))
                .map(|_| [rng.gen_range(0..n), rng.gen_range(0..n)])
                .collect();
            let p = Polylines { points, segments };
            let want = crossing_all_pairs(&p);
            crossings += want.len();
            assert_eq!(crossing_segments(&p), Ok(want), "case {case}");
        }
        assert!(crossings > 100, "{crossings}");
    }

    #[test]
    fn sd_l168_planted_crossing_and_non_finite_point_are_reported() {
        // Two diagonals of the unit square cross; a touching pair (an endpoint on the other
        // segment) and a pair sharing an endpoint do not.
        let points = vec![
            [0.0, 0.0],
            [1.0, 1.0],
            [0.0, 1.0],
            [1.0, 0.0],
            [0.5, 0.5],
            [2.0, 2.0],
        ];
        let p = Polylines {
            points: points.clone(),
            segments: vec![[0, 1], [2, 3], [4, 5], [1, 5]],
        };
        assert_eq!(crossing_segments(&p), Ok(vec![(0, 1)]));
        let mut bad = Polylines {
            points,
            segments: vec![[0, 1], [2, 3]],
        };
        bad.points[3] = [f64::NAN, 0.0];
        assert_eq!(crossing_segments(&bad), Err(3));
    }
}
