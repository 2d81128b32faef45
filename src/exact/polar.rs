//! Polar-affine maps with the exact branch-cut (wrap) analysis of Π (Def. 4.1.5).
//!
//! A point is followed through its polar angle written as a rational multiple of π,
//! `angle/π = a + b·t`, where `t = θ/π` is the angle of the *input* point and a, b ∈ Q.
//! * a rotation M_{qπ} adds q (Def. 4.1.8: R_(u,w) = M_{−2πi/m_u});
//! * g_v = Π⁻¹∘f_v∘Π (Def. 4.1.6) first applies Π, which wraps the angle into (−π, π], i.e.
//!   replaces a + b·t by a + 2k + b·t with the unique integer k making it lie in (−1, 1] —
//!   this splits the t-domain into pieces, one per k — and then multiplies by m_v/6;
//! * g_v⁻¹ (the stated inverse Π⁻¹∘f_v⁻¹∘Π) wraps and multiplies by 6/m_v;
//! * Π⁻¹ at the end needs no wrap: two chains give the same point iff their angles agree mod 2
//!   and their radial factors agree.
//!
//! The radial part of every map here is a constant factor (cos(π/6)/cos(π/m_v))^{±1}, kept
//! symbolically as an exponent per degree (the factor for m_v = 6 is 1 and is dropped).
//! Everything is exact: domains are unions of rational intervals of t with open/closed ends.

use super::q3::{is_integer, q, Q};
use num_traits::{Signed, Zero};
use std::collections::BTreeMap;
use std::fmt;

/// An interval of t = θ/π with rational ends, each open or closed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Interval {
    /// Lower end.
    pub lo: Q,
    /// Whether `lo` belongs to the interval.
    pub lo_closed: bool,
    /// Upper end.
    pub hi: Q,
    /// Whether `hi` belongs to the interval.
    pub hi_closed: bool,
}

impl Interval {
    /// (lo, hi).
    pub fn open(lo: Q, hi: Q) -> Self {
        Interval {
            lo,
            lo_closed: false,
            hi,
            hi_closed: false,
        }
    }
    /// (lo, hi].
    pub fn open_closed(lo: Q, hi: Q) -> Self {
        Interval {
            lo,
            lo_closed: false,
            hi,
            hi_closed: true,
        }
    }
    /// [lo, hi).
    pub fn closed_open(lo: Q, hi: Q) -> Self {
        Interval {
            lo,
            lo_closed: true,
            hi,
            hi_closed: false,
        }
    }
    /// [lo, hi].
    pub fn closed(lo: Q, hi: Q) -> Self {
        Interval {
            lo,
            lo_closed: true,
            hi,
            hi_closed: true,
        }
    }
    /// The range (−π, π] of Π, i.e. t ∈ (−1, 1].
    pub fn pi_range() -> Self {
        Interval::open_closed(q(-1, 1), q(1, 1))
    }
    /// Whether empty.
    pub fn is_empty(&self) -> bool {
        self.lo > self.hi || (self.lo == self.hi && !(self.lo_closed && self.hi_closed))
    }
    /// Intersection.
    pub fn intersect(&self, o: &Interval) -> Interval {
        let (lo, lo_closed) = if self.lo > o.lo {
            (self.lo.clone(), self.lo_closed)
        } else if self.lo < o.lo {
            (o.lo.clone(), o.lo_closed)
        } else {
            (self.lo.clone(), self.lo_closed && o.lo_closed)
        };
        let (hi, hi_closed) = if self.hi < o.hi {
            (self.hi.clone(), self.hi_closed)
        } else if self.hi > o.hi {
            (o.hi.clone(), o.hi_closed)
        } else {
            (self.hi.clone(), self.hi_closed && o.hi_closed)
        };
        Interval {
            lo,
            lo_closed,
            hi,
            hi_closed,
        }
    }
    /// self − o as up to two intervals.
    pub fn minus(&self, o: &Interval) -> Vec<Interval> {
        if o.is_empty() {
            return vec![self.clone()];
        }
        let left = self.intersect(&Interval {
            lo: self.lo.clone(),
            lo_closed: self.lo_closed,
            hi: o.lo.clone(),
            hi_closed: !o.lo_closed,
        });
        let right = self.intersect(&Interval {
            lo: o.hi.clone(),
            lo_closed: !o.hi_closed,
            hi: self.hi.clone(),
            hi_closed: self.hi_closed,
        });
        [left, right]
            .into_iter()
            .filter(|i| !i.is_empty())
            .collect()
    }
    /// {a + b·t : t ∈ self} (b ≠ 0), or the point {a} when b = 0.
    pub fn affine_image(&self, a: &Q, b: &Q) -> Interval {
        let l = a + b * &self.lo;
        let h = a + b * &self.hi;
        if b.is_negative() {
            Interval {
                lo: h,
                lo_closed: self.hi_closed,
                hi: l,
                hi_closed: self.lo_closed,
            }
        } else if b.is_zero() {
            Interval::closed(a.clone(), a.clone())
        } else {
            Interval {
                lo: l,
                lo_closed: self.lo_closed,
                hi: h,
                hi_closed: self.hi_closed,
            }
        }
    }
    /// {t ∈ self : a + b·t ∈ target}.
    pub fn preimage(&self, a: &Q, b: &Q, target: &Interval) -> Interval {
        if b.is_zero() {
            let inside = target.intersect(&Interval::closed(a.clone(), a.clone()));
            return if inside.is_empty() {
                Interval::open(q(0, 1), q(0, 1))
            } else {
                self.clone()
            };
        }
        let binv = q(1, 1) / b;
        let minus_a_over_b = -(a * &binv);
        self.intersect(&target.affine_image(&minus_a_over_b, &binv))
    }
    /// Translated by s.
    pub fn shift(&self, s: &Q) -> Interval {
        Interval {
            lo: &self.lo + s,
            lo_closed: self.lo_closed,
            hi: &self.hi + s,
            hi_closed: self.hi_closed,
        }
    }
}

