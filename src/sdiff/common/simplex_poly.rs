//! Exact polynomials on the m-simplex for any m (Mello–Velho Eq. (10), L123–L131), and the
//! decision of det DX > 0 on the closed simplex — the method of the planar `positivity` and of
//! the tetrahedral `tet`, in every dimension (`SD-E10(m)`, `SD-L146(4-D)`).
//!
//! A polynomial of degree n is stored homogeneous in the barycentric coordinates,
//! p = Σ_{|I|=n} α_I w^I with I ∈ ℕ^{m+1}, so products are convolutions and the Bernstein
//! coefficient of B_I is α_I·I!/n!. Chart derivatives (s_k = w_k, w_0 = 1 − Σ s) are
//! ∂p/∂s_k = ∂p/∂w_k − ∂p/∂w_0, again homogeneous. The Jacobian numerator of x = N/D is the
//! bordered determinant det \[\[D, ∇D\], \[N_c, ∇N_c\]\] = D·det A − ∇Dᵀ adj(A) N (Schur
//! complement; det A for D = 1), so with D > 0 its sign is the sign of det DX.
//!
//! Decision: all Bernstein coefficients > 0 on a piece certify it (convex hull), a corner
//! coefficient ≤ 0 is the exact value at that corner (a counterexample), otherwise the longest
//! edge (chart length) is bisected by de Casteljau on every line of coefficients parallel to
//! it, under a [`Budget`]; a piece past it is left open and the others are finished
//! (`positivity::Cover`: a counterexample anywhere wins), and with a piece left open the answer
//! is *unresolved*, never a guess. Sizes are bounded before any work ([`MAX_DIM`], [`MAX_COEFFICIENTS`]): a typed [`SimplexError`].

use crate::sdiff::common::positivity::{Budget, Cover, Decision, Strictness};
use crate::sdiff::common::rational::{multinomial, over_common_denominator, q, qr, to_f64, Q};
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};
use std::collections::{BTreeMap, HashMap};

/// Largest dimension m accepted.
pub(crate) const MAX_DIM: usize = 8;
/// Largest number of Bernstein coefficients C(n + m, m) of a polynomial to be decided.
pub const MAX_COEFFICIENTS: usize = 20_000;

/// Bad input or a size beyond the bounds.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum SimplexError {
    /// m = 0 or m > [`MAX_DIM`].
    #[error("dimension m = {m} outside 1..={max}")]
    Dimension {
        /// The dimension asked for.
        m: usize,
        /// [`MAX_DIM`].
        max: usize,
    },
    /// C(n + m, m) > [`MAX_COEFFICIENTS`].
    #[error(
        "degree {n} on the {m}-simplex needs {coefficients} Bernstein coefficients (cap {cap})"
    )]
    TooLarge {
        /// Dimension.
        m: usize,
        /// Degree.
        n: usize,
        /// C(n + m, m).
        coefficients: usize,
        /// [`MAX_COEFFICIENTS`].
        cap: usize,
    },
    /// A control point or weight list of the wrong length.
    #[error("{what}: expected {expected}, found {found}")]
    Length {
        /// Which list (names the control point index where one is wrong).
        what: String,
        /// Expected length.
        expected: usize,
        /// Found length.
        found: usize,
    },
}

/// C(n + m, m), saturating.
pub(crate) fn coefficient_count(m: usize, n: usize) -> usize {
    let mut c: u128 = 1;
    for k in 1..=m as u128 {
        c = c * (n as u128 + k) / k;
        if c > usize::MAX as u128 {
            return usize::MAX;
        }
    }
    c as usize
}

/// Checks m and the size C(n + m, m) against the bounds.
pub(crate) fn check_size(m: usize, n: usize) -> Result<(), SimplexError> {
    if m == 0 || m > MAX_DIM {
        return Err(SimplexError::Dimension { m, max: MAX_DIM });
    }
    let coefficients = coefficient_count(m, n);
    if coefficients > MAX_COEFFICIENTS {
        return Err(SimplexError::TooLarge {
            m,
            n,
            coefficients,
            cap: MAX_COEFFICIENTS,
        });
    }
    Ok(())
}

