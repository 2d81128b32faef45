//! Sec. 3.3: the two-chart stereographic atlas of Sⁿ (Def. 3.3.3), and the same sphere as a set
//! of gluing data (Def. 3.4.1): two open balls of radius ρ glued along the annulus
//! 1/ρ < ‖u‖ < ρ by the transition u ↦ u/‖u‖² (the paper's φ_SN). The p-domains must be
//! disjoint subsets of ℝⁿ, so chart i is centred at c_i = (∓3ρ, 0, …, 0).

use super::data::{GluingData, Idx, Point};
use crate::numeric::Scalar;
use crate::report::{CheckResult, Witness};
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use serde_json::json;

/// φ_N : Sⁿ − {N} → ℝⁿ, x ↦ (x_1, …, x_n)/(1 − x_{n+1}).
pub fn phi_north(x: &[f64]) -> Vec<f64> {
    let n = x.len() - 1;
    x[..n].iter().map(|c| c / (1.0 - x[n])).collect()
}
/// φ_S : Sⁿ − {S} → ℝⁿ, x ↦ (x_1, …, x_n)/(1 + x_{n+1}).
pub fn phi_south(x: &[f64]) -> Vec<f64> {
    let n = x.len() - 1;
    x[..n].iter().map(|c| c / (1.0 + x[n])).collect()
}
/// φ_N⁻¹(u) = (2u, ‖u‖² − 1)/(‖u‖² + 1). Generic over the scalar (jets give its derivatives:
/// the curvature check of `ppm render`).
pub fn phi_north_inv<S: Scalar>(u: &[S]) -> Vec<S> {
    stereo_inv(u, false)
}
/// φ_S⁻¹(u) = (2u, 1 − ‖u‖²)/(‖u‖² + 1).
pub fn phi_south_inv<S: Scalar>(u: &[S]) -> Vec<S> {
    stereo_inv(u, true)
}
fn stereo_inv<S: Scalar>(u: &[S], south: bool) -> Vec<S> {
    let prec = u.first().map_or(53, Scalar::precision_bits);
    let one = S::from_i64(1, prec);
    let two = S::from_i64(2, prec);
    let s = u
        .iter()
        .fold(S::from_i64(0, prec), |acc, c| acc.add(&c.mul(c)));
    let d = s.add(&one);
    let mut v: Vec<S> = u.iter().map(|c| two.mul(c).div(&d)).collect();
    let last = if south { one.sub(&s) } else { s.sub(&one) };
    v.push(last.div(&d));
    v
}
/// The transition φ_SN = φ_NS : u ↦ u/‖u‖² on ℝⁿ − {0} stated in Sec. 3.3.
pub fn inversion(u: &[f64]) -> Vec<f64> {
    let s: f64 = u.iter().map(|c| c * c).sum();
    u.iter().map(|c| c / s).collect()
}

fn vdist(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y) * (x - y))
        .sum::<f64>()
        .sqrt()
}

/// A uniformly random point of Sⁿ ⊂ ℝⁿ⁺¹ (normalised box sample, rejecting tiny norms).
pub fn random_sphere_point(n: usize, rng: &mut ChaCha8Rng) -> Vec<f64> {
    loop {
        let v: Vec<f64> = (0..=n).map(|_| rng.gen_range(-1.0..1.0)).collect();
        let s = v.iter().map(|c| c * c).sum::<f64>().sqrt();
        if s > 1e-3 && s <= 1.0 {
            return v.iter().map(|c| c / s).collect();
        }
    }
}

