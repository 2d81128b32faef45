//! The exact 1-D backend's data: p-domains and gluing domains are finite unions of open
//! intervals with rational endpoints, and each transition function φ_ji is piecewise affine,
//! x ↦ a·x + b on each listed piece of Ω_ij (one piece is the common case; several pieces let a
//! circle be glued from two intervals).

use super::interval::{fmt_q, Interval, OpenSet, Q};
use crate::gluing::data::Idx;
use num_traits::{One, Zero};
use std::collections::BTreeMap;

/// One affine piece of φ_ji: on the open interval `dom` ⊆ Ω_ij, φ_ji(x) = a·x + b.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Piece {
    /// The open interval of Ω_ij on which this piece applies.
    pub dom: Interval,
    /// Slope a (a ≠ 0 for the piece to be injective; not enforced here).
    pub a: Q,
    /// Offset b.
    pub b: Q,
}

impl Piece {
    /// φ_ji(x) = a·x + b (no check that x ∈ `dom`).
    pub fn eval(&self, x: &Q) -> Q {
        &self.a * x + &self.b
    }
    /// φ on the whole piece, as an open set (empty if a = 0 would collapse it).
    pub fn image(&self) -> OpenSet {
        if self.a.is_zero() {
            return OpenSet::empty();
        }
        OpenSet::from_interval(self.dom.clone()).affine_image(&self.a, &self.b)
    }
    /// The piece as text: `x ↦ a·x + b on (lo, hi)`.
    pub fn describe(&self) -> String {
        format!("x ↦ {} on {}", affine_str(&self.a, &self.b), self.dom)
    }
}

/// The pairs of K (Def. 3.4.1(3)) by first and by second index; see [`Exact1d::adjacency`].
#[derive(Clone, Debug, Default)]
pub struct Adjacency {
    out: BTreeMap<Idx, Vec<Idx>>,
    into: BTreeMap<Idx, Vec<Idx>>,
}

impl Adjacency {
    /// {j : (i, j) ∈ K}, increasing.
    pub fn outgoing(&self, i: Idx) -> &[Idx] {
        self.out.get(&i).map(|v| v.as_slice()).unwrap_or(&[])
    }
    /// {j : (j, i) ∈ K}, increasing.
    pub fn incoming(&self, i: Idx) -> &[Idx] {
        self.into.get(&i).map(|v| v.as_slice()).unwrap_or(&[])
    }
}

/// A set of gluing data in ℝ¹ (Def. 3.4.1) with exact rational data.
#[derive(Clone, Debug, Default)]
pub struct Exact1d {
    /// Ω_i for i ∈ I.
    pub domains: BTreeMap<Idx, OpenSet>,
    /// For (i, j): the pieces of φ_ji, whose domains make up Ω_ij. A missing diagonal entry
    /// (i, i) means the default Ω_ii = Ω_i, φ_ii = id (see [`Exact1d::with_default_diagonal`]).
    pub glue: BTreeMap<(Idx, Idx), Vec<Piece>>,
}

