//! Implicit plane curves g(x, y) = 0 with rational coefficients for Mello–Velho Sec. 6.2:
//! Taubin's quartic exactly as printed at L330–L334, and the circle of Fig. 4 (L183,
//! x² + y² − 0.28²). Exact values at rational points, f64 values and gradients, and the
//! natural interval extension over a box in exact rationals (the inclusion function □g of
//! L318–L320: each monomial's exact range, summed).

use crate::sdiff::common::rational::{to_f64, Q};
use num_bigint::BigInt;
use num_traits::{Signed, Zero};

/// g = Σ c · x^i y^j.
#[derive(Debug, Clone)]
pub struct Implicit {
    /// Name for reports.
    pub name: &'static str,
    /// (i, j, c).
    pub terms: Vec<(u32, u32, Q)>,
    /// The box the paper's figure shows the curve in (lo, hi).
    pub domain: ([f64; 2], [f64; 2]),
}

fn thousandths(n: i64) -> Q {
    Q::new(BigInt::from(n), BigInt::from(1000))
}

impl Implicit {
    /// Taubin's curve, L330–L334 (coefficients in thousandths). Domain [−2, 2.5]²: its zero
    /// set lies in [−1.18, 1.44] × [−1.58, 2.39] (measured on an 800² grid over [−4, 4]²).
    pub fn taubin() -> Implicit {
        let t = [
            (0, 0, 4),
            (1, 0, 110),
            (0, 1, -177),
            (2, 0, -174),
            (1, 1, 224),
            (0, 2, -303),
            (3, 0, -168),
            (2, 1, 327),
            (1, 2, -87),
            (0, 3, -13),
            (4, 0, 235),
            (3, 1, -667),
            (2, 2, 745),
            (1, 3, -29),
            (0, 4, 72),
        ];
        Implicit {
            name: "taubin",
            terms: t.iter().map(|&(i, j, c)| (i, j, thousandths(c))).collect(),
            domain: ([-2.0, -2.0], [2.5, 2.5]),
        }
    }
    /// Fig. 4: x² + y² − 0.28² on [−0.5, 0.5]².
    pub fn circle() -> Implicit {
        Implicit {
            name: "circle",
            terms: vec![
                (2, 0, thousandths(1000)),
                (0, 2, thousandths(1000)),
                (0, 0, -thousandths(280) * thousandths(280)),
            ],
            domain: ([-0.5, -0.5], [0.5, 0.5]),
        }
    }
    /// g(x, y), exact.
    pub fn eval(&self, x: &Q, y: &Q) -> Q {
        self.terms
            .iter()
            .map(|(i, j, c)| {
                c * num_traits::pow(x.clone(), *i as usize)
                    * num_traits::pow(y.clone(), *j as usize)
            })
            .sum()
    }
    /// g(x, y) in f64.
    pub fn eval_f64(&self, x: f64, y: f64) -> f64 {
        self.terms
            .iter()
            .map(|(i, j, c)| to_f64(c) * x.powi(*i as i32) * y.powi(*j as i32))
            .sum()
    }
    /// ∇g(x, y) in f64.
    pub(crate) fn grad_f64(&self, x: f64, y: f64) -> [f64; 2] {
        let mut g = [0.0; 2];
        for (i, j, c) in &self.terms {
            let c = to_f64(c);
            if *i > 0 {
                g[0] += c * *i as f64 * x.powi(*i as i32 - 1) * y.powi(*j as i32);
            }
            if *j > 0 {
                g[1] += c * *j as f64 * x.powi(*i as i32) * y.powi(*j as i32 - 1);
            }
        }
        g
    }
    /// ∂g/∂x (axis 0) or ∂g/∂y (axis 1) as an implicit polynomial.
    pub fn derivative(&self, axis: usize) -> Implicit {
        let terms = self
            .terms
            .iter()
            .filter_map(|(i, j, c)| match axis {
                0 if *i > 0 => Some((i - 1, *j, c * Q::from_integer(BigInt::from(*i)))),
                1 if *j > 0 => Some((*i, j - 1, c * Q::from_integer(BigInt::from(*j)))),
                _ => None,
            })
            .collect();
        Implicit {
            name: self.name,
            terms,
            domain: self.domain,
        }
    }
    /// □g over the box \[x0, x1\] × \[y0, y1\], exact (natural extension, monomial by monomial).
    pub fn range(&self, x: [&Q; 2], y: [&Q; 2]) -> [Q; 2] {
        let mut lo = Q::zero();
        let mut hi = Q::zero();
        for (i, j, c) in &self.terms {
            let px = pow_range(x, *i);
            let py = pow_range(y, *j);
            let prod = mul_range(&px, &py);
            let term = mul_range(&[c.clone(), c.clone()], &prod);
            lo += &term[0];
            hi += &term[1];
        }
        [lo, hi]
    }
}

/// The exact range of t^k over [a, b].
fn pow_range(t: [&Q; 2], k: u32) -> [Q; 2] {
    let (a, b) = (t[0].clone(), t[1].clone());
    let (pa, pb) = (
        num_traits::pow(a.clone(), k as usize),
        num_traits::pow(b.clone(), k as usize),
    );
    if k % 2 == 0 && a.is_negative() && b.is_positive() {
        return [Q::zero(), if pa > pb { pa } else { pb }];
    }
    if pa <= pb {
        [pa, pb]
    } else {
        [pb, pa]
    }
}

/// Interval product.
pub(crate) fn mul_range(a: &[Q; 2], b: &[Q; 2]) -> [Q; 2] {
    let c = [&a[0] * &b[0], &a[0] * &b[1], &a[1] * &b[0], &a[1] * &b[1]];
    let mut lo = c[0].clone();
    let mut hi = c[0].clone();
    for x in &c[1..] {
        if *x < lo {
            lo = x.clone();
        }
        if *x > hi {
            hi = x.clone();
        }
    }
    [lo, hi]
}
