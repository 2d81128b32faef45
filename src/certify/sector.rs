//! The exact sector argument of the star provers and of the lens agreement: it decides, with
//! no δ, the points where the open gluing domains of a star touch without meeting.
//!
//! ## Why bisection alone cannot close the star
//! In x's chart take a point p with polar coordinates (θ, r) (any real θ naming p) and put
//! α = m_xθ/6, ρ = k_x r (Def. 4.1.6). Relative to the neighbour at label k, p has principal
//! angle θ_k = θ − 2πk/m_x − 2πw_k ∈ (−π, π] for one integer w_k, and the closed form of
//! Def. 4.1.9 (module `interval`) reads b_k = ρe^{iα_k}, α_k = m_xθ_k/6, with
//!   α_k = α − πn_k/3,  n_k = k + m_x·w_k ∈ Z  (an exact identity of real numbers).
//! So in the (ρ, α) half-plane every Ω_xk is a copy of the lens E = C ∩ D (C, D the open disks
//! of radius √3/2 about 0 and 1) rotated to the angle πn_k/3. The copies at n and n + 2 are
//! *tangent*: |1 − e^{2iπ/3}| = √3 is twice the radius, so D and its rotation by 2π/3 touch at
//! (1/2)e^{iπ/3}, a point inside C, where the lenses of three labels meet in their closures.
//! Every box around that point keeps both non-adjacent labels "maybe": the δ-boxes of the
//! branch and bound. Likewise for m_u = 10 the ray α = 5π/3 (θ = π, the cut of Π) is tangent
//! to D at ρ = 1/2: the one point where the lens agreement (D4.1.9-lens) was left to δ.
//!
//! ## The exact argument
//! * **Lemma A** (sector). If R ≤ sin h, 0 < h ≤ π/2, then D(1, R) ⊂ {z ≠ 0 : |arg z| < h}: the
//!   closed set {z : z = 0 or |arg z| ≥ h} is at distance sin h from 1. [`SectorBound`] holds
//!   h = kπ/6 and checks R² ≤ sin²(kπ/6) exactly (sin² = 1/4, 3/4, 1 for k = 1, 2, 3); the
//!   paper's R = √3/2 needs k = 2, h = π/3, with equality.
//! * **Lemma B** (one sheet). If p ∈ Ω_xk then α_k ∈ (2πj − h, 2πj + h) for an integer j with
//!   12|j| < m_x + 2, and j = 0 for the literal Def. 4.1.9. Indeed b_k ∈ D(1, R) gives
//!   arg b_k ∈ (−h, h) mod 2π (Lemma A); the literal domain also has winding 0, |α_k| < π, so
//!   j = 0; the Sec. 6.1.3 lens test has no winding condition, but θ_k ∈ (−π, π] gives
//!   α_k ∈ (−m_xπ/6, m_xπ/6], which meets (2πj − π/3, 2πj + π/3) only if 12|j| − 2 < m_x.
//!   For m_x ≤ 10 only j = 0 remains: the reason the lens test agrees with Def. 4.1.9 exactly
//!   up to m_u = 10 (the interval (5π/3, 7π/3) is open, so m_u = 10 is tangent, not crossing).
//! * **Theorem.** With n′_k = n_k + 6j_k, p ∈ Ω_xk implies |α − πn′_k/3| < h. If p ∈ Ω_xa ∩ Ω_xc
//!   then |n′_a − n′_c| < 2h/(π/3) = k (in units of the sector bound). For the literal domains
//!   (j = 0, h = π/3): |n_a − n_c| ≤ 1, n_a − n_c ≡ a − c (mod m_x) and n_a ≠ n_c for a ≠ c,
//!   so a − c ≡ ±1: *non-adjacent labels have disjoint domains* (C4.2), and three labels
//!   would need three distinct integers pairwise at distance ≤ 1: *at most two* (C5.4). The
//!   same holds for the lens domains when m_x ≤ 10.
//!
//! The provers apply the theorem box by box, which also keeps it sound where it does not
//! hold for all p (lens domains, m_x ≥ 11): [`candidates`] lists, for a label and a box, every
//! n′ = k + m_x·w + 6j that a point of the box in Ω_xk can have — w the wrap integer of each
//! principal piece ([`interval::principal_pieces_k`]: the piece holding θ_k(p) has the wrap
//! integer w_k(p) for every box of angular width < 4π), j by Lemma B, and only the n′ whose
//! sector |α − πn′/3| < h is not certified disjoint from the box. Two labels share no point
//! of the box when all their candidates differ by ≥ k. Everything except that last interval
//! filter is integer arithmetic, so nothing is left to δ at the tangencies.

use super::interval;
use super::interval::{member, ratio, two_pi_frac, Deg, Domain};
use crate::numeric::interval::Interval as I;
use serde::{Deserialize, Serialize};

/// The sector claim of Lemma A (module docs): D(1, R) ⊂ {|arg z| < kπ/6}, k = `sixths`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub struct SectorBound {
    /// k: the half-angle of the sector in units of π/6 (2 for the paper's radius √3/2).
    pub sixths: u32,
}

impl SectorBound {
    /// The sharp bound for the paper's radius: h = π/3 = asin(√3/2).
    pub fn paper() -> SectorBound {
        SectorBound { sixths: 2 }
    }
    /// Lemma A's premise for a disk radius² enclosed by `r2`: R² ≤ sin²(kπ/6), decided exactly
    /// (sin² is 1/4, 3/4, 1 for k = 1, 2, 3, all exact in f64). Other k are never applicable.
    pub fn premise(&self, r2: I) -> bool {
        let s2 = match self.sixths {
            1 => 0.25,
            2 => 0.75,
            3 => 1.0,
            _ => return false,
        };
        !r2.is_empty() && r2.sup() <= s2
    }
    /// Enclosure of the half-angle h = kπ/6.
    fn half_angle(&self) -> I {
        I::PI * ratio(self.sixths as i64, 6)
    }
}

