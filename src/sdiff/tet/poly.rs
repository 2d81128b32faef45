//! The 3-D (tetrahedral) case of Mello–Velho Sec. 3.1: monotonic barycentric coordinates (9)
//! on a tetrahedron, x^i = g_i(w^i) / Σ_j g_j(w^j), i = 0..3, and the exact certificate of
//! det DX > 0 on the closed tetrahedron — the same method as the planar `positivity`: the
//! Bernstein–Bézier coefficients over ℚ of the Jacobian numerator, all > 0 a certificate, a
//! corner value ≤ 0 a counterexample, otherwise bisection of the longest edge under a budget
//! (a piece past it is left open and the others finished, `positivity::Cover`).
//!
//! det DX is independent of the embedding of the tetrahedron (DX = J·A·J⁻¹ in the plane), so
//! the reference tetrahedron ⟨0, e_1, e_2, e_3⟩ with chart (s, t, r) = (w_1, w_2, w_3) suffices.

use crate::sdiff::common::poly1::Poly1;
use crate::sdiff::common::positivity::{Budget, Cover, Decision, Strictness};
use crate::sdiff::common::rational::{multinomial, q, qr, to_f64, Q};
use num_traits::{One, Signed, Zero};
use std::collections::BTreeMap;

/// A polynomial Σ c_{abe} s^a t^b r^e over ℚ (sparse).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Poly3(pub BTreeMap<[usize; 3], Q>);

impl Poly3 {
    /// The constant k.
    pub fn constant(k: Q) -> Poly3 {
        let mut m = BTreeMap::new();
        if !k.is_zero() {
            m.insert([0, 0, 0], k);
        }
        Poly3(m)
    }
    /// The barycentric coordinate w_i (w_0 = 1 − s − t − r).
    pub fn w(i: usize) -> Poly3 {
        let mut m = BTreeMap::new();
        match i {
            0 => {
                m.insert([0, 0, 0], q(1));
                for k in 0..3 {
                    let mut e = [0; 3];
                    e[k] = 1;
                    m.insert(e, q(-1));
                }
            }
            _ => {
                let mut e = [0; 3];
                e[i - 1] = 1;
                m.insert(e, q(1));
            }
        }
        Poly3(m)
    }
    /// Total degree.
    pub fn deg(&self) -> usize {
        self.0.keys().map(|e| e[0] + e[1] + e[2]).max().unwrap_or(0)
    }
    fn insert_add(m: &mut BTreeMap<[usize; 3], Q>, e: [usize; 3], v: Q) {
        let x = m.entry(e).or_insert_with(Q::zero);
        *x += v;
        if x.is_zero() {
            m.remove(&e);
        }
    }
    /// self + k·o.
    pub fn axpy(&self, k: &Q, o: &Poly3) -> Poly3 {
        let mut m = self.0.clone();
        for (e, v) in &o.0 {
            Self::insert_add(&mut m, *e, k * v);
        }
        Poly3(m)
    }
    /// self · o.
    pub fn mul(&self, o: &Poly3) -> Poly3 {
        let mut m = BTreeMap::new();
        for (a, x) in &self.0 {
            for (b, y) in &o.0 {
                Self::insert_add(&mut m, [a[0] + b[0], a[1] + b[1], a[2] + b[2]], x * y);
            }
        }
        Poly3(m)
    }
    /// ∂/∂(s, t, r)\[axis\].
    pub fn d(&self, axis: usize) -> Poly3 {
        let mut m = BTreeMap::new();
        for (e, v) in &self.0 {
            if e[axis] > 0 {
                let mut f = *e;
                f[axis] -= 1;
                Self::insert_add(&mut m, f, v * q(e[axis] as i64));
            }
        }
        Poly3(m)
    }
    /// Exact value.
    pub fn eval(&self, p: &[Q; 3]) -> Q {
        self.0
            .iter()
            .map(|(e, v)| {
                v * num_traits::pow(p[0].clone(), e[0])
                    * num_traits::pow(p[1].clone(), e[1])
                    * num_traits::pow(p[2].clone(), e[2])
            })
            .sum()
    }
    /// p∘A, A the affine map of the reference tetrahedron onto `tet` (corners in the chart).
    pub(crate) fn compose_affine(&self, tet: &[[Q; 3]; 4]) -> Poly3 {
        let lin = |k: usize| -> Poly3 {
            let mut m = BTreeMap::new();
            Self::insert_add(&mut m, [0, 0, 0], tet[0][k].clone());
            for (j, e) in [[1, 0, 0], [0, 1, 0], [0, 0, 1]].into_iter().enumerate() {
                Self::insert_add(&mut m, e, &tet[j + 1][k] - &tet[0][k]);
            }
            Poly3(m)
        };
        let coords = [lin(0), lin(1), lin(2)];
        let mut out = Poly3::default();
        for (e, v) in &self.0 {
            let mut term = Poly3::constant(v.clone());
            for (axis, c) in coords.iter().enumerate() {
                for _ in 0..e[axis] {
                    term = term.mul(c);
                }
            }
            out = out.axpy(&q(1), &term);
        }
        out
    }
    /// Bernstein coefficients of degree n ≥ deg on the reference tetrahedron, with the corner
    /// values: (all coefficients, \[value at e_0, e_1, e_2, e_3\]).
    pub fn bernstein(&self, n: usize) -> (Vec<Q>, [Q; 4]) {
        let mut all = Vec::new();
        let mut corners = [Q::zero(), Q::zero(), Q::zero(), Q::zero()];
        for j in 0..=n {
            for k in 0..=(n - j) {
                for l in 0..=(n - j - k) {
                    let i = n - j - k - l;
                    let mut acc = Q::zero();
                    for (e, v) in &self.0 {
                        let (a, b, c) = (e[0], e[1], e[2]);
                        if a > j || b > k || c > l {
                            continue;
                        }
                        acc += v * Q::from_integer(multinomial(
                            n - a - b - c,
                            &[i, j - a, k - b, l - c],
                        )) / Q::from_integer(multinomial(n, &[i, j, k, l]));
                    }
                    // For n = 0 the one coefficient is every corner's value.
                    for (c, x) in [i, j, k, l].into_iter().enumerate() {
                        if x == n {
                            corners[c] = acc.clone();
                        }
                    }
                    all.push(acc);
                }
            }
        }
        (all, corners)
    }
}

