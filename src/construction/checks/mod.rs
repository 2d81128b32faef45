//! Conformance checks of Chapter 4 on configurations (no mesh needed).
//!
//! Every check is generic over the scalar `S` and over the model `M: Ppm<S>` (the paper's
//! construction is [`Paper`]; tests pass models with planted faults). Every check samples
//! deterministically from `seed`, and reports the number of samples examined (with per-category
//! counts in the note), the worst deviation, and the tolerance used. Tolerances are
//! `COND · ε` with ε the unit roundoff of the precision in use and `COND` a named, stated
//! condition factor; they are never tuned to make a check pass.
//!
//! Statements that fail as written are reported as `Fails` with witnesses; where the paper's
//! statement holds on a smaller domain, a second result with the suffix `[restricted]` checks
//! it there and reports `HoldsRestricted { domain }`.

use super::maps::*;
use super::sampling::*;
use crate::numeric::{Scalar, Trit};
use crate::report::{dev_max, Check, CheckResult, OnError, Restricted, Verdict, Witness};
use serde_json::json;

mod edge;
mod edge_maps;
mod polar;
mod smooth;
mod star;
mod triangle;

pub use edge::*;
pub use edge_maps::*;
pub use polar::*;
pub use star::*;
pub use triangle::*;

use edge::omega_uw_points;
use edge_maps::{guw_inner_radius, guw_lipschitz};
use smooth::{smooth_test, SmoothSpec};
use triangle::star_samples;

/// Condition factor of simple identities (Π round trip, the h-identity): a few dozen
/// operations, each with relative error ≤ ε, on points of norm ≤ 2.
pub const IDENTITY_COND: f64 = 64.0;

/// Fewest samples per category with which a sampled existence search ("Ω ≠ ∅": P4.1.3,
/// P4.2.1) may report that it found no witness as a failure. With fewer, finding none is
/// inconclusive (`Skipped`): a handful of random points missing a lens proves nothing.
pub const MIN_EMPTINESS_SAMPLES: usize = 8;

/// The `Skipped` verdict of an existence search with too few samples to conclude.
pub fn inconclusive_search(n: usize) -> Verdict {
    Verdict::Skipped {
        reason: format!(
            "inconclusive: no witness among the samples, but {n} per category is fewer than the {MIN_EMPTINESS_SAMPLES} needed to report emptiness (raise --samples)"
        ),
    }
}
/// Condition factor of the g_v round trips: 256 · max(1, m/6, 6/m) (angle scaled by m/6 then
/// by 6/m; trigonometric functions of angles up to m·π/6).
pub const GV_COND: f64 = 256.0;
/// Condition factor of the central-difference Jacobian test (Taylor remainder h²/6·|f'''| with
/// |f'''| ≤ L·max(1,k)²/r², plus rounding ε(|F(p)| + L·r)/h), a safety factor of 16.
pub const FD_COND: f64 = 16.0;
/// Condition factor of the jump test: rounding of |f(a) − f(b)| is ≤ 64·ε·(|f| + L·|p|) (the
/// error of the early stages, ε·|p|, stretched by up to L; as in the FD test).
pub const JUMP_COND: f64 = 64.0;
/// Condition factor of compositions of several g_(u,w) (P4.2.3, L4.2.2, L4.2.3, P4.2.4):
/// 2^14 · max(1, m/6) over the degrees involved.
pub const COMPOSITE_COND: f64 = 16384.0;

fn pt<S: Scalar>(p: &P2<S>) -> serde_json::Value {
    json!([p.x.to_f64(), p.y.to_f64()])
}
fn fmt<S: Scalar>(p: &P2<S>) -> String {
    format!("({:.17e}, {:.17e})", p.x.to_f64(), p.y.to_f64())
}
fn amp(ms: &[u32]) -> f64 {
    ms.iter()
        .map(|&m| (m as f64 / 6.0).max(6.0 / m as f64))
        .fold(1.0, f64::max)
}
fn angle_of<S: Scalar>(p: &P2<S>) -> Option<f64> {
    polar(p).ok().map(|q| q.theta.to_f64())
}
/// Reflection of p across the line through 0 at angle `a`.
fn reflect<S: Scalar>(p: &P2<S>, a: &S) -> P2<S> {
    let q = rotate(p, &a.neg());
    rotate(&P2::new(q.x, q.y.neg()), a)
}
fn zero_pt<S: Scalar>(prec: u32) -> P2<S> {
    P2::new(S::from_i64(0, prec), S::from_i64(0, prec))
}
fn scalar_pi<S: Scalar>(prec: u32) -> S {
    S::pi(prec)
}
fn unit_eps<S: Scalar>(prec: u32) -> f64 {
    S::from_i64(1, prec).epsilon()
}

/// Samples of Ω_u − {0} with the cut ray at the angle where g_u ∘ R_(u,w) is cut: the ray
/// opposite u'_i, angle π + 2πi/m_u.
fn omega_u_samples<S: Scalar>(e: &EdgeConfig, seed: u64, n: usize, prec: u32) -> Samples<S> {
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
fn lens_pullbacks<S: Scalar, M: Ppm<S>>(
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

fn counts_of(cats: &[Category]) -> String {
    let mut m = std::collections::BTreeMap::new();
    for c in cats {
        *m.entry(*c).or_insert(0usize) += 1;
    }
    m.iter()
        .map(|(c, n)| format!("{c:?} {n}"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// Helper for reports: the origin at precision `prec` (Π is undefined there).
pub fn origin<S: Scalar>(prec: u32) -> P2<S> {
    zero_pt(prec)
}

/// Membership as a `Trit` for the reports of the lead's mesh layer (literal Def. 4.1.9).
pub fn membership<S: Scalar>(pair: &VertexPair, p: &P2<S>) -> Trit {
    Paper.in_omega_pair(pair, p)
}
