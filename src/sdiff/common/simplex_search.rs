//! The conjecture of L146 in any dimension m: an adjusted polynomial map (Eq. (10)) of degree
//! n on the m-simplex whose non-solitary control points are fixed (b_I = I/n) is injective;
//! proved by the paper's reference for m = 2, 3 only. Searched exactly with the engine of
//! [`super::simplex_poly`]: every sample is certified (det DX > 0 on the closed simplex, which
//! with X = id on ∂σ — every B_I of a solitary I vanishes on the faces missing supp I, and the
//! point moves inside that face — makes X bijective, `SD-L101(edges)`), refuted at an exact
//! point, or unresolved (reported as skipped, never as holds).
//!
//! For n = m + 1 the only solitary index is S = (1, …, 1) and X(w) = w + (c − ι)·n!·Π w_j
//! (linear precision of the fixed points), so det DX = 1 + n!·Σ_k d_k Π_{j≠k} w_j,
//! d = c − ι (matrix determinant lemma, Σ d_k = 0). [`closed_form_top`] builds it; the search
//! checks the engine's numerator against it as a polynomial identity.

use super::simplex_poly::{
    det_decision, fixed_control, indices, is_solitary, SimplexDecision, SimplexError, SimplexMapM,
    SimplexPoly,
};
use crate::report::{CheckResult, Witness};
use crate::sdiff::common::positivity::{Budget, Decision};
use crate::sdiff::common::rational::{q, qr, Q};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde_json::json;

/// What a search found.
#[derive(Debug, Clone, Default)]
pub struct Search {
    /// Maps certified injective-by-det.
    pub certified: u64,
    /// Maps with an exact point of det ≤ 0 (description of the map, the decision).
    pub refuted: Vec<(String, Decision)>,
    /// Maps neither certified nor refuted within the budget.
    pub unresolved: u64,
}

impl Search {
    /// Counts one sample's decision; a refuted map is kept with its description (made only
    /// then). The one tally of the planar, the monotonic 3-D and the rational 3-D searches.
    pub(crate) fn record(&mut self, d: Decision, describe: impl FnOnce() -> String) {
        match d {
            Decision::Certified { .. } => self.certified += 1,
            d @ Decision::Refuted { .. } => self.refuted.push((describe(), d)),
            Decision::Unresolved { .. } => self.unresolved += 1,
        }
    }
}

/// A rational in (0, 1): extremes (1/1000, 999/1000, 1/2) one time in four, else k/997.
pub(crate) fn unit_open(rng: &mut ChaCha8Rng) -> Q {
    match rng.gen_range(0..8) {
        0 => qr(1, 1000),
        1 => qr(999, 1000),
        _ => qr(rng.gen_range(1..997), 997),
    }
}

/// A random point of the open face with support `supp` (barycentric, exact).
pub(crate) fn open_face_point(rng: &mut ChaCha8Rng, supp: &[bool]) -> Vec<Q> {
    let w: Vec<Q> = supp
        .iter()
        .map(|&s| if s { unit_open(rng) } else { q(0) })
        .collect();
    let total: Q = w.iter().cloned().sum();
    w.into_iter().map(|x| x / &total).collect()
}

/// Degree n on the m-simplex, every non-solitary b_I fixed, every solitary b_I random in the
/// open face supp I (adjusted, L137).
pub fn fixed_solitary_control(m: usize, n: usize, rng: &mut ChaCha8Rng) -> Vec<Vec<Q>> {
    let mut control = fixed_control(m, n);
    for (b, i) in control.iter_mut().zip(indices(m, n)) {
        if is_solitary(&i) {
            *b = open_face_point(rng, &i.iter().map(|&k| k > 0).collect::<Vec<_>>());
        }
    }
    control
}

