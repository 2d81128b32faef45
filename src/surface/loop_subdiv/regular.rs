//! The regular Loop patch: on a triangle all of whose corners have valence 6, the Loop limit
//! surface is the three-direction quartic box spline, a quartic polynomial in the patch
//! parameter (Loop 1987; Stam 1998, Sec. 3).
//!
//! The 12 basis polynomials are *computed here*, exactly in rationals, from the subdivision
//! rules alone: the regular net is subdivided twice on the lattice, the limit mask
//! (½ centre + 1/12 each neighbour) gives the limit value at the 15 points (i/4, j/4) of the
//! triangle, and the quartic through them is solved for. `tests` check the result against
//! limit values at level 3 (points the interpolation did not use), exactly.
//!
//! Lattice: the patch triangle is (0,0), (1,0), (0,1); edge directions (1,0), (0,1), (1,−1).
//! Net order (the same as the extraordinary net of [`super::patch`] for valence 6): the first
//! corner v, its ring r₀ … r₅ counter-clockwise from r₀ = (1,0), then o₀ … o₄.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Zero};
use std::collections::HashMap;
use std::sync::OnceLock;

/// The six neighbour directions of a lattice point, counter-clockwise.
pub const DIRS: [(i64, i64); 6] = [(1, 0), (0, 1), (-1, 1), (-1, 0), (0, -1), (1, -1)];

/// Lattice positions of the 12 points of the regular net, in net order.
pub const REGULAR_NET: [(i64, i64); 12] = [
    (0, 0),
    (1, 0),
    (0, 1),
    (-1, 1),
    (-1, 0),
    (0, -1),
    (1, -1),
    (2, -1),
    (2, 0),
    (1, 1),
    (0, 2),
    (-1, 2),
];

/// Exponents (a, b) of the 15 monomials xᵃyᵇ of degree ≤ 4, in the order used for coefficients.
pub const MONOMIALS: [(u32, u32); 15] = [
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
    (4, 0),
    (3, 1),
    (2, 2),
    (1, 3),
    (0, 4),
];

type Coeffs = Vec<BigRational>;

fn rat(p: i64, q: i64) -> BigRational {
    BigRational::new(BigInt::from(p), BigInt::from(q))
}

fn axpy(acc: &mut Coeffs, w: &BigRational, x: &Coeffs) {
    for (a, b) in acc.iter_mut().zip(x) {
        *a += w * b;
    }
}

/// Control points of the regular net after `level` subdivision steps, as exact combinations
/// of the 12 net points (memoised). `Err` names a lattice point outside the net: it cannot
/// happen for points that influence the patch (all weights are positive), see the tests.
struct Refiner {
    memo: HashMap<(u32, i64, i64), Coeffs>,
}

impl Refiner {
    fn point(&mut self, level: u32, p: (i64, i64)) -> Result<Coeffs, (u32, i64, i64)> {
        if let Some(c) = self.memo.get(&(level, p.0, p.1)) {
            return Ok(c.clone());
        }
        let mut acc: Coeffs = vec![BigRational::zero(); 12];
        if level == 0 {
            let i = REGULAR_NET
                .iter()
                .position(|&q| q == p)
                .ok_or((0, p.0, p.1))?;
            acc[i] = BigRational::one();
        } else if p.0 % 2 == 0 && p.1 % 2 == 0 {
            // Vertex rule, valence 6: β = 1/16.
            let q = (p.0 / 2, p.1 / 2);
            axpy(&mut acc, &rat(5, 8), &self.point(level - 1, q)?);
            for d in DIRS {
                axpy(
                    &mut acc,
                    &rat(1, 16),
                    &self.point(level - 1, (q.0 + d.0, q.1 + d.1))?,
                );
            }
        } else {
            // Edge rule: the edge q → q + D[i]; the opposite vertices are q + D[i∓1].
            let i = match (p.0.rem_euclid(2), p.1.rem_euclid(2)) {
                (1, 0) => 0,
                (0, 1) => 1,
                _ => 5,
            };
            let d = DIRS[i];
            let q = ((p.0 - d.0) / 2, (p.1 - d.1) / 2);
            let (a, b) = (DIRS[(i + 5) % 6], DIRS[(i + 1) % 6]);
            for (w, r) in [
                (rat(3, 8), q),
                (rat(3, 8), (q.0 + d.0, q.1 + d.1)),
                (rat(1, 8), (q.0 + a.0, q.1 + a.1)),
                (rat(1, 8), (q.0 + b.0, q.1 + b.1)),
            ] {
                axpy(&mut acc, &w, &self.point(level - 1, r)?);
            }
        }
        self.memo.insert((level, p.0, p.1), acc.clone());
        Ok(acc)
    }

    /// The limit position of the level-`level` control point at p (regular limit mask).
    fn limit(&mut self, level: u32, p: (i64, i64)) -> Result<Coeffs, (u32, i64, i64)> {
        let mut acc = vec![BigRational::zero(); 12];
        axpy(&mut acc, &rat(1, 2), &self.point(level, p)?);
        for d in DIRS {
            axpy(
                &mut acc,
                &rat(1, 12),
                &self.point(level, (p.0 + d.0, p.1 + d.1))?,
            );
        }
        Ok(acc)
    }
}

