//! The exact 1-D data seen through the sampled [`GluingData`] trait (f64 points), so the sampled
//! checkers can be cross-validated against the exact decisions on the same data.

use super::data::Exact1d;
use super::decide::glued_boundary;
use super::interval::{q_to_f64, OpenSet, Q};
use crate::gluing::data::{GluingData, Idx};
use rand::Rng;
use rand_chacha::ChaCha8Rng;

fn to_q(x: f64) -> Option<Q> {
    Q::from_float(x)
}

fn sample(set: &OpenSet, rng: &mut ChaCha8Rng, n: usize) -> Vec<[f64; 1]> {
    let parts = set.parts();
    if parts.is_empty() {
        return Vec::new();
    }
    let mut out = Vec::with_capacity(n.max(1));
    for s in 0..n.max(1) {
        let p = &parts[s % parts.len()];
        let (lo, hi) = (q_to_f64(&p.lo), q_to_f64(&p.hi));
        let w = hi - lo;
        let x = match s % 4 {
            // Near-boundary samples at geometric distances from either end.
            1 => lo + w * 2f64.powi(-((s / 4 % 30) as i32) - 1),
            3 => hi - w * 2f64.powi(-((s / 4 % 30) as i32) - 1),
            _ => lo + w * rng.gen_range(0.0..1.0),
        };
        // Rounding can land on an endpoint; such a sample is not in the open set.
        if x > lo && x < hi {
            out.push([x]);
        }
    }
    if out.is_empty() {
        out.push([(q_to_f64(&parts[0].lo) + q_to_f64(&parts[0].hi)) / 2.0]);
    }
    out
}

impl GluingData<1> for Exact1d {
    type S = f64;
    fn indices(&self) -> Vec<Idx> {
        self.ids()
    }
    fn in_p_domain(&self, i: Idx, p: &[f64; 1]) -> bool {
        to_q(p[0]).is_some_and(|x| self.omega(i).contains(&x))
    }
    fn in_gluing_domain(&self, i: Idx, j: Idx, p: &[f64; 1]) -> bool {
        to_q(p[0]).is_some_and(|x| self.omega_ij(i, j).contains(&x))
    }
    fn phi(&self, j: Idx, i: Idx, p: &[f64; 1]) -> Option<[f64; 1]> {
        let x = to_q(p[0])?;
        let piece = self.pieces(i, j).iter().find(|pc| pc.dom.contains(&x))?;
        Some([q_to_f64(&piece.a) * p[0] + q_to_f64(&piece.b)])
    }
    fn sample_p_domain(&self, i: Idx, rng: &mut ChaCha8Rng, n: usize) -> Vec<[f64; 1]> {
        sample(&self.omega(i), rng, n)
    }
    fn sample_gluing_domain(
        &self,
        i: Idx,
        j: Idx,
        rng: &mut ChaCha8Rng,
        n: usize,
    ) -> Vec<[f64; 1]> {
        sample(&self.omega_ij(i, j), rng, n)
    }
    fn gluing_boundary_points(
        &self,
        i: Idx,
        j: Idx,
        _: &mut ChaCha8Rng,
        _: usize,
    ) -> Vec<[f64; 1]> {
        glued_boundary(self, i, j)
            .iter()
            .map(|x| [q_to_f64(x)])
            .collect()
    }
    fn scale(&self) -> f64 {
        self.hull()
            .map(|(lo, hi)| q_to_f64(&lo).abs().max(q_to_f64(&hi).abs()))
            .unwrap_or(1.0)
            .max(1.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gluing::exact1d::data::q;
    use rand::SeedableRng;

    /// The sampled checkers see the exact data through this sampler: besides uniform points it
    /// puts samples s ≡ 1 and s ≡ 3 (mod 4) at 2^−(k+1)·width from the lower and the upper end,
    /// k = ⌊s/4⌋ mod 30, so faults near a boundary (Def. 3.4.1(2), (4)) are reached.
    #[test]
    fn d3_4_1_sampled_view_visits_geometric_distances_from_both_ends() {
        let set = OpenSet::from_interval(crate::gluing::exact1d::interval::Interval {
            lo: q(0, 1),
            hi: q(1, 1),
        });
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        let xs = sample(&set, &mut rng, 40);
        assert_eq!(xs.len(), 40);
        for (s, x) in xs.iter().enumerate() {
            let d = 2f64.powi(-((s / 4) as i32) - 1);
            match s % 4 {
                1 => assert_eq!(x[0], d, "sample {s}"),
                3 => assert_eq!(x[0], 1.0 - d, "sample {s}"),
                _ => assert!(x[0] > 0.0 && x[0] < 1.0),
            }
        }
    }
}