/// The worst corners of the search space: det DX is affine in each solitary point separately
/// (DX = I + Σ_S d_S ∇φ_Sᵀ, det(I + D Gᵀ) = det(I + Gᵀ D) is affine in each column d_S), so
/// for each w its minimum over the closed faces is at their vertices. Each solitary point is
/// put at (1 − ε)·(a seeded vertex of its face) + ε·(the face's centroid), ε = 1/1000 (open).
pub fn near_vertex_control(m: usize, n: usize, rng: &mut ChaCha8Rng) -> Vec<Vec<Q>> {
    near_vertex_with(m, n, |size| rng.gen_range(0..size))
}

/// The solitary points near the vertices chosen by `pick(face size)` (in index order).
fn near_vertex_with(m: usize, n: usize, mut pick: impl FnMut(usize) -> usize) -> Vec<Vec<Q>> {
    let eps = qr(1, 1000);
    let mut control = fixed_control(m, n);
    for (b, i) in control.iter_mut().zip(indices(m, n)) {
        if is_solitary(&i) {
            let supp: Vec<usize> = (0..=m).filter(|&k| i[k] > 0).collect();
            let v = supp[pick(supp.len()) % supp.len()];
            let share = &eps / q(supp.len() as i64);
            *b = (0..=m)
                .map(|k| {
                    let base = if k == v { q(1) - &eps } else { q(0) };
                    if i[k] > 0 {
                        base + &share
                    } else {
                        base
                    }
                })
                .collect();
        }
    }
    control
}

/// Number of vertex configurations: Π over solitary I of |supp I| (saturating).
pub fn vertex_configurations(m: usize, n: usize) -> usize {
    indices(m, n)
        .iter()
        .filter(|i| is_solitary(i))
        .fold(1usize, |acc, i| acc.saturating_mul(i.iter().sum::<usize>()))
}

/// Configuration number `code` (mixed radix over the solitary points in index order) of
/// [`near_vertex_control`]'s corners: every corner of the search space, enumerated.
pub fn vertex_configuration(m: usize, n: usize, code: usize) -> Vec<Vec<Q>> {
    let mut rest = code;
    near_vertex_with(m, n, |size| {
        let d = rest % size;
        rest /= size;
        d
    })
}

/// 1 + (m+1)!·Σ_k (c_k − 1/(m+1))·Π_{j≠k} w_j: det DX for n = m + 1 with the solitary point
/// at c (in homogeneous degree m).
pub fn closed_form_top(m: usize, c: &[Q]) -> SimplexPoly {
    let n = m + 1;
    let fact: i64 = (1..=n as i64).product();
    let mut out = SimplexPoly::constant(m, q(1)).elevate(m);
    for (k, ck) in c.iter().enumerate() {
        let prod = (0..=m)
            .filter(|&j| j != k)
            .fold(SimplexPoly::constant(m, q(1)), |acc, j| {
                acc.mul(&SimplexPoly::w(m, j))
            });
        let dk = ck - qr(1, n as i64);
        out = out.axpy(&(dk * q(fact)), &prod);
    }
    out
}

/// One refuted sample.
#[derive(Debug, Clone, serde::Serialize)]
pub struct Refutation {
    /// The solitary control points (index, point), exact.
    pub solitary: Vec<(Vec<usize>, Vec<String>)>,
    /// The exact decision.
    pub decision: SimplexDecision,
}

/// What a search found.
#[derive(Debug, Clone, Default, serde::Serialize)]
pub struct SolitarySearch {
    /// Dimension.
    pub m: usize,
    /// Degree.
    pub n: usize,
    /// Seed.
    pub seed: u64,
    /// Samples drawn.
    pub samples: usize,
    /// Certified det DX > 0 exactly.
    pub certified: usize,
    /// Refuted exactly.
    pub refuted: Vec<Refutation>,
    /// Neither within the budget.
    pub unresolved: usize,
    /// n = m + 1 only: samples whose numerator differs from [`closed_form_top`] (an engine
    /// defect if ever > 0).
    pub closed_form_mismatches: usize,
    /// Pieces of the largest certificate.
    pub max_pieces: usize,
}