/// Solve the square system M X = B exactly (Gauss–Jordan); `None` if singular.
fn solve_exact(
    mut m: Vec<Vec<BigRational>>,
    mut b: Vec<Vec<BigRational>>,
) -> Option<Vec<Vec<BigRational>>> {
    let n = m.len();
    for col in 0..n {
        let piv = (col..n).find(|&r| !m[r][col].is_zero())?;
        m.swap(col, piv);
        b.swap(col, piv);
        let inv = BigRational::one() / m[col][col].clone();
        for x in m[col].iter_mut() {
            *x *= &inv;
        }
        for x in b[col].iter_mut() {
            *x *= &inv;
        }
        for r in 0..n {
            if r != col && !m[r][col].is_zero() {
                let f = m[r][col].clone();
                let (mr, mc) = (m[r].clone(), m[col].clone());
                m[r] = mr.iter().zip(&mc).map(|(a, c)| a - &f * c).collect();
                let (br, bc) = (b[r].clone(), b[col].clone());
                b[r] = br.iter().zip(&bc).map(|(a, c)| a - &f * c).collect();
            }
        }
    }
    Some(b)
}

/// The 12 basis polynomials of the regular patch as exact monomial coefficients:
/// `basis()[k][j]` is the coefficient of [`MONOMIALS`]`[j]` in the basis function of net
/// point k. Computed once.
pub fn basis_exact() -> &'static Vec<Vec<BigRational>> {
    static B: OnceLock<Vec<Vec<BigRational>>> = OnceLock::new();
    B.get_or_init(|| compute_basis().unwrap_or_default())
}

fn compute_basis() -> Option<Vec<Vec<BigRational>>> {
    let mut r = Refiner {
        memo: HashMap::new(),
    };
    let mut rows = Vec::new();
    let mut rhs = Vec::new();
    for i in 0..=4i64 {
        for j in 0..=(4 - i) {
            let (x, y) = (rat(i, 4), rat(j, 4));
            rows.push(
                MONOMIALS
                    .iter()
                    .map(|&(a, b)| {
                        num_traits::pow(x.clone(), a as usize)
                            * num_traits::pow(y.clone(), b as usize)
                    })
                    .collect(),
            );
            rhs.push(r.limit(2, (i, j)).ok()?);
        }
    }
    // rows: 15 × 15 Vandermonde; rhs: 15 × 12. Solution: 15 × 12 (monomial × net point).
    let sol = solve_exact(rows, rhs)?;
    Some(
        (0..12)
            .map(|k| (0..15).map(|j| sol[j][k].clone()).collect())
            .collect(),
    )
}

/// The limit value at level-`level` lattice point p as exact weights of the 12 net points
/// (for tests: independent of the interpolation).
pub fn limit_weights_exact(level: u32, p: (i64, i64)) -> Option<Vec<BigRational>> {
    let mut r = Refiner {
        memo: HashMap::new(),
    };
    r.limit(level, p).ok()
}

/// The basis in f64, row-major 12 × 15.
pub fn basis_f64() -> &'static [[f64; 15]; 12] {
    static B: OnceLock<[[f64; 15]; 12]> = OnceLock::new();
    B.get_or_init(|| {
        let e = basis_exact();
        std::array::from_fn(|k| {
            std::array::from_fn(|j| {
                e.get(k)
                    .and_then(|r| r.get(j))
                    .map(ratio_to_f64)
                    .unwrap_or(f64::NAN)
            })
        })
    })
}

/// Nearest f64 of an exact rational (correctly rounded for the small denominators here).
pub(crate) fn ratio_to_f64(q: &BigRational) -> f64 {
    use num_traits::ToPrimitive;
    q.to_f64().unwrap_or(f64::NAN)
}

/// (numerator, denominator) as i64 when they fit, to build a [`crate::numeric::Scalar`]
/// by `from_ratio` (correctly rounded at any precision).
pub(crate) fn ratio_to_i64(q: &BigRational) -> Option<(i64, i64)> {
    use num_traits::ToPrimitive;
    Some((q.numer().to_i64()?, q.denom().to_i64()?))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn eval_exact(k: usize, x: &BigRational, y: &BigRational) -> BigRational {
        let b = basis_exact();
        MONOMIALS
            .iter()
            .zip(&b[k])
            .map(|(&(a, e), c)| {
                c * num_traits::pow(x.clone(), a as usize) * num_traits::pow(y.clone(), e as usize)
            })
            .fold(BigRational::zero(), |s, t| s + t)
    }

    #[test]
    fn loop_regular_basis_reproduces_level3_limits_exactly() {
        assert_eq!(basis_exact().len(), 12);
        for i in 0..=8i64 {
            for j in 0..=(8 - i) {
                let w = limit_weights_exact(3, (i, j)).expect("inside the net");
                for (k, wk) in w.iter().enumerate() {
                    assert_eq!(
                        eval_exact(k, &rat(i, 8), &rat(j, 8)),
                        *wk,
                        "k={k} at ({i},{j})/8"
                    );
                }
            }
        }
    }

    #[test]
    fn loop_regular_basis_partition_of_unity_and_limit_mask() {
        let b = basis_exact();
        for j in 0..15 {
            let s: BigRational = b
                .iter()
                .map(|r| r[j].clone())
                .fold(BigRational::zero(), |a, c| a + c);
            assert_eq!(
                s,
                if j == 0 {
                    BigRational::one()
                } else {
                    BigRational::zero()
                }
            );
        }
        assert_eq!(b[0][0], rat(1, 2));
        for r in &b[1..7] {
            assert_eq!(r[0], rat(1, 12));
        }
        for r in &b[7..] {
            assert_eq!(r[0], BigRational::zero());
        }
    }
}
