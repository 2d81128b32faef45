//! Truncated bivariate Taylor polynomials ("jets") of total degree ≤ 3, as a [`Scalar`].
//!
//! Evaluating θ_v (Def. 5.4.2) on `Jet<S>` inputs `x = x₀ + dx`, `y = y₀ + dy` yields every
//! partial derivative of order ≤ 3 at (x₀, y₀) exactly (up to the rounding of `S`): forward-mode
//! automatic differentiation through the maps of Chapter 4, the Bézier patches and ξ. This is
//! how the normals and curvatures of the sampled surface and the smoothness checks
//! ("derivatives up to order 3 computed in two charts agree") are obtained — no finite
//! differences.
//!
//! Coefficients are Taylor coefficients: `c[idx(i, j)] = ∂^{i+j}f / (∂x^i ∂y^j) / (i! j!)`.
//! Every decision (sign, comparison) is taken on the value part.

use super::scalar_ext::SurfaceScalar;
use crate::numeric::Scalar;
use std::cmp::Ordering;

/// Number of monomials x^i y^j with i + j ≤ 3.
pub const JET_LEN: usize = 10;
/// Maximal total order of the jets.
pub const JET_ORDER: usize = 3;

/// Exponents (i, j) of the monomial stored at each index.
pub const MONOMIALS: [(usize, usize); JET_LEN] = [
    (0, 0),
    (1, 0),
    (0, 1),
    (2, 0),
    (1, 1),
    (0, 2),
    (3, 0),
    (2, 1),
    (1, 2),
    (0, 3),
];

/// Index of the monomial x^i y^j (i + j ≤ 3).
pub const fn idx(i: usize, j: usize) -> usize {
    let d = i + j;
    d * (d + 1) / 2 + j
}

/// Jets truncated at total order 2 (value, gradient, Hessian): enough for normals and
/// curvatures, at under half the work of order 3 per product.
pub type Jet2<S> = Jet<S, 6>;
/// Jets truncated at total order 1 (value and gradient): enough for normals.
pub type Jet1<S> = Jet<S, 3>;

/// The total order of a jet with `len` coefficients (1, 3, 6 or 10).
pub const fn order_of(len: usize) -> usize {
    match len {
        1 => 0,
        3 => 1,
        6 => 2,
        10 => 3,
        _ => panic!("a jet has 1, 3, 6 or 10 coefficients (order 0..=3)"),
    }
}

/// The products of one truncation order: the triples (a, b, c) with monomial a · monomial b =
/// monomial c, and how many of the 35 slots are used.
type MulTable = ([(u8, u8, u8); 35], usize);

/// All (a, b, c) with monomial a · monomial b = monomial c of degree ≤ `order`, and how many.
const fn mul_table(order: usize) -> MulTable {
    let mut t = [(0u8, 0u8, 0u8); 35];
    let mut n = 0;
    let mut a = 0;
    while a < JET_LEN {
        let mut b = 0;
        while b < JET_LEN {
            let (ia, ja) = MONOMIALS[a];
            let (ib, jb) = MONOMIALS[b];
            if ia + ja + ib + jb <= order {
                t[n] = (a as u8, b as u8, idx(ia + ib, ja + jb) as u8);
                n += 1;
            }
            b += 1;
        }
        a += 1;
    }
    (t, n)
}

/// The product tables of the orders 0..=3 (order 3: the full table of [`JET_ORDER`]).
const MUL: [MulTable; 4] = [
    mul_table(0),
    mul_table(1),
    mul_table(2),
    mul_table(JET_ORDER),
];

/// A jet in two variables over the scalar `S` with `L` Taylor coefficients: total order 3 by
/// default (L = 10); [`Jet2`] (L = 6) and [`Jet1`] (L = 3) truncate lower.
#[derive(Clone, Debug, PartialEq)]
pub struct Jet<S, const L: usize = JET_LEN> {
    /// Taylor coefficients: `c[idx(i, j)]` multiplies xⁱyʲ (so `c[0]` is the value).
    pub c: [S; L],
}