/// Runs `samples` seeded maps of [`fixed_solitary_control`] through [`det_decision`].
pub fn search_fixed_solitary(
    m: usize,
    n: usize,
    samples: usize,
    seed: u64,
    budget: Budget,
) -> Result<SolitarySearch, SimplexError> {
    search_with(m, n, samples, seed, budget, fixed_solitary_control)
}

/// The same with another generator of control points (planted faults use it).
pub fn search_with(
    m: usize,
    n: usize,
    samples: usize,
    seed: u64,
    budget: Budget,
    mut gen: impl FnMut(usize, usize, &mut ChaCha8Rng) -> Vec<Vec<Q>>,
) -> Result<SolitarySearch, SimplexError> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut s = SolitarySearch {
        m,
        n,
        seed,
        samples,
        ..Default::default()
    };
    let idx = indices(m, n);
    let top = idx.iter().position(|i| i.iter().all(|&k| k == 1));
    for _ in 0..samples {
        let control = gen(m, n, &mut rng);
        let map = SimplexMapM::new(m, n, &control, None)?;
        if let Some(k) = top {
            let num = map.jacobian_numerator();
            let closed = closed_form_top(m, &control[k]);
            if num != closed.elevate(num.degree().saturating_sub(closed.degree())) {
                s.closed_form_mismatches += 1;
            }
        }
        match det_decision(&map, budget)? {
            SimplexDecision::Certified { pieces, .. } => {
                s.certified += 1;
                s.max_pieces = s.max_pieces.max(pieces);
            }
            d @ SimplexDecision::Refuted { .. } => s.refuted.push(Refutation {
                solitary: idx
                    .iter()
                    .zip(&control)
                    .filter(|(i, _)| is_solitary(i))
                    .map(|(i, b)| (i.clone(), b.iter().map(|x| x.to_string()).collect()))
                    .collect(),
                decision: d,
            }),
            SimplexDecision::Unresolved { .. } => s.unresolved += 1,
        }
    }
    Ok(s)
}

/// `SD-L146(4-D)` (any m) as a [`CheckResult`]: holds when every sample is certified; a
/// refutation is an offence with its exact point; unresolved samples or zero samples skip; a
/// closed-form mismatch is an offence of the engine.
pub fn judge(id: &str, s: &SolitarySearch) -> CheckResult {
    let mut r = CheckResult::new(
        id,
        format!(
            "L146, m = {}, degree {}: fixed non-solitary ⇒ injective",
            s.m, s.n
        ),
    );
    r.seed = Some(s.seed);
    r.examined = s.samples as u64;
    for f in &s.refuted {
        if let SimplexDecision::Refuted {
            point,
            point_f64,
            value,
            value_f64,
        } = &f.decision
        {
            r.offend(|| {
                Witness::new(
                    format!(
                        "det DX numerator = {value_f64:.3e} ≤ 0 at w = {point_f64:?}, solitary points {:?}",
                        f.solitary
                    ),
                    json!({"w": point, "value": value, "solitary": f.solitary}),
                )
            });
        }
    }
    if s.closed_form_mismatches > 0 {
        r.offend(|| {
            Witness::new(
                format!(
                    "{} samples whose Jacobian numerator differs from 1 + n!·Σ d_k Π_(j≠k) w_j",
                    s.closed_form_mismatches
                ),
                json!({"closed_form_mismatches": s.closed_form_mismatches}),
            )
        });
    }
    if !r.failed() {
        if s.samples == 0 {
            r.skip("zero samples");
        } else if s.unresolved > 0 {
            r.skip(format!(
                "{} of {} samples unresolved",
                s.unresolved, s.samples
            ));
        }
    }
    r.note = format!(
        "{} certified exactly, {} refuted, {} unresolved (seed {}, largest certificate {} pieces)",
        s.certified,
        s.refuted.len(),
        s.unresolved,
        s.seed,
        s.max_pieces
    );
    r
}
