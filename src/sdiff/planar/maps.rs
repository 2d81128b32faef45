//! The three families of simplicial maps of Mello–Velho Sec. 3 on one triangle, written as
//! x = (N_0, N_1, N_2) / D in barycentric components over the reference triangle.
//!
//! * monotonic, Eq. (9): x^i = g_i(w^i) / Σ_j g_j(w^j);
//! * polynomial, Eq. (10): x = Σ_{|I|=n} b_I B_I(w) (D = 1);
//! * rational, Eq. (11): x = Σ q_I b_I B_I(w) / Σ q_I B_I(w).
//!
//! The control points b_I are barycentric coordinates (they need not sum to one: Eq. (10)'s
//! partition-of-unity statement is about exactly that).

use crate::sdiff::common::poly1::Poly1;
use crate::sdiff::common::poly2::{bernstein_basis, index_of, multi_indices, Poly2};
use crate::sdiff::common::rational::{q, Q};
use num_traits::{Signed, Zero};

/// Which family of Sec. 3 a map belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Family {
    /// Sec. 3.1, Eq. (9).
    Monotonic,
    /// Sec. 3.2, Eq. (10).
    Polynomial,
    /// Sec. 3.3, Eq. (11).
    Rational,
}

/// One map of the reference triangle onto itself (hopefully), x = N / D.
#[derive(Debug, Clone)]
pub struct SimplexMap {
    /// The family.
    pub family: Family,
    /// Degree n of Eqs. (10)–(11) (for Eq. (9): the largest degree of the g_i).
    pub degree: usize,
    /// Control points b_I (barycentric), indexed by `multi_indices(degree)`; empty for Eq. (9).
    pub control: Vec<[Q; 3]>,
    /// Weights q_I of Eq. (11) (all 1 for Eq. (10)); empty for Eq. (9).
    pub weights: Vec<Q>,
    /// The g_i of Eq. (9); empty otherwise.
    pub g: Vec<Poly1>,
    /// Numerators N_0, N_1, N_2.
    pub num: [Poly2; 3],
    /// Denominator D (the constant 1 for Eq. (10)).
    pub den: Poly2,
}

impl SimplexMap {
    /// Eq. (10): x = Σ b_I B_I(w).
    pub fn polynomial(n: usize, control: Vec<[Q; 3]>) -> Self {
        let weights = vec![q(1); control.len()];
        let mut m = SimplexMap::rational(n, control, weights);
        m.family = Family::Polynomial;
        m.den = Poly2::constant(q(1));
        m
    }

    /// Eq. (11): x = Σ q_I b_I B_I / Σ q_I B_I.
    pub fn rational(n: usize, control: Vec<[Q; 3]>, weights: Vec<Q>) -> Self {
        let mut num = [Poly2::zero(n), Poly2::zero(n), Poly2::zero(n)];
        let mut den = Poly2::zero(n);
        for (idx, i) in multi_indices(n).into_iter().enumerate() {
            let b = bernstein_basis(i);
            let qi = &weights[idx];
            den = den.add(&b.scale(qi));
            for (c, nc) in num.iter_mut().enumerate() {
                let k = qi * &control[idx][c];
                if !k.is_zero() {
                    *nc = nc.add(&b.scale(&k));
                }
            }
        }
        SimplexMap {
            family: Family::Rational,
            degree: n,
            control,
            weights,
            g: Vec::new(),
            num,
            den,
        }
    }

    /// Eq. (9): x^i = g_i(w^i) / Σ_j g_j(w^j).
    pub fn monotonic(g: [Poly1; 3]) -> Self {
        let num = [
            g[0].compose(&Poly2::w(0)),
            g[1].compose(&Poly2::w(1)),
            g[2].compose(&Poly2::w(2)),
        ];
        let den = num[0].add(&num[1]).add(&num[2]);
        let degree = g
            .iter()
            .map(|p| p.0.len().saturating_sub(1))
            .max()
            .unwrap_or(0);
        SimplexMap {
            family: Family::Monotonic,
            degree,
            control: Vec::new(),
            weights: Vec::new(),
            g: g.to_vec(),
            num,
            den,
        }
    }

