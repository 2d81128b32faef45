//! The sampled checkers are generic over the scalar type: App. A.2's fork and its repair as
//! f32 data, with tolerances derived from f32's epsilon.

use crate::common;

use pseudomanifold::gluing::data::{GluingData, Idx, Point};
use pseudomanifold::gluing::sampled::{self, SampleConfig};
use rand::Rng;
use rand_chacha::ChaCha8Rng;

/// Ω_1 = (−3, −1), Ω_2 = (1, 3), Ω_12 = (−3, −2), Ω_21 = (shift − 4 + 1 … ), φ_21 = x + shift.
struct Fork32 {
    shift: f32,
}

impl Fork32 {
    fn omega(&self, i: Idx) -> (f32, f32) {
        if i == 1 {
            (-3.0, -1.0)
        } else {
            (1.0, 3.0)
        }
    }
    fn omega_ij(&self, i: Idx, j: Idx) -> Option<(f32, f32)> {
        match (i, j) {
            (1, 2) => Some((-3.0, -2.0)),
            (2, 1) => Some((-3.0 + self.shift, -2.0 + self.shift)),
            (a, b) if a == b => Some(self.omega(a)),
            _ => None,
        }
    }
}

impl GluingData<1> for Fork32 {
    type S = f32;
    fn indices(&self) -> Vec<Idx> {
        vec![1, 2]
    }
    fn in_p_domain(&self, i: Idx, p: &Point<f32, 1>) -> bool {
        let (a, b) = self.omega(i);
        a < p[0] && p[0] < b
    }
    fn in_gluing_domain(&self, i: Idx, j: Idx, p: &Point<f32, 1>) -> bool {
        self.omega_ij(i, j)
            .is_some_and(|(a, b)| a < p[0] && p[0] < b)
    }
    fn phi(&self, j: Idx, i: Idx, p: &Point<f32, 1>) -> Option<Point<f32, 1>> {
        if !self.in_gluing_domain(i, j, p) {
            return None;
        }
        Some(match (i, j) {
            (1, 2) => [p[0] + self.shift],
            (2, 1) => [p[0] - self.shift],
            _ => *p,
        })
    }
    fn sample_p_domain(&self, i: Idx, rng: &mut ChaCha8Rng, n: usize) -> Vec<Point<f32, 1>> {
        let (a, b) = self.omega(i);
        (0..n)
            .map(|_| [rng.gen_range(a + 1e-3..b - 1e-3)])
            .collect()
    }
    fn sample_gluing_domain(
        &self,
        i: Idx,
        j: Idx,
        rng: &mut ChaCha8Rng,
        n: usize,
    ) -> Vec<Point<f32, 1>> {
        match self.omega_ij(i, j) {
            Some((a, b)) => (0..n)
                .map(|_| [rng.gen_range(a + 1e-3..b - 1e-3)])
                .collect(),
            None => Vec::new(),
        }
    }
    fn gluing_boundary_points(
        &self,
        i: Idx,
        j: Idx,
        _: &mut ChaCha8Rng,
        _: usize,
    ) -> Vec<Point<f32, 1>> {
        let Some((a, b)) = self.omega_ij(i, j) else {
            return vec![];
        };
        [a, b]
            .into_iter()
            .map(|x| [x])
            .filter(|p| self.in_p_domain(i, p))
            .collect()
    }
    fn scale(&self) -> f64 {
        3.0
    }
}

#[test]
fn d3_4_1_sampled_checkers_generic_over_f32_fork_and_repair() {
    let cfg = SampleConfig { seed: 32, n: 200 };
    for r in sampled::check_all(&Fork32 { shift: 5.0 }, &cfg) {
        common::assert_holds_for("repaired fork, f32", &r);
    }
    let rs = sampled::check_all(&Fork32 { shift: 4.0 }, &cfg);
    for r in &rs {
        if r.id == "D3.4.1(4)" {
            assert!(r.failed(), "fork, f32: {r:?}");
        } else {
            common::assert_holds_for("fork, f32", r);
        }
    }
    // Tolerances come from f32's epsilon: 64·ε_f32 ≈ 7.6e-6 at unit magnitude.
    let t = rs
        .iter()
        .find(|r| r.id == "D3.4.1(3b)")
        .and_then(|r| r.tolerance)
        .unwrap_or(0.0);
    assert!(t >= 64.0 * f64::from(f32::EPSILON), "{t}");
}
