//! Exact decision procedures for every condition of Def. 3.4.1 and the Grimm–Hughes variant of
//! App. A.2 on [`Exact1d`] data: sets, images, preimages and compositions are computed exactly
//! over interval pieces, so each verdict is decided, not sampled.

use super::data::{Exact1d, Piece};
use super::interval::{fmt_q, mid, q_to_f64, Interval, OpenSet, Q};
use crate::gluing::data::Idx;
use crate::report::{dev_max, Check, CheckResult, OnError, Witness};
use num_traits::{One, Signed, Zero};
use serde_json::json;

/// {x ∈ p.dom : a·x + b ∈ iv} for one piece p and one open interval: an open interval or
/// empty. `ainv` is 1/a (ignored for a constant piece).
fn piece_preimage_interval(p: &Piece, ainv: &Q, iv: &Interval) -> Option<Interval> {
    if p.a.is_zero() {
        // A constant piece: everything or nothing (only reachable on ill-formed data).
        return iv.contains(&p.b).then(|| p.dom.clone());
    }
    Interval::between((&iv.lo - &p.b) * ainv, (&iv.hi - &p.b) * ainv)?.intersect(&p.dom)
}

fn inverse_slope(p: &Piece) -> Q {
    if p.a.is_zero() {
        Q::zero()
    } else {
        Q::one() / &p.a
    }
}

/// The exact preimage of `set` under one affine piece, inside the piece's domain.
pub fn piece_preimage(p: &Piece, set: &OpenSet) -> OpenSet {
    let ainv = inverse_slope(p);
    let parts = set.parts();
    // The parts are sorted and disjoint: only a contiguous run of them meets the image
    // p(dom), found by bisection (a file can list a hundred pieces). A constant piece has no
    // image interval and is tested against every part.
    let run = match Interval::between(p.eval(&p.dom.lo), p.eval(&p.dom.hi)) {
        None => parts,
        Some(image) => {
            let first = parts.partition_point(|iv| iv.hi <= image.lo);
            let end = parts.partition_point(|iv| iv.lo < image.hi).max(first);
            &parts[first..end]
        }
    };
    OpenSet::from_intervals(
        run.iter()
            .filter_map(|iv| piece_preimage_interval(p, &ainv, iv)),
    )
}

/// φ_ji⁻¹(set) = {x ∈ Ω_ij : φ_ji(x) ∈ set}, with φ_ji given by `pieces` (key (i, j)).
pub fn preimage(pieces: &[Piece], set: &OpenSet) -> OpenSet {
    // One normalisation of all the parts, not a union per piece (quadratic in the pieces).
    OpenSet::from_intervals(
        pieces
            .iter()
            .flat_map(|p| piece_preimage(p, set).parts().to_vec()),
    )
}

/// One cell of a composition: on `cell`, the composite is x ↦ a·x + b.
#[derive(Clone, Debug)]
pub struct Cell {
    /// The interval on which the composite is affine.
    pub cell: Interval,
    /// Slope of the composite on `cell`.
    pub a: Q,
    /// Offset of the composite on `cell`.
    pub b: Q,
}

/// The cells of second ∘ first, where both are piecewise affine: for each pair of pieces
/// (P of first, R of second) the interval {x ∈ P : P(x) ∈ R} with composite coefficients.
pub fn compose(first: &[Piece], second: &[Piece]) -> Vec<Cell> {
    let mut out = Vec::new();
    for p in first {
        let ainv = inverse_slope(p);
        for r in second {
            if let Some(cell) = piece_preimage_interval(p, &ainv, &r.dom) {
                out.push(Cell {
                    cell,
                    a: &r.a * &p.a,
                    b: &r.a * &p.b + &r.b,
                });
            }
        }
    }
    out
}

/// φ_kj ∘ φ_ji as cells, per (i, j, k), computed once for the cocycle checks that share them
/// (3(c) and both readings of Grimm–Hughes compose the same pairs).
#[derive(Default)]
pub struct Compositions {
    cells: std::collections::BTreeMap<(Idx, Idx, Idx), Vec<Cell>>,
}

