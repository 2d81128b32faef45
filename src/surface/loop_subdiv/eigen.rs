//! The eigen-structure of Loop's subdivision matrix A for valence N, in closed form, generic
//! over the scalar (f64, [`crate::numeric::Mp`]).
//!
//! A = [[S₁₁, 0], [S₂₁, S₂₂]]: the centre and its ring (N + 1 points) do not see the five
//! outer points. Each diagonal block is diagonalised exactly:
//! * S₁₁ by the discrete Fourier transform of the ring (Stam 1998, Sec. 4; Loop 1987):
//!   eigenvalue 1 on (1; 1, …, 1); λ = (3/8 + cos(2π/N)/4)² = 5/8 − Nβ on (x; 1, …, 1) with
//!   x = −8Nβ/3; λ_ω = 3/8 + cos(2πω/N)/4 on (0; cos 2πωi/N) and (0; sin 2πωi/N),
//!   1 ≤ ω < N/2; λ = 1/8 on (0; (−1)ⁱ) for even N. The inverse is the Fourier analysis.
//! * S₂₂ (fixed, N-independent) has eigenvalue 1/8 thrice and 1/16 twice, with integer
//!   eigenvectors and an integer inverse.
//!
//! A itself is *not* diagonalisable for every N: for even N, 1/8 is an eigenvalue of both
//! blocks, and for N = 3, λ = 1/16 is. Instead of VΛV⁻¹ for A, powers use the block form
//! Aᵐ = [[S₁₁ᵐ, 0], [Xₘ, S₂₂ᵐ]], Xₘ = Σ_{j<m} S₂₂^{m−1−j} S₂₁ S₁₁ʲ = W (G ∘ Dₘ) U⁻¹ with
//! G = W⁻¹S₂₁U and Dₘ\[a\]\[b\] = Σ_{j<m} μₐ^{m−1−j} λ_bʲ (the divided difference
//! (μᵐ − λᵐ)/(μ − λ), or m μ^{m−1} at a coincidence — the Jordan case).
//!
//! **How it is checked** (`tests`, and [`EigenStructure::residuals`], printed by the checks):
//! S₁₁U = UΛ₁, UU⁻¹ = I, S₂₂W = WΛ₂, WW⁻¹ = I, and Aᵐ from the formula against Aᵐ by
//! repeated multiplication for m ≤ 8, for every valence 3..=64, in f64 (bound 64·K·ε) and at
//! 256 bits (bound 64·K·2⁻²⁵⁶); f64 against 256 bits entry by entry.

use super::patch::{matmul, Mat, SubdivisionMatrices};
use super::rules::{beta, cos_sin_2pi};
use crate::numeric::Scalar;

/// Eigenvalues of S₂₂ in the order of the columns of W.
const MU: [(i64, i64); 5] = [(1, 8), (1, 8), (1, 8), (1, 16), (1, 16)];

/// Eigenvectors of S₂₂ (columns), exact.
const W: [[i64; 5]; 5] = [
    [1, 0, 0, 0, 0],
    [1, 1, 0, 1, 0],
    [0, 1, 0, 0, 0],
    [0, 1, 1, 0, 1],
    [0, 0, 1, 0, 0],
];

/// W⁻¹, exact (y = Wc ⇔ c = W⁻¹y: c₀ = y₀, c₁ = y₂, c₂ = y₄, c₃ = y₁ − y₀ − y₂,
/// c₄ = y₃ − y₂ − y₄).
const W_INV: [[i64; 5]; 5] = [
    [1, 0, 0, 0, 0],
    [0, 0, 1, 0, 0],
    [0, 0, 0, 0, 1],
    [-1, 1, -1, 0, 0],
    [0, 0, -1, 1, -1],
];