    /// The fixed control points b_I = I/n of Sec. 3.2 (X = identity for Eq. (10)).
    pub fn fixed_control(n: usize) -> Vec<[Q; 3]> {
        multi_indices(n)
            .into_iter()
            .map(|i| i.map(|k| Q::new((k as i64).into(), (n as i64).into())))
            .collect()
    }

    /// The control point of multi-index `i`.
    pub fn b(&self, i: [usize; 3]) -> &[Q; 3] {
        &self.control[index_of(self.degree, i)]
    }

    /// Numerator of det DX in the chart (s, t) = (w_1, w_2) of source and target:
    /// det DX = Jnum / D³ (for Eq. (10), D = 1 and Jnum = det DX).
    ///
    /// With x_k = N_k / D: D⁴ det DX = D·[D(N1_s N2_t − N1_t N2_s) − N2(N1_s D_t − N1_t D_s)
    /// − N1(D_s N2_t − D_t N2_s)], so sign det DX = sign(Jnum)·sign(D).
    pub fn jacobian_numerator(&self) -> Poly2 {
        let (n1, n2, d) = (&self.num[1], &self.num[2], &self.den);
        let (n1s, n1t, n2s, n2t) = (n1.ds(), n1.dt(), n2.ds(), n2.dt());
        let core = n1s.mul(&n2t).sub(&n1t.mul(&n2s));
        if self.family == Family::Polynomial {
            return core;
        }
        let (ds, dt) = (d.ds(), d.dt());
        d.mul(&core)
            .sub(&n2.mul(&n1s.mul(&dt).sub(&n1t.mul(&ds))))
            .sub(&n1.mul(&ds.mul(&n2t).sub(&dt.mul(&n2s))))
    }

    /// X at a point given in barycentric coordinates (exact), as barycentric coordinates.
    pub fn eval(&self, w: &[Q; 3]) -> Option<[Q; 3]> {
        let (s, t) = (&w[1], &w[2]);
        let d = self.den.eval(s, t);
        if d.is_zero() {
            return None;
        }
        Some([
            self.num[0].eval(s, t) / &d,
            self.num[1].eval(s, t) / &d,
            self.num[2].eval(s, t) / &d,
        ])
    }

    /// X in f64 at (s, t): the target (s, t) and the Jacobian [[x1_s, x1_t], [x2_s, x2_t]].
    pub fn eval_f64_with_jacobian(&self, s: f64, t: f64) -> ([f64; 2], [[f64; 2]; 2]) {
        let d = self.den.eval_f64(s, t);
        let (ds, dt) = (self.den.ds().eval_f64(s, t), self.den.dt().eval_f64(s, t));
        let mut x = [0.0; 2];
        let mut j = [[0.0; 2]; 2];
        for k in 0..2 {
            let n = &self.num[k + 1];
            let v = n.eval_f64(s, t);
            x[k] = v / d;
            j[k][0] = (n.ds().eval_f64(s, t) * d - v * ds) / (d * d);
            j[k][1] = (n.dt().eval_f64(s, t) * d - v * dt) / (d * d);
        }
        (x, j)
    }

    /// The partition-of-unity defect Σ_c N_c − D (zero polynomial iff Eq. (1) holds for x).
    pub fn unity_defect(&self) -> Poly2 {
        self.num[0]
            .add(&self.num[1])
            .add(&self.num[2])
            .sub(&self.den)
    }

    /// Is any weight non-positive (the hypothesis of the rational claim fails)?
    pub(crate) fn first_nonpositive_weight(&self) -> Option<(usize, Q)> {
        self.weights
            .iter()
            .enumerate()
            .find(|(_, w)| !w.is_positive())
            .map(|(i, w)| (i, w.clone()))
    }
}