/// Multi-indices I ∈ ℕ^{m+1} with |I| = n, lexicographically descending (I = n·e_0 first).
pub fn indices(m: usize, n: usize) -> Vec<Vec<usize>> {
    fn rec(left: usize, slots: usize, cur: &mut Vec<usize>, out: &mut Vec<Vec<usize>>) {
        if slots == 1 {
            cur.push(left);
            out.push(cur.clone());
            cur.pop();
            return;
        }
        for a in (0..=left).rev() {
            cur.push(a);
            rec(left - a, slots - 1, cur, out);
            cur.pop();
        }
    }
    let mut out = Vec::new();
    rec(n, m + 1, &mut Vec::with_capacity(m + 1), &mut out);
    out
}

/// A homogeneous polynomial Σ α_I w^I of degree n on the m-simplex, over ℚ (sparse).
#[derive(Debug, Clone, PartialEq)]
pub struct SimplexPoly {
    m: usize,
    n: usize,
    alpha: BTreeMap<Vec<usize>, Q>,
}

impl SimplexPoly {
    /// The constant k (degree 0).
    pub fn constant(m: usize, k: Q) -> Self {
        let mut alpha = BTreeMap::new();
        if !k.is_zero() {
            alpha.insert(vec![0; m + 1], k);
        }
        SimplexPoly { m, n: 0, alpha }
    }
    /// The barycentric coordinate w_i.
    pub fn w(m: usize, i: usize) -> Self {
        let mut e = vec![0; m + 1];
        e[i] = 1;
        SimplexPoly {
            m,
            n: 1,
            alpha: BTreeMap::from([(e, q(1))]),
        }
    }
    /// From Bernstein coefficients of degree n, in the order of [`indices`]`(m, n)`.
    pub fn from_bernstein(m: usize, n: usize, coeffs: &[Q]) -> Self {
        let mut alpha = BTreeMap::new();
        for (i, c) in indices(m, n).into_iter().zip(coeffs) {
            if !c.is_zero() {
                let k = Q::from_integer(multinomial(n, &i));
                alpha.insert(i, c * k);
            }
        }
        SimplexPoly { m, n, alpha }
    }
    /// Dimension m.
    pub fn dim(&self) -> usize {
        self.m
    }
    /// Degree n (of the homogeneous form).
    pub fn degree(&self) -> usize {
        self.n
    }
    /// The zero polynomial.
    pub fn is_zero(&self) -> bool {
        self.alpha.is_empty()
    }
    fn add_at(alpha: &mut BTreeMap<Vec<usize>, Q>, e: Vec<usize>, v: Q) {
        use std::collections::btree_map::Entry;
        match alpha.entry(e) {
            Entry::Vacant(x) => {
                if !v.is_zero() {
                    x.insert(v);
                }
            }
            Entry::Occupied(mut x) => {
                *x.get_mut() += v;
                if x.get().is_zero() {
                    x.remove();
                }
            }
        }
    }
    /// self · o.
    pub fn mul(&self, o: &SimplexPoly) -> SimplexPoly {
        // Integer products over a common denominator, one reduction per coefficient
        // (`over_common_denominator`): the same rationals as summing the products in ℚ.
        let (xa, da) = over_common_denominator(self.alpha.values());
        let (xb, db) = over_common_denominator(o.alpha.values());
        let mut sums: BTreeMap<Vec<usize>, BigInt> = BTreeMap::new();
        for (a, x) in self.alpha.keys().zip(&xa) {
            for (b, y) in o.alpha.keys().zip(&xb) {
                let e: Vec<usize> = a.iter().zip(b).map(|(u, v)| u + v).collect();
                *sums.entry(e).or_default() += x * y;
            }
        }
        let d = da * db;
        let alpha = sums
            .into_iter()
            .filter(|(_, v)| !v.is_zero())
            .map(|(e, v)| (e, Q::new(v, d.clone())))
            .collect();
        SimplexPoly {
            m: self.m,
            n: self.n + o.n,
            alpha,
        }
    }
    /// k · self.
    pub fn scale(&self, k: &Q) -> SimplexPoly {
        let mut out = self.clone();
        out.alpha.retain(|_, v| {
            *v *= k;
            !v.is_zero()
        });
        out
    }
    /// The same polynomial in degree n + k (times (Σ w)^k = 1).
    pub fn elevate(&self, k: usize) -> SimplexPoly {
        if k == 0 {
            return self.clone();
        }
        let one = SimplexPoly {
            m: self.m,
            n: k,
            alpha: indices(self.m, k)
                .into_iter()
                .map(|i| {
                    let c = Q::from_integer(multinomial(k, &i));
                    (i, c)
                })
                .collect(),
        };
        self.mul(&one)
    }
    /// self + k·o (the lower degree elevated first).
    pub fn axpy(&self, k: &Q, o: &SimplexPoly) -> SimplexPoly {
        let n = self.n.max(o.n);
        let mut out = self.elevate(n - self.n);
        for (e, v) in o.elevate(n - o.n).alpha {
            Self::add_at(&mut out.alpha, e, v * k);
        }
        out
    }
    /// ∂/∂s_k in the chart s = (w_1, …, w_m), k ∈ 1..=m: ∂/∂w_k − ∂/∂w_0.
    pub fn d(&self, k: usize) -> SimplexPoly {
        let mut alpha = BTreeMap::new();
        for (e, v) in &self.alpha {
            for (axis, sign) in [(k, q(1)), (0, q(-1))] {
                if e[axis] > 0 {
                    let mut f = e.clone();
                    f[axis] -= 1;
                    Self::add_at(&mut alpha, f, v * q(e[axis] as i64) * sign);
                }
            }
        }
        SimplexPoly {
            m: self.m,
            n: self.n.saturating_sub(1),
            alpha,
        }
    }
    /// Exact value at a barycentric point (m + 1 entries, not required to sum to 1: the form
    /// is homogeneous, so the caller normalises).
    pub fn eval(&self, w: &[Q]) -> Q {
        self.alpha
            .iter()
            .map(|(e, v)| {
                e.iter().zip(w).fold(v.clone(), |acc, (k, x)| {
                    acc * num_traits::pow(x.clone(), *k)
                })
            })
            .sum()
    }
    /// Bernstein coefficients of degree n in the order of [`indices`]`(m, n)`.
    pub fn bernstein(&self) -> Vec<Q> {
        indices(self.m, self.n)
            .into_iter()
            .map(|i| match self.alpha.get(&i) {
                Some(a) => a / Q::from_integer(multinomial(self.n, &i)),
                None => Q::zero(),
            })
            .collect()
    }
}