impl<S: Scalar, const L: usize> Jet<S, L> {
    /// The total order of the jet.
    pub const ORDER: usize = order_of(L);
    /// The constant `v` (all derivatives zero).
    pub fn constant(v: S) -> Self {
        let z = S::from_i64(0, v.precision_bits());
        let mut c: [S; L] = std::array::from_fn(|_| z.clone());
        c[0] = v;
        Jet { c }
    }
    /// The coordinate functions x, y at the point (x₀, y₀): the identity jets.
    pub fn variables(x0: S, y0: S) -> (Self, Self) {
        let prec = x0.precision_bits().max(y0.precision_bits());
        let one = S::from_i64(1, prec);
        let mut x = Jet::constant(x0);
        let mut y = Jet::constant(y0);
        if Self::ORDER >= 1 {
            x.c[idx(1, 0)] = one.clone();
            y.c[idx(0, 1)] = one;
        }
        (x, y)
    }
    /// The value at the base point.
    pub fn value(&self) -> &S {
        &self.c[0]
    }
    /// The partial derivative ∂^{i+j} / ∂x^i ∂y^j at the base point; NaN when i + j exceeds
    /// the jet's order (not tracked).
    pub fn derivative(&self, i: usize, j: usize) -> S {
        let prec = self.c[0].precision_bits();
        if i + j > Self::ORDER {
            return S::from_f64(f64::NAN, prec);
        }
        let f = |n: usize| -> i64 { (1..=n as i64).product::<i64>().max(1) };
        let k = S::from_i64(f(i) * f(j), prec);
        self.c[idx(i, j)].mul(&k)
    }
    fn zero_like(&self) -> S {
        S::from_i64(0, self.c[0].precision_bits())
    }
    fn map(&self, f: impl Fn(&S) -> S) -> Self {
        Jet {
            c: std::array::from_fn(|k| f(&self.c[k])),
        }
    }
    fn zip(&self, o: &Self, f: impl Fn(&S, &S) -> S) -> Self {
        Jet {
            c: std::array::from_fn(|k| f(&self.c[k], &o.c[k])),
        }
    }
    /// The nilpotent part (value set to zero).
    fn nil(&self) -> Self {
        let mut h = self.clone();
        h.c[0] = self.zero_like();
        h
    }
    /// f(a + h) = f₀ + f₁h + f₂/2 h² + f₃/6 h³ for a univariate f with derivatives `d` at
    /// the value a, h the nilpotent part (h⁴ = 0).
    fn compose(&self, d: [S; 4]) -> Self {
        let prec = self.c[0].precision_bits();
        let h = self.nil();
        let h2 = h.mul(&h);
        let h3 = h2.mul(&h);
        let [d0, d1, d2, d3] = d;
        let half = S::from_ratio(1, 2, prec);
        let sixth = S::from_ratio(1, 6, prec);
        let mut r = h
            .scale(&d1)
            .add(&h2.scale(&d2.mul(&half)))
            .add(&h3.scale(&d3.mul(&sixth)));
        r.c[0] = d0;
        r
    }
    /// k times the jet.
    pub fn scale(&self, k: &S) -> Self {
        self.map(|a| a.mul(k))
    }
}