impl Exact1d {
    /// I.
    pub fn ids(&self) -> Vec<Idx> {
        self.domains.keys().copied().collect()
    }
    /// Ω_i; empty if i ∉ I.
    pub fn omega(&self, i: Idx) -> OpenSet {
        self.domains.get(&i).cloned().unwrap_or_default()
    }
    /// Ω_ij: the union of the piece domains of φ_ji.
    pub fn omega_ij(&self, i: Idx, j: Idx) -> OpenSet {
        OpenSet::from_intervals(self.pieces(i, j).iter().map(|p| p.dom.clone()))
    }
    /// The pieces of φ_ji : Ω_ij → Ω_ji (note the order: key (i, j), map φ_ji).
    pub fn pieces(&self, i: Idx, j: Idx) -> &[Piece] {
        self.glue.get(&(i, j)).map(|v| v.as_slice()).unwrap_or(&[])
    }
    /// K of Def. 3.4.1(3): the pairs (i, j) ∈ I × I with Ω_ij ≠ ∅, in lexicographic order.
    /// Read from the listed pieces (a pair without pieces has Ω_ij = ∅), so its cost is the
    /// number of listed pairs, not |I|².
    pub fn k(&self) -> Vec<(Idx, Idx)> {
        self.glue
            .iter()
            .filter(|((i, j), ps)| {
                !ps.is_empty() && self.domains.contains_key(i) && self.domains.contains_key(j)
            })
            .map(|(&ij, _)| ij)
            .filter(|&(i, j)| !self.omega_ij(i, j).is_empty())
            .collect()
    }
    /// The adjacency of K: `outgoing(i)` = {j : (i, j) ∈ K} and `incoming(i)` = {j : (j, i) ∈ K}, each
    /// increasing. The cocycle checks range over these instead of all of I³: a triple outside
    /// them has an empty domain, and |I|³ is too slow for a few hundred p-domains.
    pub fn adjacency(&self) -> Adjacency {
        let mut adj = Adjacency::default();
        for (i, j) in self.k() {
            adj.out.entry(i).or_default().push(j);
            adj.into.entry(j).or_default().push(i);
        }
        adj
    }
    /// x ∈ Ω_ij, without building Ω_ij (a point lies in a union of open intervals iff it lies
    /// in one of them).
    pub fn in_omega_ij(&self, i: Idx, j: Idx, x: &Q) -> bool {
        self.pieces(i, j).iter().any(|p| p.dom.contains(x))
    }
    /// φ_ji(x) for x ∈ Ω_ij (first piece containing x); `None` outside Ω_ij.
    pub fn phi(&self, j: Idx, i: Idx, x: &Q) -> Option<Q> {
        self.pieces(i, j)
            .iter()
            .find(|p| p.dom.contains(x))
            .map(|p| p.eval(x))
    }
    /// Add a p-domain piece.
    pub fn add_domain(&mut self, i: Idx, iv: Interval) {
        let d = self.domains.entry(i).or_default();
        *d = d.union(&OpenSet::from_interval(iv));
    }
    /// Add an empty p-domain (so that i ∈ I although Ω_i = ∅).
    pub fn add_empty_domain(&mut self, i: Idx) {
        self.domains.entry(i).or_default();
    }
    /// Add a piece of φ_ji on `dom` ⊆ Ω_ij.
    pub fn add_piece(&mut self, i: Idx, j: Idx, dom: Interval, a: Q, b: Q) {
        self.glue
            .entry((i, j))
            .or_default()
            .push(Piece { dom, a, b });
    }
    /// Fill every missing diagonal entry with Ω_ii = Ω_i, φ_ii = id.
    pub fn with_default_diagonal(mut self) -> Self {
        for (i, d) in self.domains.clone() {
            self.glue.entry((i, i)).or_insert_with(|| {
                d.parts()
                    .iter()
                    .map(|iv| Piece {
                        dom: iv.clone(),
                        a: Q::one(),
                        b: Q::zero(),
                    })
                    .collect()
            });
        }
        self
    }
    /// Bounding box of all p-domains (for grids and scales).
    pub fn hull(&self) -> Option<(Q, Q)> {
        let mut lo: Option<Q> = None;
        let mut hi: Option<Q> = None;
        for d in self.domains.values() {
            for p in d.parts() {
                lo = Some(lo.map_or(p.lo.clone(), |l| l.min(p.lo.clone())));
                hi = Some(hi.map_or(p.hi.clone(), |h| h.max(p.hi.clone())));
            }
        }
        Some((lo?, hi?))
    }
}

/// Convenience constructor: integer-or-fraction rational from i64 numerator/denominator.
pub fn q(n: i64, d: i64) -> Q {
    Q::new(n.into(), d.into())
}

/// Interval with integer endpoints, unchecked (for literal data; callers keep lo < hi).
pub fn iv(lo: i64, hi: i64) -> Interval {
    Interval {
        lo: q(lo, 1),
        hi: q(hi, 1),
    }
}

/// "x + 4", "-x - 1/2", "2·x": an affine map a·x + b written as a reader would.
pub fn affine_str(a: &Q, b: &Q) -> String {
    let lin = if a.is_one() {
        "x".to_string()
    } else if (-a).is_one() {
        "-x".to_string()
    } else {
        format!("{}·x", fmt_q(a))
    };
    if b.is_zero() {
        lin
    } else if *b < Q::zero() {
        format!("{lin} - {}", fmt_q(&-b))
    } else {
        format!("{lin} + {}", fmt_q(b))
    }
}
