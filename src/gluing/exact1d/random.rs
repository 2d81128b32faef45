//! Random 1-D gluing data for property tests. Data start from a Hausdorff "world": charts
//! U_i ⊂ ℝ (intervals with half-integer endpoints) mapped to disjoint p-domains by affine
//! ψ_i(w) = s_i·w + o_i (s_i ∈ {±1, ±2}); then Ω_ij = ψ_i(U_i ∩ U_j) and φ_ji = ψ_j ∘ ψ_i⁻¹, which
//! satisfies every condition of Def. 3.4.1. Random perturbations then break some conditions
//! while keeping φ_ji a bijection Ω_ij → Ω_ji:
//! shrinking a gluing (forks), shifting it (cocycle equation), splitting it at a point
//! (Hausdorff), reflecting it (Hausdorff, cocycle), and — when `break_3ab` — a non-identity
//! φ_ii or a φ_ij that is a bijection but not φ_ji⁻¹.
//! All numbers stay in ℤ/16 or coarser, which the brute-force tests rely on.

use super::data::{q, Exact1d};
use super::interval::{Interval, Q};
use crate::gluing::data::Idx;
use num_traits::Zero;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// An affine map of the world line, w ↦ m·w + t.
#[derive(Clone)]
struct Aff {
    m: Q,
    t: Q,
}

impl Aff {
    fn apply(&self, w: &Q) -> Q {
        &self.m * w + &self.t
    }
    fn inv(&self) -> Aff {
        let m = Q::from_integer(1.into()) / &self.m;
        Aff {
            t: -(&self.t * &m),
            m,
        }
    }
    fn then(&self, o: &Aff) -> Aff {
        // o ∘ self
        Aff {
            m: &o.m * &self.m,
            t: &o.m * &self.t + &o.t,
        }
    }
    fn image(&self, iv: &Interval) -> Option<Interval> {
        let (a, b) = (self.apply(&iv.lo), self.apply(&iv.hi));
        if a < b {
            Interval::new(a, b)
        } else {
            Interval::new(b, a)
        }
    }
}

fn half(rng: &mut ChaCha8Rng, lo: i64, hi: i64) -> Q {
    q(rng.gen_range(2 * lo..=2 * hi), 2)
}

/// Random gluing data with `n` charts (2 or 3 are useful), from `seed`.
pub fn random_gluing(seed: u64, n: u32, break_3ab: bool) -> Exact1d {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut us: Vec<Interval> = Vec::new();
    let mut psi: Vec<Aff> = Vec::new();
    for c in 0..n {
        let lo = half(&mut rng, -4, 2);
        let len = half(&mut rng, 1, 4);
        us.push(Interval { hi: &lo + len, lo });
        let s = [1, -1, 2, -2][rng.gen_range(0..4)];
        psi.push(Aff {
            m: q(s, 1),
            t: q(40 * i64::from(c + 1), 1),
        });
    }
    let mut g = Exact1d::default();
    for c in 0..n as usize {
        if let Some(om) = psi[c].image(&us[c]) {
            g.add_domain(c as Idx + 1, om);
        }
    }
    let ident = Aff {
        m: q(1, 1),
        t: Q::zero(),
    };
    for a in 0..n as usize {
        for b in a + 1..n as usize {
            let Some(sub) = us[a].intersect(&us[b]) else {
                continue;
            };
            // World-level gluing: w ∈ src ⊆ U_a is identified with T(w) ∈ U_b.
            let mut pieces: Vec<(Interval, Aff)> = vec![(sub.clone(), ident.clone())];
            match rng.gen_range(0..8) {
                0 => {
                    // Shrink: a fork-like restriction of the gluing.
                    let d = half(&mut rng, 0, 1);
                    let lo = &sub.lo + &d;
                    if let Some(s2) = Interval::new(lo, sub.hi.clone()) {
                        pieces = vec![(s2, ident.clone())];
                    }
                }
                1 => {
                    // Shift by t, if the shifted piece stays inside U_b.
                    let t = half(&mut rng, -1, 1);
                    let moved = Interval {
                        lo: &sub.lo + &t,
                        hi: &sub.hi + &t,
                    };
                    if us[b].closure_contains(&moved.lo) && us[b].closure_contains(&moved.hi) {
                        pieces = vec![(sub.clone(), Aff { m: q(1, 1), t })];
                    }
                }
                2 => {
                    // Split at the midpoint: the midpoint becomes a boundary point on both sides.
                    let m = sub.midpoint();
                    pieces = vec![
                        (
                            Interval {
                                lo: sub.lo.clone(),
                                hi: m.clone(),
                            },
                            ident.clone(),
                        ),
                        (
                            Interval {
                                lo: m,
                                hi: sub.hi.clone(),
                            },
                            ident.clone(),
                        ),
                    ];
                }
                3 => {
                    // Reflect the overlap onto itself.
                    pieces = vec![(
                        sub.clone(),
                        Aff {
                            m: q(-1, 1),
                            t: &sub.lo + &sub.hi,
                        },
                    )];
                }
                _ => {}
            }
            for (src, t) in pieces {
                let Some(dst) = t.image(&src) else { continue };
                // φ_ba = ψ_b ∘ T ∘ ψ_a⁻¹ on ψ_a(src); φ_ab its inverse on ψ_b(dst).
                let fwd = psi[a].inv().then(&t).then(&psi[b]);
                let bwd = fwd.inv();
                let (ia, ib) = (a as Idx + 1, b as Idx + 1);
                if let (Some(da), Some(db)) = (psi[a].image(&src), psi[b].image(&dst)) {
                    g.add_piece(ia, ib, da, fwd.m.clone(), fwd.t.clone());
                    if break_3ab && rng.gen_range(0..6) == 0 {
                        // A bijection Ω_ba → Ω_ab that is not the inverse: compose with the
                        // reflection of the source interval.
                        let refl = Aff {
                            m: q(-1, 1),
                            t: &src.lo + &src.hi,
                        };
                        let bad = t.inv().then(&refl).then(&psi[a]);
                        let bad = psi[b].inv().then(&bad);
                        g.add_piece(ib, ia, db, bad.m, bad.t);
                    } else {
                        g.add_piece(ib, ia, db, bwd.m, bwd.t);
                    }
                }
            }
        }
    }
    if break_3ab && rng.gen_range(0..4) == 0 {
        // A non-identity bijection φ_11 of Ω_1: its reflection.
        if let Some(p) = g.omega(1).parts().first().cloned() {
            g.add_piece(1, 1, p.clone(), q(-1, 1), &p.lo + &p.hi);
            for extra in g
                .omega(1)
                .parts()
                .iter()
                .skip(1)
                .cloned()
                .collect::<Vec<_>>()
            {
                g.add_piece(1, 1, extra, q(1, 1), Q::zero());
            }
        }
    }
    g.with_default_diagonal()
}