/// Everything Stam's evaluation needs for one valence.
#[derive(Debug, Clone)]
pub struct EigenStructure<S> {
    /// Valence N.
    pub n: usize,
    /// Precision the values were computed at.
    pub prec: u32,
    /// The matrices the eigen-structure diagonalises.
    pub matrices: SubdivisionMatrices<S>,
    /// Eigenvalues of S₁₁ (N + 1), in the column order of U: 1, λ₁², then (cos, sin) pairs
    /// for ω = 1, 2, …, then 1/8 for even N.
    pub lambda: Vec<S>,
    /// Eigenvectors of S₁₁ as columns: `u[i][b]`.
    pub u: Mat<S>,
    /// U⁻¹: `u_inv[b][i]`.
    pub u_inv: Mat<S>,
    /// Eigenvalues of S₂₂.
    pub mu: [S; 5],
    /// G = W⁻¹ S₂₁ U (5 × (N + 1)).
    pub g: Mat<S>,
    /// B_k,in · U (12 × (N + 1)) for the three sub-triangles.
    pub p1: [Mat<S>; 3],
    /// B_k,out · W (12 × 5).
    pub p2: [Mat<S>; 3],
}

fn int_mat<S: Scalar>(m: &[[i64; 5]; 5], prec: u32) -> Mat<S> {
    m.iter()
        .map(|r| r.iter().map(|&x| S::from_i64(x, prec)).collect())
        .collect()
}

/// xᵐ by repeated squaring.
pub(crate) fn powi<S: Scalar>(x: &S, mut m: u64, prec: u32) -> S {
    let mut r = S::from_i64(1, prec);
    let mut b = x.clone();
    while m > 0 {
        if m & 1 == 1 {
            r = r.mul(&b);
        }
        m >>= 1;
        if m > 0 {
            b = b.sqr();
        }
    }
    r
}

/// Σ_{j<m} μ^{m−1−j} λʲ: closed form when μ and λ are well apart, the sum when they are close
/// or equal (no cancellation either way).
pub(crate) fn divided_power<S: Scalar>(mu: &S, lambda: &S, m: u64, prec: u32) -> S {
    if m == 0 {
        return S::from_i64(0, prec);
    }
    let gap = mu.sub(lambda).abs();
    if gap.lt(&mu.abs().mul(&S::from_ratio(1, 16, prec))).is_true() {
        // d_i = μ^{i−1} + λ d_{i−1}.
        let mut d = S::from_i64(0, prec);
        let mut p = S::from_i64(1, prec);
        for _ in 0..m {
            d = p.add(&lambda.mul(&d));
            p = p.mul(mu);
        }
        d
    } else {
        powi(mu, m, prec)
            .sub(&powi(lambda, m, prec))
            .div(&mu.sub(lambda))
    }
}