/// The radius² enclosure of the disk D of a domain (3/4 for the literal Def. 4.1.9).
pub(super) fn disk_r2(dom: Domain) -> I {
    match dom {
        Domain::Literal => ratio(3, 4),
        Domain::Lens { r2 } => r2,
    }
}

/// Largest |j| of Lemma B: 12|j| < m + 2 for the lens test, 0 for the literal domain.
pub fn max_sheet(m: u32, dom: Domain) -> i64 {
    match dom {
        Domain::Literal => 0,
        Domain::Lens { .. } => (m as i64 + 1) / 12,
    }
}

/// One candidate of [`candidates`]: a principal piece's wrap integer w, the sheet j and the
/// sector index n′ = k + m·w + 6j.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Candidate {
    /// Wrap integer of the principal piece.
    pub w: i64,
    /// Sheet of Lemma B.
    pub j: i64,
    /// Sector index: a point of the box in Ω_xk with this candidate has |α − πn′/3| < h.
    pub n: i64,
}

/// Every candidate (module docs) for label `k` of a star of degree `d.m` on the box (θ, r);
/// `None` when Lemma A's premise fails for `bound` (the argument does not apply).
pub fn candidates(
    d: &Deg,
    k: u32,
    th: I,
    r: I,
    dom: Domain,
    bound: SectorBound,
) -> Option<Vec<Candidate>> {
    if !bound.premise(disk_r2(dom)) || th.wid() >= 4.0 * std::f64::consts::PI * 0.99 {
        return None;
    }
    let (m, h) = (d.m as i64, bound.half_angle());
    let alpha = d.m6 * th;
    let js = max_sheet(d.m, dom);
    let mut v = Vec::new();
    for (piece, w) in interval::principal_pieces_k(th - two_pi_frac(k as i64, m)) {
        if member(d, piece, r, dom).is_false() {
            continue;
        }
        for j in -js..=js {
            let n = k as i64 + m * w + 6 * j;
            let x = alpha - I::PI * ratio(n, 3);
            // |α − πn′/3| < h is certainly false on the box: no point has this candidate.
            if x.inf() >= h.sup() || x.sup() <= -h.sup() {
                continue;
            }
            v.push(Candidate { w, j, n });
        }
    }
    Some(v)
}

/// Two labels with these candidates share no point of the box (the Theorem of the module
/// docs): every pair of sector indices differs by at least k = `bound.sixths`.
pub fn separated(a: &[Candidate], c: &[Candidate], bound: SectorBound) -> bool {
    a.iter().all(|x| {
        c.iter()
            .all(|y| (x.n - y.n).unsigned_abs() >= bound.sixths as u64)
    })
}

/// The star properties on a box by the exact argument: `true` when proven. `nonadjacent`:
/// no point of the box lies in Ω_xa ∩ Ω_xc for non-adjacent a, c (C4.2); otherwise no point
/// lies in three domains (C5.4).
pub(super) fn star_exact(
    d: &Deg,
    th: I,
    r: I,
    dom: Domain,
    bound: SectorBound,
    nonadjacent: bool,
) -> bool {
    let m = d.m as i64;
    let mut cands: Vec<(i64, Vec<Candidate>)> = Vec::new();
    for k in 0..d.m {
        match candidates(d, k, th, r, dom, bound) {
            None => return false,
            Some(v) if v.is_empty() => {}
            Some(v) => cands.push((k as i64, v)),
        }
    }
    let adjacent = |a: i64, b: i64| {
        let diff = (a - b).rem_euclid(m);
        diff == 1 || diff == m - 1
    };
    let n = cands.len();
    let mut meet = vec![false; n * n];
    for i in 0..n {
        for l in 0..n {
            meet[i * n + l] = i != l && !separated(&cands[i].1, &cands[l].1, bound);
        }
    }
    if nonadjacent {
        return (0..n)
            .all(|i| (0..n).all(|l| !meet[i * n + l] || adjacent(cands[i].0, cands[l].0)));
    }
    // Three labels share a point only with one candidate each, pairwise closer than k.
    let close = |x: &Candidate, y: &Candidate| (x.n - y.n).unsigned_abs() < bound.sixths as u64;
    for i in 0..n {
        for l in i + 1..n {
            for q in l + 1..n {
                if !(meet[i * n + l] && meet[i * n + q] && meet[l * n + q]) {
                    continue;
                }
                let (ci, cl, cq) = (&cands[i].1, &cands[l].1, &cands[q].1);
                let triple = ci.iter().any(|x| {
                    cl.iter()
                        .any(|y| close(x, y) && cq.iter().any(|z| close(x, z) && close(y, z)))
                });
                if triple {
                    return false;
                }
            }
        }
    }
    true
}

/// D4.1.9-lens on a box by the exact argument (paper's lens): every point of the box in the
/// lens E has winding 0 relative to label 0, because its only candidate sheet is j = 0
/// (Lemma B: |α_0| < π/3 < π).
pub(super) fn lens_winding0_exact(d: &Deg, th: I, r: I) -> bool {
    let dom = Domain::Lens { r2: ratio(3, 4) };
    match candidates(d, 0, th, r, dom, SectorBound::paper()) {
        None => false,
        Some(v) => v.iter().all(|c| c.j == 0),
    }
}
