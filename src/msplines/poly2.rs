//! Exact bivariate polynomials over ℚ: the pieces of a simplex spline on one cell of its knot
//! lines (Sec. 3.1.2), so smoothness across a knot line is decided as a polynomial identity
//! on the whole line, not at sample points.

use super::polar::{Q, Q2};
use num_traits::{One, Zero};
use std::collections::BTreeMap;

/// Σ c_ij x^i y^j, zero coefficients never stored.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Poly2 {
    /// (i, j) ↦ c_ij.
    pub c: BTreeMap<(u32, u32), Q>,
}

impl Poly2 {
    /// The constant a.
    pub fn constant(a: Q) -> Poly2 {
        let mut p = Poly2::default();
        p.add_term((0, 0), a);
        p
    }
    /// a·x + b·y + c.
    pub fn affine(a: Q, b: Q, c: Q) -> Poly2 {
        let mut p = Poly2::default();
        p.add_term((1, 0), a);
        p.add_term((0, 1), b);
        p.add_term((0, 0), c);
        p
    }
    fn add_term(&mut self, e: (u32, u32), a: Q) {
        if a.is_zero() {
            return;
        }
        let s = self.c.entry(e).or_insert_with(Q::zero);
        *s += a;
        if s.is_zero() {
            self.c.remove(&e);
        }
    }
    /// Is this the zero polynomial?
    pub fn is_zero(&self) -> bool {
        self.c.is_empty()
    }
    /// self + o.
    pub fn add(&self, o: &Poly2) -> Poly2 {
        let mut p = self.clone();
        for (e, a) in &o.c {
            p.add_term(*e, a.clone());
        }
        p
    }
    /// self − o.
    pub fn sub(&self, o: &Poly2) -> Poly2 {
        let mut p = self.clone();
        for (e, a) in &o.c {
            p.add_term(*e, -a.clone());
        }
        p
    }
    /// a·self.
    pub fn scale(&self, a: &Q) -> Poly2 {
        let mut p = Poly2::default();
        for (e, c) in &self.c {
            p.add_term(*e, c * a);
        }
        p
    }
    /// self·o.
    pub fn mul(&self, o: &Poly2) -> Poly2 {
        let mut p = Poly2::default();
        for ((i, j), a) in &self.c {
            for ((k, l), b) in &o.c {
                p.add_term((i + k, j + l), a * b);
            }
        }
        p
    }
    /// The value at u.
    pub fn at(&self, u: &Q2) -> Q {
        self.c.iter().fold(Q::zero(), |s, ((i, j), a)| {
            s + a * pow(&u[0], *i) * pow(&u[1], *j)
        })
    }
    /// The directional derivative along d = (d_x, d_y).
    pub fn derivative(&self, d: &Q2) -> Poly2 {
        let mut p = Poly2::default();
        for ((i, j), a) in &self.c {
            if *i > 0 {
                p.add_term((i - 1, *j), a * Q::from_integer((*i).into()) * &d[0]);
            }
            if *j > 0 {
                p.add_term((*i, j - 1), a * Q::from_integer((*j).into()) * &d[1]);
            }
        }
        p
    }
    /// The univariate restriction t ↦ self(p + t·d), coefficients by power of t.
    pub fn on_line(&self, p: &Q2, d: &Q2) -> Vec<Q> {
        let x = [p[0].clone(), d[0].clone()];
        let y = [p[1].clone(), d[1].clone()];
        let mut out: Vec<Q> = Vec::new();
        for ((i, j), a) in &self.c {
            let mut t = vec![a.clone()];
            for _ in 0..*i {
                t = mul1(&t, &x);
            }
            for _ in 0..*j {
                t = mul1(&t, &y);
            }
            if out.len() < t.len() {
                out.resize(t.len(), Q::zero());
            }
            for (o, v) in out.iter_mut().zip(t) {
                *o += v;
            }
        }
        while out.last().is_some_and(|v| v.is_zero()) {
            out.pop();
        }
        out
    }
}

fn pow(x: &Q, n: u32) -> Q {
    (0..n).fold(Q::one(), |a, _| a * x)
}

fn mul1(a: &[Q], b: &[Q]) -> Vec<Q> {
    let mut out = vec![Q::zero(); a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            out[i + j] += x * y;
        }
    }
    out
}