impl Compositions {
    /// The cells of φ_kj ∘ φ_ji (see [`compose`]).
    pub fn get(&mut self, g: &Exact1d, i: Idx, j: Idx, k: Idx) -> &[Cell] {
        self.cells
            .entry((i, j, k))
            .or_insert_with(|| compose(g.pieces(i, j), g.pieces(j, k)))
    }
}

/// Compare composite cells with the pieces of `target` on `restrict`; every disagreement is
/// reported through `bad(x, lhs, rhs)` at the midpoint x of an elementary interval (between
/// consecutive endpoints of cells, pieces and `restrict`) where some cell and some piece cover
/// x with different coefficients. Returns the number of elementary intervals compared.
///
/// A sweep over the sorted endpoints with the covering coefficients counted, not the
/// |cells| × |target| pairs: `compose` yields up to |P|² cells, so pairing them with P pieces was
/// cubic and a 4 KiB file of overlapping pieces took seconds.
fn compare_cells(
    cells: &[Cell],
    target: &[Piece],
    restrict: &OpenSet,
    mut bad: impl FnMut(&Q, &Q, &Q),
) -> u64 {
    type Coef = (Q, Q);
    /// What opens or closes at an endpoint.
    enum Side {
        Cell(Coef),
        Target(Coef),
        Restrict,
    }
    let mut events: Vec<(Q, bool, Side)> = Vec::new();
    for c in cells {
        let k = (c.a.clone(), c.b.clone());
        events.push((c.cell.lo.clone(), true, Side::Cell(k.clone())));
        events.push((c.cell.hi.clone(), false, Side::Cell(k)));
    }
    for t in target {
        let k = (t.a.clone(), t.b.clone());
        events.push((t.dom.lo.clone(), true, Side::Target(k.clone())));
        events.push((t.dom.hi.clone(), false, Side::Target(k)));
    }
    for r in restrict.parts() {
        events.push((r.lo.clone(), true, Side::Restrict));
        events.push((r.hi.clone(), false, Side::Restrict));
    }
    events.sort_by(|x, y| x.0.cmp(&y.0));
    // Coefficients covering the current elementary interval, with multiplicity: [cells, target].
    let mut active: [std::collections::BTreeMap<Coef, usize>; 2] = Default::default();
    let mut in_restrict = 0usize;
    let mut n = 0;
    let mut e = 0;
    while e < events.len() {
        let at = events[e].0.clone();
        // Apply every event at this endpoint; open intervals do not contain it.
        while e < events.len() && events[e].0 == at {
            let (_, opens, side) = &events[e];
            let (m, k) = match side {
                Side::Restrict => {
                    if *opens {
                        in_restrict += 1;
                    } else {
                        in_restrict = in_restrict.saturating_sub(1);
                    }
                    e += 1;
                    continue;
                }
                Side::Cell(k) => (&mut active[0], k),
                Side::Target(k) => (&mut active[1], k),
            };
            if *opens {
                *m.entry(k.clone()).or_insert(0) += 1;
            } else if let Some(c) = m.get_mut(k) {
                *c -= 1;
                if *c == 0 {
                    m.remove(k);
                }
            }
            e += 1;
        }
        let Some(next) = events.get(e).map(|x| &x.0) else {
            break;
        };
        if in_restrict == 0 || active[0].is_empty() || active[1].is_empty() {
            continue;
        }
        n += 1;
        // Two affine maps agree on an open interval iff their coefficients agree.
        let pair = active[0].keys().find_map(|c| {
            active[1]
                .keys()
                .find(|t| *t != c)
                .map(|t| (c.clone(), t.clone()))
        });
        if let Some(((ca, cb), (ta, tb))) = pair {
            let x = where_differ(&at, next, (&ca, &cb), (&ta, &tb));
            bad(&x, &(&ta * &x + &tb), &(&ca * &x + &cb));
        }
    }
    n
}

/// A point of the open interval (lo, hi) where the affine maps x ↦ a·x + b and x ↦ c·x + d
/// differ, given that their coefficients differ: they agree at one point at most, so of the
/// midpoint and the midpoint of (lo, midpoint) one is a witness (a witness must show two
/// different values, never "3/2 ≠ 3/2").
fn where_differ(lo: &Q, hi: &Q, f: (&Q, &Q), g: (&Q, &Q)) -> Q {
    let x = mid(lo, hi);
    if f.0 * &x + f.1 != g.0 * &x + g.1 {
        x
    } else {
        mid(lo, &x)
    }
}

