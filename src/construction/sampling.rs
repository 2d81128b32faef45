//! Deterministic seeded samplers (ChaCha8 from a `u64` seed) for the Chapter 4 checks.
//!
//! Points are generated directly in the scalar type `S` (radii like ρ(1 − 10^−k) are formed in
//! `S`, so `Mp` samples really lie at distance 10^−k even beyond f64 resolution). Every
//! sampler returns [`Samples`], which counts points per [`Category`] for reports.

use super::maps::{cos_pi_6, P2};
use crate::numeric::Scalar;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::collections::BTreeMap;

/// What region a sample was drawn from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, serde::Serialize)]
pub(crate) enum Category {
    /// Uniform in the disk/lens.
    Uniform,
    /// Radius ρ(1 − 10^−k): just inside the boundary circle.
    NearBoundary,
    /// Radius 10^−k: near the origin.
    NearOrigin,
    /// Angle cut + 10^−k·t (t ∈ [1/2, 1]): just counterclockwise of the cut ray (for Π's cut
    /// at angle π, i.e. the negative x-axis, this is *below* the axis: θ wraps to −π + …).
    NearCutCcw,
    /// Angle cut − 10^−k·t: just clockwise of the cut ray (for Π: *above* the negative x-axis).
    NearCutCw,
    /// Exactly on a boundary arc (up to the rounding of the scalar type).
    OnBoundary,
    /// Within 10^−k of a boundary curve of a lens, inside or outside.
    NearLensBoundary,
    /// Within 10^−k of the symmetry axis (the x-axis) of the canonical lens.
    NearLensAxis,
}

/// Sampled points with their categories.
#[derive(Clone, Debug)]
pub(crate) struct Samples<S> {
    /// The points, each with the region it was drawn from.
    pub points: Vec<(Category, P2<S>)>,
}

impl<S> Samples<S> {
    /// Number of points per category.
    pub(crate) fn counts(&self) -> BTreeMap<Category, usize> {
        let mut m = BTreeMap::new();
        for (c, _) in &self.points {
            *m.entry(*c).or_insert(0) += 1;
        }
        m
    }
    /// "Uniform 400, NearBoundary 150, ..." for reports.
    pub(crate) fn counts_string(&self) -> String {
        self.counts()
            .iter()
            .map(|(c, n)| format!("{c:?} {n}"))
            .collect::<Vec<_>>()
            .join(", ")
    }
    /// Number of points.
    pub(crate) fn len(&self) -> usize {
        self.points.len()
    }
}

/// Largest k used for 10^−k offsets at a precision: leaves 3 decimal digits of resolution,
/// capped at 30.
pub(crate) fn max_offset_exponent(prec: u32) -> u32 {
    let digits = (prec as f64 * std::f64::consts::LOG10_2).floor() as u32;
    digits.saturating_sub(3).clamp(1, 30)
}

/// The RNG used by all samplers.
pub(crate) fn rng(seed: u64) -> ChaCha8Rng {
    ChaCha8Rng::seed_from_u64(seed)
}

fn pow10_neg<S: Scalar>(k: u32, prec: u32) -> S {
    let mut x = S::from_i64(1, prec);
    let ten = S::from_i64(10, prec);
    for _ in 0..k {
        x = x.div(&ten);
    }
    x
}

fn point_polar<S: Scalar>(r: &S, angle: &S) -> P2<S> {
    P2::new(r.mul(&angle.cos()), r.mul(&angle.sin()))
}

/// Samples of the open disk of radius `rho` about the origin, with a distinguished cut ray at
/// angle `cut` (π for Π's branch cut). Proportions: 40% uniform, 15% near the boundary circle
/// (radius ρ(1 − 10^−k), k = 1..kmax), 15% near the origin (radius ρ·10^−k), 30% near the cut
/// (angle cut ± 10^−k, both sides equally, radius uniform).
pub(crate) fn sample_disk<S: Scalar>(
    seed: u64,
    n: usize,
    rho: &S,
    cut: &S,
    prec: u32,
) -> Samples<S> {
    let mut g = rng(seed);
    let kmax = max_offset_exponent(prec);
    let pi = S::pi(prec);
    let one = S::from_i64(1, prec);
    let mut points = Vec::with_capacity(n);
    for idx in 0..n {
        let bucket = idx % 20;
        let k = 1 + (idx as u32 / 20) % kmax;
        let ang_frac: f64 = g.gen_range(-1.0..1.0);
        let angle = pi.mul(&S::from_f64(ang_frac, prec));
        let t: f64 = g.gen_range(0.5..1.0);
        let (cat, p) = if bucket < 8 {
            let u: f64 = g.gen_range(0.0..1.0);
            let r = rho.mul(&S::from_f64(u, prec).sqrt());
            (Category::Uniform, point_polar(&r, &angle))
        } else if bucket < 11 {
            let r = rho.mul(&one.sub(&pow10_neg::<S>(k, prec).mul(&S::from_f64(t, prec))));
            (Category::NearBoundary, point_polar(&r, &angle))
        } else if bucket < 14 {
            let r = rho.mul(&pow10_neg::<S>(k, prec)).mul(&S::from_f64(t, prec));
            (Category::NearOrigin, point_polar(&r, &angle))
        } else {
            let u: f64 = g.gen_range(0.0..1.0);
            let r = rho.mul(&S::from_f64(u, prec).sqrt());
            let off = pow10_neg::<S>(k, prec).mul(&S::from_f64(t, prec));
            if bucket < 17 {
                (Category::NearCutCcw, point_polar(&r, &cut.add(&off)))
            } else {
                (Category::NearCutCw, point_polar(&r, &cut.sub(&off)))
            }
        };
        points.push((cat, p));
    }
    Samples { points }
}

