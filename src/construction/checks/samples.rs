//! Sample points of the domains the checks of Chapter 4 run on: Ω_u with its cut ray, the
//! pull-backs of the canonical lens, Ω_uw (literal Def. 4.1.9) and the star of a vertex.

use super::common::scalar_pi;
use crate::construction::maps::*;
use crate::construction::sampling::*;
use crate::numeric::Scalar;

/// Samples of Ω_u − {0} with the cut ray at the angle where g_u ∘ R_(u,w) is cut: the ray
/// opposite u'_i, angle π + 2πi/m_u.
pub(super) fn omega_u_samples<S: Scalar>(
    e: &EdgeConfig,
    seed: u64,
    n: usize,
    prec: u32,
) -> Samples<S> {
    let r = omega_radius::<S>(e.m_u, prec);
    let cut = scalar_pi::<S>(prec).mul(&S::from_ratio(
        e.m_u as i64 + 2 * e.i as i64,
        e.m_u as i64,
        prec,
    ));
    sample_disk(seed, n, &r, &cut, prec)
}

/// Points of Ω_uw obtained by pulling the canonical-lens samples back by R_(u,w)⁻¹ ∘ g_u⁻¹
/// (candidates: membership is still decided by the model's literal Def. 4.1.9 test).
pub(super) fn lens_pullbacks<S: Scalar, M: Ppm<S>>(
    model: &M,
    e: &EdgeConfig,
    seed: u64,
    n: usize,
    prec: u32,
) -> Vec<(Category, P2<S>, P2<S>)> {
    let lens = sample_lens::<S>(seed, n, prec);
    let mut out = Vec::new();
    for (c, q) in lens.points {
        if let Ok(a) = model.g_v_inv(e.m_u, &q) {
            out.push((c, model.r_uw_inv(e, &a), q));
        }
    }
    out
}

/// Samples of Ω_u for an edge: the disk sampler (cut at the ray opposite u'_i) and the lens
/// pull-backs, with category labels.
pub(super) fn edge_domain_samples<S: Scalar, M: Ppm<S>>(
    model: &M,
    e: &EdgeConfig,
    seed: u64,
    n: usize,
    prec: u32,
) -> Vec<(Category, P2<S>)> {
    let mut v: Vec<(Category, P2<S>)> = omega_u_samples::<S>(e, seed, n, prec).points;
    v.extend(
        lens_pullbacks(model, e, seed ^ 0x1e75, n, prec)
            .into_iter()
            .map(|(c, p, _)| (c, p)),
    );
    v
}

/// Points of Ω_uw (literal Def. 4.1.9) from the edge samples.
pub(super) fn omega_uw_points<S: Scalar, M: Ppm<S>>(
    model: &M,
    e: &EdgeConfig,
    seed: u64,
    n: usize,
    prec: u32,
) -> Vec<(Category, P2<S>)> {
    edge_domain_samples(model, e, seed, n, prec)
        .into_iter()
        .filter(|(_, p)| model.in_omega_uw_literal(e, p).is_true())
        .collect()
}

/// Points of Ω_x near the gluing domains of the two edges x→a, x→b: disk samples of Ω_x plus
/// lens pull-backs for both edges.
pub(super) fn star_samples<S: Scalar, M: Ppm<S>>(
    model: &M,
    edges: &[EdgeConfig],
    seed: u64,
    n: usize,
    prec: u32,
) -> Vec<(Category, P2<S>)> {
    let mut v: Vec<(Category, P2<S>)> = Vec::new();
    if let Some(e0) = edges.first() {
        v.extend(omega_u_samples::<S>(e0, seed, n, prec).points);
    }
    for (k, e) in edges.iter().enumerate() {
        v.extend(
            lens_pullbacks(model, e, seed ^ (0x51 + k as u64), n, prec)
                .into_iter()
                .map(|(c, p, _)| (c, p)),
        );
    }
    v
}