fn qs(x: &Q) -> serde_json::Value {
    serde_json::Value::String(fmt_q(x))
}

/// Close an exact check: the harness applies rule 3 (nothing examined is skipped).
fn exact(r: Check) -> CheckResult {
    let note = if r.note.is_empty() {
        "exact (rational arithmetic)".to_string()
    } else {
        format!("exact (rational arithmetic); {}", r.note)
    };
    r.finish(note)
}

fn dev(r: &mut Check, d: &Q) {
    let d = q_to_f64(&d.abs());
    r.worst_deviation = Some(dev_max(r.worst_deviation.unwrap_or(0.0), d));
}

/// A value in a witness: a composition the statement needs may be undefined on ill-formed
/// data, and a witness must say so rather than print a made-up number.
fn at(v: &Option<Q>) -> String {
    v.as_ref().map_or_else(|| "undefined".into(), fmt_q)
}

fn qs_opt(v: &Option<Q>) -> serde_json::Value {
    v.as_ref().map_or(serde_json::Value::Null, qs)
}

/// A composition the statement claims defined is not: an evaluation error, counted and an
/// offence (rule 2 of the harness).
const UNDEFINED: &str = "composition undefined where the statement claims it defined";

/// Def. 3.4.1(1): I ≠ ∅; each Ω_i non-empty and open (open by representation); pairwise disjoint.
pub fn check_1(g: &Exact1d) -> CheckResult {
    let mut r = Check::new("D3.4.1(1)", "p-domains non-empty, open, disjoint");
    let ids = g.ids();
    if ids.is_empty() {
        r.offend(|| {
            Witness::new(
                "the index set I is empty",
                json!({"kind": "empty_index_set"}),
            )
        });
    }
    for (n, &i) in ids.iter().enumerate() {
        r.examined += 1;
        if g.omega(i).is_empty() {
            r.offend(|| Witness::new(format!("Ω_{i} is empty"), json!({"kind": "empty", "i": i})));
        }
        for &j in &ids[n + 1..] {
            r.examined += 1;
            let both = g.omega(i).intersect(&g.omega(j));
            if let Some(p) = both.parts().first() {
                let x = p.midpoint();
                r.offend(|| {
                    Witness::new(
                        format!("Ω_{i} ∩ Ω_{j} = {both} ∋ {}", fmt_q(&x)),
                        json!({"kind": "overlap", "i": i, "j": j, "x": qs(&x)}),
                    )
                });
            }
        }
    }
    exact(r.with_note("open by construction (open rational intervals)"))
}

/// Def. 3.4.1(2): Ω_ij ⊆ Ω_i (open by representation), Ω_ii = Ω_i, Ω_ij ≠ ∅ ⇔ Ω_ji ≠ ∅.
pub fn check_2(g: &Exact1d) -> CheckResult {
    let mut r = Check::new("D3.4.1(2)", "Ω_ij ⊆ Ω_i open, Ω_ii = Ω_i, K symmetric");
    let ids = g.ids();
    for &i in &ids {
        for &j in &ids {
            r.examined += 1;
            let oij = g.omega_ij(i, j);
            if let Some(x) = oij.subset_witness(&g.omega(i)) {
                r.offend(|| {
                    Witness::new(
                        format!("Ω_({i},{j}) = {oij} ⊄ Ω_{i}: {} ∉ Ω_{i}", fmt_q(&x)),
                        json!({"kind": "not_subset", "i": i, "j": j, "x": qs(&x)}),
                    )
                });
            }
            if i == j {
                if let Some(x) = g.omega(i).subset_witness(&oij) {
                    r.offend(|| {
                        Witness::new(
                            format!(
                                "Ω_({i},{i}) = {oij} ≠ Ω_{i}: {} ∈ Ω_{i} ∖ Ω_({i},{i})",
                                fmt_q(&x)
                            ),
                            json!({"kind": "diag", "i": i, "x": qs(&x)}),
                        )
                    });
                }
            }
            if oij.is_empty() != g.omega_ij(j, i).is_empty() {
                r.offend(|| {
                    Witness::new(
                        format!(
                            "Ω_({i},{j}) = {oij} but Ω_({j},{i}) = {}: Ω_ij ≠ ∅ ⇔ Ω_ji ≠ ∅ fails",
                            g.omega_ij(j, i)
                        ),
                        json!({"kind": "asymmetric_k", "i": i, "j": j}),
                    )
                });
            }
        }
    }
    exact(r)
}