impl fmt::Display for Interval {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.lo == self.hi {
            return write!(f, "{{{}}}", self.lo);
        }
        write!(
            f,
            "{}{}, {}{}",
            if self.lo_closed { "[" } else { "(" },
            self.lo,
            self.hi,
            if self.hi_closed { "]" } else { ")" }
        )
    }
}

/// A finite union of intervals, kept sorted, disjoint, non-empty and merged.
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub struct Region(pub Vec<Interval>);

impl Region {
    /// The empty region.
    pub fn empty() -> Self {
        Region(Vec::new())
    }
    /// A single interval.
    pub fn of(i: Interval) -> Self {
        Region::from_intervals(vec![i])
    }
    /// Normalised union of the given intervals.
    pub fn from_intervals(mut v: Vec<Interval>) -> Self {
        v.retain(|i| !i.is_empty());
        v.sort_by(|x, y| x.lo.cmp(&y.lo).then(y.lo_closed.cmp(&x.lo_closed)));
        let mut out: Vec<Interval> = Vec::new();
        for i in v {
            if let Some(last) = out.last_mut() {
                let touches =
                    i.lo < last.hi || (i.lo == last.hi && (last.hi_closed || i.lo_closed));
                if touches {
                    if i.hi > last.hi || (i.hi == last.hi && i.hi_closed) {
                        // Decided before `last.hi` moves: [0, 1] ∪ [1/2, 2) is [0, 2).
                        let closed = i.hi_closed || (i.hi == last.hi && last.hi_closed);
                        last.hi = i.hi.clone();
                        last.hi_closed = closed;
                    }
                    continue;
                }
            }
            out.push(i);
        }
        Region(out)
    }
    /// Whether empty.
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }
    /// Union.
    pub fn union(&self, o: &Region) -> Region {
        Region::from_intervals(self.0.iter().chain(o.0.iter()).cloned().collect())
    }
    /// Intersection.
    pub fn intersect(&self, o: &Region) -> Region {
        let mut v = Vec::new();
        for a in &self.0 {
            for b in &o.0 {
                v.push(a.intersect(b));
            }
        }
        Region::from_intervals(v)
    }
    /// Difference self − o.
    pub fn minus(&self, o: &Region) -> Region {
        let mut cur: Vec<Interval> = self.0.clone();
        for b in &o.0 {
            cur = cur.iter().flat_map(|a| a.minus(b)).collect();
        }
        Region::from_intervals(cur)
    }
    /// Whether self ⊆ o.
    pub fn subset_of(&self, o: &Region) -> bool {
        self.minus(o).is_empty()
    }
    /// Reduce mod 2 into (−1, 1] (angles of points).
    pub fn mod2(&self) -> Region {
        let mut v = Vec::new();
        for i in &self.0 {
            for k in shift_range(&i.lo, &i.hi) {
                v.push(i.shift(&q(2 * k, 1)).intersect(&Interval::pi_range()));
            }
        }
        Region::from_intervals(v)
    }
}

