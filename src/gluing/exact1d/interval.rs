//! Open subsets of ℝ that are finite unions of open intervals with rational endpoints — the sets
//! of the exact 1-D backend. Openness (Def. 3.2.1's "usual" topology) holds by construction:
//! only open intervals can be represented, so every operation below returns an open set.

use num_traits::{One, Zero};
use std::fmt;

pub use crate::numeric::Q;

/// Parse "p", "p/q", "-p/q" or a finite decimal "1.25" into an exact rational.
pub(crate) fn parse_q(s: &str) -> Option<Q> {
    let s = s.trim();
    if let Some((int, frac)) = s.split_once('.') {
        if frac.is_empty() || !frac.bytes().all(|c| c.is_ascii_digit()) {
            return None;
        }
        let neg = int.starts_with('-');
        let int_part: num_bigint::BigInt = if int == "-" || int.is_empty() {
            num_bigint::BigInt::zero()
        } else {
            int.parse().ok()?
        };
        let frac_num: num_bigint::BigInt = frac.parse().ok()?;
        let den = num_bigint::BigInt::from(10u32).pow(frac.len() as u32);
        let f = Q::new(frac_num, den);
        let i = Q::from_integer(int_part);
        return Some(if neg { i - f } else { i + f });
    }
    let r: Q = s.parse().ok()?;
    Some(r)
}

/// Render a rational compactly ("3", "-1/2").
pub(crate) fn fmt_q(q: &Q) -> String {
    if q.is_integer() {
        q.numer().to_string()
    } else {
        format!("{}/{}", q.numer(), q.denom())
    }
}

/// Lossy conversion for display of deviations.
pub(crate) fn q_to_f64(q: &Q) -> f64 {
    use num_traits::ToPrimitive;
    q.to_f64().unwrap_or(f64::NAN)
}

/// a < b by cross-multiplication (denominators are positive once normalised). Same answer as
/// `Ord`, which num-rational computes by a continued-fraction expansion with a big-integer
/// division per step; membership tests are the inner loop of the gluing checks.
pub(crate) fn q_lt(a: &Q, b: &Q) -> bool {
    if a.denom() == b.denom() {
        a.numer() < b.numer()
    } else {
        a.numer() * b.denom() < b.numer() * a.denom()
    }
}

/// Midpoint of two rationals.
pub fn mid(a: &Q, b: &Q) -> Q {
    (a + b) / Q::from_integer(2.into())
}

/// A non-empty open interval (lo, hi), lo < hi.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub struct Interval {
    /// Left endpoint (excluded).
    pub lo: Q,
    /// Right endpoint (excluded).
    pub hi: Q,
}

impl Interval {
    /// `None` when lo ≥ hi (the empty interval).
    pub fn new(lo: Q, hi: Q) -> Option<Interval> {
        q_lt(&lo, &hi).then_some(Interval { lo, hi })
    }
    /// The open interval between u and w, in either order; `None` when u = w.
    pub fn between(u: Q, w: Q) -> Option<Interval> {
        if q_lt(&u, &w) {
            Interval::new(u, w)
        } else {
            Interval::new(w, u)
        }
    }
    /// lo < x < hi.
    pub fn contains(&self, x: &Q) -> bool {
        q_lt(&self.lo, x) && q_lt(x, &self.hi)
    }
    /// (lo + hi) / 2.
    pub fn midpoint(&self) -> Q {
        mid(&self.lo, &self.hi)
    }
    /// The intersection, `None` if empty.
    pub fn intersect(&self, o: &Interval) -> Option<Interval> {
        Interval::new(
            self.lo.clone().max(o.lo.clone()),
            self.hi.clone().min(o.hi.clone()),
        )
    }
    /// x lies in the closure [lo, hi].
    pub fn closure_contains(&self, x: &Q) -> bool {
        !q_lt(x, &self.lo) && !q_lt(&self.hi, x)
    }
}

impl fmt::Display for Interval {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "({}, {})", fmt_q(&self.lo), fmt_q(&self.hi))
    }
}

/// A finite union of open intervals, kept sorted with pairwise disjoint members. Intervals that
/// touch at a point, like (0,1) and (1,2), stay separate: the shared endpoint is not in the set.
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub struct OpenSet {
    parts: Vec<Interval>,
}