/// Def. 3.4.1(3): for (i, j) ∈ K, φ_ji is a well-defined bijection Ω_ij → Ω_ji (affine pieces
/// with a ≠ 0, pieces not overlapping with different maps, images pairwise disjoint, union of
/// images = Ω_ji). Affine pieces with a ≠ 0 are C^∞, so only bijectivity needs deciding.
pub fn check_bijection(g: &Exact1d) -> CheckResult {
    let mut r = Check::new("D3.4.1(3)", "φ_ji : Ω_ij → Ω_ji a (C^∞) bijection");
    for (i, j) in g.k() {
        r.examined += 1;
        let ps = g.pieces(i, j);
        for p in ps {
            if p.a.is_zero() {
                r.offend(|| {
                    Witness::new(
                        format!("φ_({j},{i}) is constant on {}: not injective", p.dom),
                        json!({"kind": "constant", "i": i, "j": j}),
                    )
                });
            }
        }
        for (n, p) in ps.iter().enumerate() {
            for o in &ps[n + 1..] {
                if let Some(c) = p.dom.intersect(&o.dom) {
                    if p.a != o.a || p.b != o.b {
                        let x = where_differ(&c.lo, &c.hi, (&p.a, &p.b), (&o.a, &o.b));
                        r.offend(|| {
                            Witness::new(
                                format!(
                                    "φ_({j},{i}) given twice at {}: {} vs {}",
                                    fmt_q(&x),
                                    fmt_q(&p.eval(&x)),
                                    fmt_q(&o.eval(&x))
                                ),
                                json!({"kind": "not_function", "i": i, "j": j, "x": qs(&x)}),
                            )
                        });
                    }
                }
                let both = p.image().intersect(&o.image());
                if let Some(c) = both.parts().first() {
                    if p.dom.intersect(&o.dom).is_none() {
                        let y = c.midpoint();
                        r.offend(|| {
                            Witness::new(
                                format!(
                                    "φ_({j},{i}) not injective: {} has preimages in {} and {}",
                                    fmt_q(&y),
                                    p.dom,
                                    o.dom
                                ),
                                json!({"kind": "not_injective", "i": i, "j": j, "y": qs(&y)}),
                            )
                        });
                    }
                }
            }
        }
        let image = ps
            .iter()
            .fold(OpenSet::empty(), |acc, p| acc.union(&p.image()));
        let target = g.omega_ij(j, i);
        if let Some(y) = image.subset_witness(&target) {
            r.offend(|| {
                Witness::new(
                    format!(
                        "φ_({j},{i})(Ω_({i},{j})) = {image} ⊄ Ω_({j},{i}) = {target}: {} ∉ Ω_({j},{i})",
                        fmt_q(&y)
                    ),
                    json!({"kind": "not_into", "i": i, "j": j, "y": qs(&y)}),
                )
            });
        }
        if let Some(y) = target.subset_witness(&image) {
            r.offend(|| {
                Witness::new(
                    format!(
                        "φ_({j},{i}) not onto Ω_({j},{i}) = {target}: {} has no preimage",
                        fmt_q(&y)
                    ),
                    json!({"kind": "not_onto", "i": i, "j": j, "y": qs(&y)}),
                )
            });
        }
    }
    exact(r)
}