/// The reference tetrahedron in the chart.
pub(crate) fn reference_tet() -> [[Q; 3]; 4] {
    [
        [q(0), q(0), q(0)],
        [q(1), q(0), q(0)],
        [q(0), q(1), q(0)],
        [q(0), q(0), q(1)],
    ]
}

/// Decide p > 0 on the closed reference tetrahedron (strict), exactly.
pub fn decide_tet(p: &Poly3, budget: Budget) -> Decision {
    decide_tet_with(p, Strictness::Positive, budget)
}

/// Decide p > 0 or p ≥ 0 (`strict`) on the closed reference tetrahedron, exactly.
pub(crate) fn decide_tet_with(p: &Poly3, strict: Strictness, budget: Budget) -> Decision {
    let bad = |v: &Q| match strict {
        Strictness::Positive => !v.is_positive(),
        Strictness::NonNegative => v.is_negative(),
    };
    let n = p.deg();
    let mut stack = vec![(reference_tet(), 0u32)];
    // Depth in units of three bisections (one planar 1-to-4 split's worth of shrinking).
    let mut cover = Cover::new(budget.max_depth.saturating_mul(3), budget.max_pieces);
    while let Some((t, depth)) = stack.pop() {
        cover.visit(depth);
        let (coeffs, corners) = p.compose_affine(&t).bernstein(n);
        for (c, v) in corners.iter().enumerate() {
            if bad(v) {
                let pt = &t[c];
                let w0 = Q::one() - &pt[0] - &pt[1] - &pt[2];
                let w = [w0, pt[0].clone(), pt[1].clone(), pt[2].clone()];
                return Decision::Refuted {
                    point: [w[1].to_string(), w[2].to_string(), w[3].to_string()],
                    point_f64: [to_f64(&w[1]), to_f64(&w[2]), to_f64(&w[3])],
                    value: v.to_string(),
                    value_f64: to_f64(v),
                };
            }
        }
        if coeffs.iter().all(|c| !bad(c)) {
            cover.certify(&coeffs);
            continue;
        }
        if !cover.split(depth) {
            continue;
        }
        // Bisect the longest edge (squared chart length).
        let mut best = (0, 1, Q::zero());
        for a in 0..4 {
            for b in (a + 1)..4 {
                let l: Q = (0..3)
                    .map(|k| (&t[a][k] - &t[b][k]) * (&t[a][k] - &t[b][k]))
                    .sum();
                if l > best.2 {
                    best = (a, b, l);
                }
            }
        }
        let (a, b) = (best.0, best.1);
        let mid: [Q; 3] = std::array::from_fn(|k| (&t[a][k] + &t[b][k]) * qr(1, 2));
        let mut t1 = t.clone();
        t1[b] = mid.clone();
        let mut t2 = t;
        t2[a] = mid;
        stack.push((t1, depth + 1));
        stack.push((t2, depth + 1));
    }
    cover.finish()
}

