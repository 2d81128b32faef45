//! Where the surface checks look: the examined vertices and random points of Ω_v and of its
//! overlaps.

use crate::construction::P2;
use crate::mesh::VertexId;
use crate::report::{Check, OnError, Witness};
use crate::surface::pps::Pps;
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use serde_json::json;

/// The examined vertices (evenly spaced subset).
pub fn examined_vertices(pps: &Pps, max: Option<usize>) -> Vec<VertexId> {
    let all: Vec<VertexId> = pps.vertices().collect();
    match max {
        Some(n) if n < all.len() && n > 0 => {
            let step = all.len() as f64 / n as f64;
            (0..n).map(|i| all[(i as f64 * step) as usize]).collect()
        }
        _ => all,
    }
}

/// Uniform random point of Ω_v scaled by `frac` (frac < 1 keeps away from the rim).
pub(super) fn random_in_omega(rng: &mut ChaCha8Rng, radius: f64, frac: f64) -> [f64; 2] {
    loop {
        let x: f64 = rng.gen_range(-1.0..1.0);
        let y: f64 = rng.gen_range(-1.0..1.0);
        if x * x + y * y < 1.0 {
            return [x * radius * frac, y * radius * frac];
        }
    }
}

/// Random points of Ω_v lying in some gluing domain Ω_vu, u ≠ v. A failed J_v(p) is an
/// evaluation error of `chk` (an offence: p ∈ Ω_v is in the domain of Eq. 5.1).
pub(super) fn overlap_points(
    pps: &Pps,
    v: VertexId,
    rng: &mut ChaCha8Rng,
    n: usize,
    chk: &mut Check,
) -> Vec<[f64; 2]> {
    let c = pps.consts_f64();
    let r = c.degree(pps.degree(v)).map(|d| d.radius).unwrap_or(0.5);
    let mut out = Vec::with_capacity(n);
    let mut tries = 0;
    while out.len() < n && tries < 50 * n {
        tries += 1;
        let p = random_in_omega(rng, r, 0.999);
        match pps.terms(v, &P2::new(p[0], p[1]), c, None) {
            Ok(t) if t.len() > 1 => out.push(p),
            Ok(_) => {}
            Err(e) => chk.error(OnError::Offence, &e, || {
                Witness::new(
                    format!("v={v} p={p:?}: J_v(p) failed: {e}"),
                    json!({"v": v, "p": p}),
                )
            }),
        }
    }
    out
}