/// Def. 3.4.1(3a): φ_ii = id_{Ω_i}: every piece of φ_ii is x ↦ 1·x + 0, and φ_ii is defined on
/// all of Ω_i (otherwise the identity of Ω_i is not φ_ii).
pub fn check_3a(g: &Exact1d) -> CheckResult {
    let mut r = Check::new("D3.4.1(3a)", "φ_ii = id");
    for i in g.ids() {
        r.examined += 1;
        for p in g.pieces(i, i) {
            if !(p.a.is_one() && p.b.is_zero()) {
                let x = where_differ(&p.dom.lo, &p.dom.hi, (&p.a, &p.b), (&Q::one(), &Q::zero()));
                let y = p.eval(&x);
                dev(&mut r, &(&y - &x));
                r.offend(|| {
                    Witness::new(
                        format!(
                            "φ_({i},{i})({}) = {} ≠ {} ({})",
                            fmt_q(&x),
                            fmt_q(&y),
                            fmt_q(&x),
                            p.describe()
                        ),
                        json!({"kind": "not_identity", "i": i, "x": qs(&x), "phi": qs(&y)}),
                    )
                });
            }
        }
        if let Some(x) = g.omega(i).subset_witness(&g.omega_ij(i, i)) {
            r.error(OnError::Offence, UNDEFINED, || {
                Witness::new(
                    format!(
                        "φ_({i},{i})({}) undefined, but id_Ω_{i} is defined there",
                        fmt_q(&x)
                    ),
                    json!({"kind": "undefined", "i": i, "x": qs(&x)}),
                )
            });
        }
    }
    exact(r)
}

/// Def. 3.4.1(3b): φ_ij = φ_ji⁻¹ for (i, j) ∈ K, decided as φ_ij ∘ φ_ji = id on Ω_ij (for both
/// orders of every pair, so both inverse laws are covered) including definedness.
pub fn check_3b(g: &Exact1d) -> CheckResult {
    let mut r = Check::new("D3.4.1(3b)", "φ_ij = φ_ji⁻¹");
    for (i, j) in g.k() {
        r.examined += 1;
        let first = g.pieces(i, j);
        let second = g.pieces(j, i);
        let oij = g.omega_ij(i, j);
        let defined = preimage(first, &g.omega_ij(j, i));
        if let Some(x) = oij.subset_witness(&defined) {
            r.error(OnError::Offence, UNDEFINED, || {
                Witness::new(
                    format!("φ_({i},{j})(φ_({j},{i})({})) undefined", fmt_q(&x)),
                    json!({"kind": "undefined", "i": i, "j": j, "x": qs(&x)}),
                )
            });
        }
        let ident = [Piece {
            dom: match (oij.parts().first(), oij.parts().last()) {
                (Some(a), Some(b)) => Interval {
                    lo: a.lo.clone(),
                    hi: b.hi.clone(),
                },
                _ => continue,
            },
            a: Q::one(),
            b: Q::zero(),
        }];
        let cells = compose(first, second);
        let mut found = Vec::new();
        r.examined += compare_cells(&cells, &ident, &oij, |x, _, rhs| {
            found.push((x.clone(), rhs.clone()))
        });
        for (x, z) in found {
            dev(&mut r, &(&z - &x));
            r.offend(|| {
                Witness::new(
                    format!(
                        "φ_({i},{j})(φ_({j},{i})({})) = {} ≠ x",
                        fmt_q(&x),
                        fmt_q(&z)
                    ),
                    json!({"kind": "not_inverse", "i": i, "j": j, "x": qs(&x), "back": qs(&z)}),
                )
            });
        }
    }
    exact(r)
}

/// The domain of the cocycle condition: φ_ji⁻¹(Ω_ji ∩ Ω_jk).
pub fn cocycle_domain(g: &Exact1d, i: Idx, j: Idx, k: Idx) -> OpenSet {
    preimage(
        g.pieces(i, j),
        &g.omega_ij(j, i).intersect(&g.omega_ij(j, k)),
    )
}

/// Def. 3.4.1(3c), decided: for all i, j, k with Ω_ji ∩ Ω_jk ≠ ∅, D = φ_ji⁻¹(Ω_ji ∩ Ω_jk) ⊆ Ω_ik
/// (exact inclusion of interval unions) and φ_ki = φ_kj ∘ φ_ji on D (coefficients compared on
/// every cell of the piecewise-affine composition).
pub fn check_3c(g: &Exact1d) -> CheckResult {
    check_3c_with(g, &mut Compositions::default())
}