/// det of a square matrix of polynomials (Laplace along the first row, minors memoised by
/// their column set). Terms of different degree are elevated (`axpy`).
pub fn det(a: &[Vec<SimplexPoly>], m: usize) -> SimplexPoly {
    let size = a.len();
    let mut memo: HashMap<(usize, u32), SimplexPoly> = HashMap::new();
    fn minor(
        a: &[Vec<SimplexPoly>],
        row: usize,
        cols: u32,
        m: usize,
        memo: &mut HashMap<(usize, u32), SimplexPoly>,
    ) -> SimplexPoly {
        if row == a.len() {
            return SimplexPoly::constant(m, q(1));
        }
        if let Some(p) = memo.get(&(row, cols)) {
            return p.clone();
        }
        let mut acc: Option<SimplexPoly> = None;
        let mut sign = q(1);
        for c in 0..a.len() {
            if cols & (1 << c) == 0 {
                continue;
            }
            let sub = minor(a, row + 1, cols & !(1 << c), m, memo);
            let term = a[row][c].mul(&sub);
            acc = Some(match acc {
                None => term.scale(&sign),
                Some(x) => x.axpy(&sign, &term),
            });
            sign = -sign;
        }
        let out = acc.unwrap_or_else(|| SimplexPoly::constant(m, q(1)));
        memo.insert((row, cols), out.clone());
        out
    }
    minor(a, 0, (1u32 << size) - 1, m, &mut memo)
}

/// x = N/D of Eq. (10)/(11) on the m-simplex: chart components N_1..N_m (w_0's component is
/// 1 − Σ by partition of unity) and D (None for Eq. (10), D = 1).
#[derive(Debug, Clone)]
pub struct SimplexMapM {
    /// Dimension.
    pub m: usize,
    /// Degree.
    pub n: usize,
    /// N_1, …, N_m.
    pub num: Vec<SimplexPoly>,
    /// D (Eq. (11)), None for Eq. (10).
    pub den: Option<SimplexPoly>,
}

