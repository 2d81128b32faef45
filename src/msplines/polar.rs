//! Sec. 3.1.1–3.1.2 in exact rationals: polar forms (blossoms, Defs. 1–2, Prop. 3) and the
//! B-patch evaluation recurrence (4) over the knot clouds (1)–(3).
//!
//! A polynomial is held as Σ_j c_j Π_{i<k} ℓ_{j,i}(u) with affine ℓ; its blossom is the
//! symmetrised product (1/k!) Σ_π Π_i ℓ_{j,i}(u_{π(i)}), symmetric and multi-affine by
//! construction; the checks below decide that, and the diagonal identity, exactly.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Zero};

pub use crate::numeric::Q;
/// A point of ℚ².
pub type Q2 = [Q; 2];

/// a/b as a rational.
pub fn q(a: i64, b: i64) -> Q {
    BigRational::new(BigInt::from(a), BigInt::from(b))
}
/// (x, y) from integer pairs a/b.
pub fn q2(x: (i64, i64), y: (i64, i64)) -> Q2 {
    [q(x.0, x.1), q(y.0, y.1)]
}

/// An affine function ℓ(u) = a·u_x + b·u_y + c.
#[derive(Clone, Debug, PartialEq)]
pub struct Affine {
    /// Coefficients (a, b, c).
    pub abc: [Q; 3],
}

impl Affine {
    /// ℓ(u).
    pub fn at(&self, u: &Q2) -> Q {
        &self.abc[0] * &u[0] + &self.abc[1] * &u[1] + &self.abc[2]
    }
}

/// A degree-k polynomial ℝ² → ℝ as a sum of products of k affine factors.
#[derive(Clone, Debug)]
pub struct ProductPoly {
    /// Degree k.
    pub k: usize,
    /// (c_j, [ℓ_{j,0}, …, ℓ_{j,k−1}]).
    pub terms: Vec<(Q, Vec<Affine>)>,
    /// Planted fault: evaluate the blossom without symmetrising (not symmetric).
    pub unsymmetrised: bool,
}

fn permutations(n: usize) -> Vec<Vec<usize>> {
    if n == 0 {
        return vec![vec![]];
    }
    let mut out = Vec::new();
    for p in permutations(n - 1) {
        for pos in 0..=p.len() {
            let mut q = p.clone();
            q.insert(pos, n - 1);
            out.push(q);
        }
    }
    out
}

impl ProductPoly {
    /// F(u).
    pub fn eval(&self, u: &Q2) -> Q {
        self.terms
            .iter()
            .map(|(c, ls)| ls.iter().fold(c.clone(), |acc, l| acc * l.at(u)))
            .fold(Q::zero(), |a, b| a + b)
    }
    /// The blossom f(u_1, …, u_k) (Prop. 3).
    pub fn blossom(&self, us: &[Q2]) -> Q {
        let mut total = Q::zero();
        for (c, ls) in &self.terms {
            if self.unsymmetrised {
                total += ls
                    .iter()
                    .zip(us)
                    .fold(c.clone(), |acc, (l, u)| acc * l.at(u));
                continue;
            }
            let perms = permutations(self.k);
            let n = perms.len() as i64;
            let mut s = Q::zero();
            for p in &perms {
                s += p
                    .iter()
                    .enumerate()
                    .fold(Q::one(), |acc, (i, &pi)| acc * ls[i].at(&us[pi]));
            }
            total += c * s / q(n, 1);
        }
        total
    }
}

/// The knot clouds of one triangle Δ^I (eq. (1)): `clouds[i][l]` = t_{i,l}, l = 0..=k, with
/// t_{i,0} the triangle's vertex i.
#[derive(Clone, Debug)]
pub struct KnotClouds {
    /// Degree k.
    pub k: usize,
    /// The clouds.
    pub clouds: [Vec<Q2>; 3],
}

/// Multi-indices β with |β| = n, in a fixed order.
pub fn multi_indices(n: usize) -> Vec<[usize; 3]> {
    let mut out = Vec::new();
    for a in 0..=n {
        for b in 0..=n - a {
            out.push([a, b, n - a - b]);
        }
    }
    out
}

/// Barycentric coordinates of u with respect to [a, b, c], or None if degenerate.
pub fn barycentric(t: [&Q2; 3], u: &Q2) -> Option<[Q; 3]> {
    let det = |p: &Q2, q1: &Q2, r: &Q2| {
        (&q1[0] - &p[0]) * (&r[1] - &p[1]) - (&r[0] - &p[0]) * (&q1[1] - &p[1])
    };
    let d = det(t[0], t[1], t[2]);
    if d.is_zero() {
        return None;
    }
    Some([
        det(u, t[1], t[2]) / &d,
        det(t[0], u, t[2]) / &d,
        det(t[0], t[1], u) / &d,
    ])
}

impl KnotClouds {
    /// X^β of eq. (2): the first β_i knots of each cloud (|β| = k knots).
    pub fn x_beta(&self, b: &[usize; 3]) -> Vec<Q2> {
        (0..3)
            .flat_map(|i| self.clouds[i][..b[i]].iter().cloned())
            .collect()
    }
    /// Δ^β = [t_{0,β0}, t_{1,β1}, t_{2,β2}].
    pub fn delta(&self, b: &[usize; 3]) -> [&Q2; 3] {
        [
            &self.clouds[0][b[0]],
            &self.clouds[1][b[1]],
            &self.clouds[2][b[2]],
        ]
    }
    /// Every knot transformed by `phi`.
    pub fn mapped(&self, phi: &dyn Fn(&Q2) -> Q2) -> KnotClouds {
        KnotClouds {
            k: self.k,
            clouds: self.clouds.clone().map(|c| c.iter().map(phi).collect()),
        }
    }
    /// Recurrence (4): F(u) = C_0^k(u) from the poles `pole(β)`, |β| = k. None when some
    /// Δ^β is degenerate.
    pub fn eval(&self, pole: &dyn Fn(&[usize; 3]) -> Q, u: &Q2) -> Option<Q> {
        let k = self.k;
        let mut c: Vec<([usize; 3], Q)> = multi_indices(k)
            .into_iter()
            .map(|b| (b, pole(&b)))
            .collect();
        for v in 0..k {
            let n = k - v - 1;
            let mut next = Vec::new();
            for b in multi_indices(n) {
                let lam = barycentric(self.delta(&b), u)?;
                let mut s = Q::zero();
                for (i, l) in lam.iter().enumerate() {
                    let mut bi = b;
                    bi[i] += 1;
                    let cv = c.iter().find(|(x, _)| *x == bi).map(|(_, y)| y.clone())?;
                    s += l * cv;
                }
                next.push((b, s));
            }
            c = next;
        }
        c.into_iter().next().map(|(_, y)| y)
    }
    /// The B-patch basis function B_β(u): the pole of β set to 1, all others 0.
    pub fn basis(&self, beta: &[usize; 3], u: &Q2) -> Option<Q> {
        self.eval(&|b| if b == beta { Q::one() } else { Q::zero() }, u)
    }
}
