//! Shared vocabulary for the exact replays (proofs/appendix_a1.rs, proofs/eval_c6_1_4.rs):
//! the maps of Defs. 4.1.6–4.1.8 as polar chains and affine maps, the angular extents of the
//! disks C, D, F, G, and the triangle configuration with its labels; and, for every proof
//! target, what a passing check result is ([`assert_holds_for`]).
#![allow(dead_code)]

use pseudomanifold::exact::plane::{disks, Affine, Disk};
use pseudomanifold::exact::polar::{Chain, Interval, PMap, Region};
use pseudomanifold::exact::q3::{q, Q};
use pseudomanifold::exact::replay::{Expect, Step, StepCheck};

#[path = "../tests/common/verdicts.rs"]
mod verdicts;
#[allow(unused_imports)]
pub use verdicts::{
    assert_caught, assert_fails_as_written, assert_holds, assert_holds_for, record, Seen,
};

/// A triangle [u, w, x] of K, oriented counterclockwise (the orientation of Lemma 4.2.2's
/// "without loss of generality" and of Sec. 6.1.4's triangle t = (a, b, c)):
/// s_u(x) = s_u(w) + 1, s_w(u) = s_w(x) + 1, s_x(w) = s_x(u) + 1 (mod degree).
#[derive(Clone, Copy, Debug)]
pub struct Tri {
    pub mu: u32,
    pub mw: u32,
    pub mx: u32,
    /// s_u(w).
    pub i: u32,
    /// s_w(x).
    pub j: u32,
    /// s_x(u).
    pub k: u32,
}

impl Tri {
    pub fn su_w(&self) -> u32 {
        self.i
    }
    pub fn su_x(&self) -> u32 {
        (self.i + 1) % self.mu
    }
    pub fn sw_x(&self) -> u32 {
        self.j
    }
    pub fn sw_u(&self) -> u32 {
        (self.j + 1) % self.mw
    }
    pub fn sx_u(&self) -> u32 {
        self.k
    }
    pub fn sx_w(&self) -> u32 {
        (self.k + 1) % self.mx
    }
    /// Every labelled configuration with degrees in `degs` and labels in 0..m (bounded
    /// exhaustive enumeration; labels sampled at 0, 1, m−1 when `all_labels` is false).
    pub fn all(degs: &[u32], all_labels: bool) -> Vec<Tri> {
        let labels = |m: u32| -> Vec<u32> {
            if all_labels {
                (0..m).collect()
            } else {
                let mut v = vec![0, 1, m - 1];
                v.dedup();
                v
            }
        };
        let mut out = Vec::new();
        for &mu in degs {
            for &mw in degs {
                for &mx in degs {
                    for i in labels(mu) {
                        for j in labels(mw) {
                            for k in labels(mx) {
                                out.push(Tri {
                                    mu,
                                    mw,
                                    mx,
                                    i,
                                    j,
                                    k,
                                });
                            }
                        }
                    }
                }
            }
        }
        out
    }
}

/// R_(v,y) for s_v(y) = label (Def. 4.1.8): rotation by −2π·label/m_v.
pub fn r(name: &str, label: u32, m: u32) -> PMap {
    PMap::rot(name, q(-i64::from(label) * 2, i64::from(m)))
}
/// R_(v,y)⁻¹: rotation by +2π·label/m_v.
pub fn r_inv(name: &str, label: u32, m: u32) -> PMap {
    PMap::rot(name, q(i64::from(label) * 2, i64::from(m)))
}
/// M_{qπ} in a polar chain.
pub fn m_rot(name: &str, turn: Q) -> PMap {
    PMap::rot(name, turn)
}
pub fn g(name: &str, m: u32) -> PMap {
    PMap::g(name, m)
}
pub fn gi(name: &str, m: u32) -> PMap {
    PMap::g_inv(name, m)
}
pub fn chain(v: Vec<PMap>) -> Chain {
    Chain(v)
}
/// M_{kπ/6} as an affine map.
pub fn rot6(k: i64) -> Affine {
    Affine::rot_sixths(k)
}
pub fn h() -> Affine {
    Affine::h()
}

