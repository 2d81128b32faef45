//! Seeded searches of the rational family (Eq. (11)) on a tetrahedron (m = 3), each sample
//! certified or refuted exactly by `tet::checks::det_decision` (SPEC `SD-L161(3-D)`):
//!
//! * L161 as stated ("adjusted rational, all control points fixed, weights positive ⇒
//!   injective, for any dimension"), degrees 1..=4 in 3-D;
//! * beyond the statement: adjusted rational maps whose control points are *not* fixed
//!   (random in their open faces) with random positive weights — the paper claims nothing
//!   there, so a refutation is a finding about the hypothesis "fixed", not an erratum.

use super::checks::det_decision;
use super::maps::{fixed_control4, random_adjusted4};
use super::params::TetMap;
use crate::sdiff::common::positivity::Budget;
use crate::sdiff::common::rational::{q, qr, Q};
use crate::sdiff::common::simplex_search::Search;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// A positive weight: 1/100 or 100 one time in three, else k/97, k ∈ 1..1000.
pub(crate) fn random_weight(rng: &mut ChaCha8Rng) -> Q {
    match rng.gen_range(0..6) {
        0 => qr(1, 100),
        1 => q(100),
        _ => qr(rng.gen_range(1..1000), 97),
    }
}

fn describe(m: &TetMap) -> String {
    let w: Vec<String> = m.weights.iter().map(|x| x.to_string()).collect();
    let b: Vec<Vec<String>> = m
        .control
        .iter()
        .map(|p| p.iter().map(|x| x.to_string()).collect())
        .collect();
    format!("n = {}, weights {w:?}, control {b:?}", m.degree)
}

/// L161 in 3-D: fixed control points b_I = I/n, random positive weights.
pub fn random_rational_fixed4(n: usize, rng: &mut ChaCha8Rng) -> TetMap {
    let control = fixed_control4(n);
    let weights = control.iter().map(|_| random_weight(rng)).collect();
    TetMap::bezier(n, control, Some(weights))
}

/// Adjusted (control points random in their open faces) with random positive weights.
pub fn random_rational_adjusted4(n: usize, rng: &mut ChaCha8Rng) -> TetMap {
    let control = random_adjusted4(n, rng);
    let weights = control.iter().map(|_| random_weight(rng)).collect();
    TetMap::bezier(n, control, Some(weights))
}

/// Runs `samples` maps of `gen` through the exact det decision.
pub fn search3(
    samples: usize,
    seed: u64,
    budget: Budget,
    mut gen: impl FnMut(&mut ChaCha8Rng) -> TetMap,
) -> Search {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut s = Search::default();
    for _ in 0..samples {
        let m = gen(&mut rng);
        s.record(det_decision(&m, budget), || describe(&m));
    }
    s
}