/// [`check_3c`] with shared compositions.
pub fn check_3c_with(g: &Exact1d, comp: &mut Compositions) -> CheckResult {
    let mut r = Check::new(
        "D3.4.1(3c)",
        "cocycle: domain inclusion and φ_ki = φ_kj∘φ_ji",
    );
    // Ω_ji ∩ Ω_jk ≠ ∅ needs (j, i) ∈ K and (j, k) ∈ K; same order as i, j, k over I³.
    let adj = g.adjacency();
    for i in g.ids() {
        for &j in adj.incoming(i) {
            for &k in adj.outgoing(j) {
                if g.omega_ij(j, i).intersect(&g.omega_ij(j, k)).is_empty() {
                    continue;
                }
                r.examined += 1;
                let d = cocycle_domain(g, i, j, k);
                let oik = g.omega_ij(i, k);
                let (outside, points) = d.minus(&oik);
                for x in outside.parts().iter().map(|p| p.midpoint()).chain(points) {
                    let y = g.phi(j, i, &x);
                    let z = y.as_ref().and_then(|y| g.phi(k, j, y));
                    r.offend(|| {
                        Witness::new(
                            format!(
                                "(i,j,k)=({i},{j},{k}): x = {} ∈ φ_({j},{i})⁻¹(Ω_({j},{i}) ∩ Ω_({j},{k})) = {d} but x ∉ Ω_({i},{k}) = {oik}; so {} ∼ {} ∼ {} yet φ_({k},{i})({}) is undefined",
                                fmt_q(&x), fmt_q(&x), at(&y), at(&z), fmt_q(&x)
                            ),
                            json!({"kind": "inclusion", "i": i, "j": j, "k": k, "x": qs(&x), "y": qs_opt(&y), "z": qs_opt(&z)}),
                        )
                    });
                }
                let cells = comp.get(g, i, j, k);
                let mut found = Vec::new();
                r.examined += compare_cells(cells, g.pieces(i, k), &d, |x, l, rr| {
                    found.push((x.clone(), l.clone(), rr.clone()))
                });
                for (x, lhs, rhs) in found {
                    dev(&mut r, &(&lhs - &rhs));
                    r.offend(|| {
                        Witness::new(
                            format!(
                                "(i,j,k)=({i},{j},{k}): φ_({k},{i})({}) = {} ≠ φ_({k},{j})(φ_({j},{i})(x)) = {}",
                                fmt_q(&x), fmt_q(&lhs), fmt_q(&rhs)
                            ),
                            json!({"kind": "equation", "i": i, "j": j, "k": k, "x": qs(&x), "lhs": qs(&lhs), "rhs": qs(&rhs)}),
                        )
                    });
                }
            }
        }
    }
    if r.worst_deviation.is_none() && !r.failed() {
        r.worst_deviation = Some(0.0);
    }
    exact(r)
}

/// App. A.2, the Grimm–Hughes cocycle condition, decided: for all i, j, k and x ∈ Ω_ij ∩ Ω_ik,
/// φ_ki(x) = φ_kj ∘ φ_ji(x). `strict = false`: required where the right side is defined (the
/// reading under which App. A.2 calls it "too weak"); `strict = true`: the right side must
/// also be defined on all of Ω_ij ∩ Ω_ik.
pub fn check_grimm_hughes(g: &Exact1d, strict: bool) -> CheckResult {
    check_grimm_hughes_with(g, strict, &mut Compositions::default())
}