impl fmt::Display for Region {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.0.is_empty() {
            return write!(f, "∅");
        }
        let parts: Vec<String> = self.0.iter().map(|i| i.to_string()).collect();
        write!(f, "{}", parts.join(" ∪ "))
    }
}

fn floor_i64(x: Q) -> i64 {
    x.floor().to_integer().try_into().unwrap_or(0)
}

/// The integers k with [lo, hi] + 2k meeting (−1, 1]: lo + 2k ≤ 1 and hi + 2k > −1, i.e.
/// ⌊(−1 − hi)/2⌋ < k ≤ ⌊(1 − lo)/2⌋ (exactly; open or closed ends of [lo, hi] only decide
/// whether an extreme k gives an empty piece, which the callers drop).
fn shift_range(lo: &Q, hi: &Q) -> std::ops::RangeInclusive<i64> {
    let kmin = floor_i64((q(-1, 1) - hi) / q(2, 1)) + 1;
    let kmax = floor_i64((q(1, 1) - lo) / q(2, 1));
    kmin..=kmax
}

/// The integers k with `own` meeting `img` + 2k: 2k ∈ [own.lo − img.hi, own.hi − img.lo].
fn overlap_shifts(own: &Interval, img: &Interval) -> std::ops::RangeInclusive<i64> {
    let kmin = -floor_i64((&img.hi - &own.lo) / q(2, 1));
    let kmax = floor_i64((&own.hi - &img.lo) / q(2, 1));
    kmin..=kmax
}

/// A polar-affine map.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum PMap {
    /// Rotation about (0,0) by turn·π; `name` is how the paper writes it (R_(u,w), M_{−π/3}, …).
    Rot {
        /// Display name.
        name: String,
        /// Angle / π.
        turn: Q,
    },
    /// g_v for a vertex of degree m (Def. 4.1.6): Π, then θ ↦ m/6·θ.
    G {
        /// Display name (g_u, …).
        name: String,
        /// Degree m_v.
        m: u32,
    },
    /// g_v⁻¹ as stated in Def. 4.1.6: Π, then β ↦ 6/m·β.
    GInv {
        /// Display name.
        name: String,
        /// Degree m_v.
        m: u32,
    },
}

impl PMap {
    /// Rotation by turn·π.
    pub fn rot(name: &str, turn: Q) -> Self {
        PMap::Rot {
            name: name.to_string(),
            turn,
        }
    }
    /// g_v.
    pub fn g(name: &str, m: u32) -> Self {
        PMap::G {
            name: name.to_string(),
            m,
        }
    }
    /// g_v⁻¹.
    pub fn g_inv(name: &str, m: u32) -> Self {
        PMap::GInv {
            name: name.to_string(),
            m,
        }
    }
    /// Display name.
    pub fn name(&self) -> &str {
        match self {
            PMap::Rot { name, .. } | PMap::G { name, .. } | PMap::GInv { name, .. } => name,
        }
    }
    /// The same map with the rotation angle negated (used to plant a sign error).
    pub fn sign_flipped(&self) -> PMap {
        match self {
            PMap::Rot { name, turn } => PMap::Rot {
                name: name.clone(),
                turn: -turn,
            },
            other => other.clone(),
        }
    }
}

