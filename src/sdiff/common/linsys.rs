//! Exact homogeneous linear systems over ℚ (Mello–Velho L217–L219: the C¹ conditions (12) are
//! linear and homogeneous in the weights q_I): reduced row echelon form by Gaussian
//! elimination, and the search for a solution with every unknown ≥ 1 (equivalently > 0, the
//! system being homogeneous) by Fourier–Motzkin elimination over the free unknowns.
//!
//! Fourier–Motzkin is exact and complete: it either derives 0 ≥ r > 0 (no positive solution,
//! a proof) or ends with a consistent system and back-substitutes a solution. The number of
//! inequalities can grow quadratically per step, so it runs under a budget; over budget the
//! answer is *undecided*, never a guess.

use crate::sdiff::common::rational::{q, Q};
use num_traits::{One, Signed, Zero};

/// A matrix in reduced row echelon form.
#[derive(Debug, Clone)]
pub struct Rref {
    /// The non-zero rows (each with a leading 1 in its pivot column).
    pub rows: Vec<Vec<Q>>,
    /// Pivot column of each row.
    pub pivots: Vec<usize>,
    /// Columns without a pivot.
    pub free: Vec<usize>,
    /// Number of columns.
    pub cols: usize,
}

/// Gaussian elimination with exact rationals.
pub fn rref(mut a: Vec<Vec<Q>>, cols: usize) -> Rref {
    let mut pivots = Vec::new();
    let mut r = 0;
    for c in 0..cols {
        let Some(p) = (r..a.len()).find(|&i| !a[i][c].is_zero()) else {
            continue;
        };
        a.swap(r, p);
        let inv = Q::one() / &a[r][c];
        for x in a[r].iter_mut() {
            *x *= &inv;
        }
        let pivot_row = a[r].clone();
        for (i, row) in a.iter_mut().enumerate() {
            if i != r && !row[c].is_zero() {
                let k = row[c].clone();
                for (x, p) in row.iter_mut().zip(&pivot_row) {
                    *x -= &k * p;
                }
            }
        }
        pivots.push(c);
        r += 1;
        if r == a.len() {
            break;
        }
    }
    a.truncate(r);
    let free = (0..cols).filter(|c| !pivots.contains(c)).collect();
    Rref {
        rows: a,
        pivots,
        free,
        cols,
    }
}

impl Rref {
    /// Rank.
    pub fn rank(&self) -> usize {
        self.pivots.len()
    }
    /// The solution with the free unknowns set to `t` (in the order of `free`).
    pub fn solution(&self, t: &[Q]) -> Vec<Q> {
        let mut x = vec![Q::zero(); self.cols];
        for (j, &c) in self.free.iter().enumerate() {
            x[c] = t[j].clone();
        }
        for (row, &p) in self.rows.iter().zip(&self.pivots) {
            let mut v = Q::zero();
            for (j, &c) in self.free.iter().enumerate() {
                v -= &row[c] * &t[j];
            }
            x[p] = v;
        }
        x
    }
}

/// How a positive solution was found, or why none is reported.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[serde(rename_all = "snake_case", tag = "kind")]
pub enum Positive {
    /// Every free unknown = 1 already gives all unknowns ≥ 1.
    FreeOnes,
    /// Fourier–Motzkin found a solution with all unknowns ≥ 1.
    FourierMotzkin {
        /// Largest inequality set met.
        peak: usize,
    },
    /// Fourier–Motzkin derived 0 ≥ r with r > 0: no solution has every unknown > 0.
    Infeasible {
        /// Largest inequality set met.
        peak: usize,
    },
    /// Over the inequality budget: neither found nor excluded.
    Undecided {
        /// Inequalities when the budget ran out.
        inequalities: usize,
    },
}

/// An inequality Σ a_j t_j ≥ b.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
struct Ineq {
    a: Vec<Q>,
    b: Q,
}

impl Ineq {
    /// Scaled so the first non-zero |a_j| is 1 (for de-duplication).
    fn normalised(mut self) -> Ineq {
        if let Some(k) = self.a.iter().find(|x| !x.is_zero()).map(|x| x.abs()) {
            for x in self.a.iter_mut() {
                *x /= &k;
            }
            self.b /= &k;
        }
        self
    }
}