impl SimplexMapM {
    /// Eq. (10) (`weights` None) or (11): control points b_I ∈ ℚ^{m+1} (barycentric) in the
    /// order of [`indices`]`(m, n)`, weights q_I in the same order.
    pub fn new(
        m: usize,
        n: usize,
        control: &[Vec<Q>],
        weights: Option<&[Q]>,
    ) -> Result<Self, SimplexError> {
        let numerator_degree = if weights.is_some() {
            n + m * n.saturating_sub(1)
        } else {
            m * n.saturating_sub(1)
        };
        check_size(m, numerator_degree)?;
        let idx = indices(m, n);
        if control.len() != idx.len() {
            return Err(SimplexError::Length {
                what: format!("control points of degree {n} on the {m}-simplex"),
                expected: idx.len(),
                found: control.len(),
            });
        }
        if let Some(w) = weights {
            if w.len() != idx.len() {
                return Err(SimplexError::Length {
                    what: "weights".into(),
                    expected: idx.len(),
                    found: w.len(),
                });
            }
        }
        let mut num = vec![BTreeMap::new(); m];
        let mut den = BTreeMap::new();
        for (k, (i, b)) in idx.into_iter().zip(control).enumerate() {
            if b.len() != m + 1 {
                return Err(SimplexError::Length {
                    what: format!("control point {k} (I = {i:?})"),
                    expected: m + 1,
                    found: b.len(),
                });
            }
            let wk = weights.map(|w| w[k].clone()).unwrap_or_else(|| q(1));
            let basis = Q::from_integer(multinomial(n, &i)) * &wk;
            for (c, nc) in num.iter_mut().enumerate() {
                SimplexPoly::add_at(nc, i.clone(), &basis * &b[c + 1]);
            }
            SimplexPoly::add_at(&mut den, i, basis);
        }
        let poly = |alpha| SimplexPoly { m, n, alpha };
        Ok(SimplexMapM {
            m,
            n,
            num: num.into_iter().map(poly).collect(),
            den: weights.map(|_| poly(den)),
        })
    }
    /// The numerator of det DX (chart s = (w_1..w_m)): det A (Eq. (10)) or the bordered
    /// det \[\[D, ∇D\], \[N, A\]\] = D·det A − ∇Dᵀ adj(A) N (Eq. (11)), A = ∂N/∂s.
    pub fn jacobian_numerator(&self) -> SimplexPoly {
        let row = |p: &SimplexPoly| -> Vec<SimplexPoly> { (1..=self.m).map(|k| p.d(k)).collect() };
        match &self.den {
            None => det(&self.num.iter().map(row).collect::<Vec<_>>(), self.m),
            Some(d) => {
                let mut rows = Vec::with_capacity(self.m + 1);
                for p in std::iter::once(d).chain(self.num.iter()) {
                    let mut r = vec![p.clone()];
                    r.extend(row(p));
                    rows.push(r);
                }
                det(&rows, self.m)
            }
        }
    }
}

/// The answer of [`decide`]; points in barycentric coordinates of the reference m-simplex.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[serde(rename_all = "snake_case", tag = "kind")]
pub enum SimplexDecision {
    /// Every piece has all Bernstein coefficients > 0 (≥ 0).
    Certified {
        /// Pieces of the final cover.
        pieces: usize,
        /// Deepest bisection used.
        depth: u32,
        /// Smallest Bernstein coefficient over the cover (a lower bound), as f64.
        lower_bound: f64,
    },
    /// p(point) ≤ 0 (< 0), exactly.
    Refuted {
        /// The point (w_0, …, w_m), exact.
        point: Vec<String>,
        /// The same in f64.
        point_f64: Vec<f64>,
        /// p at the point, exact.
        value: String,
        /// p at the point, f64.
        value_f64: f64,
    },
    /// Neither within the budget.
    Unresolved {
        /// Pieces examined.
        pieces: usize,
        /// Depth reached.
        depth: u32,
    },
}