impl<S: Scalar> EigenStructure<S> {
    /// The eigen-structure for valence n ≥ 3 at precision `prec` (f64 ignores it).
    pub fn new(n: usize, prec: u32) -> Option<Self> {
        let matrices = SubdivisionMatrices::<S>::new(n, prec)?;
        let c = |p: i64, q: i64| S::from_ratio(p, q, prec);
        let zero = c(0, 1);
        let ni = n as i64;
        let b = beta::<S>(n as u32, prec);
        let nb = b.mul(&c(ni, 1));
        let x = nb.mul(&c(-8, 3));
        // Columns of U and their eigenvalues.
        let mut cols: Vec<Vec<S>> = Vec::with_capacity(n + 1);
        let mut lambda = Vec::with_capacity(n + 1);
        cols.push(vec![c(1, 1); n + 1]);
        lambda.push(c(1, 1));
        let mut col = vec![c(1, 1); n + 1];
        col[0] = x.clone();
        cols.push(col);
        lambda.push(c(5, 8).sub(&nb));
        // Rows of U⁻¹ (same order).
        let xm1 = x.sub(&c(1, 1));
        let mut rows: Vec<Vec<S>> = Vec::with_capacity(n + 1);
        let ring_gamma = c(-1, ni).div(&xm1);
        let mut r0 = vec![c(1, ni).sub(&ring_gamma); n + 1];
        r0[0] = c(-1, 1).div(&xm1);
        let mut r1 = vec![ring_gamma; n + 1];
        r1[0] = c(1, 1).div(&xm1);
        rows.push(r0);
        rows.push(r1);
        for w in 1..=((n - 1) / 2) as i64 {
            let (cw, _) = cos_sin_2pi::<S>(w, ni, prec);
            let lw = c(3, 8).add(&cw.mul(&c(1, 4)));
            let trig: Vec<(S, S)> = (0..ni).map(|i| cos_sin_2pi::<S>(w * i, ni, prec)).collect();
            for pick_sin in [false, true] {
                let mut col = vec![zero.clone()];
                col.extend(
                    trig.iter()
                        .map(|(co, si)| if pick_sin { si.clone() } else { co.clone() }),
                );
                let mut row: Vec<S> = col.iter().map(|e| e.mul(&c(2, ni))).collect();
                row[0] = zero.clone();
                cols.push(col);
                rows.push(row);
                lambda.push(lw.clone());
            }
        }
        if n % 2 == 0 {
            let mut col = vec![zero.clone()];
            col.extend((0..n).map(|i| c(if i % 2 == 0 { 1 } else { -1 }, 1)));
            let mut row: Vec<S> = col.iter().map(|e| e.mul(&c(1, ni))).collect();
            row[0] = zero.clone();
            cols.push(col);
            rows.push(row);
            lambda.push(c(1, 8));
        }
        let u: Mat<S> = (0..=n)
            .map(|i| cols.iter().map(|col| col[i].clone()).collect())
            .collect();
        let u_inv = rows;
        let w = int_mat::<S>(&W, prec);
        let w_inv = int_mat::<S>(&W_INV, prec);
        let s21: Mat<S> = matrices.a[n + 1..]
            .iter()
            .map(|r| r[..=n].to_vec())
            .collect();
        let g = matmul(&matmul(&w_inv, &s21, prec), &u, prec);
        let split = |k: usize| -> (Mat<S>, Mat<S>) {
            let bin: Mat<S> = matrices.pick[k].iter().map(|r| r[..=n].to_vec()).collect();
            let bout: Mat<S> = matrices.pick[k]
                .iter()
                .map(|r| r[n + 1..].to_vec())
                .collect();
            (matmul(&bin, &u, prec), matmul(&bout, &w, prec))
        };
        let (a1, b1) = split(0);
        let (a2, b2) = split(1);
        let (a3, b3) = split(2);
        Some(EigenStructure {
            n,
            prec,
            lambda,
            u,
            u_inv,
            mu: MU.map(|(p, q)| c(p, q)),
            g,
            p1: [a1, a2, a3],
            p2: [b1, b2, b3],
            matrices,
        })
    }

    /// The eigen-coordinates of a net: (U⁻¹ C_in, W⁻¹ C_out).
    pub fn project(&self, net: &[[S; 3]]) -> (Vec<[S; 3]>, Vec<[S; 3]>) {
        let n = self.n;
        let zero = S::from_i64(0, self.prec);
        let apply = |rows: &Mat<S>, pts: &[[S; 3]]| -> Vec<[S; 3]> {
            rows.iter()
                .map(|r| {
                    let mut acc = [zero.clone(), zero.clone(), zero.clone()];
                    for (w, p) in r.iter().zip(pts) {
                        if w.sign() == Some(std::cmp::Ordering::Equal) {
                            continue;
                        }
                        for d in 0..3 {
                            acc[d] = acc[d].add(&w.mul(&p[d]));
                        }
                    }
                    acc
                })
                .collect()
        };
        let w_inv = int_mat::<S>(&W_INV, self.prec);
        (apply(&self.u_inv, &net[..=n]), apply(&w_inv, &net[n + 1..]))
    }

    /// The regular net of sub-triangle k (0, 1, 2 for Stam's 1, 2, 3) after m further steps:
    /// B_k Aᵐ C₀ from the eigen-coordinates of C₀.
    pub fn sub_net(&self, k: usize, m: u64, cin: &[[S; 3]], cout: &[[S; 3]]) -> [[S; 3]; 12] {
        self.sub_net_as(k, m, cin, cout, false)
    }