/// Points exactly on the circle of radius `rho` (as exactly as the scalar type rounds), at
/// angles uniform in `(a0, a1)`.
pub(crate) fn sample_circle_arc<S: Scalar>(
    seed: u64,
    n: usize,
    rho: &S,
    centre: &P2<S>,
    a0: &S,
    a1: &S,
    prec: u32,
) -> Samples<S> {
    let mut g = rng(seed);
    let mut points = Vec::with_capacity(n);
    for _ in 0..n {
        let t: f64 = g.gen_range(0.0..1.0);
        let a = a0.add(&a1.sub(a0).mul(&S::from_f64(t, prec)));
        points.push((Category::OnBoundary, centre.add(&point_polar(rho, &a))));
    }
    Samples { points }
}

/// Half-opening angle α₀ = atan(√2) of the canonical lens seen from the origin: the corners of
/// E are (1/2, ±√2/2) (intersection of ∂C and ∂D).
pub(crate) fn lens_corner_angle<S: Scalar>(prec: u32) -> S {
    let s2h = S::from_i64(2, prec).sqrt().div(&S::from_i64(2, prec));
    s2h.atan2(&S::from_ratio(1, 2, prec))
}

/// Samples of the canonical lens E (Sec. 4.1): 40% uniform in E (rejection from its bounding
/// box, points outside are dropped), 40% within ρ·10^−k of the two boundary arcs (∂C inside D
/// and ∂D inside C), on both sides, including near the corners, 20% within 10^−k of the
/// lens axis y = 0 (x uniform in (1 − cos π/6, cos π/6)).
pub(crate) fn sample_lens<S: Scalar>(seed: u64, n: usize, prec: u32) -> Samples<S> {
    let mut g = rng(seed);
    let kmax = max_offset_exponent(prec);
    let rho = cos_pi_6::<S>(prec);
    let a0 = lens_corner_angle::<S>(prec);
    let pi = S::pi(prec);
    let one = S::from_i64(1, prec);
    let zero = S::from_i64(0, prec);
    let d_centre = P2::new(one.clone(), zero.clone());
    let three_quarters = S::from_ratio(3, 4, prec);
    let mut points = Vec::with_capacity(n);
    for idx in 0..n {
        let k = 1 + (idx as u32 / 2) % kmax;
        if idx % 5 == 4 {
            let x: f64 = g.gen_range(0.1340..0.8660);
            let s: f64 = g.gen_range(0.5..1.0);
            let side = if g.gen_bool(0.5) { 1.0 } else { -1.0 };
            let y = pow10_neg::<S>(k, prec).mul(&S::from_f64(side * s, prec));
            points.push((Category::NearLensAxis, P2::new(S::from_f64(x, prec), y)));
        } else if idx % 2 == 0 {
            let x: f64 = g.gen_range(0.1339..0.8661);
            let y: f64 = g.gen_range(-0.7072..0.7072);
            let p = P2::<S>::from_f64(x, y, prec);
            let in_c = p.norm2().lt(&three_quarters).is_true();
            let in_d = p.sub(&d_centre).norm2().lt(&three_quarters).is_true();
            if in_c && in_d {
                points.push((Category::Uniform, p));
            }
        } else {
            let t: f64 = g.gen_range(-1.0..1.0);
            let s: f64 = g.gen_range(0.5..1.0);
            let side = if g.gen_bool(0.5) { 1.0 } else { -1.0 };
            let corner_bias = g.gen_bool(0.2);
            let tt = if corner_bias {
                t.signum() * (1.0 - 1e-3 * t.abs())
            } else {
                t
            };
            let off = pow10_neg::<S>(k, prec).mul(&S::from_f64(side * s, prec));
            let r = rho.mul(&one.add(&off));
            let ang = a0.mul(&S::from_f64(tt, prec));
            let p = if g.gen_bool(0.5) {
                point_polar(&r, &ang)
            } else {
                d_centre.add(&point_polar(&r, &pi.sub(&ang)))
            };
            points.push((Category::NearLensBoundary, p));
        }
    }
    Samples { points }
}

/// Points exactly on the arc ∂D ∩ int(C) (the inner boundary of E, whose pull-back by
/// R_(u,w)⁻¹∘g_u⁻¹ is ∂Ω_uw ∩ Ω_u, used for condition (4) / L4.2.3).
pub(crate) fn sample_lens_inner_arc<S: Scalar>(seed: u64, n: usize, prec: u32) -> Samples<S> {
    let rho = cos_pi_6::<S>(prec);
    let a0 = lens_corner_angle::<S>(prec);
    let pi = S::pi(prec);
    let centre = P2::new(S::from_i64(1, prec), S::from_i64(0, prec));
    // Stay 1% inside the corners so the arc points are in int(C).
    let shrink = S::from_ratio(99, 100, prec);
    let lo = pi.sub(&a0.mul(&shrink));
    let hi = pi.add(&a0.mul(&shrink));
    sample_circle_arc(seed, n, &rho, &centre, &lo, &hi, prec)
}