impl SimplexDecision {
    /// Certified.
    pub fn certified(&self) -> bool {
        matches!(self, SimplexDecision::Certified { .. })
    }
    /// Refuted.
    pub fn refuted(&self) -> bool {
        matches!(self, SimplexDecision::Refuted { .. })
    }
    /// "certified" | "refuted" | "unresolved", to compare with the 2-D and 3-D engines.
    pub fn kind(&self) -> &'static str {
        match self {
            SimplexDecision::Certified { .. } => "certified",
            SimplexDecision::Refuted { .. } => "refuted",
            SimplexDecision::Unresolved { .. } => "unresolved",
        }
    }
}

/// Lines of the coefficient lattice parallel to edge (a, b): positions of I − j e_a + j e_b,
/// j = 0..k, for each I with I_b = 0 (k = I_a).
fn lines(
    idx: &[Vec<usize>],
    pos: &HashMap<Vec<usize>, usize>,
    a: usize,
    b: usize,
) -> Vec<Vec<usize>> {
    idx.iter()
        .filter(|i| i[b] == 0)
        .map(|i| {
            (0..=i[a])
                .map(|j| {
                    let mut e = i.clone();
                    e[a] -= j;
                    e[b] += j;
                    pos[&e]
                })
                .collect()
        })
        .collect()
}

/// Splits the Bernstein coefficients at the midpoint of edge (a, b): (child with vertex b
/// moved to the midpoint, child with vertex a moved to it), by de Casteljau at 1/2 on each line.
fn split(coeffs: &[Q], lines_ab: &[Vec<usize>]) -> (Vec<Q>, Vec<Q>) {
    let half = qr(1, 2);
    let (mut left, mut right) = (coeffs.to_vec(), coeffs.to_vec());
    for line in lines_ab {
        let k = line.len() - 1;
        let mut arr: Vec<Q> = line.iter().map(|&p| coeffs[p].clone()).collect();
        for r in 1..=k {
            for i in 0..=(k - r) {
                arr[i] = (&arr[i] + &arr[i + 1]) * &half;
            }
            left[line[r]] = arr[0].clone();
            right[line[k - r]] = arr[k - r].clone();
        }
    }
    (left, right)
}

/// Decide p > 0 (or ≥ 0) on the closed reference m-simplex. Depth is counted in bisections;
/// the budget's `max_depth` is in halvings of every edge, i.e. m bisections each.
pub fn decide(
    p: &SimplexPoly,
    strict: Strictness,
    budget: Budget,
) -> Result<SimplexDecision, SimplexError> {
    let (m, n) = (p.m, p.n);
    check_size(m, n)?;
    let bad = |v: &Q| match strict {
        Strictness::Positive => !v.is_positive(),
        Strictness::NonNegative => v.is_negative(),
    };
    let idx = indices(m, n);
    let pos: HashMap<Vec<usize>, usize> = idx
        .iter()
        .cloned()
        .enumerate()
        .map(|(k, i)| (i, k))
        .collect();
    let corner_pos: Vec<usize> = (0..=m)
        .map(|c| {
            let mut e = vec![0; m + 1];
            e[c] = n;
            pos[&e]
        })
        .collect();
    let mut line_cache: HashMap<(usize, usize), Vec<Vec<usize>>> = HashMap::new();
    let reference: Vec<Vec<Q>> = (0..=m)
        .map(|c| (0..=m).map(|k| if k == c { q(1) } else { q(0) }).collect())
        .collect();
    let mut stack = vec![(reference, p.bernstein(), 0u32)];
    let mut cover = Cover::new(budget.max_depth.saturating_mul(m as u32), budget.max_pieces);
    while let Some((verts, coeffs, depth)) = stack.pop() {
        cover.visit(depth);
        for (c, &cp) in corner_pos.iter().enumerate() {
            if bad(&coeffs[cp]) {
                return Ok(SimplexDecision::Refuted {
                    point: verts[c].iter().map(|x| x.to_string()).collect(),
                    point_f64: verts[c].iter().map(to_f64).collect(),
                    value: coeffs[cp].to_string(),
                    value_f64: to_f64(&coeffs[cp]),
                });
            }
        }
        if coeffs.iter().all(|c| !bad(c)) {
            cover.certify(&coeffs);
            continue;
        }
        if !cover.split(depth) {
            continue;
        }
        // Longest edge in the chart (components 1..m), first in index order on ties.
        let mut best = (0, 1, Q::zero());
        for a in 0..=m {
            for b in (a + 1)..=m {
                let l: Q = (1..=m)
                    .map(|k| (&verts[a][k] - &verts[b][k]) * (&verts[a][k] - &verts[b][k]))
                    .sum();
                if l > best.2 {
                    best = (a, b, l);
                }
            }
        }
        let (a, b) = (best.0, best.1);
        let ls = line_cache
            .entry((a, b))
            .or_insert_with(|| lines(&idx, &pos, a, b));
        let (left, right) = split(&coeffs, ls);
        let mid: Vec<Q> = (0..=m)
            .map(|k| (&verts[a][k] + &verts[b][k]) * qr(1, 2))
            .collect();
        let mut v1 = verts.clone();
        v1[b] = mid.clone();
        let mut v2 = verts;
        v2[a] = mid;
        stack.push((v1, left, depth + 1));
        stack.push((v2, right, depth + 1));
    }
    Ok(match cover.finish() {
        Decision::Certified {
            pieces,
            depth,
            lower_bound,
        } => SimplexDecision::Certified {
            pieces,
            depth,
            lower_bound,
        },
        _ => SimplexDecision::Unresolved {
            pieces: cover.pieces,
            depth: cover.deepest,
        },
    })
}