    /// [`Self::sub_net`], or with `authors_jordan` what the authors' evaluator computes
    /// (docs/authors-code.md, defect D3): for valence 3, where λ = μ = 1/16 and A has a
    /// Jordan block, their `EvalStruct::eval_surf` takes the off-diagonal entry of Jᵐ as
    /// (m − 1)·λ^(m−1) instead of m·λ^(m−1) for m ≥ 2.
    pub fn sub_net_as(
        &self,
        k: usize,
        m: u64,
        cin: &[[S; 3]],
        cout: &[[S; 3]],
        authors_jordan: bool,
    ) -> [[S; 3]; 12] {
        let prec = self.prec;
        let zero = S::from_i64(0, prec);
        let z3 = || [zero.clone(), zero.clone(), zero.clone()];
        let lm: Vec<S> = self.lambda.iter().map(|l| powi(l, m, prec)).collect();
        let y: Vec<[S; 3]> = cin
            .iter()
            .zip(&lm)
            .map(|(p, l)| [p[0].mul(l), p[1].mul(l), p[2].mul(l)])
            .collect();
        // Dₘ per distinct μ (1/8, 1/16).
        let d8: Vec<S> = self
            .lambda
            .iter()
            .map(|l| divided_power(&self.mu[0], l, m, prec))
            .collect();
        let d16: Vec<S> = self
            .lambda
            .iter()
            .map(|l| {
                let d = divided_power(&self.mu[3], l, m, prec);
                let coincident = l.sub(&self.mu[3]).sign() == Some(std::cmp::Ordering::Equal);
                if authors_jordan && self.n == 3 && m >= 2 && coincident {
                    d.sub(&powi(l, m - 1, prec))
                } else {
                    d
                }
            })
            .collect();
        let z: Vec<[S; 3]> = (0..5)
            .map(|a| {
                let ma = powi(&self.mu[a], m, prec);
                let mut acc = [
                    cout[a][0].mul(&ma),
                    cout[a][1].mul(&ma),
                    cout[a][2].mul(&ma),
                ];
                let dd = if a < 3 { &d8 } else { &d16 };
                for (b, p) in cin.iter().enumerate() {
                    let w = self.g[a][b].mul(&dd[b]);
                    if w.sign() == Some(std::cmp::Ordering::Equal) {
                        continue;
                    }
                    for d in 0..3 {
                        acc[d] = acc[d].add(&w.mul(&p[d]));
                    }
                }
                acc
            })
            .collect();
        std::array::from_fn(|j| {
            let mut acc = z3();
            for (w, p) in self.p1[k][j]
                .iter()
                .zip(&y)
                .chain(self.p2[k][j].iter().zip(&z))
            {
                for d in 0..3 {
                    acc[d] = acc[d].add(&w.mul(&p[d]));
                }
            }
            acc
        })
    }