impl OpenSet {
    /// The empty set.
    pub fn empty() -> OpenSet {
        OpenSet { parts: Vec::new() }
    }
    /// The set consisting of one interval.
    pub fn from_interval(iv: Interval) -> OpenSet {
        OpenSet { parts: vec![iv] }
    }
    /// Union of arbitrary (possibly overlapping) intervals, normalised.
    pub fn from_intervals(ivs: impl IntoIterator<Item = Interval>) -> OpenSet {
        let mut v: Vec<Interval> = ivs.into_iter().collect();
        v.sort();
        let mut parts: Vec<Interval> = Vec::new();
        for iv in v {
            match parts.last_mut() {
                // Overlapping (not merely touching) intervals merge.
                Some(last) if iv.lo < last.hi => {
                    if iv.hi > last.hi {
                        last.hi = iv.hi;
                    }
                }
                _ => parts.push(iv),
            }
        }
        OpenSet { parts }
    }
    /// The disjoint intervals, sorted.
    pub fn parts(&self) -> &[Interval] {
        &self.parts
    }
    /// True when the set has no interval.
    pub fn is_empty(&self) -> bool {
        self.parts.is_empty()
    }
    /// x lies in some interval of the set.
    pub fn contains(&self, x: &Q) -> bool {
        self.parts.iter().any(|p| p.contains(x))
    }
    /// The intersection, normalised.
    pub fn intersect(&self, o: &OpenSet) -> OpenSet {
        let mut v = Vec::new();
        for a in &self.parts {
            for b in &o.parts {
                if let Some(c) = a.intersect(b) {
                    v.push(c);
                }
            }
        }
        OpenSet::from_intervals(v)
    }
    /// The union, normalised (touching intervals stay separate).
    pub fn union(&self, o: &OpenSet) -> OpenSet {
        OpenSet::from_intervals(self.parts.iter().chain(o.parts.iter()).cloned())
    }
    /// The open set self ∖ closure(o) together with the finitely many points of self ∩ ∂o:
    /// returned as (open part, isolated points) so that self ∖ o is their union exactly.
    pub fn minus(&self, o: &OpenSet) -> (OpenSet, Vec<Q>) {
        // Cut self at every endpoint of o and keep the cells not inside o.
        let mut open = Vec::new();
        let mut points = Vec::new();
        for a in &self.parts {
            let mut cuts: Vec<Q> = o.boundary().into_iter().filter(|c| a.contains(c)).collect();
            cuts.sort();
            cuts.dedup();
            let mut lo = a.lo.clone();
            for c in &cuts {
                if !o.contains(c) {
                    points.push(c.clone());
                }
                if let Some(cell) = Interval::new(lo.clone(), c.clone()) {
                    if !o.contains(&cell.midpoint()) {
                        open.push(cell);
                    }
                }
                lo = c.clone();
            }
            if let Some(cell) = Interval::new(lo, a.hi.clone()) {
                if !o.contains(&cell.midpoint()) {
                    open.push(cell);
                }
            }
        }
        (OpenSet::from_intervals(open), points)
    }
    /// self ⊆ o, decided exactly; on failure returns a rational witness of self ∖ o.
    pub fn subset_witness(&self, o: &OpenSet) -> Option<Q> {
        let (open, points) = self.minus(o);
        if let Some(p) = open.parts.first() {
            return Some(p.midpoint());
        }
        points.into_iter().next()
    }
    /// ∂(self): all endpoints that are not interior points (a touching point such as 1 in
    /// (0,1) ∪ (1,2) is a boundary point).
    pub fn boundary(&self) -> Vec<Q> {
        let mut v: Vec<Q> = Vec::new();
        for p in &self.parts {
            v.push(p.lo.clone());
            v.push(p.hi.clone());
        }
        v.sort();
        v.dedup();
        v
    }
    /// Image under x ↦ a·x + b (a ≠ 0).
    pub fn affine_image(&self, a: &Q, b: &Q) -> OpenSet {
        OpenSet::from_intervals(
            self.parts
                .iter()
                .filter_map(|p| Interval::between(a * &p.lo + b, a * &p.hi + b)),
        )
    }
    /// Preimage under x ↦ a·x + b (a ≠ 0): the image under the inverse map.
    pub fn affine_preimage(&self, a: &Q, b: &Q) -> OpenSet {
        let ainv = Q::one() / a;
        let binv = -(b * &ainv);
        self.affine_image(&ainv, &binv)
    }
}

impl fmt::Display for OpenSet {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.parts.is_empty() {
            return write!(f, "∅");
        }
        let s: Vec<String> = self.parts.iter().map(|p| p.to_string()).collect();
        write!(f, "{}", s.join(" ∪ "))
    }
}
