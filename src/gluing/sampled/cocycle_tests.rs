//! Unit tests of the sampled cocycle checks (Def. 3.4.1(3b), (3c)): their tolerance
//! 64·ε·|value| is multiplied by the data's declared amplification.

use super::*;
use crate::gluing::data::{Idx, Point};
use crate::gluing::sampled::SampleConfig;
use crate::report::Verdict;
use rand::Rng;
use rand_chacha::ChaCha8Rng;

/// Three copies of ℝ², every φ_ji (j ≠ i) the scaling x ↦ c·x with c = 1 + δ, so that
/// φ_ij∘φ_ji and φ_kj∘φ_ji miss the identity and φ_ki by about δ·|x|: a deviation of the size
/// of a rounding error, which an amplification of the maps may or may not excuse.
struct Scaled {
    delta: f64,
    amplification: f64,
}

impl GluingData<2> for Scaled {
    type S = f64;
    fn indices(&self) -> Vec<Idx> {
        vec![0, 1, 2]
    }
    fn in_p_domain(&self, _: Idx, _: &Point<f64, 2>) -> bool {
        true
    }
    fn in_gluing_domain(&self, _: Idx, _: Idx, _: &Point<f64, 2>) -> bool {
        true
    }
    fn phi(&self, j: Idx, i: Idx, p: &Point<f64, 2>) -> Option<Point<f64, 2>> {
        let c = if i == j { 1.0 } else { 1.0 + self.delta };
        Some([c * p[0], c * p[1]])
    }
    fn sample_p_domain(&self, _: Idx, rng: &mut ChaCha8Rng, n: usize) -> Vec<Point<f64, 2>> {
        (0..n)
            .map(|_| [rng.gen_range(0.5..1.0), rng.gen_range(0.5..1.0)])
            .collect()
    }
    fn sample_gluing_domain(
        &self,
        i: Idx,
        _: Idx,
        rng: &mut ChaCha8Rng,
        n: usize,
    ) -> Vec<Point<f64, 2>> {
        self.sample_p_domain(i, rng, n)
    }
    fn gluing_boundary_points(
        &self,
        _: Idx,
        _: Idx,
        _: &mut ChaCha8Rng,
        _: usize,
    ) -> Vec<Point<f64, 2>> {
        vec![]
    }
    fn amplification(&self) -> f64 {
        self.amplification
    }
}

/// δ = 4·(64ε): deviations between 4·64ε·|x| and 8·64ε·|x|, with |x| ≤ √2, under the tolerance
/// 64ε·max(1, |value|)·a for a = 1000 and above it for a = 1.
fn verdicts(amplification: f64) -> [Verdict; 2] {
    let g = Scaled {
        delta: 4.0 * 64.0 * f64::EPSILON,
        amplification,
    };
    let cfg = SampleConfig { seed: 3, n: 40 };
    [check_3b(&g, &cfg).verdict(), check_3c(&g, &cfg).verdict()]
}

/// D3.4.1(3b), (3c): the tolerance of the equation checks is 64·ε·|value| times the declared
/// amplification of the maps, so a deviation of a few times 64·ε·|value| holds for maps that
/// amplify rounding a thousandfold and fails for isometries.
#[test]
fn d3_4_1_3b_d3_4_1_3c_tolerance_scales_with_the_declared_amplification() {
    for v in verdicts(1000.0) {
        assert!(matches!(v, Verdict::Holds), "{v:?}");
    }
    for v in verdicts(1.0) {
        assert!(matches!(v, Verdict::Fails), "{v:?}");
    }
}