/// A composite f₁∘f₂∘…∘fₙ, stored in the paper's order (fₙ applied first).
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub struct Chain(pub Vec<PMap>);

impl fmt::Display for Chain {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.0.is_empty() {
            return write!(f, "id");
        }
        let n: Vec<&str> = self.0.iter().map(|m| m.name()).collect();
        write!(f, "{}", n.join("∘"))
    }
}

/// One piece of the evaluation of a chain: on `dom` (values of t) the output angle is
/// (a + b·t)·π and the radius is r·Π c_m^{e_m}; `wraps` lists the k chosen by each Π.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Piece {
    /// Sub-domain of t.
    pub dom: Interval,
    /// Constant term of angle/π.
    pub a: Q,
    /// Coefficient of t in angle/π.
    pub b: Q,
    /// Exponent of c_m = cos(π/6)/cos(π/m) per degree m ≠ 6.
    pub radial: BTreeMap<u32, i32>,
    /// The wrap 2k added by each Π, in application order.
    pub wraps: Vec<i64>,
}

fn apply_pi(p: &Piece) -> Vec<Piece> {
    let img = p.dom.affine_image(&p.a, &p.b);
    let mut out = Vec::new();
    for k in shift_range(&img.lo, &img.hi) {
        let shift = q(2 * k, 1);
        let target = Interval::pi_range().shift(&-&shift);
        let dom = p.dom.preimage(&p.a, &p.b, &target);
        if !dom.is_empty() {
            let mut wraps = p.wraps.clone();
            wraps.push(k);
            out.push(Piece {
                dom,
                a: &p.a + &shift,
                b: p.b.clone(),
                radial: p.radial.clone(),
                wraps,
            });
        }
    }
    out
}

fn scale(p: &mut Piece, f: &Q, m: u32, e: i32) {
    p.a = &p.a * f;
    p.b = &p.b * f;
    if m != 6 {
        let slot = p.radial.entry(m).or_insert(0);
        *slot += e;
        if *slot == 0 {
            p.radial.remove(&m);
        }
    }
}

impl Chain {
    /// Evaluate exactly on the t-region `dom`: the list of pieces.
    pub fn eval(&self, dom: &Region) -> Vec<Piece> {
        let mut pieces: Vec<Piece> = dom
            .0
            .iter()
            .map(|d| Piece {
                dom: d.clone(),
                a: q(0, 1),
                b: q(1, 1),
                radial: BTreeMap::new(),
                wraps: vec![],
            })
            .collect();
        for map in self.0.iter().rev() {
            pieces = match map {
                PMap::Rot { turn, .. } => pieces
                    .into_iter()
                    .map(|mut p| {
                        p.a = &p.a + turn;
                        p
                    })
                    .collect(),
                PMap::G { m, .. } => pieces
                    .iter()
                    .flat_map(apply_pi)
                    .map(|mut p| {
                        scale(&mut p, &q(i64::from(*m), 6), *m, 1);
                        p
                    })
                    .collect(),
                PMap::GInv { m, .. } => pieces
                    .iter()
                    .flat_map(apply_pi)
                    .map(|mut p| {
                        scale(&mut p, &q(6, i64::from(*m)), *m, -1);
                        p
                    })
                    .collect(),
            };
        }
        pieces
    }

    /// The set of output angles (mod 2, in (−1, 1]) of the points of the t-region `dom`.
    pub fn image(&self, dom: &Region) -> Region {
        Region::from_intervals(
            self.eval(dom)
                .iter()
                .map(|p| p.dom.affine_image(&p.a, &p.b))
                .collect(),
        )
        .mod2()
    }

