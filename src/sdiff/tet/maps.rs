//! The polynomial (Eq. (10)) and rational (Eq. (11)) families on a tetrahedron (m = 3):
//! x = Σ_{|I|=n} q_I b_I B_I(w) / Σ q_I B_I(w) with I ∈ ℕ⁴, b_I barycentric in ℚ⁴, and the
//! exact det DX certificate of `tet` (D > 0 first, then the Jacobian numerator). Used for the
//! 3-D readings of L141 (adjusted quadratics) and L146 (degree 4, every non-solitary control
//! point fixed, the solitary (1,1,1,1) free in the open tetrahedron; proved for m = 3).
//! The independent interval route for tetrahedra is `tet::interval`.

use super::poly::{decide_tet, jacobian_numerator, Poly3};
use crate::sdiff::common::positivity::{Budget, Decision};
use crate::sdiff::common::rational::{multinomial, q, Q};
use crate::sdiff::common::simplex_search::unit_open;
use num_bigint::BigInt;
use rand_chacha::ChaCha8Rng;

/// Multi-indices I ∈ ℕ⁴ with |I| = n, in lexicographic order.
pub fn multi_indices4(n: usize) -> Vec<[usize; 4]> {
    let mut out = Vec::new();
    for a in (0..=n).rev() {
        for b in (0..=n - a).rev() {
            for c in (0..=n - a - b).rev() {
                out.push([a, b, c, n - a - b - c]);
            }
        }
    }
    out
}

/// B_I(w) = n!/(I!) Π w_k^{I_k} on the reference tetrahedron.
pub(crate) fn bernstein4(i: [usize; 4]) -> Poly3 {
    let n: usize = i.iter().sum();
    let c: BigInt = multinomial(n, &i);
    (0..4).fold(Poly3::constant(Q::from_integer(c)), |acc, k| {
        (0..i[k]).fold(acc, |a, _| a.mul(&Poly3::w(k)))
    })
}

/// (N_1, N_2, N_3, D) of Eq. (11) (`weights` = None: Eq. (10), D = 1), chart components 1..3.
pub fn tet_map(n: usize, control: &[[Q; 4]], weights: Option<&[Q]>) -> ([Poly3; 3], Poly3) {
    let mut num = [Poly3::default(), Poly3::default(), Poly3::default()];
    let mut den = Poly3::default();
    for (k, i) in multi_indices4(n).into_iter().enumerate() {
        let b = bernstein4(i);
        let w = weights
            .and_then(|w| w.get(k))
            .cloned()
            .unwrap_or_else(|| q(1));
        for (c, nc) in num.iter_mut().enumerate() {
            *nc = nc.axpy(&(&w * &control[k][c + 1]), &b);
        }
        den = den.axpy(&w, &b);
    }
    if weights.is_none() {
        den = Poly3::constant(q(1));
    }
    (num, den)
}

/// det DX > 0 on the closed tetrahedron, exactly (D > 0 first).
pub fn tet_det(n: &[Poly3; 3], d: &Poly3, budget: Budget) -> Decision {
    let dd = decide_tet(d, budget);
    if !dd.certified() {
        return dd;
    }
    decide_tet(&jacobian_numerator(n, d), budget)
}

/// b_I = I/n (the fixed control points, X = id).
pub fn fixed_control4(n: usize) -> Vec<[Q; 4]> {
    multi_indices4(n)
        .into_iter()
        .map(|i| i.map(|k| Q::new((k as i64).into(), (n as i64).into())))
        .collect()
}

/// A random point of the open face with support `supp`.
pub(crate) fn open_face_point4(rng: &mut ChaCha8Rng, supp: [bool; 4]) -> [Q; 4] {
    let w: [Q; 4] = std::array::from_fn(|c| if supp[c] { unit_open(rng) } else { q(0) });
    let total: Q = w.iter().cloned().sum();
    w.map(|x| x / &total)
}

/// An adjusted polynomial map of degree n on the tetrahedron: b_I in the open face supp I.
pub fn random_adjusted4(n: usize, rng: &mut ChaCha8Rng) -> Vec<[Q; 4]> {
    multi_indices4(n)
        .into_iter()
        .map(|i| open_face_point4(rng, i.map(|k| k > 0)))
        .collect()
}

/// Degree 4, every non-solitary control point fixed, the solitary (1,1,1,1) random in the
/// open tetrahedron (L146, m = 3).
pub fn random_fixed_solitary4(rng: &mut ChaCha8Rng) -> Vec<[Q; 4]> {
    let mut control = fixed_control4(4);
    if let Some(k) = multi_indices4(4).iter().position(|i| *i == [1, 1, 1, 1]) {
        control[k] = open_face_point4(rng, [true; 4]);
    }
    control
}
