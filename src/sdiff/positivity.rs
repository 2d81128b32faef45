//! Deciding p > 0 (or p ≥ 0) on the closed reference triangle exactly: Bernstein coefficients
//! over ℚ, subdivided until a certificate or a counterexample.
//!
//! * every Bernstein coefficient > 0 on a piece ⇒ p > 0 on that closed piece (convex-hull
//!   property of the Bernstein basis);
//! * a corner coefficient is the value at that corner, so a corner coefficient ≤ 0 (< 0 for
//!   the non-strict question) is an exact counterexample;
//! * otherwise the piece is split into four by its edge midpoints, up to a depth and a piece
//!   budget (bounded time): then the answer is *unresolved*, never a guess.

use super::poly::{qr, to_f64, Poly2, Q};
use num_traits::{Signed, Zero};

/// Strict (p > 0) or non-strict (p ≥ 0).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Strictness {
    /// p > 0 on the closed triangle.
    Positive,
    /// p ≥ 0 on the closed triangle.
    NonNegative,
}

/// The answer of [`decide`].
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[serde(rename_all = "snake_case", tag = "kind")]
pub enum Decision {
    /// Certified: every piece has all Bernstein coefficients > 0 (≥ 0).
    Certified {
        /// Pieces of the final cover.
        pieces: usize,
        /// Deepest subdivision used.
        depth: u32,
        /// Smallest Bernstein coefficient over the cover (a lower bound of p), as f64.
        lower_bound: f64,
    },
    /// Refuted: p(point) ≤ 0 (< 0), decided exactly.
    Refuted {
        /// The counterexample in barycentric coordinates (w_0, w_1, w_2), as exact strings.
        point: [String; 3],
        /// The same point in f64.
        point_f64: [f64; 3],
        /// p at the point, exact.
        value: String,
        /// p at the point, as f64.
        value_f64: f64,
    },
    /// Neither within the depth and piece budget.
    Unresolved {
        /// Pieces examined.
        pieces: usize,
        /// Depth reached.
        depth: u32,
    },
}

impl Decision {
    /// Certified.
    pub fn certified(&self) -> bool {
        matches!(self, Decision::Certified { .. })
    }
    /// Refuted.
    pub fn refuted(&self) -> bool {
        matches!(self, Decision::Refuted { .. })
    }
}

/// Budget of [`decide`].
#[derive(Debug, Clone, Copy)]
pub struct Budget {
    /// Maximal subdivision depth.
    pub max_depth: u32,
    /// Maximal number of pieces examined.
    pub max_pieces: usize,
}

impl Default for Budget {
    fn default() -> Self {
        Budget {
            max_depth: 10,
            max_pieces: 20_000,
        }
    }
}

type Tri = [[Q; 2]; 3];

/// Decide p > 0 (or p ≥ 0) on the closed reference triangle.
pub fn decide(p: &Poly2, strict: Strictness, budget: Budget) -> Decision {
    decide_on(p, reference_triangle(), strict, budget)
}

/// The reference triangle in the chart (s, t).
pub fn reference_triangle() -> Tri {
    [
        [qr(0, 1), qr(0, 1)],
        [qr(1, 1), qr(0, 1)],
        [qr(0, 1), qr(1, 1)],
    ]
}

/// Decide on the triangle `tri` of the chart (s, t).
pub fn decide_on(p: &Poly2, tri: Tri, strict: Strictness, budget: Budget) -> Decision {
    let n = p.deg();
    let bad = |v: &Q| match strict {
        Strictness::Positive => !v.is_positive(),
        Strictness::NonNegative => v.is_negative(),
    };
    let mut stack: Vec<(Tri, u32)> = vec![(tri, 0)];
    let mut pieces = 0usize;
    let mut deepest = 0u32;
    let mut lower: Option<Q> = None;
    while let Some((t, depth)) = stack.pop() {
        pieces += 1;
        deepest = deepest.max(depth);
        let coeffs = p.compose_affine(&t).bernstein(n);
        // Corners of the piece: indices (n,0,0), (0,n,0), (0,0,n) hold p at t[0], t[1], t[2].
        let corners = [
            (super::poly::index_of(n, [n, 0, 0]), 0usize),
            (super::poly::index_of(n, [0, n, 0]), 1),
            (super::poly::index_of(n, [0, 0, n]), 2),
        ];
        for (idx, c) in corners {
            if bad(&coeffs[idx]) {
                let (s, tt) = (t[c][0].clone(), t[c][1].clone());
                let w0 = Q::from_integer(1.into()) - &s - &tt;
                let pt = [w0, s, tt];
                return Decision::Refuted {
                    point_f64: [to_f64(&pt[0]), to_f64(&pt[1]), to_f64(&pt[2])],
                    point: pt.map(|x| x.to_string()),
                    value_f64: to_f64(&coeffs[idx]),
                    value: coeffs[idx].to_string(),
                };
            }
        }
        if coeffs.iter().all(|c| !bad(c)) {
            let m = coeffs.iter().min().cloned().unwrap_or_else(Q::zero);
            lower = Some(match lower {
                Some(l) if l < m => l,
                _ => m,
            });
            continue;
        }
        if depth >= budget.max_depth || pieces >= budget.max_pieces {
            return Decision::Unresolved {
                pieces,
                depth: deepest,
            };
        }
        let mid = |a: &[Q; 2], b: &[Q; 2]| -> [Q; 2] {
            let h = qr(1, 2);
            [(&a[0] + &b[0]) * &h, (&a[1] + &b[1]) * &h]
        };
        let (m01, m12, m20) = (mid(&t[0], &t[1]), mid(&t[1], &t[2]), mid(&t[2], &t[0]));
        stack.push(([t[0].clone(), m01.clone(), m20.clone()], depth + 1));
        stack.push(([m01.clone(), t[1].clone(), m12.clone()], depth + 1));
        stack.push(([m20.clone(), m12.clone(), t[2].clone()], depth + 1));
        stack.push(([m12, m20, m01], depth + 1));
    }
    Decision::Certified {
        pieces,
        depth: deepest,
        lower_bound: lower.as_ref().map(to_f64).unwrap_or(f64::NAN),
    }
}