    /// The part of `dom` on which the chain is not injective (points whose image is also the
    /// image of another point of `dom`; all pieces carry the same radial factor, so equal
    /// angles mod 2 mean equal points).
    pub fn non_injective(&self, dom: &Region) -> Region {
        let ps = self.eval(dom);
        let mut bad = Vec::new();
        for (i, pi) in ps.iter().enumerate() {
            for (j, pj) in ps.iter().enumerate() {
                let img = pj.dom.affine_image(&pj.a, &pj.b);
                let own = pi.dom.affine_image(&pi.a, &pi.b);
                for k in overlap_shifts(&own, &img) {
                    if i == j && k == 0 {
                        continue;
                    }
                    bad.push(pi.dom.preimage(&pi.a, &pi.b, &img.shift(&q(2 * k, 1))));
                }
            }
        }
        Region::from_intervals(bad)
    }
}

/// Result of comparing two chains pointwise on a region.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Comparison {
    /// Where the two chains give the same point.
    pub holds: Region,
    /// Where they differ.
    pub fails: Region,
    /// Image under the left chain of the failing part (angles mod 2).
    pub fails_lhs_image: Region,
    /// Human-readable description of the failing pieces (wraps and angle offsets).
    pub detail: Vec<String>,
}

/// Compare `lhs` and `rhs` pointwise (as maps to R² − {0}) on the t-region `dom`.
pub fn compare(lhs: &Chain, rhs: &Chain, dom: &Region) -> Comparison {
    let l = lhs.eval(dom);
    let r = rhs.eval(dom);
    let mut holds = Vec::new();
    let mut fails = Vec::new();
    let mut img = Vec::new();
    let mut detail = Vec::new();
    for pl in &l {
        for pr in &r {
            let d = pl.dom.intersect(&pr.dom);
            if d.is_empty() {
                continue;
            }
            let same =
                pl.b == pr.b && is_integer(&((&pl.a - &pr.a) / q(2, 1))) && pl.radial == pr.radial;
            if same {
                holds.push(d);
            } else {
                detail.push(format!(
                    "t ∈ {d}: lhs angle/π = {} + {}·t (Π wraps {:?}), rhs angle/π = {} + {}·t (Π wraps {:?})",
                    pl.a, pl.b, pl.wraps, pr.a, pr.b, pr.wraps
                ));
                img.push(d.affine_image(&pl.a, &pl.b));
                fails.push(d);
            }
        }
    }
    Comparison {
        holds: Region::from_intervals(holds),
        fails: Region::from_intervals(fails),
        fails_lhs_image: Region::from_intervals(img).mod2(),
        detail,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interval_intersection_keeps_the_stricter_end() {
        // Equal ends: closed only if both are (mutation campaign: `>`/`>=`, `&&`/`||`).
        let closed = Interval::closed(q(0, 1), q(1, 1));
        let open_lo = Interval::open_closed(q(0, 1), q(1, 1));
        assert_eq!(closed.intersect(&open_lo), open_lo);
        assert_eq!(open_lo.intersect(&closed), open_lo);
        let open_hi = Interval::closed_open(q(0, 1), q(1, 1));
        assert_eq!(closed.intersect(&open_hi), open_hi);
        assert_eq!(open_hi.intersect(&closed), open_hi);
    }

    #[test]
    fn region_union_merges_only_touching_intervals() {
        let a = Interval::closed(q(0, 1), q(1, 1));
        let b = Interval::closed(q(2, 1), q(3, 1));
        let r = Region::from_intervals(vec![b.clone(), a.clone()]);
        assert_eq!(r.0, vec![a.clone(), b]);
        // [0, 1] ∪ (1, 2] = [0, 2]; [0, 1) ∪ (1, 2] stays two pieces.
        let c = Interval::open_closed(q(1, 1), q(2, 1));
        assert_eq!(
            Region::from_intervals(vec![a, c.clone()]).0,
            vec![Interval::closed(q(0, 1), q(2, 1))]
        );
        let d = Interval::closed_open(q(0, 1), q(1, 1));
        assert_eq!(Region::from_intervals(vec![d, c]).0.len(), 2);
        // An interval inside the last one leaves it alone; one that extends it brings its own
        // upper end: [0, 3] ∪ [1, 2] = [0, 3], [0, 1] ∪ [1/2, 2) = [0, 2) (it used to come out
        // as [0, 2], the closedness read after the end had moved).
        let big = Interval::closed(q(0, 1), q(3, 1));
        assert_eq!(
            Region::from_intervals(vec![big.clone(), Interval::closed(q(1, 1), q(2, 1))]).0,
            vec![big]
        );
        assert_eq!(
            Region::from_intervals(vec![
                Interval::closed(q(0, 1), q(1, 1)),
                Interval::closed_open(q(1, 2), q(2, 1))
            ])
            .0,
            vec![Interval::closed_open(q(0, 1), q(2, 1))]
        );
    }

    #[test]
    fn shift_windows_are_exact() {
        // [5/2, 3] + 2k meets (−1, 1] only for k = −1.
        assert_eq!(shift_range(&q(5, 2), &q(3, 1)), -1..=-1);
        // [−1, 1]: k = 0, and k = 1 for the point −1 + 2 = 1 (empty when −1 is an open end,
        // as in (−1, 1]: the callers drop it); [1, 3]: k = 0 (the point 1) and k = −1.
        assert_eq!(shift_range(&q(-1, 1), &q(1, 1)), 0..=1);
        assert_eq!(shift_range(&q(1, 1), &q(3, 1)), -1..=0);
        // Images far from (−1, 1] (chains ending in rotations are not reduced): own = [4, 5]
        // meets img = (−1, 0] + 2k for k = 2, 3. (Before, the window was taken around
        // −(own − img) with slack, which held only for images near (−1, 1].)
        let own = Interval::closed(q(4, 1), q(5, 1));
        let img = Interval::open_closed(q(-1, 1), q(0, 1));
        assert_eq!(overlap_shifts(&own, &img), 2..=3);
        assert_eq!(overlap_shifts(&img, &own), -3..=-2);
    }

    #[test]
    fn conjugated_rotation_wraps_exactly_for_degree_three() {
        // g_u∘M_{−2π/3}∘g_u⁻¹ vs M_{−π/3} on (−1/3, 1/3), m_u = 3.
        let lhs = Chain(vec![
            PMap::g("g_u", 3),
            PMap::rot("M", q(-2, 3)),
            PMap::g_inv("g_u⁻¹", 3),
        ]);
        let rhs = Chain(vec![PMap::rot("M_{−π/3}", q(-1, 3))]);
        let c = compare(&lhs, &rhs, &Region::of(Interval::open(q(-1, 3), q(1, 3))));
        assert_eq!(
            c.fails,
            Region::of(Interval::open_closed(q(-1, 3), q(-1, 6)))
        );
        assert_eq!(c.holds, Region::of(Interval::open(q(-1, 6), q(1, 3))));
        // g_v is injective on (−1, 1] iff m ≤ 6.
        let g7 = Chain(vec![PMap::g("g", 7)]);
        assert!(!g7
            .non_injective(&Region::of(Interval::pi_range()))
            .is_empty());
        let g6 = Chain(vec![PMap::g("g", 6)]);
        assert!(g6
            .non_injective(&Region::of(Interval::pi_range()))
            .is_empty());
        // After a rotation by π/2 the chain has two pieces (Π wraps at t = 1/2), whose images
        // touch: g_7 ∘ R identifies φ = Π(t + 1/2) with φ ∓ 12/7 exactly where g_7 does,
        // on (−1, −5/7] ∪ (5/7, 1] in φ, i.e. t ∈ (3/14, 11/14]; g_6 ∘ R is injective.
        let r = || PMap::rot("R", q(1, 2));
        let pi = Region::of(Interval::pi_range());
        assert_eq!(Chain(vec![PMap::g("g", 7), r()]).eval(&pi).len(), 2);
        assert_eq!(
            Chain(vec![PMap::g("g", 7), r()]).non_injective(&pi),
            Region::of(Interval::open_closed(q(3, 14), q(11, 14)))
        );
        assert!(Chain(vec![PMap::g("g", 6), r()])
            .non_injective(&pi)
            .is_empty());
    }
}