/// [`check_grimm_hughes`] with shared compositions.
pub fn check_grimm_hughes_with(g: &Exact1d, strict: bool, comp: &mut Compositions) -> CheckResult {
    let (id, name) = if strict {
        (
            "CA.2-GH-strict",
            "Grimm–Hughes cocycle, RHS required defined",
        )
    } else {
        ("CA.2-GH", "Grimm–Hughes cocycle (where both sides defined)")
    };
    let mut r = Check::new(id, name);
    // Ω_ij ∩ Ω_ik ≠ ∅ needs (i, j) ∈ K and (i, k) ∈ K; same order as i, j, k over I³.
    let adj = g.adjacency();
    for i in g.ids() {
        for &j in adj.outgoing(i) {
            for &k in adj.outgoing(i) {
                let e = g.omega_ij(i, j).intersect(&g.omega_ij(i, k));
                if e.is_empty() {
                    continue;
                }
                r.examined += 1;
                if strict {
                    let defined = cocycle_domain(g, i, j, k);
                    let (outside, points) = e.minus(&defined);
                    for x in outside.parts().iter().map(|p| p.midpoint()).chain(points) {
                        let y = g.phi(j, i, &x);
                        r.offend(|| {
                            Witness::new(
                                format!(
                                    "(i,j,k)=({i},{j},{k}): x = {} ∈ Ω_({i},{j}) ∩ Ω_({i},{k}) but φ_({j},{i})(x) = {} ∉ Ω_({j},{k}), so φ_({k},{j})∘φ_({j},{i})(x) is undefined",
                                    fmt_q(&x), at(&y)
                                ),
                                json!({"kind": "rhs_undefined", "i": i, "j": j, "k": k, "x": qs(&x), "y": qs_opt(&y)}),
                            )
                        });
                    }
                }
                let cells = comp.get(g, i, j, k);
                let mut found = Vec::new();
                r.examined += compare_cells(cells, g.pieces(i, k), &e, |x, l, rr| {
                    found.push((x.clone(), l.clone(), rr.clone()))
                });
                for (x, lhs, rhs) in found {
                    dev(&mut r, &(&lhs - &rhs));
                    r.offend(|| {
                        Witness::new(
                            format!("(i,j,k)=({i},{j},{k}): φ_({k},{i})({}) = {} ≠ φ_({k},{j})∘φ_({j},{i})(x) = {}", fmt_q(&x), fmt_q(&lhs), fmt_q(&rhs)),
                            json!({"kind": "equation", "i": i, "j": j, "k": k, "x": qs(&x)}),
                        )
                    });
                }
            }
        }
    }
    exact(r)
}

/// Separating balls for one pair (x, y) of Def. 3.4.1(4), exact.
#[derive(Clone, Debug, PartialEq)]
pub struct Separation {
    /// First chart index of the pair (i, j) ∈ K.
    pub i: Idx,
    /// Second chart index.
    pub j: Idx,
    /// x ∈ ∂Ω_ij ∩ Ω_i.
    pub x: Q,
    /// y ∈ ∂Ω_ji ∩ Ω_j.
    pub y: Q,
    /// Radius of V_x: min(d / (2A), δ).
    pub r_x: Q,
    /// Radius of V_y: d / 2.
    pub r_y: Q,
}

/// ∂Ω_ij ∩ Ω_i.
pub fn glued_boundary(g: &Exact1d, i: Idx, j: Idx) -> Vec<Q> {
    let om = g.omega(i);
    g.omega_ij(i, j)
        .boundary()
        .into_iter()
        .filter(|x| om.contains(x))
        .collect()
}