    /// Residuals of the eigen-structure: max over entries of |S₁₁U − UΛ₁|, |UU⁻¹ − I|,
    /// |S₂₂W − WΛ₂|, |WW⁻¹ − I|, and |B_k Aᵐ − (formula)| for m ≤ `max_m`, as f64.
    pub fn residuals(&self, max_m: u64) -> f64 {
        let n = self.n;
        let prec = self.prec;
        let k = n + 6;
        let a = &self.matrices.a;
        let mut worst = 0.0f64;
        let mut note = |x: &S| {
            let v = x.to_f64().abs();
            // NaN-propagating: `NaN.max(v)` is v, which would drop an earlier NaN.
            worst = crate::report::dev_max(worst, v);
        };
        let s11: Mat<S> = a[..=n].iter().map(|r| r[..=n].to_vec()).collect();
        let su = matmul(&s11, &self.u, prec);
        for (su_i, u_i) in su.iter().zip(&self.u).take(n + 1) {
            for ((sib, uib), lb) in su_i.iter().zip(u_i).zip(&self.lambda).take(n + 1) {
                note(&sib.sub(&uib.mul(lb)));
            }
        }
        let uu = matmul(&self.u, &self.u_inv, prec);
        let w = int_mat::<S>(&W, prec);
        let w_inv = int_mat::<S>(&W_INV, prec);
        let ww = matmul(&w, &w_inv, prec);
        for (m, sz) in [(&uu, n + 1), (&ww, 5)] {
            for (i, m_i) in m.iter().enumerate().take(sz) {
                for (j, mij) in m_i.iter().enumerate().take(sz) {
                    let id = S::from_i64((i == j) as i64, prec);
                    note(&mij.sub(&id));
                }
            }
        }
        let s22: Mat<S> = a[n + 1..].iter().map(|r| r[n + 1..].to_vec()).collect();
        let sw = matmul(&s22, &w, prec);
        for i in 0..5 {
            for b in 0..5 {
                note(&sw[i][b].sub(&w[i][b].mul(&self.mu[b])));
            }
        }
        // B_k Aᵐ e_j, column by column, against sub_net on unit nets (one coordinate).
        let mut am: Mat<S> = (0..k)
            .map(|i| (0..k).map(|j| S::from_i64((i == j) as i64, prec)).collect())
            .collect();
        for m in 0..=max_m {
            for (kk, pick) in self.matrices.pick.iter().enumerate() {
                let direct = matmul(pick, &am, prec);
                for j in 0..k {
                    let net: Vec<[S; 3]> = (0..k)
                        .map(|i| {
                            let e = S::from_i64((i == j) as i64, prec);
                            [e.clone(), e.clone(), e]
                        })
                        .collect();
                    let (cin, cout) = self.project(&net);
                    let q = self.sub_net(kk, m, &cin, &cout);
                    for (row, qj) in direct.iter().zip(&q) {
                        note(&row[j].sub(&qj[0]));
                    }
                }
            }
            am = matmul(a, &am, prec);
        }
        worst
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numeric::Mp;

    #[test]
    fn loop_eigen_reconstructs_powers_f64_valences_3_to_64() {
        for n in 3..=64usize {
            let e = EigenStructure::<f64>::new(n, 53).expect("eigen");
            assert_eq!(e.lambda.len(), n + 1);
            let r = e.residuals(8);
            let bound = 64.0 * (n + 6) as f64 * f64::EPSILON;
            assert!(r <= bound, "n = {n}: residual {r:e} > {bound:e}");
        }
    }

    #[test]
    fn loop_eigen_mp256_reconstructs_and_agrees_with_f64() {
        for n in [3usize, 4, 7, 12, 31] {
            let e = EigenStructure::<Mp>::new(n, 256).expect("eigen");
            let r = e.residuals(2);
            let bound = 64.0 * (n + 6) as f64 * 2f64.powi(-256);
            assert!(r <= bound, "n = {n}: residual {r:e} > {bound:e}");
            let f = EigenStructure::<f64>::new(n, 53).expect("eigen");
            for (lm, lf) in e.lambda.iter().zip(&f.lambda) {
                assert!((lm.to_f64() - lf).abs() <= 4.0 * f64::EPSILON, "n = {n}");
            }
            for (rm, rf) in e.g.iter().zip(&f.g) {
                for (a, b) in rm.iter().zip(rf) {
                    assert!((a.to_f64() - b).abs() <= 64.0 * f64::EPSILON, "n = {n}");
                }
            }
        }
    }

    #[test]
    fn loop_eigen_jordan_coincidences_are_exact() {
        // Even N: 1/8 is an eigenvalue of S₁₁; N = 3: λ₁² = 1/16. Both exactly.
        let e = EigenStructure::<f64>::new(8, 53).expect("eigen");
        assert_eq!(*e.lambda.last().expect("λ"), 0.125);
        let e = EigenStructure::<f64>::new(3, 53).expect("eigen");
        assert_eq!(e.lambda[1], 0.0625);
        assert_eq!(
            divided_power(&0.0625, &0.0625, 5, 53),
            5.0 * 0.0625f64.powi(4)
        );
    }
}