/// Eq. (9) on the reference tetrahedron: (N_1, N_2, N_3, D) with N_i = g_i(w_i), D = Σ_j g_j(w_j).
pub fn monotonic(g: &[Poly1; 4]) -> ([Poly3; 3], Poly3) {
    let comp = |p: &Poly1, w: &Poly3| -> Poly3 {
        p.0.iter().rev().fold(Poly3::default(), |acc, c| {
            acc.mul(w).axpy(&q(1), &Poly3::constant(c.clone()))
        })
    };
    let n: Vec<Poly3> = (0..4).map(|i| comp(&g[i], &Poly3::w(i))).collect();
    let d = n.iter().fold(Poly3::default(), |acc, x| acc.axpy(&q(1), x));
    ([n[1].clone(), n[2].clone(), n[3].clone()], d)
}

/// The numerator of det DX for x = N/D in the chart: det DX = (D·det A − ∇Dᵀ adj(A) N) / D⁴,
/// A = ∂N/∂(s, t, r) (matrix determinant lemma on D·A − N ∇Dᵀ), so with D > 0 the sign of
/// det DX is the sign of the returned polynomial.
pub fn jacobian_numerator(n: &[Poly3; 3], d: &Poly3) -> Poly3 {
    let a: Vec<Vec<Poly3>> = n
        .iter()
        .map(|ni| (0..3).map(|k| ni.d(k)).collect())
        .collect();
    let m = |x: &Poly3, y: &Poly3| x.mul(y);
    let sub = |x: &Poly3, y: &Poly3| x.axpy(&q(-1), y);
    // adj(A)[i][j] = cofactor C[j][i].
    let cof = |r: usize, c: usize| -> Poly3 {
        let rs: Vec<usize> = (0..3).filter(|&x| x != r).collect();
        let cs: Vec<usize> = (0..3).filter(|&x| x != c).collect();
        let minor = sub(
            &m(&a[rs[0]][cs[0]], &a[rs[1]][cs[1]]),
            &m(&a[rs[0]][cs[1]], &a[rs[1]][cs[0]]),
        );
        if (r + c) % 2 == 0 {
            minor
        } else {
            minor.axpy(&q(-2), &minor)
        }
    };
    let det_a = (0..3).fold(Poly3::default(), |acc, c| {
        acc.axpy(&q(1), &m(&a[0][c], &cof(0, c)))
    });
    let grad_d: Vec<Poly3> = (0..3).map(|k| d.d(k)).collect();
    let mut lemma = Poly3::default();
    for (i, gi) in grad_d.iter().enumerate() {
        for (j, nj) in n.iter().enumerate() {
            // ∇D_i · adj(A)[i][j] · N_j
            lemma = lemma.axpy(&q(1), &m(&m(gi, &cof(j, i)), nj));
        }
    }
    sub(&m(d, &det_a), &lemma)
}

/// det DX > 0 on the closed reference tetrahedron for the monotonic map of `g` (D > 0 first).
pub fn monotonic_det(g: &[Poly1; 4], budget: Budget) -> Decision {
    let (n, d) = monotonic(g);
    let dd = decide_tet(&d, budget);
    if !dd.certified() {
        return dd;
    }
    decide_tet(&jacobian_numerator(&n, &d), budget)
}

/// `SD-L115(3-D)`: seeded monotonic maps on the tetrahedron (g_i = a t + b t² + c t³ with
/// a, b, c drawn as in the planar search), each certified or refuted exactly.
pub fn search_monotonic(
    samples: usize,
    seed: u64,
    budget: Budget,
) -> crate::sdiff::common::simplex_search::Search {
    use rand::SeedableRng;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let mut s = crate::sdiff::common::simplex_search::Search::default();
    for _ in 0..samples {
        let g: [Poly1; 4] = std::array::from_fn(|_| {
            Poly1(vec![
                q(0),
                crate::sdiff::common::simplex_search::unit_open(&mut rng) * q(10),
                crate::sdiff::common::simplex_search::unit_open(&mut rng) * q(10),
                crate::sdiff::common::simplex_search::unit_open(&mut rng) * q(10),
            ])
        });
        s.record(monotonic_det(&g, budget), || {
            format!(
                "{:?}",
                g.iter()
                    .map(|p| p.0.iter().map(|x| x.to_string()).collect::<Vec<_>>())
                    .collect::<Vec<_>>()
            )
        });
    }
    s
}