/// Def. 3.4.1(4), decided. For x ∈ ∂Ω_ij ∩ Ω_i, only the pieces P of φ_ji whose closure
/// contains x meet small balls V_x; each extends affinely to x with limit L_P = a_P·x + b_P.
/// Claim: (4) fails at (x, y) iff L_P = y for some such P. If so, φ_ji maps P ∩ V_x onto an
/// interval of Ω_ji with endpoint y, which meets every V_y ∩ Ω_ji. If not, with
/// d = min_P |L_P − y| > 0, A = max_P |a_P| and δ = distance from x to the other pieces, the
/// balls r_x = min(d / (2A), δ), r_y = d / 2 work: φ_ji(V_x ∩ Ω_ij) ⊆ ∪_P B(L_P, d/2), disjoint
/// from B(y, d/2). Returns the verdict and the radii of every separated pair.
pub fn check_4_with_radii(g: &Exact1d) -> (CheckResult, Vec<Separation>) {
    let mut r = Check::new("D3.4.1(4)", "Hausdorff condition (separating balls)");
    let mut seps = Vec::new();
    for (i, j) in g.k() {
        if i == j {
            continue;
        }
        let ys = glued_boundary(g, j, i);
        for x in glued_boundary(g, i, j) {
            let (touch, other): (Vec<&Piece>, Vec<&Piece>) = g
                .pieces(i, j)
                .iter()
                .partition(|p| p.dom.closure_contains(&x));
            // δ: distance from x to the pieces whose closure misses x (independent of y).
            let delta = other
                .iter()
                .map(|o| {
                    if x <= o.dom.lo {
                        &o.dom.lo - &x
                    } else {
                        &x - &o.dom.hi
                    }
                })
                .min();
            for y in &ys {
                r.examined += 1;
                if let Some(p) = touch.iter().find(|p| &p.eval(&x) == y) {
                    r.worst_deviation = Some(0.0);
                    r.offend(|| {
                        Witness::new(
                            format!(
                                "(i,j)=({i},{j}): x = {} ∈ ∂Ω_({i},{j}) ∩ Ω_{i}, y = {} ∈ ∂Ω_({j},{i}) ∩ Ω_{j}, and φ_({j},{i}) ({}) extends continuously with x ↦ y: no balls separate them",
                                fmt_q(&x), fmt_q(y), p.describe()
                            ),
                            json!({"kind": "not_separated", "i": i, "j": j, "x": qs(&x), "y": qs(y)}),
                        )
                    });
                    continue;
                }
                let d = touch
                    .iter()
                    .map(|p| (p.eval(&x) - y).abs())
                    .min()
                    .unwrap_or_else(|| Q::from_integer(1.into()));
                let amax = touch
                    .iter()
                    .map(|p| p.a.abs())
                    .max()
                    .filter(|a| !a.is_zero())
                    .unwrap_or_else(Q::one);
                let two = Q::from_integer(2.into());
                let mut r_x = &d / (&two * amax);
                if let Some(delta) = &delta {
                    r_x = r_x.min(delta.clone());
                }
                seps.push(Separation {
                    i,
                    j,
                    x: x.clone(),
                    y: y.clone(),
                    r_x,
                    r_y: d / two,
                });
            }
        }
    }
    let listed: Vec<String> = seps
        .iter()
        .take(6)
        .map(|s| {
            format!(
                "({},{}) x={} y={}: r_x={}, r_y={}",
                s.i,
                s.j,
                fmt_q(&s.x),
                fmt_q(&s.y),
                fmt_q(&s.r_x),
                fmt_q(&s.r_y)
            )
        })
        .collect();
    r.note = format!(
        "{} separated pair(s){}{}",
        seps.len(),
        if listed.is_empty() { "" } else { "; radii " },
        listed.join("; ")
    );
    (exact(r), seps)
}

/// Def. 3.4.1(4), decided (see [`check_4_with_radii`]).
pub fn check_4(g: &Exact1d) -> CheckResult {
    check_4_with_radii(g).0
}

/// Every exact check of Def. 3.4.1 and App. A.2, in the order of the definition.
pub fn check_all(g: &Exact1d) -> Vec<CheckResult> {
    let mut comp = Compositions::default();
    vec![
        check_1(g),
        check_2(g),
        check_bijection(g),
        check_3a(g),
        check_3b(g),
        check_3c_with(g, &mut comp),
        check_grimm_hughes_with(g, false, &mut comp),
        check_grimm_hughes_with(g, true, &mut comp),
        check_4(g),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gluing::exact1d::data::q;

    /// A witness of two affine maps that differ must show two different values, even when they
    /// meet at the midpoint of the interval: x ↦ x and x ↦ 2 − x on (0, 2) meet at 1.
    #[test]
    fn d3_4_1_3c_witness_point_shows_two_different_values() {
        let (f, g) = ((q(1, 1), q(0, 1)), (q(-1, 1), q(2, 1)));
        let x = where_differ(&q(0, 1), &q(2, 1), (&f.0, &f.1), (&g.0, &g.1));
        assert_eq!(x, q(1, 2));
        assert_ne!(&f.0 * &x + &f.1, &g.0 * &x + &g.1);
        // Where they do not meet at the midpoint, the midpoint is the witness.
        let h = (q(1, 1), q(1, 1));
        let y = where_differ(&q(0, 1), &q(2, 1), (&f.0, &f.1), (&h.0, &h.1));
        assert_eq!(y, q(1, 1));
    }
}