/// Def. 3.3.3 for the stereographic atlas {(U_N, φ_N), (U_S, φ_S)} of Sⁿ, on `samples` random
/// points: (1) both charts land in ℝⁿ and are homeomorphisms onto ℝⁿ (φ⁻¹∘φ = id on the sphere,
/// φ∘φ⁻¹ = id on ℝⁿ); (2) U_N ∪ U_S covers Sⁿ; (3) on U_N ∩ U_S the transition φ_S ∘ φ_N⁻¹
/// equals `transition` (the paper: u ↦ u/‖u‖²), which is an involution, hence a bijection of
/// ℝⁿ − {0} with smooth inverse. `transition` is a parameter so that a wrong formula is caught.
pub fn check_atlas(
    n: usize,
    transition: impl Fn(&[f64]) -> Vec<f64>,
    samples: usize,
    rng: &mut ChaCha8Rng,
    seed: u64,
) -> CheckResult {
    let mut r = CheckResult::new("D3.3.3", "stereographic atlas of Sⁿ is a C^∞ n-atlas")
        .with_note(format!("sampled on S^{n}"));
    r.seed = Some(seed);
    let t = crate::gluing::tolerance::tol::<f64>(1.0) * 1e3; // ill-conditioned near the poles
    r.tolerance = Some(t);
    let mut worst: f64 = 0.0;
    let bad = |r: &mut CheckResult, what: &str, p: &[f64], d: f64| {
        r.offend(|| {
            Witness::new(
                format!("{what} at {p:?}: deviation {d:.3e}"),
                json!({"kind": what, "p": p, "deviation": d}),
            )
        });
    };
    for _ in 0..samples {
        let x = random_sphere_point(n, rng);
        r.examined += 1;
        // Keep away from the poles, where the charts blow up (they are not in the overlap).
        if x[n].abs() > 0.99 {
            continue;
        }
        let (un, us) = (phi_north(&x), phi_south(&x));
        if un.len() != n || us.len() != n {
            bad(&mut r, "chart dimension", &x, 1.0);
        }
        let d1 = vdist(&phi_north_inv(&un), &x).max(vdist(&phi_south_inv(&us), &x));
        let d2 = vdist(&phi_north(&phi_north_inv(&un)), &un)
            .max(vdist(&phi_south(&phi_south_inv(&us)), &us));
        let tr = transition(&un);
        let d3 = vdist(&tr, &phi_south(&phi_north_inv(&un)));
        let d4 = vdist(&transition(&tr), &un);
        for (what, d) in [
            ("phi_inv_phi", d1),
            ("phi_phi_inv", d2),
            ("transition", d3),
            ("involution", d4),
        ] {
            worst = worst.max(d);
            if d > t * (1.0 + un.iter().map(|c| c * c).sum::<f64>()) {
                bad(&mut r, what, &x, d);
            }
        }
    }
    // (2) cover: N ∈ U_S and S ∈ U_N; every other point is in both.
    let mut north = vec![0.0; n + 1];
    north[n] = 1.0;
    let south: Vec<f64> = north.iter().map(|c| -c).collect();
    if !(phi_south(&north).iter().all(|c| c.is_finite())
        && phi_north(&south).iter().all(|c| c.is_finite()))
    {
        bad(&mut r, "cover", &north, f64::INFINITY);
    }
    r.worst_deviation = Some(worst);
    r
}

/// Sⁿ as gluing data: Ω_1 = B(c_1, ρ) (chart φ_N), Ω_2 = B(c_2, ρ) (chart φ_S),
/// Ω_12 = {1/ρ < ‖u − c_1‖ < ρ}, φ_21(u) = c_2 + (u − c_1)/‖u − c_1‖², symmetrically φ_12.
/// `glue_outer` < ρ shrinks the annulus to 1/g < ‖·‖ < g (a planted fault for (C′)).
#[derive(Clone, Debug)]
pub struct StereoSphere<const N: usize> {
    /// Radius ρ of both p-domains (ρ > 1 for a non-empty annulus).
    pub rho: f64,
    /// Outer radius g of the gluing annulus (ρ unless shrunk to plant a fault).
    pub glue_outer: f64,
}

impl<const N: usize> StereoSphere<N> {
    /// The sphere with the full annulus, `glue_outer` = ρ.
    pub fn new(rho: f64) -> Self {
        StereoSphere {
            rho,
            glue_outer: rho,
        }
    }
    /// Centre c_i of Ω_i: (−3ρ, 0, …) for i = 1, (3ρ, 0, …) otherwise, so the p-domains are disjoint.
    pub fn center(&self, i: Idx) -> [f64; N] {
        let mut c = [0.0; N];
        if N > 0 {
            c[0] = if i == 1 {
                -3.0 * self.rho
            } else {
                3.0 * self.rho
            };
        }
        c
    }
    /// Local coordinate u = p − c_i.
    pub fn local(&self, i: Idx, p: &[f64; N]) -> [f64; N] {
        let c = self.center(i);
        let mut u = *p;
        for m in 0..N {
            u[m] -= c[m];
        }
        u
    }
    /// θ_1 = φ_N⁻¹ and θ_2 = φ_S⁻¹ in local coordinates: a PPM of dimension N in ℝᴺ⁺¹.
    pub fn theta(&self, i: Idx, p: &[f64; N]) -> Vec<f64> {
        let u = self.local(i, p);
        if i == 1 {
            phi_north_inv(&u)
        } else {
            phi_south_inv(&u)
        }
    }
    fn r(&self, i: Idx, p: &[f64; N]) -> f64 {
        self.local(i, p).iter().map(|c| c * c).sum::<f64>().sqrt()
    }
}

