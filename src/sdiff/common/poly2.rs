//! Exact bivariate polynomials over ℚ on the reference triangle, and their Bernstein–Bézier
//! form (Mello–Velho Eq. (10), after Farin 1986).
//!
//! A point of the reference triangle ⟨e_0, e_1, e_2⟩ has barycentric coordinates
//! (w_0, w_1, w_2) = (1 − s − t, s, t); polynomials are stored densely in the affine chart
//! (s, t). Why by hand: no maintained crate offers exact multivariate polynomials with
//! Bernstein conversion over `BigRational`; the operations needed (sum, product, partial
//! derivatives, composition with an affine map, Bernstein coefficients) are a few dozen lines.

use super::rational::{multinomial, over_common_denominator, q, to_f64, Q};
use num_bigint::BigInt;
use num_traits::{One, Zero};

/// Σ c\[a\]\[b\] s^a t^b, dense, total degree ≤ `deg`.
#[derive(Debug, Clone, PartialEq)]
pub struct Poly2 {
    /// Total degree bound (coefficients with a + b > deg are absent).
    deg: usize,
    /// `c[a * (deg + 1) + b]`, zero when a + b > deg.
    c: Vec<Q>,
}

impl Poly2 {
    /// The zero polynomial of degree bound `deg`.
    pub fn zero(deg: usize) -> Self {
        Poly2 {
            deg,
            c: vec![Q::zero(); (deg + 1) * (deg + 1)],
        }
    }
    /// The constant `k`.
    pub fn constant(k: Q) -> Self {
        let mut p = Poly2::zero(0);
        p.c[0] = k;
        p
    }
    /// s (= w_1).
    pub fn s() -> Self {
        let mut p = Poly2::zero(1);
        p.set(1, 0, q(1));
        p
    }
    /// t (= w_2).
    pub fn t() -> Self {
        let mut p = Poly2::zero(1);
        p.set(0, 1, q(1));
        p
    }
    /// 1 − s − t (= w_0).
    pub fn w0() -> Self {
        let mut p = Poly2::zero(1);
        p.set(0, 0, q(1));
        p.set(1, 0, q(-1));
        p.set(0, 1, q(-1));
        p
    }
    /// The barycentric coordinate w_i, i ∈ {0, 1, 2}.
    pub fn w(i: usize) -> Self {
        match i {
            0 => Poly2::w0(),
            1 => Poly2::s(),
            _ => Poly2::t(),
        }
    }
    /// Degree bound.
    pub fn deg(&self) -> usize {
        self.deg
    }
    /// Coefficient of s^a t^b.
    pub fn get(&self, a: usize, b: usize) -> Q {
        if a + b > self.deg {
            Q::zero()
        } else {
            self.c[a * (self.deg + 1) + b].clone()
        }
    }
    fn set(&mut self, a: usize, b: usize, v: Q) {
        let d = self.deg;
        self.c[a * (d + 1) + b] = v;
    }
    /// Every coefficient is zero.
    pub fn is_zero(&self) -> bool {
        self.c.iter().all(|x| x.is_zero())
    }
    /// self + o.
    pub fn add(&self, o: &Poly2) -> Poly2 {
        let d = self.deg.max(o.deg);
        let mut r = Poly2::zero(d);
        for a in 0..=d {
            for b in 0..=(d - a) {
                r.set(a, b, self.get(a, b) + o.get(a, b));
            }
        }
        r
    }
    /// self − o.
    pub fn sub(&self, o: &Poly2) -> Poly2 {
        self.add(&o.scale(&q(-1)))
    }
    /// k · self.
    pub fn scale(&self, k: &Q) -> Poly2 {
        Poly2 {
            deg: self.deg,
            c: self.c.iter().map(|x| x * k).collect(),
        }
    }
    /// self · o.
    pub fn mul(&self, o: &Poly2) -> Poly2 {
        // Integer products over a common denominator, one reduction per coefficient
        // (`over_common_denominator`): the same rationals as summing the products in ℚ.
        let d = self.deg + o.deg;
        let (xa, da) = over_common_denominator(self.c.iter());
        let (xb, db) = over_common_denominator(o.c.iter());
        let mut sums = vec![BigInt::zero(); (d + 1) * (d + 1)];
        for a in 0..=self.deg {
            for b in 0..=(self.deg - a) {
                let x = &xa[a * (self.deg + 1) + b];
                if x.is_zero() {
                    continue;
                }
                for c in 0..=o.deg {
                    for e in 0..=(o.deg - c) {
                        let y = &xb[c * (o.deg + 1) + e];
                        if !y.is_zero() {
                            sums[(a + c) * (d + 1) + b + e] += x * y;
                        }
                    }
                }
            }
        }
        let den = da * db;
        Poly2 {
            deg: d,
            c: sums
                .into_iter()
                .map(|v| {
                    if v.is_zero() {
                        Q::zero()
                    } else {
                        Q::new(v, den.clone())
                    }
                })
                .collect(),
        }
    }
    /// self^k.
    pub fn pow(&self, k: usize) -> Poly2 {
        let mut r = Poly2::constant(q(1));
        for _ in 0..k {
            r = r.mul(self);
        }
        r
    }
    /// ∂/∂s.
    pub fn ds(&self) -> Poly2 {
        let d = self.deg.saturating_sub(1);
        let mut r = Poly2::zero(d);
        for a in 1..=self.deg {
            for b in 0..=(self.deg - a) {
                r.set(a - 1, b, self.get(a, b) * q(a as i64));
            }
        }
        r
    }
    /// ∂/∂t.
    pub fn dt(&self) -> Poly2 {
        let d = self.deg.saturating_sub(1);
        let mut r = Poly2::zero(d);
        for a in 0..self.deg {
            for b in 1..=(self.deg - a) {
                r.set(a, b - 1, self.get(a, b) * q(b as i64));
            }
        }
        r
    }
    /// Exact value at (s, t).
    pub fn eval(&self, s: &Q, t: &Q) -> Q {
        let mut acc = Q::zero();
        let mut sa = q(1);
        for a in 0..=self.deg {
            let mut tb = sa.clone();
            for b in 0..=(self.deg - a) {
                let x = &self.c[a * (self.deg + 1) + b];
                if !x.is_zero() {
                    acc += x * &tb;
                }
                tb *= t;
            }
            sa *= s;
        }
        acc
    }
    /// Value in f64 (coefficients rounded first: for plots and Newton steps only).
    pub fn eval_f64(&self, s: f64, t: f64) -> f64 {
        let mut acc = 0.0;
        let mut sa = 1.0;
        for a in 0..=self.deg {
            let mut tb = sa;
            for b in 0..=(self.deg - a) {
                acc += to_f64(&self.c[a * (self.deg + 1) + b]) * tb;
                tb *= t;
            }
            sa *= s;
        }
        acc
    }
    /// p∘A where A maps the reference triangle affinely onto the triangle with corners
    /// `corners` (each given as (s, t)): A(s, t) = c0 + s (c1 − c0) + t (c2 − c0).
    pub(crate) fn compose_affine(&self, corners: &[[Q; 2]; 3]) -> Poly2 {
        let lin = |k: usize| -> Poly2 {
            let mut p = Poly2::zero(1);
            p.set(0, 0, corners[0][k].clone());
            p.set(1, 0, &corners[1][k] - &corners[0][k]);
            p.set(0, 1, &corners[2][k] - &corners[0][k]);
            p
        };
        let (sx, tx) = (lin(0), lin(1));
        let mut r = Poly2::zero(self.deg);
        let mut spow = Poly2::constant(q(1));
        for a in 0..=self.deg {
            let mut term = spow.clone();
            for b in 0..=(self.deg - a) {
                let x = self.get(a, b);
                if !x.is_zero() {
                    r = r.add(&term.scale(&x));
                }
                term = term.mul(&tx);
            }
            spow = spow.mul(&sx);
        }
        r.truncate(self.deg)
    }
    fn truncate(mut self, deg: usize) -> Poly2 {
        if self.deg == deg {
            return self;
        }
        let mut r = Poly2::zero(deg);
        for a in 0..=deg.min(self.deg) {
            for b in 0..=(deg - a).min(self.deg - a) {
                r.set(a, b, std::mem::take(&mut self.c[a * (self.deg + 1) + b]));
            }
        }
        r
    }
    /// Bernstein–Bézier coefficients of degree `n ≥ deg` on the reference triangle, indexed by
    /// [`multi_indices`]`(n)`: p = Σ_{|I|=n} b_I B_I(w_0, w_1, w_2).
    ///
    /// From s^a t^b = w_1^a w_2^b (w_0 + w_1 + w_2)^{n−a−b}: the coefficient of B_(i,j,k) is
    /// Σ_{a≤j, b≤k} c_ab · multinom(n−a−b; i, j−a, k−b) / multinom(n; i, j, k).
    pub fn bernstein(&self, n: usize) -> Vec<Q> {
        assert!(
            n >= self.deg,
            "Bernstein degree below the polynomial's degree"
        );
        multi_indices(n)
            .into_iter()
            .map(|[i, j, k]| {
                let mut acc = Q::zero();
                for a in 0..=j {
                    for b in 0..=k {
                        let x = self.get(a, b);
                        if x.is_zero() {
                            continue;
                        }
                        acc +=
                            x * Q::new(multinomial(n - a - b, &[i, j - a, k - b]), BigInt::one())
                                / Q::from_integer(multinomial(n, &[i, j, k]));
                    }
                }
                acc
            })
            .collect()
    }
}