/// A solution of the system with every unknown ≥ 1, if one exists (decided within
/// `max_inequalities`): first all free unknowns = 1, then Fourier–Motzkin.
pub fn positive_solution(r: &Rref, max_inequalities: usize) -> (Positive, Option<Vec<Q>>) {
    let nf = r.free.len();
    let ones = vec![q(1); nf];
    let x = r.solution(&ones);
    if x.iter().all(|v| *v >= q(1)) {
        return (Positive::FreeOnes, Some(x));
    }
    // x = M t with t the free unknowns; require every x_i ≥ 1.
    let mut ineqs: Vec<Ineq> = Vec::new();
    for (j, _) in r.free.iter().enumerate() {
        let mut a = vec![Q::zero(); nf];
        a[j] = q(1);
        ineqs.push(Ineq { a, b: q(1) });
    }
    for row in &r.rows {
        let a: Vec<Q> = r.free.iter().map(|&c| -row[c].clone()).collect();
        ineqs.push(Ineq { a, b: q(1) });
    }
    // A pivot unknown with no free unknown in its row is forced to 0: 0 ≥ 1.
    if ineqs
        .iter()
        .any(|e| e.a.iter().all(|x| x.is_zero()) && e.b.is_positive())
    {
        return (Positive::Infeasible { peak: ineqs.len() }, None);
    }
    let mut stages: Vec<Vec<Ineq>> = Vec::new();
    let mut peak = ineqs.len();
    for k in (0..nf).rev() {
        let (mut lo, mut hi, mut rest) = (Vec::new(), Vec::new(), Vec::new());
        for e in &ineqs {
            if e.a[k].is_positive() {
                lo.push(e);
            } else if e.a[k].is_negative() {
                hi.push(e);
            } else {
                rest.push(e.clone());
            }
        }
        let mut next: std::collections::HashSet<Ineq> = rest.into_iter().collect();
        for l in &lo {
            for h in &hi {
                // (−h_k)·l + l_k·h eliminates t_k.
                let (cl, ch) = (-h.a[k].clone(), l.a[k].clone());
                let a: Vec<Q> = (0..nf).map(|j| &cl * &l.a[j] + &ch * &h.a[j]).collect();
                let b = &cl * &l.b + &ch * &h.b;
                let e = Ineq { a, b }.normalised();
                if e.a.iter().all(|x| x.is_zero()) {
                    if e.b.is_positive() {
                        return (Positive::Infeasible { peak }, None);
                    }
                    continue;
                }
                next.insert(e);
                if next.len() > max_inequalities {
                    return (
                        Positive::Undecided {
                            inequalities: next.len(),
                        },
                        None,
                    );
                }
            }
        }
        stages.push(ineqs);
        ineqs = next.into_iter().collect();
        peak = peak.max(ineqs.len());
    }
    // Back-substitution: stage s (from the end) constrains t_0..t_{nf-1-s}.
    let mut t = vec![Q::zero(); nf];
    for (k, stage) in stages.iter().rev().enumerate() {
        // `stage` is the set before t_k was eliminated: variables t_0..=t_k.
        let mut lower: Option<Q> = None;
        let mut upper: Option<Q> = None;
        for e in stage {
            let rest: Q = (0..k).map(|j| &e.a[j] * &t[j]).sum();
            let (ak, rhs) = (&e.a[k], &e.b - rest);
            if ak.is_positive() {
                let v = rhs / ak;
                lower = Some(lower.map_or(v.clone(), |l| if v > l { v } else { l }));
            } else if ak.is_negative() {
                let v = rhs / ak;
                upper = Some(upper.map_or(v.clone(), |u| if v < u { v } else { u }));
            }
        }
        t[k] = lower.or(upper).unwrap_or_else(|| q(1));
    }
    let x = r.solution(&t);
    if x.iter().all(|v| *v >= q(1)) {
        (Positive::FourierMotzkin { peak }, Some(x))
    } else {
        // Cannot happen when the elimination is right; reported, not hidden.
        (Positive::Undecided { inequalities: peak }, None)
    }
}