impl<const N: usize> GluingData<N> for StereoSphere<N> {
    type S = f64;
    fn indices(&self) -> Vec<Idx> {
        vec![1, 2]
    }
    fn in_p_domain(&self, i: Idx, p: &Point<f64, N>) -> bool {
        (i == 1 || i == 2) && self.r(i, p) < self.rho
    }
    fn in_gluing_domain(&self, i: Idx, j: Idx, p: &Point<f64, N>) -> bool {
        if i == j {
            return self.in_p_domain(i, p);
        }
        let r = self.r(i, p);
        (i == 1 || i == 2) && (j == 1 || j == 2) && r > 1.0 / self.glue_outer && r < self.glue_outer
    }
    fn phi(&self, j: Idx, i: Idx, p: &Point<f64, N>) -> Option<Point<f64, N>> {
        if !self.in_gluing_domain(i, j, p) {
            return None;
        }
        if i == j {
            return Some(*p);
        }
        let u = self.local(i, p);
        let s: f64 = u.iter().map(|c| c * c).sum();
        let c = self.center(j);
        let mut v = [0.0; N];
        for m in 0..N {
            v[m] = c[m] + u[m] / s;
        }
        Some(v)
    }
    fn sample_p_domain(&self, i: Idx, rng: &mut ChaCha8Rng, n: usize) -> Vec<Point<f64, N>> {
        self.sample_shell(i, 0.0, self.rho, rng, n)
    }
    fn sample_gluing_domain(
        &self,
        i: Idx,
        j: Idx,
        rng: &mut ChaCha8Rng,
        n: usize,
    ) -> Vec<Point<f64, N>> {
        if i == j {
            return self.sample_p_domain(i, rng, n);
        }
        self.sample_shell(i, 1.0 / self.glue_outer, self.glue_outer, rng, n)
    }
    fn gluing_boundary_points(
        &self,
        i: Idx,
        j: Idx,
        rng: &mut ChaCha8Rng,
        n: usize,
    ) -> Vec<Point<f64, N>> {
        if i == j {
            return Vec::new();
        }
        // ∂Ω_ij ∩ Ω_i is the inner sphere ‖u‖ = 1/g (the outer one lies on ∂Ω_i when g = ρ,
        // and inside Ω_i when the annulus is shrunk).
        let mut radii = vec![1.0 / self.glue_outer];
        if self.glue_outer < self.rho {
            radii.push(self.glue_outer);
        }
        let c = self.center(i);
        let mut out = Vec::new();
        for s in 0..n.max(1) {
            let d = unit::<N>(rng);
            let rad = radii[s % radii.len()];
            let mut p = c;
            for m in 0..N {
                p[m] += rad * d[m];
            }
            out.push(p);
        }
        out
    }
    fn scale(&self) -> f64 {
        self.rho
    }
}

fn unit<const N: usize>(rng: &mut ChaCha8Rng) -> [f64; N] {
    loop {
        let mut d = [0.0; N];
        for c in d.iter_mut() {
            *c = rng.gen_range(-1.0..1.0);
        }
        let s = d.iter().map(|c| c * c).sum::<f64>().sqrt();
        if s > 1e-3 && s <= 1.0 {
            for c in d.iter_mut() {
                *c /= s;
            }
            return d;
        }
    }
}

impl<const N: usize> StereoSphere<N> {
    /// Uniform-in-radius samples of the shell lo < ‖u‖ < hi, plus points near both radii.
    fn sample_shell(
        &self,
        i: Idx,
        lo: f64,
        hi: f64,
        rng: &mut ChaCha8Rng,
        n: usize,
    ) -> Vec<Point<f64, N>> {
        let c = self.center(i);
        let mut out = Vec::new();
        for s in 0..n.max(1) {
            let d = unit::<N>(rng);
            let w = hi - lo;
            let rad = match s % 4 {
                1 => lo + w * 2f64.powi(-((s / 4 % 30) as i32) - 2),
                3 => hi - w * 2f64.powi(-((s / 4 % 30) as i32) - 2),
                _ => lo + w * rng.gen_range(0.001..0.999),
            };
            let mut p = c;
            for m in 0..N {
                p[m] += rad * d[m];
            }
            let r = self.r(i, &p);
            if r > lo && r < hi {
                out.push(p);
            }
        }
        out
    }
}