/// Multi-indices I = (I^0, I^1, I^2), |I| = n, in a fixed order: I^1 outer, I^2 inner.
pub fn multi_indices(n: usize) -> Vec<[usize; 3]> {
    let mut v = Vec::with_capacity((n + 1) * (n + 2) / 2);
    for j in 0..=n {
        for k in 0..=(n - j) {
            v.push([n - j - k, j, k]);
        }
    }
    v
}

/// Position of `I` in [`multi_indices`]`(n)`: row j = I^1 starts after Σ_{j'<j} (n − j' + 1)
/// entries.
pub fn index_of(n: usize, i: [usize; 3]) -> usize {
    let j = i[1];
    j * (n + 1) - j * j.saturating_sub(1) / 2 + i[2]
}

/// The Bernstein polynomial B_I(w) = multinom(n; I) w_0^I0 w_1^I1 w_2^I2 as a [`Poly2`].
pub fn bernstein_basis(i: [usize; 3]) -> Poly2 {
    let n = i[0] + i[1] + i[2];
    Poly2::w0()
        .pow(i[0])
        .mul(&Poly2::s().pow(i[1]))
        .mul(&Poly2::t().pow(i[2]))
        .scale(&Q::from_integer(multinomial(n, &i)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sdiff::common::rational::qr;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    fn random_poly(rng: &mut ChaCha8Rng, deg: usize) -> Poly2 {
        let mut p = Poly2::zero(deg);
        for a in 0..=deg {
            for b in 0..=(deg - a) {
                // Zeros, integers and fractions with unlike denominators.
                let v = match rng.gen_range(0..4) {
                    0 => Q::zero(),
                    1 => q(rng.gen_range(-9..10)),
                    _ => qr(rng.gen_range(-999..1000), rng.gen_range(1..64)),
                };
                p.set(a, b, v);
            }
        }
        p
    }

    /// The product over a common denominator is the sum of the products in ℚ, coefficient for
    /// coefficient (and so equal as a value, reduced form included).
    #[test]
    fn sd_poly2_product_over_a_common_denominator_equals_the_sum_in_q() {
        let mut rng = ChaCha8Rng::seed_from_u64(2);
        for case in 0..100 {
            let (da, db) = (rng.gen_range(0..5), rng.gen_range(0..5));
            let (x, y) = (random_poly(&mut rng, da), random_poly(&mut rng, db));
            let mut want = Poly2::zero(da + db);
            for a in 0..=da {
                for b in 0..=(da - a) {
                    for c in 0..=db {
                        for e in 0..=(db - c) {
                            let v = want.get(a + c, b + e) + x.get(a, b) * y.get(c, e);
                            want.set(a + c, b + e, v);
                        }
                    }
                }
            }
            assert_eq!(x.mul(&y), want, "case {case}");
        }
        // A product that cancels to zero keeps the canonical zero.
        let p = Poly2::s().mul(&Poly2::constant(qr(1, 3)));
        assert!(p.sub(&p).mul(&p).is_zero());
    }
}
