//! Deciding p > 0 (or p ≥ 0) on the closed reference triangle exactly: Bernstein coefficients
//! over ℚ, subdivided until a certificate or a counterexample.
//!
//! * every Bernstein coefficient > 0 on a piece ⇒ p > 0 on that closed piece (convex-hull
//!   property of the Bernstein basis);
//! * a corner coefficient is the value at that corner, so a corner coefficient ≤ 0 (< 0 for
//!   the non-strict question) is an exact counterexample;
//! * otherwise the piece is split into four by its edge midpoints, up to a depth and a piece
//!   budget (bounded time): a piece past it is left open and the other pieces are still
//!   examined ([`Cover`]), so a counterexample anywhere wins; with a piece left open the answer
//!   is *unresolved*, never a guess.

use super::poly2::Poly2;
use super::rational::{qr, to_f64, Q};
use num_traits::Signed;

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

/// The bookkeeping shared by the branch-and-bound deciders ([`decide_on`],
/// `tet::decide_tet_with`, `simplex_poly::decide`). A piece neither certified nor refuted that
/// is past the depth budget, or met once the piece budget is spent, is left *open* and the
/// other pieces are still examined: a counterexample at a corner of any examined piece wins
/// over "unresolved", and an open piece never counts as certified. Nothing is split once the
/// piece budget is spent, so at most `max_pieces` plus the pending stack (≤ (k − 1)·depth + 1
/// for k children per split) pieces are examined.
#[derive(Debug, Clone)]
pub(crate) struct Cover {
    /// Pieces examined.
    pub pieces: usize,
    /// Deepest piece examined.
    pub deepest: u32,
    /// Pieces left open (past a budget).
    pub open: usize,
    lower: Option<Q>,
    max_depth: u32,
    max_pieces: usize,
}

impl Cover {
    /// A cover of no pieces yet; `max_depth` in the engine's units of subdivision.
    pub(crate) fn new(max_depth: u32, max_pieces: usize) -> Cover {
        Cover {
            pieces: 0,
            deepest: 0,
            open: 0,
            lower: None,
            max_depth,
            max_pieces,
        }
    }
    /// Count a piece taken at `depth`.
    pub(crate) fn visit(&mut self, depth: u32) {
        self.pieces += 1;
        self.deepest = self.deepest.max(depth);
    }
    /// A certified piece: its coefficients bound p from below.
    pub(crate) fn certify(&mut self, coeffs: &[Q]) {
        if let Some(m) = coeffs.iter().min() {
            if self.lower.as_ref().map_or(true, |l| m < l) {
                self.lower = Some(m.clone());
            }
        }
    }
    /// Whether an undecided piece at `depth` may be split; if not it is left open.
    pub(crate) fn split(&mut self, depth: u32) -> bool {
        if depth >= self.max_depth || self.pieces >= self.max_pieces {
            self.open += 1;
            false
        } else {
            true
        }
    }
    /// After the last piece (no counterexample found): certified iff no piece was left open.
    pub(crate) fn finish(&self) -> Decision {
        if self.open > 0 {
            Decision::Unresolved {
                pieces: self.pieces,
                depth: self.deepest,
            }
        } else {
            Decision::Certified {
                pieces: self.pieces,
                depth: self.deepest,
                lower_bound: self.lower.as_ref().map(to_f64).unwrap_or(f64::NAN),
            }
        }
    }
}

/// Decide p > 0 (or p ≥ 0) on the closed reference triangle.
pub fn decide(p: &Poly2, strict: Strictness, budget: Budget) -> Decision {
    decide_on(p, reference_triangle(), strict, budget)
}

/// The reference triangle in the chart (s, t).
pub(crate) fn reference_triangle() -> Tri {
    [
        [qr(0, 1), qr(0, 1)],
        [qr(1, 1), qr(0, 1)],
        [qr(0, 1), qr(1, 1)],
    ]
}

/// Decide on the triangle `tri` of the chart (s, t).
pub(crate) fn decide_on(p: &Poly2, tri: Tri, strict: Strictness, budget: Budget) -> Decision {
    let n = p.deg();
    let bad = |v: &Q| match strict {
        Strictness::Positive => !v.is_positive(),
        Strictness::NonNegative => v.is_negative(),
    };
    let mut stack: Vec<(Tri, u32)> = vec![(tri, 0)];
    let mut cover = Cover::new(budget.max_depth, budget.max_pieces);
    while let Some((t, depth)) = stack.pop() {
        cover.visit(depth);
        let coeffs = p.compose_affine(&t).bernstein(n);
        // Corners of the piece: indices (n,0,0), (0,n,0), (0,0,n) hold p at t[0], t[1], t[2].
        let corners = [
            (super::poly2::index_of(n, [n, 0, 0]), 0usize),
            (super::poly2::index_of(n, [0, n, 0]), 1),
            (super::poly2::index_of(n, [0, 0, n]), 2),
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
            cover.certify(&coeffs);
            continue;
        }
        if !cover.split(depth) {
            continue;
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
    cover.finish()
}