/// det DX > 0 on the closed m-simplex, exactly (D > 0 first for Eq. (11)).
pub fn det_decision(map: &SimplexMapM, budget: Budget) -> Result<SimplexDecision, SimplexError> {
    if let Some(d) = &map.den {
        let dd = decide(d, Strictness::Positive, budget)?;
        if !dd.certified() {
            return Ok(dd);
        }
    }
    decide(&map.jacobian_numerator(), Strictness::Positive, budget)
}

/// b_I = I/n (X = id), in the order of [`indices`].
pub fn fixed_control(m: usize, n: usize) -> Vec<Vec<Q>> {
    indices(m, n)
        .into_iter()
        .map(|i| i.into_iter().map(|k| qr(k as i64, n as i64)).collect())
        .collect()
}

/// L146: b_I is *solitary* when every I^i ∈ {0, 1}.
pub(crate) fn is_solitary(i: &[usize]) -> bool {
    i.iter().all(|&k| k <= 1)
}

/// p ≡ 1 (every Bernstein coefficient is 1): the numerator of X = id.
pub fn is_one(p: &SimplexPoly) -> bool {
    p.bernstein().iter().all(|c| c.is_one())
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    fn random_poly(rng: &mut ChaCha8Rng, m: usize, n: usize) -> SimplexPoly {
        let coeffs: Vec<Q> = indices(m, n)
            .iter()
            .map(|_| match rng.gen_range(0..4) {
                0 => Q::zero(),
                1 => q(rng.gen_range(-9..10)),
                _ => qr(rng.gen_range(-999..1000), rng.gen_range(1..64)),
            })
            .collect();
        SimplexPoly::from_bernstein(m, n, &coeffs)
    }

    /// The product over a common denominator is the sum of the products in ℚ (`add_at`, the
    /// definition), monomial for monomial, zeros dropped.
    #[test]
    fn sd_simplex_poly_product_over_a_common_denominator_equals_the_sum_in_q() {
        let mut rng = ChaCha8Rng::seed_from_u64(4);
        for case in 0..60 {
            let m = rng.gen_range(1..4);
            let (na, nb) = (rng.gen_range(0..4), rng.gen_range(0..4));
            let (x, y) = (random_poly(&mut rng, m, na), random_poly(&mut rng, m, nb));
            let mut want = BTreeMap::new();
            for (a, u) in &x.alpha {
                for (b, v) in &y.alpha {
                    let e: Vec<usize> = a.iter().zip(b).map(|(i, j)| i + j).collect();
                    SimplexPoly::add_at(&mut want, e, u * v);
                }
            }
            let got = x.mul(&y);
            assert_eq!((got.m, got.n), (m, x.n + y.n));
            assert_eq!(got.alpha, want, "case {case}");
        }
    }
}
