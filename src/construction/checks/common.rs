//! What the checks of Chapter 4 share: the stated condition factors of their tolerances, the
//! verdict of an inconclusive search, and the formatting of points in reports.

use crate::construction::maps::*;
use crate::construction::sampling::Category;
use crate::numeric::{Scalar, Trit};
use crate::report::Verdict;
use serde_json::json;

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

pub(super) fn pt<S: Scalar>(p: &P2<S>) -> serde_json::Value {
    json!([p.x.to_f64(), p.y.to_f64()])
}
pub(super) fn fmt<S: Scalar>(p: &P2<S>) -> String {
    format!("({:.17e}, {:.17e})", p.x.to_f64(), p.y.to_f64())
}
pub(super) fn amp(ms: &[u32]) -> f64 {
    ms.iter()
        .map(|&m| (m as f64 / 6.0).max(6.0 / m as f64))
        .fold(1.0, f64::max)
}
pub(super) fn angle_of<S: Scalar>(p: &P2<S>) -> Option<f64> {
    polar(p).ok().map(|q| q.theta.to_f64())
}
/// Reflection of p across the line through 0 at angle `a`.
pub(super) fn reflect<S: Scalar>(p: &P2<S>, a: &S) -> P2<S> {
    let q = rotate(p, &a.neg());
    rotate(&P2::new(q.x, q.y.neg()), a)
}
pub(super) fn zero_pt<S: Scalar>(prec: u32) -> P2<S> {
    P2::new(S::from_i64(0, prec), S::from_i64(0, prec))
}
pub(super) fn scalar_pi<S: Scalar>(prec: u32) -> S {
    S::pi(prec)
}
pub(super) fn unit_eps<S: Scalar>(prec: u32) -> f64 {
    S::from_i64(1, prec).epsilon()
}

pub(super) fn counts_of(cats: &[Category]) -> String {
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

#[cfg(test)]
mod tests {
    use super::amp;

    /// The tolerances' amplification by degree: max over the degrees of max(m/6, 6/m), at
    /// least 1 (g_v stretches angles by m/6, g_v⁻¹ by 6/m).
    #[test]
    fn amp_is_the_largest_angle_stretch_of_the_degrees() {
        assert_eq!(amp(&[]), 1.0);
        assert_eq!(amp(&[6]), 1.0);
        assert_eq!(amp(&[3]), 2.0);
        assert_eq!(amp(&[7]), 7.0 / 6.0);
        assert_eq!(amp(&[12, 4]), 2.0);
        assert_eq!(amp(&[5, 13]), 13.0 / 6.0);
    }
}
