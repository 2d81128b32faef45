//! The tolerances of the surface checks (the module doc of `checks`):
//! `COND · max(1, m/6) · l · ε · S`.

use crate::mesh::VertexId;
use crate::numeric::Scalar;
use crate::surface::pps::Pps;

/// Condition factor of the tolerances (see the module doc).
pub const COND: f64 = 4096.0;

/// Euclidean distance of two points of R³ in `S`, in f64.
pub(super) fn dist3<S: Scalar>(a: &[S; 3], b: &[S; 3]) -> f64 {
    let mut s = 0.0;
    for d in 0..3 {
        let x = a[d].sub(&b[d]).to_f64();
        s += x * x;
    }
    s.sqrt()
}

/// Largest |control point coordinate| of the patches of the given vertices.
pub fn local_scale(pps: &Pps, vs: &[VertexId]) -> f64 {
    vs.iter()
        .flat_map(|&v| pps.patch(v).0.iter().flat_map(|c| c.iter()))
        .fold(0.0f64, |a, &b| a.max(b.abs()))
}

/// Tolerance for comparing θ values around vertex v at unit roundoff `eps`.
pub fn tolerance(pps: &Pps, v: VertexId, eps: f64) -> f64 {
    let m = pps.degree(v);
    let mut vs = vec![v];
    let mut l = pps.patch(v).1;
    for i in 0..m {
        let u = pps.link(v, i);
        vs.push(u);
        l = l.max(pps.patch(u).1);
    }
    let mmax = vs.iter().map(|&u| pps.degree(u)).max().unwrap_or(6);
    COND * (mmax as f64 / 6.0).max(1.0) * l as f64 * eps * local_scale(pps, &vs)
}