/// Open interval (a/b, c/d) of θ/π.
pub fn oo(a: i64, b: i64, c: i64, d: i64) -> Region {
    Region::of(Interval::open(q(a, b), q(c, d)))
}
/// (a/b, c/d].
pub fn oc(a: i64, b: i64, c: i64, d: i64) -> Region {
    Region::of(Interval::open_closed(q(a, b), q(c, d)))
}
/// [a/b, c/d].
pub fn cc(a: i64, b: i64, c: i64, d: i64) -> Region {
    Region::of(Interval::closed(q(a, b), q(c, d)))
}
/// The range (−1, 1] of Π.
pub fn pi_range() -> Region {
    Region::of(Interval::pi_range())
}
/// Angular extent of int(D) ⊇ E = C∩D: |θ| < π/3 (step `…-extD`).
pub fn ext_d() -> Region {
    oo(-1, 3, 1, 3)
}
/// Angular extent of int(G) (centre (1/2, −√3/2)): θ ∈ (−2π/3, 0).
pub fn ext_g() -> Region {
    oo(-2, 3, 0, 1)
}
/// Angular extent of int(F) (centre (1/2, √3/2)): θ ∈ (0, 2π/3).
pub fn ext_f() -> Region {
    oo(0, 1, 2, 3)
}

/// The sector-extent facts used by every replay (exact tangency tests over Q(√3)).
pub fn extent_steps(prefix: &str) -> Vec<Step> {
    vec![
        Step::new(
            &format!("{prefix}-extD"),
            "int(D) lies in the open sector |θ| < π/3 (the rays at ±π/3 are tangent to D), so E = C∩D has angles in (−π/3, π/3)",
            StepCheck::DiskInSector { disk: disks::d(), lo: -2, hi: 2 },
            Expect::Holds,
        ),
        Step::new(
            &format!("{prefix}-extG"),
            "int(G), G of centre (1/2, −√3/2), lies in the open sector θ ∈ (−2π/3, 0)",
            StepCheck::DiskInSector { disk: disks::g(), lo: -4, hi: 0 },
            Expect::Holds,
        ),
        Step::new(
            &format!("{prefix}-extF"),
            "int(F), F of centre (1/2, √3/2), lies in the open sector θ ∈ (0, 2π/3)",
            StepCheck::DiskInSector { disk: disks::f(), lo: 0, hi: 4 },
            Expect::Holds,
        ),
    ]
}

/// Where g_v (m = degree) fails to be injective on (−π, π]: θ/π ∈ (−1, 1 − 12/m] ∪
/// (−1 + 12/m, 1] for m > 6 (a point at θ has a twin at θ ± 12π/m), nowhere for m ≤ 6.
pub fn g_non_injective(m: u32) -> Expect {
    if m <= 6 {
        return Expect::Holds;
    }
    let m = i64::from(m);
    Expect::FailsOn(oc(-1, 1, m - 12, m).union(&oc(12 - m, m, 1, 1)))
}

/// Which angles of (−π, π] are not hit by g_v on (−π, π] (image |θ| ≤ m_vπ/6):
/// (−1, −m/6] ∪ (m/6, 1] for m < 6.
pub fn g_uncovered(m: u32) -> Expect {
    if m >= 6 {
        return Expect::Holds;
    }
    let m = i64::from(m);
    Expect::FailsOn(oc(-1, 1, -m, 6).union(&oc(m, 6, 1, 1)))
}

/// Disk comparisons as an exact fact.
pub fn disk_eq(map: &[Affine], d: &Disk, e: &Disk) -> bool {
    d.image(&Affine::compose(map)).as_ref() == Some(e)
}

/// Print a replay and panic with the first mismatch.
pub fn assert_replay(title: &str, steps: &[Step]) {
    use pseudomanifold::exact::replay::{first_mismatch, render, replay};
    let out = replay(steps);
    if let Some(bad) = first_mismatch(&out) {
        panic!(
            "{title}: replay differs from the recorded verdict at step {}\n{}",
            bad.id,
            render(steps, &out)
        );
    }
}