impl<S: Scalar, const L: usize> Scalar for Jet<S, L> {
    fn type_name(&self) -> String {
        format!("jet{}<{}>", Self::ORDER, self.c[0].type_name())
    }
    fn from_f64(x: f64, prec: u32) -> Self {
        Jet::constant(S::from_f64(x, prec))
    }
    fn from_i64(x: i64, prec: u32) -> Self {
        Jet::constant(S::from_i64(x, prec))
    }
    fn from_ratio(p: i64, q: i64, prec: u32) -> Self {
        Jet::constant(S::from_ratio(p, q, prec))
    }
    fn pi(prec: u32) -> Self {
        Jet::constant(S::pi(prec))
    }
    fn to_f64(&self) -> f64 {
        self.c[0].to_f64()
    }
    fn precision_bits(&self) -> u32 {
        self.c[0].precision_bits()
    }
    fn add(&self, o: &Self) -> Self {
        self.zip(o, |a, b| a.add(b))
    }
    fn sub(&self, o: &Self) -> Self {
        self.zip(o, |a, b| a.sub(b))
    }
    fn mul(&self, o: &Self) -> Self {
        let z = self.zero_like();
        let mut c: [S; L] = std::array::from_fn(|_| z.clone());
        let (table, n) = &MUL[Self::ORDER];
        for &(a, b, r) in &table[..*n] {
            let t = self.c[a as usize].mul(&o.c[b as usize]);
            c[r as usize] = c[r as usize].add(&t);
        }
        Jet { c }
    }
    fn div(&self, o: &Self) -> Self {
        let prec = o.c[0].precision_bits();
        let a = &o.c[0];
        let one = S::from_i64(1, prec);
        let r = one.div(a);
        let r2 = r.mul(&r);
        let r3 = r2.mul(&r);
        let r4 = r3.mul(&r);
        let inv = o.compose([
            r,
            r2.neg(),
            r3.mul(&S::from_i64(2, prec)),
            r4.mul(&S::from_i64(-6, prec)),
        ]);
        self.mul(&inv)
    }
    fn neg(&self) -> Self {
        self.map(|a| a.neg())
    }
    fn sqrt(&self) -> Self {
        let prec = self.c[0].precision_bits();
        let s = self.c[0].sqrt();
        let inv = S::from_i64(1, prec).div(&s); // a^{-1/2}
        let a_inv = inv.mul(&inv); // 1/a
        let d1 = inv.mul(&S::from_ratio(1, 2, prec));
        let d2 = d1.mul(&a_inv).mul(&S::from_ratio(-1, 2, prec));
        let d3 = d2.mul(&a_inv).mul(&S::from_ratio(-3, 2, prec));
        self.compose([s, d1, d2, d3])
    }
    fn sin(&self) -> Self {
        let (s, c) = (self.c[0].sin(), self.c[0].cos());
        self.compose([s.clone(), c.clone(), s.neg(), c.neg()])
    }
    fn cos(&self) -> Self {
        let (s, c) = (self.c[0].sin(), self.c[0].cos());
        self.compose([c.clone(), s.neg(), c.neg(), s])
    }
    fn abs(&self) -> Self {
        match self.c[0].sign() {
            Some(Ordering::Less) => self.neg(),
            _ => self.clone(),
        }
    }
    /// atan2(y, x) = atan2(y₀, x₀) + atan(z), z = (x₀·y − y₀·x)/(x₀·x + y₀·y) (z nilpotent),
    /// atan(z) = z − z³/3.
    fn atan2(&self, x: &Self) -> Self {
        let prec = self.c[0].precision_bits();
        let (y0, x0) = (&self.c[0], &x.c[0]);
        let num = self.scale(x0).sub(&x.scale(y0)).nil();
        let den = x.scale(x0).add(&self.scale(y0));
        let z = num.div(&den).nil();
        let z3 = z.mul(&z).mul(&z);
        let mut r = z.sub(&z3.scale(&S::from_ratio(1, 3, prec)));
        r.c[0] = y0.atan2(x0);
        r
    }
    fn sign(&self) -> Option<Ordering> {
        self.c[0].sign()
    }
}

impl<S: SurfaceScalar, const L: usize> SurfaceScalar for Jet<S, L> {
    fn exp(&self) -> Self {
        let e = self.c[0].exp();
        self.compose([e.clone(), e.clone(), e.clone(), e])
    }
    fn scale_f64(&self, k: f64) -> Self {
        Jet {
            c: std::array::from_fn(|i| self.c[i].scale_f64(k)),
        }
    }
    /// Jets of f64 (the sampling's normals and curvatures) evaluate ψ on the CPU's vector
    /// extensions, with the same operations in the same order (the output is byte-identical).
    fn patch(cp: &[[f64; 3]], l: usize, half: f64, x: &Self, y: &Self) -> [Self; 3] {
        if std::any::TypeId::of::<S>() == std::any::TypeId::of::<f64>() {
            super::scalar_ext::eval_patch_simd(cp, l, half, x, y)
        } else {
            super::scalar_ext::eval_patch(cp, l, half, x, y)
        }
    }
}
